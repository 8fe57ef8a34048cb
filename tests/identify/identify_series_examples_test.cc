// The shipped time-series examples (data/quick_release.yaml, data/tetanus_transducer.yaml)
// identified on the simulator's own sensitivities: recovery from 20 seeded noisy data sets
// made here over a noise-free run of the truth (independent of scripts/make_series_data.py),
// recovery from noise-free data, and parameters the experiment cannot determine flagged.
#include "musclesim/identify/identify_series.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "musclesim/io/readers/identify_series_spec.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/sensitivity_run.h"
#include "support/normal_noise.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// The truth: the values the example's scenario file holds (its data were made from it).
const std::map<std::string, double> kQuickReleaseTruth = {
    {"model.f_iso", 100.0}, {"model.velocity.v_max", 1.0}, {"model.passive.slack_length", 0.105}};
const std::map<std::string, double> kTetanusTruth = {{"model.f_iso", 100.0},
                                                     {"activation_dynamics.tau_activation", 0.015},
                                                     {"activation_dynamics.tau_deactivation", 0.05},
                                                     {"model.passive.slack_length", 0.105},
                                                     {"model.velocity.v_max", 1.0}};

struct Example {
  IdentifySeriesSpec spec;
  std::vector<MeasuredSeries> series;  // the data file's times, columns and noise levels
  std::vector<double> exact;           // the truth's values there, series by series, row-major
};

// The example's data file with its measured values replaced by a noise-free run of its
// scenario (the truth) at the same times.
Example Load(const std::string& name) {
  Example e;
  e.spec = LoadIdentifySeriesSpec(std::string(MUSCLESIM_SOURCE_DIR) + "/data/" + name);
  e.series = ReadMeasuredSeries(e.spec, false);
  std::vector<std::string> paths;
  for (const SeriesParameterSpec& p : e.spec.parameters) paths.push_back(p.path);
  for (MeasuredSeries& s : e.series) {
    const SensitivityTable truth =
        RunWithSensitivities(LoadScenario(e.spec.scenario), paths, s.times);
    EXPECT_EQ(truth.rows(), s.times.size());
    for (std::size_t r = 0; r < s.times.size(); ++r) {
      for (std::size_t c = 0; c < s.columns.size(); ++c) {
        const int column = truth.FindColumn(s.columns[c]);
        s.values[r * s.columns.size() + c] = truth.value(r, static_cast<std::size_t>(column));
      }
    }
    e.exact.insert(e.exact.end(), s.values.begin(), s.values.end());
  }
  return e;
}

// The example's series with seeded N(0, noise^2) added to the exact values.
std::vector<MeasuredSeries> Noisy(const Example& e, std::uint64_t seed) {
  testing::Noise normal(seed);
  std::vector<MeasuredSeries> noisy = e.series;
  for (MeasuredSeries& s : noisy) {
    for (std::size_t i = 0; i < s.values.size(); ++i) {
      s.values[i] += s.noise[i % s.columns.size()] * normal();
    }
  }
  return noisy;
}

SeriesIdentification Fit(const Example& e, const std::vector<MeasuredSeries>& series) {
  return FitSeries(e.spec, series, ScenarioSensitivityRunner(LoadScenario(e.spec.scenario)));
}

// Over 20 seeded data sets, how often each parameter's estimate lies within 3 standard
// errors of the truth. The fits start at the truth, which saves runs: where they start does
// not matter to where they end (the noise-free tests start from the data files' values).
std::map<std::string, int> WithinThreeErrors(const std::string& name,
                                             const std::map<std::string, double>& truth) {
  Example e = Load(name);
  for (SeriesParameterSpec& p : e.spec.parameters) p.start = truth.at(p.path);
  std::map<std::string, int> within;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const SeriesIdentification fit = Fit(e, Noisy(e, seed));
    EXPECT_TRUE(fit.converged) << name << " seed " << seed << ": " << fit.stop_reason;
    for (const SeriesParameterResult& p : fit.parameters) {
      if (p.verdict != Identifiability::kIdentifiable) continue;
      within[p.path] += std::abs(p.estimate - truth.at(p.path)) <= 3.0 * p.standard_error;
    }
  }
  return within;
}

// With right standard errors each estimate is within 3 of them with probability 0.997
// (nearly linear models at this noise): 18 of 20 is a loose floor, and an error that
// understated the spread by half would miss it (within 1.5 true errors: 87%, 17 of 20).
TEST(IdentifySeriesExamples, QuickReleaseRecoversWithinThreeStandardErrors) {
  const auto within = WithinThreeErrors("quick_release.yaml", kQuickReleaseTruth);
  EXPECT_GE(within.at("model.f_iso"), 18);
  EXPECT_GE(within.at("model.velocity.v_max"), 18);
  EXPECT_EQ(within.count("model.passive.slack_length"), 0u);  // never called identifiable
}

TEST(IdentifySeriesExamples, TetanusRecoversWithinThreeStandardErrors) {
  const auto within = WithinThreeErrors("tetanus_transducer.yaml", kTetanusTruth);
  ASSERT_EQ(within.size(), kTetanusTruth.size());  // every parameter identifiable
  for (const auto& [path, count] : within) EXPECT_GE(count, 18) << path;
}

// Noise-free data: the minimum is the truth, found to within the fit's stopping rules and
// the runs' numerical error (rtol 1e-8 in both scenarios): 1e-6 relative.
void ExpectNoiseFreeRecovery(const std::string& name, const std::map<std::string, double>& truth) {
  const Example e = Load(name);
  const SeriesIdentification fit = Fit(e, e.series);
  EXPECT_TRUE(fit.converged) << fit.stop_reason;
  for (const SeriesParameterResult& p : fit.parameters) {
    if (p.verdict == Identifiability::kNegligibleColumn) continue;
    EXPECT_NEAR(p.estimate, truth.at(p.path), 1e-6 * truth.at(p.path)) << p.path;
  }
}

TEST(IdentifySeriesExamples, QuickReleaseRecoversNoiseFreeDataToOneInAMillion) {
  ExpectNoiseFreeRecovery("quick_release.yaml", kQuickReleaseTruth);
}

TEST(IdentifySeriesExamples, TetanusRecoversNoiseFreeDataToOneInAMillion) {
  ExpectNoiseFreeRecovery("tetanus_transducer.yaml", kTetanusTruth);
}

TEST(IdentifySeriesExamples, TheSlackLengthAQuickReleaseNeverReachesIsFlagged) {
  // the length stays below 0.1 m < 0.105 m: the passive curve is zero throughout, and its
  // slack length's column exactly zero, in the design and in every fit
  const Example e = Load("quick_release.yaml");
  const SeriesIdentification design =
      DesignSeries(e.spec, e.series, ScenarioSensitivityRunner(LoadScenario(e.spec.scenario)));
  const SeriesIdentification fit = Fit(e, Noisy(e, 1));
  for (const SeriesIdentification* r : {&design, &fit}) {
    const SeriesParameterResult& slack = r->parameters[2];
    ASSERT_EQ(slack.path, "model.passive.slack_length");
    EXPECT_EQ(slack.verdict, Identifiability::kNegligibleColumn);
    EXPECT_EQ(slack.column_ratio, 0.0);
    EXPECT_EQ(slack.estimate, 0.11);  // its start: the data cannot move it
    EXPECT_THAT(IdentifiabilityVerdict(*r),
                HasSubstr("model.passive.slack_length is not: its column is zero"));
  }
}

TEST(IdentifySeriesExamples, ForcesAndMassScaledTogetherAreAnUnresolvedCombination) {
  // in the quick release (no passive tension) m x'' = F(t) - f_iso f_L(x) g(v): scaling
  // f_iso, both load steps and the mass by one factor leaves x(t) unchanged, so only their
  // ratios are determined; the design must find that direction, (1, 1, 1, 1) / 2 in
  // relative changes (the second load step is negative), and still determine v_max
  const std::string data = testing::WriteTempFile(
      "data.yaml", "scenario: " + testing::ScenarioPath("quick_release.yaml") +
                       "\nseries:\n  - noise: {length: 2.0e-5}\nparameters:\n"
                       "  - {path: model.f_iso}\n  - {path: \"load[0].after\"}\n"
                       "  - {path: \"load[1].after\"}\n  - {path: actuator.mass}\n"
                       "  - {path: model.velocity.v_max}\n");
  const IdentifySeriesSpec spec = LoadIdentifySeriesSpec(data);
  const SeriesIdentification design = DesignSeries(
      spec, ReadMeasuredSeries(spec, true), ScenarioSensitivityRunner(LoadScenario(spec.scenario)));
  ASSERT_EQ(design.weak_directions.size(), 1u);
  const WeakDirection& w = design.weak_directions[0];
  // the sensitivities are accurate to about 1e-8 here (rtol 1e-8): the direction's ratio
  // is far below the 1e-6 threshold, and its components are 1/2 to within 1e-4
  EXPECT_LT(w.ratio, 1e-7);
  const double sign = w.components[0] > 0 ? 1.0 : -1.0;
  EXPECT_NEAR(sign * w.components[0], 0.5, 1e-4);
  EXPECT_NEAR(sign * w.components[1], 0.5, 1e-4);
  EXPECT_NEAR(sign * w.components[2], -0.5, 1e-4);  // d p / |p| of a negative load
  EXPECT_NEAR(sign * w.components[3], 0.5, 1e-4);
  EXPECT_LT(std::abs(w.components[4]), kComponentFloor);
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_EQ(design.parameters[j].verdict, Identifiability::kDependent) << j;
  }
  EXPECT_EQ(design.parameters[4].verdict, Identifiability::kIdentifiable);
}

}  // namespace
}  // namespace musclesim
