// `--to-gaussians`: the paper's model fitted to another family's curves. DeGroote's passive
// curve is exactly the paper's exponential (slack length l_min l_opt, rate kPE / (e0 l_opt)),
// so that fit must recover those constants; the active and velocity fits are checked off
// their samples, on a finer grid, against the family itself, and their reported RMSE
// against the one measured there.
#include "musclesim/identify/paper_model_fit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/model/degroote2016.h"
#include "musclesim/model/tension.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

constexpr double kFiso = 400.0, kOptimalLength = 0.1, kMaxSpeed = 1.0;  // N, m, m/s

ModelParams DeGroote() {
  ModelParams p;
  p.family = CurveFamily::kDeGroote2016;
  p.f_iso = kFiso;
  p.degroote2016.optimal_fiber_length = kOptimalLength;
  p.degroote2016.max_contraction_velocity = kMaxSpeed / kOptimalLength;
  return p;
}

// The RMSE of `fitted` against `truth` on `points` evenly spaced points of [a, b] that are
// not the fit's samples; and the largest error, in `max_error`.
template <typename Fitted, typename Truth>
double OffSampleRmse(double a, double b, Fitted fitted, Truth truth, double& max_error) {
  constexpr int points = 997;
  double sum = 0.0;
  max_error = 0.0;
  for (int i = 0; i < points; ++i) {
    const double x = a + (b - a) * (i + 0.5) / points;
    const double error = fitted(x) - truth(x);
    sum += error * error;
    max_error = std::max(max_error, std::abs(error));
  }
  return std::sqrt(sum / points);
}

TEST(PaperModelFit, DeGrootesPassiveCurveIsThePapersExponentialAndIsRecovered) {
  const TensionModel model(DeGroote());
  const PaperModelFit fit = FitPaperModel(model, 3, kOptimalLength, kMaxSpeed);
  const double e0 = 0.6, rate = degroote2016::kPassiveRate;
  const double offset = std::exp(rate * (degroote2016::kPassiveMinimumLength - 1.0) / e0);
  // (exp(kPE (l/l_opt - 1)/e0) - o) / (exp(kPE) - o) = o/(exp(kPE) - o) (exp(a (l - l0)) - 1)
  const double alpha = rate / (e0 * kOptimalLength);
  const double slack = degroote2016::kPassiveMinimumLength * kOptimalLength;
  const double k_p = kFiso * offset / (std::exp(rate) - offset);
  EXPECT_NEAR(fit.passive.alpha.value, alpha, 1e-6 * alpha);
  EXPECT_NEAR(fit.passive.slack_length.value, slack, 1e-6 * kOptimalLength);
  EXPECT_NEAR(fit.passive.k_p.value, k_p, 1e-5 * k_p);
  EXPECT_LT(fit.passive.rmse, 1e-9 * kFiso);
}

TEST(PaperModelFit, ActiveCurveOffItsSamplesIsWithinTheReportedError) {
  const TensionModel model(DeGroote());
  double previous = kFiso;
  for (const int count : {2, 3, 5, 8}) {
    const PaperModelFit fit = FitPaperModel(model, count, kOptimalLength, kMaxSpeed);
    double max_error = 0.0;
    const double rmse = OffSampleRmse(
        0.3 * kOptimalLength, 2.0 * kOptimalLength,
        [&](double x) { return fit.active.Evaluate(x); },
        [&](double x) { return kFiso * model.ActiveLengthFactor(x).value; }, max_error);
    // the samples are dense: the reported RMSE is the curve's, not the samples' only
    EXPECT_NEAR(rmse, fit.active.rmse, 0.05 * fit.active.rmse) << count;
    EXPECT_LT(max_error, 5.0 * rmse) << count;
    // DeGroote's terms are Gaussians whose width grows with length: more Gaussians of fixed
    // width approach them ever closer
    EXPECT_LT(fit.active.rmse, 0.5 * previous) << count;
    previous = fit.active.rmse;
  }
  EXPECT_LT(previous, 1e-3 * kFiso);
}

TEST(PaperModelFit, VelocityCurveOffItsSamplesIsWithinTheReportedError) {
  const TensionModel model(DeGroote());
  const PaperModelFit fit = FitPaperModel(model, 3, kOptimalLength, kMaxSpeed);
  double max_error = 0.0;
  const double rmse = OffSampleRmse(
      -0.9 * kMaxSpeed, 0.9 * kMaxSpeed, [&](double v) { return fit.velocity.Evaluate(v); },
      [&](double v) { return kFiso * model.VelocityFactor(v).value; }, max_error);
  ASSERT_TRUE(fit.velocity.eccentric.has_value());
  ASSERT_TRUE(fit.velocity.eccentric->identified);
  // the reported RMSEs are per branch, over its half of the samples: the whole curve's lies
  // between them
  const double concentric = fit.velocity.best.rmse, eccentric = fit.velocity.eccentric->best.rmse;
  EXPECT_LT(rmse, 1.05 * std::max(concentric, eccentric));
  EXPECT_GT(rmse, 0.95 * std::min(concentric, eccentric));
  EXPECT_LT(max_error, 0.2 * kFiso);
}

TEST(PaperModelFit, CountOutOfRangeIsRefusedWithTheRule) {
  const TensionModel model(DeGroote());
  for (const int count : {0, 21}) {
    try {
      FitPaperModel(model, count, kOptimalLength, kMaxSpeed);
      ADD_FAILURE() << count;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("must be a whole number from 1 to 20"));
    }
  }
}

}  // namespace
}  // namespace musclesim
