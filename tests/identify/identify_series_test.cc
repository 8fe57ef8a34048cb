// Time-series identification end to end on a closed-form stand-in for the scenario's run:
// the fit, its standard errors, the verdict, the design ranking and the checks of the data
// against the run, each compared with an independent computation.
#include "musclesim/identify/identify_series.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "musclesim/core/errors.h"
#include "support/normal_noise.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// The stand-in: a release to a new length, length(t) = base - amp (1 - exp(-t / tau)), and a
// tension that decays with it, tension_total(t) = 100 amp exp(-t / tau); `unused` changes
// nothing. Parameters as dotted paths, each set to a value as a scenario's handle sets it.
const std::map<std::string, double> kScenario = {
    {"release.amp", 0.02}, {"release.tau", 0.05}, {"release.base", 0.1}, {"unused", 3.0}};

struct Values {
  double length, tension;
  std::map<std::string, std::pair<double, double>> d;  // d length, d tension per path
};

Values Closed(const std::map<std::string, double>& p, double t) {
  const double amp = p.at("release.amp"), tau = p.at("release.tau"), base = p.at("release.base");
  const double e = std::exp(-t / tau);
  Values v{base - amp * (1 - e), 100 * amp * e, {}};
  v.d["release.amp"] = {-(1 - e), 100 * e};
  v.d["release.tau"] = {amp * e * t / (tau * tau), 100 * amp * e * t / (tau * tau)};
  v.d["release.base"] = {1.0, 0.0};
  v.d["unused"] = {0.0, 0.0};
  return v;
}

// The grid of the stand-in scenario: 0 to 0.3 s every 5 ms.
std::vector<double> Grid() {
  std::vector<double> t;
  for (int i = 0; i <= 60; ++i) t.push_back(0.005 * i);
  return t;
}

struct StandIn {
  int runs = 0;
  int failures = 0;
  int fail_every = 0;  // > 0: every so many runs fails, as a solver may at a trial point

  // SensitivityRunner's call: `values` (none: the scenario as it is) at `parameters`
  SensitivityTable operator()(const std::vector<std::string>& parameters,
                              const std::vector<double>& values, const std::vector<double>& times,
                              const std::vector<double>&) {
    ++runs;
    std::map<std::string, double> p = kScenario;
    for (const std::string& path : parameters) {
      if (!p.count(path)) throw InputError("--sensitivity " + path + ": no such number");
    }
    for (std::size_t i = 0; i < values.size(); ++i) p.at(parameters[i]) = values[i];
    SensitivityTable table;
    table.columns = {"length", "tension_total"};
    table.parameters = parameters;
    for (const std::string& path : parameters) table.parameter_values.push_back(p.at(path));
    table.times = times.empty() ? Grid() : times;
    if (fail_every > 0 && runs % fail_every == 0) {
      ++failures;
      table.stats.status = RunStatus::kFailed;
      table.stats.message = "CV_CONV_FAILURE at t = 0.01";
      table.times.resize(2);
    }
    for (double t : table.times) {
      const Values v = Closed(p, t);
      table.values.push_back(v.length);
      table.values.push_back(v.tension);
      for (const std::string& path : parameters) {
        table.derivatives.push_back(v.d.at(path).first);
        table.derivatives.push_back(v.d.at(path).second);
      }
    }
    return table;
  }
};

SeriesParameterSpec Parameter(const std::string& path, std::optional<double> start,
                              std::optional<double> lower = {}, std::optional<double> upper = {}) {
  return {path, start, lower, upper, InputPlace{"data.yaml", 9, 5}};
}

// A measured series of `columns` at `times`, values from the closed form at `truth` plus
// noise * N(0, 1) (seeded), with noise levels `noise` (NaN: none given).
MeasuredSeries Measured(const std::vector<std::string>& columns, const std::vector<double>& times,
                        const std::map<std::string, double>& truth,
                        const std::vector<double>& noise, std::uint64_t seed) {
  testing::Noise normal(seed);
  MeasuredSeries s;
  s.source = "measured.csv";
  s.at = InputPlace{"data.yaml", 3, 5};
  s.columns = columns;
  s.noise = noise;
  s.times = times;
  for (double t : times) {
    const Values v = Closed(truth, t);
    s.lines.push_back(s.lines.size() + 2);
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const double exact = columns[c] == "length" ? v.length : v.tension;
      s.values.push_back(exact + (std::isnan(noise[c]) ? 0.0 : noise[c] * normal()));
    }
  }
  return s;
}

// The same without noise in the values, the noise levels still stated.
MeasuredSeries Exact(const std::vector<std::string>& columns, const std::vector<double>& times,
                     const std::map<std::string, double>& truth, const std::vector<double>& noise) {
  MeasuredSeries s =
      Measured(columns, times, truth, std::vector<double>(columns.size(), std::nan("")), 0);
  s.noise = noise;
  return s;
}

IdentifySeriesSpec Spec(std::vector<SeriesParameterSpec> parameters) {
  IdentifySeriesSpec spec;
  spec.source = "data.yaml";
  spec.scenario = "release.yaml";
  spec.scenario_at = InputPlace{"data.yaml", 1, 11};
  spec.parameters = std::move(parameters);
  return spec;
}

std::vector<double> Times(double from, double step, int count) {
  std::vector<double> t;
  for (int i = 0; i < count; ++i) t.push_back(from + step * i);
  return t;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(FitSeries, RecoversExactDataFromTwoSeriesAtDifferentTimes) {
  const auto truth = kScenario;
  const IdentifySeriesSpec spec =
      Spec({Parameter("release.amp", 0.01), Parameter("release.tau", 0.08, 0.001, 1.0),
            Parameter("release.base", 0.09)});
  // lengths every 4 ms, tensions every 10 ms from 2 ms: few times shared
  const std::vector<MeasuredSeries> exact = {
      Exact({"length"}, Times(0.0, 0.004, 60), truth, {1e-5}),
      Exact({"tension_total"}, Times(0.002, 0.01, 25), truth, {0.05})};
  StandIn model;
  const SeriesIdentification fit = FitSeries(spec, exact, std::ref(model));
  EXPECT_TRUE(fit.converged) << fit.stop_reason;
  // exact data: the truth with zero residual; the fit stops when the Gauss-Newton step,
  // about the remaining error, is below 1e-10 relative
  EXPECT_NEAR(fit.parameters[0].estimate, 0.02, 1e-9 * 0.02);
  EXPECT_NEAR(fit.parameters[1].estimate, 0.05, 1e-9 * 0.05);
  EXPECT_NEAR(fit.parameters[2].estimate, 0.1, 1e-9 * 0.1);
  EXPECT_EQ(fit.values, 85u);
  EXPECT_EQ(fit.residuals.size(), 85u);
  EXPECT_EQ(fit.residuals[60].output, "tension_total");
  EXPECT_NEAR(fit.residuals[60].t, 0.002, 1e-15);
  EXPECT_EQ(fit.parameters[1].scenario_value, 0.05);
  EXPECT_EQ(fit.parameters[1].start, 0.08);
}

TEST(FitSeries, StandardErrorsAreTheInverseFisherInformationAtTheEstimate) {
  // exact data, so the estimate is the truth and J there is the closed form's: the
  // standard errors must be sqrt(diag((J^T W J)^-1)) computed here from it
  const auto truth = kScenario;
  const std::vector<double> lt = Times(0.0, 0.004, 60), tt = Times(0.002, 0.01, 25);
  const double noise_l = 1e-5, noise_t = 0.05;
  const std::vector<std::string> paths = {"release.amp", "release.tau", "release.base"};
  Eigen::MatrixXd j(85, 3);
  for (int i = 0; i < 85; ++i) {
    const bool is_length = i < 60;
    const Values v = Closed(truth, is_length ? lt[i] : tt[i - 60]);
    for (int k = 0; k < 3; ++k) {
      j(i, k) = is_length ? v.d.at(paths[k]).first / noise_l : v.d.at(paths[k]).second / noise_t;
    }
  }
  const Eigen::Matrix3d covariance = (j.transpose() * j).inverse();
  const std::vector<MeasuredSeries> series = {Exact({"length"}, lt, truth, {noise_l}),
                                              Exact({"tension_total"}, tt, truth, {noise_t})};
  StandIn model;
  const SeriesIdentification fit = FitSeries(
      Spec({Parameter(paths[0], 0.015), Parameter(paths[1], 0.06), Parameter(paths[2], 0.11)}),
      series, std::ref(model));
  ASSERT_TRUE(fit.noise_given);
  for (int k = 0; k < 3; ++k) {
    const double se = std::sqrt(covariance(k, k));
    // a 3 x 3 inverse against an SVD, at an estimate equal to the truth to 1e-10: 1e-6
    EXPECT_NEAR(fit.parameters[static_cast<std::size_t>(k)].standard_error, se, 1e-6 * se) << k;
  }
  const double rho = covariance(0, 1) / std::sqrt(covariance(0, 0) * covariance(1, 1));
  EXPECT_NEAR(fit.correlation(0, 1), rho, 1e-6);  // as above
}

TEST(FitSeries, NoisyEstimatesLieWithinThreeStandardErrorsOfTheTruth) {
  // 20 seeded data sets: with right standard errors each estimate is within 3 of them with
  // probability 0.997, so 18 of 20 is a loose floor
  const auto truth = kScenario;
  int within[3] = {0, 0, 0};
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const std::vector<MeasuredSeries> series = {
        Measured({"length", "tension_total"}, Times(0.0, 0.005, 50), truth, {2e-4, 0.1}, seed)};
    StandIn model;
    const SeriesIdentification fit =
        FitSeries(Spec({Parameter("release.amp", 0.01), Parameter("release.tau", 0.1),
                        Parameter("release.base", 0.09)}),
                  series, std::ref(model));
    const double expected[3] = {0.02, 0.05, 0.1};
    for (int k = 0; k < 3; ++k) {
      const SeriesParameterResult& p = fit.parameters[static_cast<std::size_t>(k)];
      within[k] += std::abs(p.estimate - expected[k]) <= 3 * p.standard_error;
    }
  }
  for (int k = 0; k < 3; ++k) EXPECT_GE(within[k], 18) << k;
}

TEST(FitSeries, WithoutNoiseLevelsTheResidualsGiveTheVariance) {
  // one column, no noise level: s^2 = RSS / (N - P), and the standardised residuals are the
  // residuals over s
  const auto truth = kScenario;
  std::vector<MeasuredSeries> series = {
      Measured({"length"}, Times(0.0, 0.005, 50), truth, {3e-4}, 7)};
  series[0].noise = {kNaN};
  StandIn model;
  const SeriesIdentification fit =
      FitSeries(Spec({Parameter("release.amp", 0.01), Parameter("release.tau", 0.1),
                      Parameter("release.base", 0.09)}),
                series, std::ref(model));
  EXPECT_FALSE(fit.noise_given);
  double rss = 0.0;
  for (const ResidualRow& r : fit.residuals) rss += (r.measured - r.model) * (r.measured - r.model);
  EXPECT_NEAR(fit.variance_factor, rss / (50 - 3), 1e-12 * rss);  // summation order
  const double s = std::sqrt(fit.variance_factor);
  EXPECT_NEAR(fit.residuals[4].standardised,
              (fit.residuals[4].measured - fit.residuals[4].model) / s, 1e-12);
  EXPECT_THAT(FormatSeriesReport(fit, "data.yaml"),
              HasSubstr("No noise levels: standard errors from s^2 (J^T J)^-1"));
}

TEST(FitSeries, AParameterTheOutputsIgnoreIsFlaggedAndKeptAtItsStart) {
  const auto truth = kScenario;
  const std::vector<MeasuredSeries> series = {
      Measured({"length"}, Times(0.0, 0.005, 50), truth, {1e-5}, 3)};
  StandIn model;
  const SeriesIdentification fit =
      FitSeries(Spec({Parameter("release.amp", 0.01), Parameter("release.tau", 0.1),
                      Parameter("unused", 2.5)}),
                series, std::ref(model));
  EXPECT_EQ(fit.parameters[2].verdict, Identifiability::kNegligibleColumn);
  EXPECT_EQ(fit.parameters[2].estimate, 2.5);
  EXPECT_TRUE(std::isinf(fit.parameters[2].standard_error));
  EXPECT_EQ(IdentifiabilityVerdict(fit),
            "release.amp and release.tau are identifiable from this experiment; unused is not: "
            "its column is zero (the outputs do not depend on it).");
}

TEST(FitSeries, AFailedRunAtATrialPointShortensTheStep) {
  const auto truth = kScenario;
  const std::vector<MeasuredSeries> exact = {
      Exact({"length"}, Times(0.0, 0.005, 50), truth, {1e-5})};
  StandIn model;
  model.fail_every = 3;  // the baseline and the start run (1, 2); then every third fails
  const SeriesIdentification fit =
      FitSeries(Spec({Parameter("release.amp", 0.005), Parameter("release.tau", 0.1),
                      Parameter("release.base", 0.1)}),
                exact, std::ref(model));
  EXPECT_TRUE(fit.converged) << fit.stop_reason;
  EXPECT_NEAR(fit.parameters[1].estimate, 0.05, 1e-9 * 0.05);  // exact data, as above
  EXPECT_GT(model.failures, 0);  // the fit did meet the failing region
}

TEST(FitSeries, RefusesDataTheRunCannotMatch) {
  const auto truth = kScenario;
  StandIn model;
  const auto message = [&](const IdentifySeriesSpec& spec, const std::vector<MeasuredSeries>& s) {
    try {
      FitSeries(spec, s, std::ref(model));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const IdentifySeriesSpec spec = Spec({Parameter("release.amp", 0.01)});
  EXPECT_EQ(message(spec, {Measured({"speed"}, Times(0, 0.01, 5), truth, {1.0}, 1)}),
            "series[0] (data.yaml:3:5): column speed is not an output the scenario's run "
            "differentiates; these are: length, tension_total");
  // a column that is one in the stand-in's table, measured twice without noise levels
  std::vector<MeasuredSeries> two = {
      Measured({"length"}, Times(0, 0.01, 5), truth, {kNaN}, 1),
      Measured({"tension_total"}, Times(0, 0.01, 5), truth, {kNaN}, 1)};
  EXPECT_THAT(message(spec, two), HasSubstr("the series measure 2 different columns and give no "
                                            "noise levels"));
  two[0].noise = {1e-5};
  EXPECT_THAT(message(spec, two), HasSubstr("noise levels are given for some columns and not "
                                            "for others"));
  EXPECT_EQ(message(Spec({Parameter("release.amp", 0.01), Parameter("release.tau", 0.1)}),
                    {Measured({"length"}, Times(0, 0.01, 2), truth, {1e-5}, 1)}),
            "data.yaml: 2 measured values for 2 parameters: need more values than parameters");
  EXPECT_EQ(message(Spec({Parameter("release.tau", std::nullopt, 0.1, 1.0)}),
                    {Measured({"length"}, Times(0, 0.01, 5), truth, {1e-5}, 1)}),
            "release.tau (data.yaml:9:5): starts at the scenario's value 0.05, outside its bounds "
            "[0.1, 1]: give a start within them");
  EXPECT_EQ(message(Spec({Parameter("release.nothing", 1.0)}),
                    {Measured({"length"}, Times(0, 0.01, 5), truth, {1e-5}, 1)}),
            "data.yaml:9:5: parameters[0].path = release.nothing in scenario release.yaml: "
            "--sensitivity release.nothing: no such number");
  // the stand-in's run ends at 0.3 s; the third row of this series (line 4) is later
  EXPECT_EQ(message(spec, {Measured({"length"}, Times(0.1, 0.1, 4), truth, {1e-5}, 1)}),
            "series[0].csv = measured.csv:4: t = 0.30000000000000004 lies outside the "
            "scenario's run, from 0 to 0.3 s");
}

TEST(FitSeries, TheEstimatesAsOverridesReadBackExactly) {
  SeriesIdentification fit;
  fit.parameters.resize(2);
  fit.parameters[0].path = "model.f_iso";
  fit.parameters[0].estimate = 0.1 + 0.2;  // 0.30000000000000004
  fit.parameters[1].path = "load[0].value";
  fit.parameters[1].estimate = -1e-300;
  const std::vector<std::string> o = EstimateOverrides(fit);
  ASSERT_EQ(o.size(), 2u);
  EXPECT_EQ(std::stod(o[0].substr(o[0].find('=') + 1)), 0.1 + 0.2);
  EXPECT_EQ(o[1].substr(0, 14), "load[0].value=");
  EXPECT_EQ(std::stod(o[1].substr(14)), -1e-300);
}

TEST(DesignSeries, RanksByTheCramerRaoErrorsAtTheStartOnTheScenarioGrid) {
  // no csv: the scenario's grid (61 times), noise 1e-5 on length; the errors against the
  // closed form's (J^T W J)^-1 at the start values
  MeasuredSeries planned;
  planned.columns = {"length"};
  planned.noise = {1e-5};
  planned.at = InputPlace{"data.yaml", 3, 5};
  const std::map<std::string, double> start = {
      {"release.amp", 0.03}, {"release.tau", 0.02}, {"release.base", 0.1}, {"unused", 3.0}};
  const std::vector<std::string> paths = {"release.tau", "release.amp", "unused"};
  Eigen::MatrixXd j(61, 2);
  for (int i = 0; i < 61; ++i) {
    const Values v = Closed(start, Grid()[static_cast<std::size_t>(i)]);
    j(i, 0) = v.d.at(paths[0]).first / 1e-5;
    j(i, 1) = v.d.at(paths[1]).first / 1e-5;
  }
  const Eigen::Matrix2d covariance = (j.transpose() * j).inverse();
  StandIn model;
  const SeriesIdentification design =
      DesignSeries(Spec({Parameter(paths[0], 0.02), Parameter(paths[1], 0.03),
                         Parameter(paths[2], std::nullopt)}),
                   {planned}, std::ref(model));
  EXPECT_EQ(design.values, 61u);
  // a 2 x 2 inverse against an SVD: rounding, with room
  EXPECT_NEAR(design.parameters[0].standard_error, std::sqrt(covariance(0, 0)),
              1e-9 * std::sqrt(covariance(0, 0)));
  EXPECT_NEAR(design.parameters[1].relative_standard_error, std::sqrt(covariance(1, 1)) / 0.03,
              1e-9 * std::sqrt(covariance(1, 1)) / 0.03);
  EXPECT_EQ(design.parameters[2].verdict, Identifiability::kNegligibleColumn);
  const std::string report = FormatDesignReport(design, "data.yaml");
  const bool amp_first = covariance(1, 1) / (0.03 * 0.03) < covariance(0, 0) / (0.02 * 0.02);
  const auto amp = report.find("| release.amp |"), tau = report.find("| release.tau |");
  EXPECT_EQ(amp < tau, amp_first) << report;
  EXPECT_LT(tau, report.find("| unused |"));  // not determined: last
}

TEST(FitSeries, ResidualCsvHoldsEveryValue) {
  SeriesIdentification fit;
  fit.residuals = {{0, "length", 0.5, 0.1, 0.09, 2.0}, {1, "a,b", 1.0, 3.0, 4.0, -0.5}};
  EXPECT_EQ(FormatResidualCsv(fit),
            "series,output,t,measured,model,residual,standardised\n"
            "0,length,0.5,0.10000000000000001,0.089999999999999997,0.010000000000000009,2\n"
            "1,\"a,b\",1,3,4,-1,-0.5\n");
}

}  // namespace
}  // namespace musclesim
