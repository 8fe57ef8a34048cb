// Test helper: the independent reference for forward sensitivities (docs/model.md 10). A
// sensitivity d column / d p is checked against finite differences of FULL runs of the
// scenario with p moved by `--set p=value +- h`: nothing of the sensitivity machinery (no
// sensitivity equation, no df/dp, no chain rule) enters the reference, only plain
// trajectories integrated at tight tolerance.
//
// The quotients are Richardson-extrapolated over steps h, h/2, h/4, at steps from 0.3 to
// 2e-5 of the parameter; each column keeps the two extrapolations (from disjoint runs) that agree
// best, and their difference is the reference's own uncertainty, checked and reported beside the
// error (DifferenceReference).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/scenario/sensitivity_run.h"
#include "musclesim/solver/simulation.h"

namespace musclesim::testing {

// `path=value` as `--set` takes it, with every digit of the double (17 significant digits
// read back exactly), so that the reference runs at exactly the values it divides by.
inline std::string SetTo(const std::string& path, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  return path + "=" + text;
}

// A full run's trajectory in the columns a sensitivity run differentiates
// (scenario/sensitivity_run.h), by their names, from the plain runs' samples.
struct FullTrajectory {
  std::vector<double> times;
  std::vector<std::string> columns;
  std::vector<double> values;  // rows x columns, row-major
  std::size_t rows() const { return times.size(); }
  double value(std::size_t row, std::size_t column) const {
    return values[row * columns.size() + column];
  }
};

namespace detail {

// A single actuator's row: length, shortening_velocity, activation (a state only with
// activation dynamics), tension_passive, tension_active, tension_total.
inline void AppendActuatorRow(FullTrajectory& out, const ActuatorSample& s, bool activation) {
  out.values.push_back(s.length);
  out.values.push_back(s.shortening_velocity);
  if (activation) out.values.push_back(s.activation);
  out.values.push_back(s.tension.passive);
  out.values.push_back(s.tension.active);
  out.values.push_back(s.tension.total);
}

// In 2 or 3 dimensions a free node's columns are its coordinates, NODE.x, NODE.y (NODE.z),
// then their rates NODE.vx ..., read from the sample's d numbers per node.
inline FullTrajectory FromNetworkRun(const Scenario& spec, const NetworkRunResult& result) {
  FullTrajectory out;
  out.times = result.times;
  const std::size_t d = static_cast<std::size_t>(spec.space.dimensions);
  const char* const axes[] = {"x", "y", "z"};
  for (const Node& node : spec.nodes) {
    if (node.kind != NodeKind::kFree) continue;
    if (d > 1) {
      for (std::size_t c = 0; c < d; ++c) out.columns.push_back(node.name + "." + axes[c]);
      for (std::size_t c = 0; c < d; ++c) out.columns.push_back(node.name + ".v" + axes[c]);
      continue;
    }
    out.columns.push_back(node.name + ".position");
    out.columns.push_back(node.name + ".velocity");
  }
  for (const Element& element : spec.elements) {
    out.columns.push_back(element.name + ".length");
    out.columns.push_back(element.name + ".tension");
    if (element.kind != ElementKind::kActuator) continue;
    if (element.excitation) out.columns.push_back(element.name + ".activation");
    out.columns.push_back(element.name + ".tension_passive");
    out.columns.push_back(element.name + ".tension_active");
  }
  for (const NetworkSample& sample : result.samples) {
    for (std::size_t i = 0; i < spec.nodes.size(); ++i) {
      if (spec.nodes[i].kind != NodeKind::kFree) continue;
      if (d > 1) {
        for (std::size_t c = 0; c < d; ++c) out.values.push_back(sample.position[i * d + c]);
        for (std::size_t c = 0; c < d; ++c) out.values.push_back(sample.velocity[i * d + c]);
        continue;
      }
      out.values.push_back(sample.position[i]);
      out.values.push_back(sample.velocity[i]);
    }
    for (std::size_t e = 0; e < spec.elements.size(); ++e) {
      const ElementSample& element = sample.elements[e];
      out.values.push_back(element.length);
      out.values.push_back(element.tension);
      if (spec.elements[e].kind != ElementKind::kActuator) continue;
      if (spec.elements[e].excitation) out.values.push_back(element.activation);
      out.values.push_back(element.parts.passive);
      out.values.push_back(element.parts.active);
    }
  }
  return out;
}

}  // namespace detail

// The full run of `scenario` (a single actuator or a network) with `extra` added to
// `overrides`, by the plain integrator (Simulation::Run of the scenario's network, no
// sensitivity in it); rows on the scenario's grid, or at listed `times`. A single actuator's
// rows are its actuator's samples (ActuatorSampleOf), as its sensitivity columns are.
inline FullTrajectory FullRun(const std::string& scenario,
                              const std::vector<std::string>& overrides,
                              const std::string& extra = "",
                              const std::vector<double>& times = {}) {
  std::vector<std::string> all = overrides;
  if (!extra.empty()) all.push_back(extra);
  const Scenario spec = LoadScenario(scenario, all);
  NetworkRunRequest request = spec.Request();
  request.output_times = times;
  Simulation simulation;
  const NetworkRunResult result = simulation.Run(spec.Build(), spec.solver, request);
  EXPECT_EQ(result.stats.status, RunStatus::kCompleted) << result.stats.message;
  if (spec.form == ScenarioForm::kNetwork) return detail::FromNetworkRun(spec, result);
  const bool activation = spec.elements[kActuatorElement].excitation.has_value();
  FullTrajectory out;
  out.columns = {"length", "shortening_velocity"};
  if (activation) out.columns.push_back("activation");
  for (const char* c : {"tension_passive", "tension_active", "tension_total"}) {
    out.columns.push_back(c);
  }
  out.times = result.times;
  for (const NetworkSample& sample : result.samples) {
    detail::AppendActuatorRow(out, ActuatorSampleOf(sample), activation);
  }
  return out;
}

// RunWithSensitivities of the scenario file `scenario` with `overrides` (as `--set` gives
// them) applied.
inline SensitivityTable RunFileWithSensitivities(const std::string& scenario,
                                                 const std::vector<std::string>& overrides,
                                                 const std::vector<std::string>& parameters,
                                                 const std::vector<double>& times = {}) {
  return RunWithSensitivities(LoadScenario(scenario, overrides), parameters, times);
}

// One parameter to differentiate by: its path, its value as written in the scenario (the
// test's own copy, not the library's reading of it), the scale its steps are relative to
// (|value|, or a natural size when the value is 0), and whether only values at or above it
// are valid (a damping of 0: then the quotients are one-sided, forward).
struct Differentiated {
  std::string path;
  double value = 0.0;
  double scale = 1.0;
  bool forward_only = false;
};

inline Differentiated At(const std::string& path, double value) {
  return {path, value, std::abs(value), false};
}

// The steps tried: h_j = 0.3 2^-j times the parameter's scale, j = 0..14 (down to 2e-5).
// Which suits a column depends on how strongly it depends on p: the quotient's share of the
// integrator's error, ~ rtol |C| / (h |dC/dp|), is large for a column that p barely moves (a
// tension held near the load by the force balance, under a passive k_p of 1 N), while the
// truncation error grows with h, and jumps where a step moves a kink (the slack length,
// v = 0) across an output row. Every column takes the steps that suit it (below).
inline constexpr double kLargestRelativeStep = 0.3;
inline constexpr int kHalvings = 14;

// dC/dp by differences of full runs, extrapolated, at the steps that suit each column;
// rows x columns, row-major.
struct Reference {
  std::vector<double> times;
  std::vector<std::string> columns;
  std::vector<double> derivative;   // rows x columns
  std::vector<double> uncertainty;  // its estimated error, rows x columns
  std::vector<double> value_scale;  // per column, max |C| over the run
};

namespace detail {

// D(h): a central difference (p +- h), or a forward one of second order
// (-3 C(p) + 4 C(p + h) - C(p + 2h)) / 2h, both divided by the steps as rounded. Throws
// InputError when the scenario rejects p +- h.
inline std::vector<double> Quotient(const std::string& scenario,
                                    const std::vector<std::string>& overrides,
                                    const Differentiated& p, double h,
                                    const std::vector<double>& times, const FullTrajectory& base) {
  std::vector<double> d(base.values.size());
  const double first = p.forward_only ? p.value + h : p.value - h;
  const double second = p.value + (p.forward_only ? 2.0 : 1.0) * h;
  const FullTrajectory a = FullRun(scenario, overrides, SetTo(p.path, first), times);
  const FullTrajectory b = FullRun(scenario, overrides, SetTo(p.path, second), times);
  EXPECT_EQ(a.times, base.times) << p.path;
  EXPECT_EQ(b.times, base.times) << p.path;
  if (a.values.size() != d.size() || b.values.size() != d.size()) return d;
  for (std::size_t i = 0; i < d.size(); ++i) {
    d[i] = p.forward_only ? (-3.0 * base.values[i] + 4.0 * a.values[i] - b.values[i]) /
                                (2.0 * (first - p.value))
                          : (b.values[i] - a.values[i]) / (second - first);
  }
  return d;
}

// Richardson's step on quotients at h and h/2 whose error leads with h^order.
inline std::vector<double> Extrapolate(const std::vector<double>& at_h,
                                       const std::vector<double>& at_half, int order) {
  const double w = std::ldexp(1.0, order);  // 2^order
  std::vector<double> out(at_h.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = (w * at_half[i] - at_h[i]) / (w - 1.0);
  return out;
}

}  // namespace detail

// The quotients D(h_j) at every step are extrapolated twice over h_j, h_j/2, h_j/4: a
// central quotient's error c2 h^2 + c4 h^4 + c6 h^6 leaves O(h^6); a forward one's,
// c2 h^2 + c3 h^3 + c4 h^4, leaves O(h^4). Two extrapolations from disjoint runs, at steps
// 8 times apart, have errors of different sizes from both sources (truncation and noise),
// so where they agree both are right to about their difference: each column keeps the pair
// that agrees best over the whole run (two wrong estimates agreeing at every row by chance
// is not plausible; at one row it is), their mean as the reference and their difference as
// its uncertainty. A step whose values the scenario rejects (an end of optimal_range passing
// the other) is left out.
inline Reference DifferenceReference(const std::string& scenario,
                                     const std::vector<std::string>& overrides,
                                     const Differentiated& p,
                                     const std::vector<double>& times = {}) {
  const FullTrajectory base = FullRun(scenario, overrides, "", times);
  Reference r;
  r.times = base.times;
  r.columns = base.columns;
  const std::size_t columns = base.columns.size(), n = base.values.size();
  std::vector<std::vector<double>> quotients(kHalvings + 1);  // empty: not a valid step
  for (int j = 0; j <= kHalvings; ++j) {
    const double h = std::ldexp(kLargestRelativeStep, -j) * p.scale;
    try {
      quotients[static_cast<std::size_t>(j)] =
          detail::Quotient(scenario, overrides, p, h, times, base);
    } catch (const InputError&) {
      // p +- h is no valid value: this step is not tried
    }
  }
  const int first_order = 2, second_order = p.forward_only ? 3 : 4;
  std::vector<std::vector<double>> twice(quotients.size());  // at j: from j, j + 1, j + 2
  for (std::size_t j = 0; j + 2 < quotients.size(); ++j) {
    if (quotients[j].empty() || quotients[j + 1].empty() || quotients[j + 2].empty()) continue;
    twice[j] = detail::Extrapolate(
        detail::Extrapolate(quotients[j], quotients[j + 1], first_order),
        detail::Extrapolate(quotients[j + 1], quotients[j + 2], first_order), second_order);
  }
  r.derivative.assign(n, 0.0);
  r.uncertainty.assign(n, std::numeric_limits<double>::infinity());
  std::vector<double> best(columns, std::numeric_limits<double>::infinity());
  for (std::size_t j = 0; j + 3 < twice.size(); ++j) {
    const std::vector<double>& a = twice[j];
    const std::vector<double>& b = twice[j + 3];
    if (a.empty() || b.empty()) continue;
    for (std::size_t c = 0; c < columns; ++c) {
      double worst = 0.0;
      for (std::size_t i = c; i < n; i += columns) worst = std::max(worst, std::abs(a[i] - b[i]));
      if (!(worst < best[c])) continue;
      best[c] = worst;
      for (std::size_t i = c; i < n; i += columns) {
        r.derivative[i] = 0.5 * (a[i] + b[i]);
        r.uncertainty[i] = std::abs(a[i] - b[i]);
      }
    }
  }
  r.value_scale.assign(columns, 0.0);
  for (std::size_t row = 0; row < base.rows(); ++row) {
    for (std::size_t c = 0; c < columns; ++c) {
      r.value_scale[c] = std::max(r.value_scale[c], std::abs(base.value(row, c)));
    }
  }
  return r;
}

// The requirement: relative agreement 1e-5, each column compared at every row against its
// own scale, the largest |reference derivative| over the run.
inline constexpr double kRequiredAgreement = 1e-5;

// A column whose reference derivative is nowhere above 1e-5 |C|max / |p| (relative
// sensitivity 1e-5) does not depend on p (an activation state on a mechanical parameter, an
// end of optimal_range that does not hold the maximum): its reference is the integrators'
// noise, ~ rtol |C| / h, nothing to compare with. There the sensitivity must be flat itself:
// |dC/dp| at most 1e-5 of that floor, a relative sensitivity of 1e-10.
inline constexpr double kFlat = 1e-5;

// The reference must itself be good to well within the requirement: its estimated error at
// most a third of it, over the same scale, so that passing bounds the sensitivity's error by
// 1.3e-5 at worst. (At rtol 1e-12 the noise of the full runs limits the reference to about
// 1e-6 where p barely moves a column: a tension held near the load by the force balance, or
// gaussians[0] of the canonical curve, whose centre lies 3 widths from the motion. Most
// columns reach 1e-7 or better.)
inline constexpr double kReferenceAccuracy = kRequiredAgreement / 3.0;

// The worst disagreement of one parameter's sensitivity columns with the reference.
struct Agreement {
  double worst = 0.0;  // max over columns and rows of |s - ref| / scale
  std::string column;  // where
  double time = 0.0;
  double uncertainty = 0.0;  // the reference's largest estimated error over its scale
  std::string uncertain;     // where
  int flat_columns = 0;      // columns checked for flatness (kFlat)
};

inline Agreement Compare(const SensitivityTable& table, const std::string& path,
                         const Reference& reference, double parameter_scale) {
  Agreement a;
  const std::size_t p = static_cast<std::size_t>(
      std::find(table.parameters.begin(), table.parameters.end(), path) - table.parameters.begin());
  EXPECT_LT(p, table.parameters.size()) << path;
  EXPECT_EQ(table.columns, reference.columns) << path;
  EXPECT_EQ(table.times, reference.times) << path;
  if (p >= table.parameters.size() || table.columns != reference.columns ||
      table.times != reference.times) {
    a.worst = std::numeric_limits<double>::infinity();
    return a;
  }
  const std::size_t columns = table.columns.size();
  for (std::size_t c = 0; c < columns; ++c) {
    double scale = 0.0;
    for (std::size_t row = 0; row < table.rows(); ++row) {
      scale = std::max(scale, std::abs(reference.derivative[row * columns + c]));
    }
    const double floor = kFlat * reference.value_scale[c] / parameter_scale;
    const bool flat = scale <= floor;
    if (flat) {
      ++a.flat_columns;
      scale = floor;
    }
    if (scale == 0.0) scale = 1.0;  // a column 0 throughout (its derivative must be 0 too)
    for (std::size_t row = 0; row < table.rows(); ++row) {
      const double s = table.derivative(row, p, c);
      const double error = std::abs(flat ? s : s - reference.derivative[row * columns + c]) / scale;
      if (!(error <= a.worst)) {  // NaN counts as the worst
        a.worst = error;
        a.column = table.columns[c];
        a.time = table.times[row];
      }
      const double uncertainty = flat ? 0.0 : reference.uncertainty[row * columns + c] / scale;
      if (uncertainty > a.uncertainty) {
        a.uncertainty = uncertainty;
        a.uncertain = table.columns[c];
      }
    }
  }
  return a;
}

// Runs `scenario` with the sensitivities to all of `parameters` at once, and checks each
// against its own difference reference; prints the worst relative error of each.
inline void ExpectSensitivitiesMatchDifferences(const std::string& scenario,
                                                const std::vector<std::string>& overrides,
                                                const std::vector<Differentiated>& parameters,
                                                const std::vector<double>& times = {}) {
  std::vector<std::string> paths;
  for (const Differentiated& p : parameters) paths.push_back(p.path);
  const SensitivityTable table = RunFileWithSensitivities(scenario, overrides, paths, times);
  ASSERT_EQ(table.stats.status, RunStatus::kCompleted) << table.stats.message;
  ASSERT_EQ(table.parameters, paths);
  for (const Differentiated& p : parameters) {
    const Reference reference = DifferenceReference(scenario, overrides, p, times);
    const Agreement a = Compare(table, p.path, reference, p.scale);
    std::printf("[ sensitivity ] %-44s worst %.1e (%s, t = %.4g); reference %.0e (%s)%s\n",
                p.path.c_str(), a.worst, a.column.c_str(), a.time, a.uncertainty,
                a.uncertain.c_str(), a.flat_columns > 0 ? ", some columns flat" : "");
    EXPECT_LE(a.uncertainty, kReferenceAccuracy)
        << p.path << ": the difference reference of " << a.uncertain
        << " is not accurate enough to judge";
    EXPECT_LE(a.worst, kRequiredAgreement)
        << p.path << ": d_" << a.column << "/d_" << p.path << " at t = " << a.time;
  }
}

}  // namespace musclesim::testing
