// Time-series identification: the measured values laid against a run with sensitivities at
// their times, the bounded Levenberg-Marquardt fit (or, for the design, the start alone) and
// the analysis of the Jacobian there.
#include "musclesim/identify/identify_series.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "musclesim/core/bounded_least_squares.h"
#include "identify/identify_series_statistics.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

using identify_series_detail::AnalyseJacobian;
using identify_series_detail::JacobianAnalysis;
using identify_series_detail::ParameterScales;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// One measured value: where it sits in the merged run and in its series.
struct Observation {
  std::size_t series = 0;
  std::size_t column = 0;      // in the series
  std::size_t row = 0;         // in the merged times
  std::size_t run_column = 0;  // in the sensitivity table
  double measured = 0.0;
  double weight = 1.0;
};

// Everything a fit or a design evaluates the model with.
struct Setup {
  std::vector<std::string> paths;
  std::vector<double> times;  // merged over the series
  std::vector<Observation> observations;
  std::vector<double> scenario_values;
  Eigen::VectorXd start, lower, upper;
  std::vector<double> sizes;  // each parameter's scale, from its start and bounds
  bool noise_given = false;
};

// "path=value, ..." of the parameters at `p`, for messages.
std::string Describe(const Setup& setup, const Eigen::VectorXd& p) {
  std::string text;
  for (std::size_t j = 0; j < setup.paths.size(); ++j) {
    text += (text.empty() ? "" : ", ") + setup.paths[j] + "=" +
            FormatNumber(p[static_cast<Eigen::Index>(j)]);
  }
  return text;
}

// Why a run cannot serve the fit, or "" when it can.
std::string Unusable(const SensitivityTable& table, std::size_t rows) {
  if (table.stats.status == RunStatus::kFailed) return "the run failed: " + table.stats.message;
  if (table.stats.status == RunStatus::kLimit || table.rows() != rows) {
    return "the run ended at t = " + FormatNumber(table.stats.final_time) + " (" +
           table.stats.message + "), before the last measured time " +
           FormatNumber(table.times.empty() ? 0.0 : table.times.back());
  }
  return "";
}

ModelPoint Evaluate(const Setup& setup, const SensitivityRunner& run, const Eigen::VectorXd& p) {
  const std::vector<double> values(p.data(), p.data() + p.size());
  const SensitivityTable table = run(setup.paths, values, setup.times, setup.sizes);
  if (const std::string why = Unusable(table, setup.times.size()); !why.empty()) {
    throw EvaluationFailure("at " + Describe(setup, p) + ": " + why);
  }
  const Eigen::Index n = static_cast<Eigen::Index>(setup.observations.size());
  const Eigen::Index np = static_cast<Eigen::Index>(setup.paths.size());
  ModelPoint point{Eigen::VectorXd(n), Eigen::MatrixXd(n, np)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const Observation& o = setup.observations[static_cast<std::size_t>(i)];
    point.predictions[i] = table.value(o.row, o.run_column);
    for (Eigen::Index j = 0; j < np; ++j) {
      point.jacobian(i, j) = table.derivative(o.row, static_cast<std::size_t>(j), o.run_column);
    }
  }
  return point;
}

// Merged times of the series that have them, and of the output grid for those that do not.
std::vector<double> MergedTimes(std::vector<MeasuredSeries>& series,
                                const std::vector<double>& grid) {
  std::vector<double> times;
  for (MeasuredSeries& s : series) {
    if (s.times.empty()) s.times = grid;
    times.insert(times.end(), s.times.begin(), s.times.end());
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

// The scenario as given, on its output grid: its values of the parameters, its columns, the
// span the measured times must lie in, and the grid for a series without times. A scenario
// that refuses the parameters is reported at the first entry it refuses on its own.
SensitivityTable BaselineRun(const IdentifySeriesSpec& spec, const std::vector<std::string>& paths,
                             const SensitivityRunner& run) {
  SensitivityTable baseline;
  try {
    baseline = run(paths, {}, {}, {});
  } catch (const InputError& e) {
    // name the entry at fault: the first parameter the scenario refuses on its own
    for (std::size_t i = 0; i < spec.parameters.size(); ++i) {
      try {
        run({spec.parameters[i].path}, {}, {}, {});
      } catch (const InputError& alone) {
        const std::string key = "parameters[" + std::to_string(i) + "].path";
        const SeriesParameterSpec& given = spec.parameters[i];
        throw InputError(PlaceText(given.at) + ": " + key + " = " + given.path + " ",
                         InputFault{given.at, key, given.path,
                                    "in scenario " + spec.scenario + ": " + alone.what()});
      }
    }
    throw InputError(spec.source + ": scenario " + spec.scenario + " (" +
                         PlaceText(spec.scenario_at) + ") with the parameters of this file",
                     e);
  }
  if (baseline.stats.status == RunStatus::kFailed || baseline.times.empty()) {
    throw std::runtime_error(spec.source + ": scenario " + spec.scenario +
                             " fails as given: " + baseline.stats.message);
  }
  return baseline;
}

// Every measured time within the baseline run's span.
void RequireTimesInRun(const std::vector<MeasuredSeries>& series,
                       const SensitivityTable& baseline) {
  const double first = baseline.times.front(), last = baseline.times.back();
  for (std::size_t s = 0; s < series.size(); ++s) {
    for (std::size_t r = 0; r < series[s].times.size(); ++r) {
      const double t = series[s].times[r];
      if (t >= first && t <= last) continue;
      const std::string label = "series[" + std::to_string(s) + "]";
      const std::string row = std::to_string(series[s].lines[r]);
      throw InputError(
          (series[s].source.empty() ? label + " (row " + row + ")"  // values given in memory
                                    : label + ".csv = " + series[s].source + ":" + row) +
          ": t = " + FormatNumber(t) + " lies outside the scenario's run, from " +
          FormatNumber(first) + " to " + FormatNumber(last) + " s" +
          (baseline.stats.status == RunStatus::kLimit ? " (where " + baseline.stats.message + ")"
                                                      : ""));
    }
  }
}

// The index of series[s]'s column c among the run's differentiated outputs.
std::size_t RunColumn(const std::vector<std::string>& columns, const MeasuredSeries& m,
                      std::size_t s, std::size_t c) {
  const auto found = std::find(columns.begin(), columns.end(), m.columns[c]);
  if (found == columns.end()) {
    std::string known;
    for (const std::string& name : columns) {
      known += (known.empty() ? "" : ", ") + name;
    }
    throw InputError(InputFault{m.at, "series[" + std::to_string(s) + "]", std::nullopt,
                                "column " + m.columns[c] +
                                    " is not an output the scenario's run differentiates; "
                                    "these are: " +
                                    known});
  }
  return static_cast<std::size_t>(found - columns.begin());
}

// Whether the noise is given: for every measured column or for none, and without it the
// series must measure one column (there is no other weight between quantities).
bool NoiseGiven(const IdentifySeriesSpec& spec, std::size_t with_noise, std::size_t without_noise,
                std::size_t distinct_columns) {
  if (with_noise > 0 && without_noise > 0) {
    throw InputError(spec.source +
                     ": noise levels are given for some columns and not for others: "
                     "give one for every measured column (or for none, when every series "
                     "measures one and the same column)");
  }
  if (with_noise == 0 && distinct_columns > 1) {
    throw InputError(spec.source + ": the series measure " + std::to_string(distinct_columns) +
                     " different columns and give no noise levels: give noise: {COLUMN: SD} "
                     "for each, which weighs values of different quantities against each other");
  }
  return with_noise > 0;
}

// setup.observations: the measured columns among the run's differentiated ones, each value
// at its row of the merged times; the noise all or nothing; more values than parameters.
void AddObservations(const IdentifySeriesSpec& spec, const std::vector<MeasuredSeries>& series,
                     const std::vector<std::string>& run_columns, bool design, Setup& setup) {
  std::size_t with_noise = 0, without_noise = 0;
  std::set<std::string> names;
  for (std::size_t s = 0; s < series.size(); ++s) {
    const MeasuredSeries& m = series[s];
    for (std::size_t c = 0; c < m.columns.size(); ++c) {
      const std::size_t run_column = RunColumn(run_columns, m, s, c);
      (std::isnan(m.noise[c]) ? without_noise : with_noise) += 1;
      names.insert(m.columns[c]);
      const double weight = std::isnan(m.noise[c]) ? 1.0 : 1.0 / m.noise[c];
      std::size_t merged = 0;
      for (std::size_t r = 0; r < m.times.size(); ++r) {
        while (setup.times[merged] < m.times[r]) ++merged;
        const double measured = design ? 0.0 : m.values[r * m.columns.size() + c];
        setup.observations.push_back({s, c, merged, run_column, measured, weight});
      }
    }
  }
  setup.noise_given = NoiseGiven(spec, with_noise, without_noise, names.size());
  if (setup.observations.size() <= setup.paths.size()) {
    throw InputError(spec.source + ": " + std::to_string(setup.observations.size()) +
                     " measured values for " + std::to_string(setup.paths.size()) +
                     " parameters: need more values than parameters");
  }
}

// Each parameter's start (the entry's, or the scenario's value) and bounds; the start must
// lie within them.
void SetStartsAndBounds(const IdentifySeriesSpec& spec, Setup& setup) {
  const Eigen::Index np = static_cast<Eigen::Index>(spec.parameters.size());
  setup.start.resize(np);
  setup.lower = Eigen::VectorXd::Constant(np, -kInfinity);
  setup.upper = Eigen::VectorXd::Constant(np, kInfinity);
  for (Eigen::Index j = 0; j < np; ++j) {
    const SeriesParameterSpec& p = spec.parameters[static_cast<std::size_t>(j)];
    setup.start[j] = p.start.value_or(setup.scenario_values[static_cast<std::size_t>(j)]);
    if (p.lower) setup.lower[j] = *p.lower;
    if (p.upper) setup.upper[j] = *p.upper;
    if (!(setup.lower[j] <= setup.start[j] && setup.start[j] <= setup.upper[j])) {
      throw InputError(InputFault{p.at, p.path, std::nullopt,
                                  "starts at the scenario's value " + FormatNumber(setup.start[j]) +
                                      ", outside its bounds [" + FormatNumber(setup.lower[j]) +
                                      ", " + FormatNumber(setup.upper[j]) +
                                      "]: give a start within them"});
    }
  }
}

Setup Prepare(const IdentifySeriesSpec& spec, std::vector<MeasuredSeries> series,
              const SensitivityRunner& run, bool design) {
  Setup setup;
  for (const SeriesParameterSpec& p : spec.parameters) setup.paths.push_back(p.path);
  const SensitivityTable baseline = BaselineRun(spec, setup.paths, run);
  RequireTimesInRun(series, baseline);
  setup.scenario_values = baseline.parameter_values;
  setup.times = MergedTimes(series, baseline.times);
  AddObservations(spec, series, baseline.columns, design, setup);
  SetStartsAndBounds(spec, setup);
  const Eigen::VectorXd sizes = ParameterScales(setup.start, setup.start, setup.lower, setup.upper);
  setup.sizes.assign(sizes.data(), sizes.data() + sizes.size());
  return setup;
}

// The weighted Jacobian W J of a model point.
Eigen::MatrixXd Weighted(const Setup& setup, const Eigen::MatrixXd& jacobian) {
  Eigen::VectorXd w(static_cast<Eigen::Index>(setup.observations.size()));
  for (std::size_t i = 0; i < setup.observations.size(); ++i) {
    w[static_cast<Eigen::Index>(i)] = setup.observations[i].weight;
  }
  return w.asDiagonal() * jacobian;
}

SeriesIdentification Result(const IdentifySeriesSpec& spec, const Setup& setup,
                            const Eigen::VectorXd& estimate, const JacobianAnalysis& a) {
  SeriesIdentification result;
  result.scenario = spec.scenario;
  for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
    const Eigen::Index k = static_cast<Eigen::Index>(j);
    SeriesParameterResult p;
    p.path = spec.parameters[j].path;
    p.scenario_value = setup.scenario_values[j];
    p.start = setup.start[k];
    p.estimate = estimate[k];
    p.standard_error = a.standard_errors[k];
    p.relative_standard_error = a.relative_standard_errors[k];
    p.column_ratio = a.column_ratios[k];
    p.lower = spec.parameters[j].lower;
    p.upper = spec.parameters[j].upper;
    p.verdict = a.verdicts[j];
    result.parameters.push_back(p);
  }
  result.correlation = a.correlation;
  result.singular_values = a.singular_values;
  result.noise_given = setup.noise_given;
  result.variance_factor = a.variance_factor;
  result.values = setup.observations.size();
  result.degrees_of_freedom = a.degrees_of_freedom;
  for (const auto& w : a.weak_directions) result.weak_directions.push_back({w.ratio, w.components});
  return result;
}

}  // namespace

SeriesIdentification FitSeries(const IdentifySeriesSpec& spec,
                               const std::vector<MeasuredSeries>& series,
                               const SensitivityRunner& run, const SeriesFitOptions& options) {
  const Setup setup = Prepare(spec, series, run, false);
  BoundedLeastSquaresProblem problem;
  problem.model = [&](const Eigen::VectorXd& p) { return Evaluate(setup, run, p); };
  const Eigen::Index n = static_cast<Eigen::Index>(setup.observations.size());
  problem.data.resize(n);
  problem.weights.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    problem.data[i] = setup.observations[static_cast<std::size_t>(i)].measured;
    problem.weights[i] = setup.observations[static_cast<std::size_t>(i)].weight;
  }
  problem.start = setup.start;
  problem.lower = setup.lower;
  problem.upper = setup.upper;
  LeastSquaresOptions lm;
  lm.max_evaluations = options.max_evaluations;
  LeastSquaresResult solved;
  try {
    solved = SolveBoundedLeastSquares(problem, lm);
  } catch (const EvaluationFailure& e) {
    throw std::runtime_error(spec.source +
                             ": the scenario's run at the start values cannot "
                             "serve the fit: " +
                             e.what());
  }

  const JacobianAnalysis a =
      AnalyseJacobian(Weighted(setup, solved.at_solution.jacobian),
                      ParameterScales(solved.parameters, setup.start, setup.lower, setup.upper),
                      setup.noise_given, solved.cost, solved.at_bound);
  SeriesIdentification result = Result(spec, setup, solved.parameters, a);
  result.weighted_rss = solved.cost;
  result.iterations = solved.iterations;
  result.evaluations = solved.evaluations;
  result.converged = solved.converged;
  result.stop_reason = solved.stop_reason;
  const double s = std::sqrt(a.variance_factor);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Observation& o = setup.observations[static_cast<std::size_t>(i)];
    const double model = solved.at_solution.predictions[i];
    result.residuals.push_back({o.series, series[o.series].columns[o.column], setup.times[o.row],
                                o.measured, model, (o.measured - model) * o.weight / s});
  }
  return result;
}

SeriesIdentification DesignSeries(const IdentifySeriesSpec& spec,
                                  const std::vector<MeasuredSeries>& series,
                                  const SensitivityRunner& run) {
  const Setup setup = Prepare(spec, series, run, true);
  ModelPoint point;
  try {
    point = Evaluate(setup, run, setup.start);
  } catch (const EvaluationFailure& e) {
    throw std::runtime_error(spec.source +
                             ": the scenario's run at the start values fails: " + e.what());
  }
  const JacobianAnalysis a = AnalyseJacobian(
      Weighted(setup, point.jacobian),
      ParameterScales(setup.start, setup.start, setup.lower, setup.upper), true, 0.0, {});
  return Result(spec, setup, setup.start, a);
}

std::vector<std::string> EstimateOverrides(const SeriesIdentification& fit) {
  std::vector<std::string> overrides;
  for (const SeriesParameterResult& p : fit.parameters) {
    overrides.push_back(p.path + "=" + FormatNumber(p.estimate));
  }
  return overrides;
}

}  // namespace musclesim
