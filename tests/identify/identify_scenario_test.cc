// Identification from time series on a Scenario built in code (identify/identify_series.h),
// with no file anywhere: the measured series are a plain run of the truth (no sensitivity in
// it), the scenario handed to the fit holds wrong values, and the fit recovers the truth;
// the estimated scenario (EstimatedScenario) then runs as the truth does.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "musclesim/identify/identify_series.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/scenario.h"
#include "support/canonical_scenarios.h"
#include "support/normal_noise.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

constexpr double kTrueFIso = 100.0, kTrueVMax = 1.0;  // [N], [m/s]: the concentric actuator's

// The concentric contraction (scenarios/concentric.yaml, built in code) for 0.3 s at tight
// tolerances, so that a plain run and a run with sensitivities agree to ~1e-11 m, far below
// what the fits below resolve; `f_iso` and `v_max` set through their handles.
Scenario Concentric(double f_iso, double v_max) {
  ActuatorScenarioSpec spec = testing::ConcentricSpec();
  spec.t_end = 0.3;
  spec.solver.rtol = 1e-10;
  spec.solver.atol = 1e-13;
  Scenario s = MakeActuatorScenario(spec);
  SetParameters(s, {s.parameter("model.f_iso"), s.parameter("model.velocity.v_max")},
                {f_iso, v_max});
  return s;
}

// The truth's lengths, every 5 ms from 0.05 s (the step) on, from a plain run; `noise`
// [m] the standard deviation stated, and with `seed` > 0 added to the values.
MeasuredSeries Lengths(double noise, std::uint64_t seed, std::size_t first_row = 50) {
  const RecordedRun truth = RunScenario(Concentric(kTrueFIso, kTrueVMax));
  EXPECT_EQ(truth.stats.status, RunStatus::kCompleted) << truth.stats.message;
  const std::vector<double>& t = testing::ColumnOf(truth, "t");
  const std::vector<double>& length = testing::ColumnOf(truth, "length");
  testing::Noise normal(seed);
  MeasuredSeries s;
  s.columns = {"length"};
  s.noise = {noise};
  for (std::size_t r = first_row; r < t.size(); r += 5) {
    s.times.push_back(t[r]);
    s.values.push_back(length[r] + (seed > 0 ? noise * normal() : 0.0));
    s.lines.push_back(s.lines.size() + 1);  // values in memory: rows by their index
  }
  return s;
}

// The data file's part, written in code: the two parameters, from the scenario's values.
IdentifySeriesSpec Spec() {
  IdentifySeriesSpec spec;
  spec.source = "identification in code";
  spec.scenario = "concentric in code";
  spec.parameters = {
      {"model.f_iso", std::nullopt, 10.0, 1000.0, InputPlace{"parameters[0]"}},
      {"model.velocity.v_max", std::nullopt, 0.1, 10.0, InputPlace{"parameters[1]"}}};
  return spec;
}

TEST(IdentifyScenario, NoiseFreeSeriesOfARunGiveBackTheTruth) {
  // the scenario the fit starts from holds f_iso 10% low and v_max 20% high
  const Scenario wrong = Concentric(90.0, 1.2);
  const SeriesIdentification fit =
      FitSeries(Spec(), {Lengths(1e-5, 0)}, ScenarioSensitivityRunner(wrong));
  ASSERT_TRUE(fit.converged) << fit.stop_reason;
  ASSERT_EQ(fit.parameters.size(), 2u);
  EXPECT_EQ(fit.parameters[0].scenario_value, 90.0);
  EXPECT_EQ(fit.parameters[1].scenario_value, 1.2);
  // the data differ from the fit's model only by the two integrations' errors, ~1e-11 m on
  // lengths whose sensitivity to f_iso is ~1e-4 m/N: the estimates are right to far better
  // than 1e-6 of them
  EXPECT_NEAR(fit.parameters[0].estimate, kTrueFIso, 1e-6 * kTrueFIso);
  EXPECT_NEAR(fit.parameters[1].estimate, kTrueVMax, 1e-6 * kTrueVMax);
  for (const SeriesParameterResult& p : fit.parameters) {
    EXPECT_EQ(p.verdict, Identifiability::kIdentifiable) << p.path;
  }

  // the estimated scenario is the truth again: its run agrees with the truth's to the
  // solver's tolerance (rtol 1e-10 of 0.1 m), and its values are the estimates
  const Scenario estimated = EstimatedScenario(wrong, fit);
  EXPECT_EQ(estimated.models.at("model").spec.params.f_iso, fit.parameters[0].estimate);
  EXPECT_EQ(estimated.elements[kActuatorElement].model->params().velocity.v_max,
            fit.parameters[1].estimate);
  const std::vector<double> lengths = testing::ColumnOf(RunScenario(estimated), "length");
  const std::vector<double> truth =
      testing::ColumnOf(RunScenario(Concentric(kTrueFIso, kTrueVMax)), "length");
  ASSERT_EQ(lengths.size(), truth.size());
  for (std::size_t r = 0; r < truth.size(); ++r) EXPECT_NEAR(lengths[r], truth[r], 1e-9) << r;
}

TEST(IdentifyScenario, NoisySeriesGiveTheTruthWithinTheirStandardErrors) {
  // 10 um of noise on every length: each estimate within 4 of its standard errors of the
  // truth (a fixed seed, so this passes always or never; 4 errors leave 6e-5 to chance)
  const double noise = 1e-5;
  const SeriesIdentification fit =
      FitSeries(Spec(), {Lengths(noise, 7)}, ScenarioSensitivityRunner(Concentric(90.0, 1.2)));
  ASSERT_TRUE(fit.converged) << fit.stop_reason;
  EXPECT_TRUE(fit.noise_given);
  const double truth[] = {kTrueFIso, kTrueVMax};
  for (std::size_t j = 0; j < 2; ++j) {
    const SeriesParameterResult& p = fit.parameters[j];
    ASSERT_TRUE(std::isfinite(p.standard_error)) << p.path;
    EXPECT_GT(p.standard_error, 0.0) << p.path;
    EXPECT_LT(std::abs(p.estimate - truth[j]), 4.0 * p.standard_error) << p.path;
  }
  // weighted residuals of the right size: their sum of squares near its degrees of freedom
  // (chi-squared with ~50 degrees of freedom: within a factor of 2 but for a 1e-4 chance)
  EXPECT_GT(fit.weighted_rss, 0.5 * fit.degrees_of_freedom);
  EXPECT_LT(fit.weighted_rss, 2.0 * fit.degrees_of_freedom);
}

TEST(IdentifyScenario, AParameterWhoseTruthIsZeroIsIdentifiedAndCalledSo) {
  // the initial lengthening rate, 0 in the truth, started at 0.01 m/s: the fit finds 0 to
  // roundoff, and an estimate of 0 must not make its sensitivity vanish (it is relative to
  // the start's size, as in the design at that start, which says the same)
  IdentifySeriesSpec spec = Spec();
  spec.parameters.push_back(
      {"initial.lengthening_rate", 0.01, -1.0, 1.0, InputPlace{"parameters[2]"}});
  const MeasuredSeries lengths = Lengths(1e-5, 0, 0);
  const SensitivityRunner run = ScenarioSensitivityRunner(Concentric(90.0, 1.2));
  const SeriesIdentification fit = FitSeries(spec, {lengths}, run);
  ASSERT_TRUE(fit.converged) << fit.stop_reason;
  const SeriesParameterResult& rate = fit.parameters[2];
  EXPECT_NEAR(rate.estimate, 0.0, 1e-9);  // [m/s], against a start of 0.01
  EXPECT_EQ(rate.verdict, Identifiability::kIdentifiable) << rate.estimate;
  const SeriesIdentification design = DesignSeries(spec, {lengths}, run);
  EXPECT_EQ(design.parameters[2].verdict, Identifiability::kIdentifiable);
  // both judge it at the start's size: their column ratios agree to the change of the
  // Jacobian between start and estimate, far from the 1e-6 that makes a column negligible
  EXPECT_GT(rate.column_ratio, 1e-3);
  EXPECT_NEAR(rate.column_ratio / design.parameters[2].column_ratio, 1.0, 0.5);
}

TEST(IdentifyScenario, TheRunnerSetsValuesThroughHandlesOnCopies) {
  // the runner's scenario is its own copy: runs at other values leave it as it was
  const Scenario wrong = Concentric(90.0, 1.2);
  const SensitivityRunner run = ScenarioSensitivityRunner(wrong);
  const SensitivityTable moved = run({"model.f_iso"}, {100.0}, {0.1, 0.2}, {});
  const SensitivityTable as_is = run({"model.f_iso"}, {}, {0.1, 0.2}, {});
  EXPECT_EQ(moved.parameter_values, std::vector<double>{100.0});
  EXPECT_EQ(as_is.parameter_values, std::vector<double>{90.0});
  EXPECT_EQ(moved.times, (std::vector<double>{0.1, 0.2}));
  // a value a handle refuses is its ParameterError
  EXPECT_THROW(run({"model.f_iso"}, {-5.0}, {}, {}), ParameterError);
}

}  // namespace
}  // namespace musclesim
