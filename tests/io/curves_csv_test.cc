// The curves tabulated as CSV, checked against the closed forms of docs/model.md sections 2-4.
#include "musclesim/io/writers/curves_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "musclesim/core/errors.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// One Gaussian centred inside L_opt: its maximum over L_opt is at its centre, so
// f_L(x) = exp(-b (x - d)^2 / (2 sigma)) exactly, whatever the amplitude.
constexpr double kWidthFactor = 9000.0;  // b [1/m^2]
constexpr double kCenter = 0.1;          // d [m]

ModelParams OneGaussianModel() {
  ModelParams p;
  p.f_iso = 100.0;
  p.passive = {2.0, 30.0, 0.105};
  p.active_length.optimal_min = 0.095;
  p.active_length.optimal_max = 0.105;
  p.active_length.sigma = 1.0;
  p.active_length.gaussians = {Gaussian{0.05, kWidthFactor, kCenter}};
  p.velocity = {1.5, 3, 1e-3};
  return p;
}

// The CSV as its header and rows of numbers.
struct Table {
  std::string header;
  std::vector<std::vector<double>> rows;
};

Table Parse(const std::string& csv) {
  Table table;
  std::istringstream in(csv);
  std::getline(in, table.header);
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    table.rows.push_back(row);
  }
  return table;
}

TEST(CurvesCsv, LengthTableMatchesTheClosedForms) {
  const Table t = Parse(FormatLengthCurvesCsv(TensionModel(OneGaussianModel()), {0.08, 0.12, 9}));
  EXPECT_EQ(t.header, "length,f_L,tension_passive");
  ASSERT_EQ(t.rows.size(), 9u);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    ASSERT_EQ(t.rows[i].size(), 3u);
    const double x = 0.08 + 0.005 * static_cast<double>(i);
    // the grid spacing 0.04 / 8 is inexact in binary: agree to a few ulps
    EXPECT_NEAR(t.rows[i][0], x, 1e-16);
    const double f_l = std::exp(-kWidthFactor * (x - kCenter) * (x - kCenter) / 2.0);
    // the normaliser is found by bisection to the last bit: a few ulps of relative error
    EXPECT_NEAR(t.rows[i][1], f_l, 1e-13 * f_l);
    const double passive = x > 0.105 ? 2.0 * (std::exp(30.0 * (x - 0.105)) - 1.0) : 0.0;
    EXPECT_NEAR(t.rows[i][2], passive, 1e-13);  // eq. 1, exp near 1: absolute rounding
  }
  // the ends are the grid's own numbers, printed to be read back exactly
  EXPECT_EQ(t.rows.front()[0], 0.08);
  EXPECT_EQ(t.rows.back()[0], 0.12);
  EXPECT_EQ(t.rows[4][1], 1.0);  // x = d: the peak, f_L = 1 by construction
}

TEST(CurvesCsv, VelocityTableMatchesTheRegularisedPowerLaw) {
  const Table t = Parse(FormatVelocityCurveCsv(TensionModel(OneGaussianModel()), {-2.0, 2.0, 5}));
  EXPECT_EQ(t.header, "shortening_velocity,g");
  ASSERT_EQ(t.rows.size(), 5u);
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    ASSERT_EQ(t.rows[i].size(), 2u);
    const double v = -2.0 + static_cast<double>(i);  // exact in binary
    EXPECT_EQ(t.rows[i][0], v);
    // eq. 12 with the eps-regularisation (docs/model.md section 4), alpha = 1/n = 1/3
    const double alpha = 1.0 / 3.0, eps = 1e-3;
    const double phi = v * std::pow(v * v + eps * eps, (alpha - 1.0) / 2.0);
    const double g = 1.0 - phi / std::pow(1.5, alpha);
    EXPECT_NEAR(t.rows[i][1], g, 1e-14);  // two pows of values near 1: rounding only
  }
  EXPECT_EQ(t.rows[2][1], 1.0);  // v = 0: no velocity effect
}

TEST(CurvesCsv, NumbersCarrySeventeenDigits) {
  const std::string csv = FormatVelocityCurveCsv(TensionModel(OneGaussianModel()), {0.1, 0.3, 2});
  // 0.1 is not exact in binary: 17 significant digits show it
  EXPECT_THAT(csv, HasSubstr("\n0.10000000000000001,"));
}

TEST(CurvesCsv, RejectsABrokenGrid) {
  const TensionModel model(OneGaussianModel());
  EXPECT_THROW(FormatLengthCurvesCsv(model, {0.1, 0.1, 5}), ParameterError);
  EXPECT_THROW(FormatLengthCurvesCsv(model, {0.1, 0.2, 1}), ParameterError);
  EXPECT_THROW(FormatVelocityCurveCsv(model, {-1.0, NAN, 5}), ParameterError);
}

TEST(CurvesCsv, AValueThatOverflowsIsAnErrorNotARow) {
  // T_p = k_p (exp(alpha (x - slack)) - 1) with alpha = 30 /m: exp overflows past
  // x = slack + 709.8 / 30 = 23.8 m, so the grid point 30 m has an infinite tension
  const TensionModel model(OneGaussianModel());
  EXPECT_THAT(
      [&] {
        FormatLengthCurvesCsv(model, {0.1, 30.0, 2});
      },
      ::testing::ThrowsMessage<ParameterError>(
          HasSubstr("length = 30: tension_passive = inf there")));
  EXPECT_NO_THROW(FormatLengthCurvesCsv(model, {0.1, 23.0, 2}));
}

}  // namespace
}  // namespace musclesim
