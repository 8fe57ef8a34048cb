#include "musclesim/io/trajectory_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include "musclesim/io/output_file.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

TrajectoryPoint Point(double t, double length, double v) {
  TrajectoryPoint p{t, {}};
  p.sample.length = length;
  p.sample.shortening_velocity = v;
  p.sample.activation = 0.75;
  p.sample.tension.passive = 1.0 / 3.0;
  p.sample.tension.active = 2.0 / 3.0;
  p.sample.tension.total = 1.0;
  p.sample.load = -40.0;
  return p;
}

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

TEST(TrajectoryCsv, HeaderIsTheDocumentedOne) {
  // README "Scenarios": the header is exactly this
  EXPECT_EQ(FormatTrajectoryCsv({}, 1e-3),
            "t,length,shortening_velocity,activation,tension_passive,tension_active,"
            "tension_total,load,phase\n");
}

TEST(TrajectoryCsv, RowHoldsEveryFieldWithSeventeenDigits) {
  std::string row;
  AppendTrajectoryRow(row, Point(0.1, 0.2, 0.3), 1e-3);
  EXPECT_EQ(row,
            "0.10000000000000001,0.20000000000000001,0.29999999999999999,0.75,"
            "0.33333333333333331,0.66666666666666663,1,-40,concentric\n");
}

TEST(TrajectoryCsv, NumbersReadBackToTheSameDoubles) {
  // %.17g is enough digits for every double to survive the round trip through text
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  std::vector<TrajectoryPoint> points;
  for (int i = 0; i < 2000; ++i) {
    TrajectoryPoint p = Point(mantissa(rng), std::ldexp(mantissa(rng), exponent(rng)),
                              std::ldexp(mantissa(rng), exponent(rng) / 10));
    p.sample.tension.total = std::ldexp(mantissa(rng), exponent(rng));
    points.push_back(p);
  }
  points.push_back(Point(5e-324, 1.7976931348623157e308, -0.0));  // the extremes
  const std::vector<std::string> lines = Split(FormatTrajectoryCsv(points, 0.0), '\n');
  ASSERT_EQ(lines.size(), points.size() + 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::vector<std::string> fields = Split(lines[i + 1], ',');
    ASSERT_EQ(fields.size(), 9u) << lines[i + 1];
    const TrajectoryPoint& p = points[i];
    const double expected[8] = {p.t, p.sample.length, p.sample.shortening_velocity,
                                p.sample.activation, p.sample.tension.passive,
                                p.sample.tension.active, p.sample.tension.total, p.sample.load};
    for (int k = 0; k < 8; ++k) {
      EXPECT_EQ(std::strtod(fields[k].c_str(), nullptr), expected[k]) << fields[k];
      // at most 17 significant digits (fewer when they end in zeros, as 0.75 does): the
      // digits of the mantissa from its first non-zero one
      const std::string mantissa_text = fields[k].substr(0, fields[k].find('e'));
      const std::size_t first = mantissa_text.find_first_of("123456789");
      std::size_t digits = 0;
      if (first != std::string::npos) {
        for (char c : mantissa_text.substr(first)) {
          digits += std::isdigit(static_cast<unsigned char>(c)) != 0;
        }
      }
      EXPECT_LE(digits, 17u) << fields[k];
    }
  }
}

TEST(TrajectoryCsv, PhaseIsIsometricUpToAndIncludingTheTolerance) {
  // docs/model.md section 6: concentric when v > v_tol, eccentric when v < -v_tol
  const double tol = 1e-3;
  EXPECT_EQ(ClassifyPhase(tol, tol), Phase::kIsometric);
  EXPECT_EQ(ClassifyPhase(-tol, tol), Phase::kIsometric);
  EXPECT_EQ(ClassifyPhase(0.0, tol), Phase::kIsometric);
  EXPECT_EQ(ClassifyPhase(std::nextafter(tol, 1.0), tol), Phase::kConcentric);
  EXPECT_EQ(ClassifyPhase(std::nextafter(-tol, -1.0), tol), Phase::kEccentric);
  EXPECT_EQ(ClassifyPhase(0.0, 0.0), Phase::kIsometric);
  EXPECT_EQ(ClassifyPhase(1e-300, 0.0), Phase::kConcentric);
  // and in the CSV, by name
  std::string rows;
  for (double v : {std::nextafter(tol, 1.0), tol, -tol, std::nextafter(-tol, -1.0)}) {
    AppendTrajectoryRow(rows, Point(0.0, 0.1, v), tol);
  }
  std::vector<std::string> phases;
  for (const std::string& line : Split(rows, '\n')) phases.push_back(Split(line, ',').back());
  EXPECT_THAT(phases, ::testing::ElementsAre("concentric", "isometric", "isometric", "eccentric"));
}

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "trajectory_csv_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(TrajectoryCsv, StreamedWriterWritesWhatTheWholeFormatterDoes) {
  // 3000 rows of ~200 bytes span several of the writer's 64 KiB blocks
  std::vector<TrajectoryPoint> points;
  for (int i = 0; i < 3000; ++i) {
    points.push_back(Point(1e-3 * i, 0.1 + 1e-6 * i, 2e-3 * std::sin(0.01 * i)));
  }
  const std::string path = TempPath("streamed.csv");
  std::remove(path.c_str());
  {
    StreamedOutput output(path);
    TrajectoryCsvWriter writer(output, 1e-3);
    for (const TrajectoryPoint& p : points) writer.Record(p);
    EXPECT_EQ(writer.rows(), 3000);
    EXPECT_EQ(writer.last().t, points.back().t);
    writer.Flush();
    output.Commit();
  }
  EXPECT_EQ(ReadFile(path), FormatTrajectoryCsv(points, 1e-3));
}

TEST(TrajectoryCsv, StreamedWriterOfAnEmptyRunWritesTheHeader) {
  const std::string path = TempPath("empty.csv");
  {
    StreamedOutput output(path);
    TrajectoryCsvWriter writer(output, 1e-3);
    EXPECT_EQ(writer.rows(), 0);
    writer.Flush();
    output.Commit();
  }
  EXPECT_EQ(ReadFile(path), FormatTrajectoryCsv({}, 1e-3));
}

TEST(TrajectoryCsv, StatsJsonHoldsEveryCounterAndEscapesTheMessage) {
  RunStats stats;
  stats.steps = 12;
  stats.rhs_evals = 34;
  stats.jac_evals = 5;
  stats.linear_setups = 6;
  stats.newton_iters = 78;
  stats.newton_conv_fails = 1;
  stats.error_test_fails = 2;
  stats.wall_seconds = 0.25;
  stats.final_time = 0.1;
  stats.linear_solver = LinearSolverKind::kBand;
  stats.status = RunStatus::kFailed;
  stats.message = "CVODE said \"no\" at C:\\path\n\tthen stopped";
  EXPECT_EQ(FormatStatsJson(stats),
            "{\n"
            "  \"steps\": 12,\n"
            "  \"rhs_evals\": 34,\n"
            "  \"jac_evals\": 5,\n"
            "  \"linear_setups\": 6,\n"
            "  \"newton_iters\": 78,\n"
            "  \"newton_conv_fails\": 1,\n"
            "  \"error_test_fails\": 2,\n"
            "  \"wall_seconds\": 0.25,\n"
            "  \"final_time\": 0.10000000000000001,\n"
            "  \"linear_solver\": \"band\",\n"
            "  \"status\": \"failed\",\n"
            // quotes and backslashes escaped; control characters (not valid raw in a JSON
            // string) become spaces
            "  \"message\": \"CVODE said \\\"no\\\" at C:\\\\path  then stopped\"\n"
            "}\n");
  stats.status = RunStatus::kLimit;
  EXPECT_THAT(FormatStatsJson(stats), HasSubstr("\"status\": \"limit\""));
  stats.status = RunStatus::kCompleted;
  stats.message.clear();
  EXPECT_THAT(FormatStatsJson(stats), HasSubstr("\"status\": \"completed\",\n  \"message\": \"\""));
}

}  // namespace
}  // namespace musclesim
