// The standard force-length curves against their sources: each written out again here from
// the publication (not from the code), its peak, one published value, the scaling to l_opt,
// and the table `musclesim curves --preset` prints.
#include "musclesim/model/force_length_presets.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/writers/curves_csv.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// --- the curves, written out from their sources --------------------------------------------

// De Groote et al. 2016, supplement eq. S2 with the paper's constants (denominator squared)
double DeGrootePublished(double l) {
  const double terms[3][4] = {
      {0.815, 1.055, 0.162, 0.063}, {0.433, 0.717, -0.030, 0.200}, {0.100, 1.000, 0.354, 0.000}};
  double f = 0.0;
  for (const auto& b : terms) {
    const double width = b[2] + b[3] * l;
    f += b[0] * std::exp(-0.5 * (l - b[1]) * (l - b[1]) / (width * width));
  }
  return f;
}

// The published curve's maximum by golden-section search on [0.9, 1.1]: the peak's position
// is found to about sqrt(machine epsilon) relative, 1e-8, its value to roundoff.
struct Peak {
  double at, value;
};
Peak DeGrootePublishedPeak() {
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = 0.9, hi = 1.1;
  for (int i = 0; i < 200 && hi - lo > 1e-14; ++i) {
    const double left = hi - ratio * (hi - lo), right = lo + ratio * (hi - lo);
    (DeGrootePublished(left) < DeGrootePublished(right) ? lo : hi) =
        DeGrootePublished(left) < DeGrootePublished(right) ? left : right;
  }
  const double at = 0.5 * (lo + hi);
  return {at, DeGrootePublished(at)};
}

// Thelen 2003 eq. 3, gamma = 0.45
double Thelen(double s) { return std::exp(-(s - 1.0) * (s - 1.0) / 0.45); }

// MuJoCo's mju_muscleGainLength with lmin = 0.5, lmax = 1.6 (so a = 0.75, b = 1.3)
double MuJoCo(double s) {
  if (s < 0.5 || s > 1.6) return 0.0;
  if (s <= 0.75) return 0.5 * std::pow((s - 0.5) / 0.25, 2);
  if (s <= 1.0) return 1.0 - 0.5 * std::pow((1.0 - s) / 0.25, 2);
  if (s <= 1.3) return 1.0 - 0.5 * std::pow((s - 1.0) / 0.3, 2);
  return 0.5 * std::pow((1.6 - s) / 0.3, 2);
}

// Gordon, Huxley and Julian 1966 from the repository's data file: (length [um], tension)
std::vector<std::array<double, 2>> GordonBreakpoints() {
  std::ifstream in(std::string(MUSCLESIM_SOURCE_DIR) + "/data/ghj1966_breakpoints.csv");
  std::vector<std::array<double, 2>> points;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 'l') continue;  // comments, header
    const auto comma = line.find(',');
    points.push_back({std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1))});
  }
  return points;
}

// ... normalised by the middle of its plateau, (2.0 + 2.25) / 2 = 2.125 um
double Gordon(double s) {
  static const std::vector<std::array<double, 2>> points = GordonBreakpoints();
  const double l = s * 2.125;
  if (l < points.front()[0] || l > points.back()[0]) return 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const auto& p = points[i];
    const auto& q = points[i + 1];
    if (l <= q[0]) return p[1] + (q[1] - p[1]) * (l - p[0]) / (q[0] - p[0]);
  }
  return 0.0;
}

struct Reference {
  ForceLengthPreset preset;
  std::function<double(double)> curve;  // of the normalised length
  double lo, hi;                        // where the preset is cut to zero
};

std::vector<Reference> References() {
  const Peak peak = DeGrootePublishedPeak();
  const double thelen_reach = 6.0 * std::sqrt(0.45 / 2.0);  // six standard deviations
  return {
      {ForceLengthPreset::kDeGroote2016,
       [peak](double s) { return DeGrootePublished(s * peak.at) / peak.value; }, 0.0, 3.0},
      {ForceLengthPreset::kThelen2003, Thelen, 1.0 - thelen_reach, 1.0 + thelen_reach},
      {ForceLengthPreset::kGordon1966, Gordon, 1.27 / 2.125, 3.65 / 2.125},
      {ForceLengthPreset::kMuJoCo, MuJoCo, 0.5, 1.6},
  };
}

// --- the presets ---------------------------------------------------------------------------

TEST(ForceLengthPresets, NamesReadBackAndUnknownNamesListThemAll) {
  for (const char* name : {"degroote2016", "thelen2003", "gordon1966", "mujoco"}) {
    EXPECT_EQ(ToString(ParseForceLengthPreset(name)), name);
  }
  EXPECT_EQ(AllForceLengthPresets().size(), 4u);
  try {
    ParseForceLengthPreset("hill");
    ADD_FAILURE() << "hill accepted";
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(),
                 "name = hill: must be one of degroote2016, thelen2003, gordon1966, mujoco");
  }
}

TEST(ForceLengthPresets, PeakIsOneAtTheOptimalLength) {
  for (const Reference& r : References()) {
    SCOPED_TRACE(std::string(ToString(r.preset)));
    EXPECT_DOUBLE_EQ(EvaluatePreset(r.preset, 1.0), 1.0);
    // nowhere above 1: every point of a fine grid over and beyond the support (1 ulp of
    // slack for the rounding of a quotient)
    for (int i = 0; i <= 100000; ++i) {
      const double s = -4.0 + 9.0 * i / 100000;
      EXPECT_LE(EvaluatePreset(r.preset, s), 1.0 + 2.3e-16) << "s = " << s;
    }
  }
}

TEST(ForceLengthPresets, DeGrooteRescaledSoItsPublishedPeakIsOne) {
  // the published constants put the peak off (1, 1), as the README and the source say:
  // f(1) by hand from the paper's constants, 0.99933; the maximum 1.00047 at l = 1.0136
  const double at_one = 0.815 * std::exp(-0.5 * std::pow((1.0 - 1.055) / (0.162 + 0.063), 2)) +
                        0.433 * std::exp(-0.5 * std::pow((1.0 - 0.717) / (-0.030 + 0.200), 2)) +
                        0.100;
  EXPECT_NEAR(at_one, 0.99933, 5e-6);  // the figure quoted, to its last digit
  const Peak peak = DeGrootePublishedPeak();
  EXPECT_NEAR(peak.at, 1.0136, 5e-5);
  EXPECT_NEAR(peak.value, 1.00047, 5e-6);
  // the preset at the paper's l = 1, which is s = 1 / l_peak, is f(1) / f_max: the golden
  // section locates l_peak to 1e-8, which moves f by at most its slope (< 4) times that
  EXPECT_NEAR(EvaluatePreset(ForceLengthPreset::kDeGroote2016, 1.0 / peak.at), at_one / peak.value,
              1e-7);
}

TEST(ForceLengthPresets, PublishedValueAtOneMorePoint) {
  // Thelen: at s = 1 + sqrt(gamma) the exponent is -1
  EXPECT_NEAR(EvaluatePreset(ForceLengthPreset::kThelen2003, 1.0 + std::sqrt(0.45)), std::exp(-1.0),
              1e-15);
  // MuJoCo: at the joins a = 0.75 and b = 1.3, x = 1 and the curve is 0.5
  EXPECT_NEAR(EvaluatePreset(ForceLengthPreset::kMuJoCo, 0.75), 0.5, 1e-15);
  EXPECT_NEAR(EvaluatePreset(ForceLengthPreset::kMuJoCo, 1.3), 0.5, 1e-15);
  // Gordon, Huxley and Julian: 0.84 at the kink, 1.67 um; at 3.0 um, 1 - 0.75 / 1.4 on the
  // descending limb from (2.25, 1) to (3.65, 0)
  EXPECT_NEAR(EvaluatePreset(ForceLengthPreset::kGordon1966, 1.67 / 2.125), 0.84, 1e-15);
  EXPECT_NEAR(EvaluatePreset(ForceLengthPreset::kGordon1966, 3.0 / 2.125), 1.0 - 0.75 / 1.4, 1e-15);
  // De Groote: see DeGrooteRescaledSoItsPublishedPeakIsOne
}

TEST(ForceLengthPresets, EqualTheirSourcesEverywhere) {
  for (const Reference& r : References()) {
    SCOPED_TRACE(std::string(ToString(r.preset)));
    for (int i = 0; i <= 20000; ++i) {
      const double s = -4.0 + 9.0 * i / 20000;
      const double expected = s < r.lo || s > r.hi ? 0.0 : r.curve(s);
      // 1e-7: De Groote's reference peak is located to 1e-8 (above); the others to roundoff
      EXPECT_NEAR(EvaluatePreset(r.preset, s), expected, 1e-7) << "s = " << s;
    }
  }
}

TEST(ForceLengthPresets, PiecesSpanTheSupportWithTheKinksBetween) {
  for (const Reference& r : References()) {
    SCOPED_TRACE(std::string(ToString(r.preset)));
    const PresetPieces pieces = PiecesOf(r.preset);
    ASSERT_GE(pieces.breaks.size(), 2u);
    EXPECT_NEAR(pieces.breaks.front(), r.lo, 1e-15);
    EXPECT_NEAR(pieces.breaks.back(), r.hi, 1e-15);
    EXPECT_GT(pieces.panel, 0.0);
    // just outside the support the curve is zero
    EXPECT_EQ(EvaluatePreset(r.preset, r.lo - 1e-9), 0.0);
    EXPECT_EQ(EvaluatePreset(r.preset, r.hi + 1e-9), 0.0);
  }
  // the polygon's and the quadratics' joins are breaks
  EXPECT_EQ(PiecesOf(ForceLengthPreset::kGordon1966).breaks.size(), GordonBreakpoints().size());
  EXPECT_THAT(PiecesOf(ForceLengthPreset::kMuJoCo).breaks,
              ::testing::ElementsAre(0.5, 0.75, 1.0, 1.3, 1.6));
}

// --- the preset scaled to l_opt, as tabulated ----------------------------------------------

std::vector<std::vector<double>> ParseCsv(const std::string& text, std::string* header) {
  std::istringstream in(text);
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST(ForceLengthPresets, TableScaledToTheOptimalLength) {
  const double l_opt = 0.037;  // m
  for (const Reference& r : References()) {
    SCOPED_TRACE(std::string(ToString(r.preset)));
    std::string header;
    const auto rows = ParseCsv(FormatPresetCurveCsv(r.preset, l_opt, {0.0, 0.08, 81}), &header);
    EXPECT_EQ(header, "length,normalized_length,f_L");
    ASSERT_EQ(rows.size(), 81u);
    for (const auto& row : rows) {
      ASSERT_EQ(row.size(), 3u);
      // f(l_opt * s) is the normalised curve at s
      EXPECT_NEAR(row[1], row[0] / l_opt, 1e-15 * std::max(1.0, row[1]));
      EXPECT_NEAR(row[2], EvaluatePreset(r.preset, row[0] / l_opt), 1e-16);
      const double s = row[0] / l_opt;
      EXPECT_NEAR(row[2], s < r.lo || s > r.hi ? 0.0 : r.curve(s), 1e-7);  // as above
    }
  }
  EXPECT_THROW(FormatPresetCurveCsv(ForceLengthPreset::kMuJoCo, 0.0, {0.0, 1.0, 3}),
               ParameterError);
}

// --- `musclesim curves --preset`, end to end -------------------------------------------------

struct Outcome {
  int exit_code;
  std::string out, err;
};

Outcome RunCli(const std::string& arguments) {
  const std::string err_path = ::testing::TempDir() + "presets_test_stderr_" +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string command = std::string(MUSCLESIM_BINARY) + " " + arguments + " 2>" + err_path;
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  std::ifstream err_file(err_path);
  std::stringstream err;
  err << err_file.rdbuf();
  return {WEXITSTATUS(status), out, err.str()};
}

TEST(ForceLengthPresets, CurvesCommandTabulatesZeroToTwiceTheOptimalLength) {
  const Outcome r = RunCli("curves --preset mujoco --optimal-length 0.1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  const auto rows = ParseCsv(r.out, &header);
  EXPECT_EQ(header, "length,normalized_length,f_L");
  ASSERT_EQ(rows.size(), 201u);  // the default 0:2L:201
  EXPECT_EQ(rows.front()[0], 0.0);
  EXPECT_NEAR(rows.back()[0], 0.2, 1e-16);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_NEAR(rows[i][0], 0.001 * i, 1e-16);  // steps of L / 100
    EXPECT_NEAR(rows[i][2], MuJoCo(rows[i][0] / 0.1), 1e-15);
  }
  EXPECT_EQ(rows[100][2], 1.0);  // the peak, at l = L

  // without --optimal-length, lengths are normalised; --length sets the grid
  const Outcome g = RunCli("curves --preset thelen2003 --length 0.5:1.5:3");
  ASSERT_EQ(g.exit_code, 0) << g.err;
  const auto three = ParseCsv(g.out, &header);
  ASSERT_EQ(three.size(), 3u);
  EXPECT_EQ(three[0][0], 0.5);
  EXPECT_EQ(three[0][1], 0.5);
  EXPECT_NEAR(three[0][2], Thelen(0.5), 1e-16);
  EXPECT_EQ(three[1][2], 1.0);
  EXPECT_NEAR(three[2][2], Thelen(1.5), 1e-16);
}

TEST(ForceLengthPresets, CurvesCommandRejectsBadPresetArguments) {
  Outcome r = RunCli("curves --preset hill");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--preset hill: must be one of degroote2016, thelen2003, "
                               "gordon1966, mujoco"));
  r = RunCli("curves --preset mujoco --optimal-length 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--optimal-length 0: must be > 0 and <= 1000 [m]"));
  r = RunCli("curves --preset mujoco --velocity 0:1:3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--velocity does not apply"));
}

}  // namespace
}  // namespace musclesim
