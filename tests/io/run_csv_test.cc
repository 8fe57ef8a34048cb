// A run as CSV (io/writers/run_csv.h) and its stats as JSON (io/writers/stats_json.h): the single
// actuator's documented header, rows of 17 significant digits that read back to the same doubles,
// the phase words, and the streamed writer writing what the whole formatter does.
#include "musclesim/io/writers/run_csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>

#include "musclesim/io/writers/output_file.h"
#include "musclesim/io/writers/stats_json.h"
#include "support/canonical_scenarios.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

// The single actuator's columns (scenarios/concentric.yaml built in code), with
// output.phase_tolerance set when given; with `excitation`, activation dynamics.
RunColumns ActuatorColumns(std::optional<double> phase_tolerance = std::nullopt,
                           bool excitation = false) {
  ActuatorScenarioSpec spec = testing::ConcentricSpec();
  spec.output.phase_tolerance = phase_tolerance;
  if (excitation) spec.excitation = ExcitationInput{Waveform::Constant(0.5), {}, std::nullopt};
  const Scenario scenario = MakeActuatorScenario(spec);
  return RunColumns(scenario, scenario.Build());
}

// What the actuator's network observes when the actuator is `length` long and shortens at
// `v`: element 0 the actuator, node 1 its tip (docs/model.md 7.4).
NetworkSample Sample(double length, double v) {
  NetworkSample s;
  s.position = {0.0, length};
  s.velocity = {0.0, -v};
  s.load = {0.0, -40.0};
  s.elements.resize(3);
  ElementSample& actuator = s.elements[kActuatorElement];
  actuator.length = length;
  actuator.lengthening_rate = -v;
  actuator.activation = 0.75;
  actuator.excitation = 0.75;
  actuator.parts.passive = 1.0 / 3.0;
  actuator.parts.active = 2.0 / 3.0;
  actuator.parts.total = 1.0;
  actuator.tension = 1.0;
  return s;
}

struct Point {
  double t;
  NetworkSample sample;
};

Point At(double t, double length, double v) { return {t, Sample(length, v)}; }

// The run that recorded `points`, in memory, as a ColumnRecorder would hold it.
RecordedRun Recorded(const RunColumns& columns, const std::vector<Point>& points) {
  RecordedRun run{columns, std::vector<std::vector<double>>(columns.size()), {}};
  std::vector<double> row(columns.size());
  for (const Point& p : points) {
    columns.Fill(p.t, p.sample, row.data());
    for (std::size_t c = 0; c < row.size(); ++c) run.values[c].push_back(row[c]);
  }
  return run;
}

// The CSV line (without its newline) of one point.
std::string Row(const RunColumns& columns, const Point& p) {
  std::vector<double> row(columns.size());
  columns.Fill(p.t, p.sample, row.data());
  std::string csv;
  AppendCsvRow(csv, columns, row.data());
  return csv;
}

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

TEST(TrajectoryCsv, HeaderIsTheDocumentedOne) {
  // docs/guide/scenarios.md: the header is exactly this
  EXPECT_EQ(FormatRunCsv(Recorded(ActuatorColumns(), {})),
            "t,length,shortening_velocity,activation,tension_passive,tension_active,"
            "tension_total,load,phase\n");
  // with activation dynamics, `excitation` right after `activation`
  EXPECT_EQ(CsvHeader(ActuatorColumns(std::nullopt, true)),
            "t,length,shortening_velocity,activation,excitation,tension_passive,"
            "tension_active,tension_total,load,phase");
}

TEST(TrajectoryCsv, RowHoldsEveryFieldWithSeventeenDigits) {
  EXPECT_EQ(Row(ActuatorColumns(), At(0.1, 0.2, 0.3)),
            "0.10000000000000001,0.20000000000000001,0.29999999999999999,0.75,"
            "0.33333333333333331,0.66666666666666663,1,-40,concentric");
}

TEST(TrajectoryCsv, NumbersReadBackToTheSameDoubles) {
  // %.17g is enough digits for every double to survive the round trip through text
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  std::vector<Point> points;
  for (int i = 0; i < 2000; ++i) {
    Point p = At(mantissa(rng), std::ldexp(mantissa(rng), exponent(rng)),
                 std::ldexp(mantissa(rng), exponent(rng) / 10));
    p.sample.elements[kActuatorElement].parts.total = std::ldexp(mantissa(rng), exponent(rng));
    points.push_back(p);
  }
  points.push_back(At(5e-324, 1.7976931348623157e308, -0.0));  // the extremes
  const RunColumns columns = ActuatorColumns(0.0);
  const std::vector<std::string> lines = Split(FormatRunCsv(Recorded(columns, points)), '\n');
  ASSERT_EQ(lines.size(), points.size() + 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::vector<std::string> fields = Split(lines[i + 1], ',');
    ASSERT_EQ(fields.size(), 9u) << lines[i + 1];
    const NetworkSample& s = points[i].sample;
    const ElementSample& a = s.elements[kActuatorElement];
    const double expected[8] = {
        points[i].t,     a.length,       -a.lengthening_rate, a.activation,
        a.parts.passive, a.parts.active, a.parts.total,       s.load[kActuatorTipNode]};
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
  const RunColumns columns = ActuatorColumns(tol);
  std::vector<std::string> phases;
  for (double v : {std::nextafter(tol, 1.0), tol, -tol, std::nextafter(-tol, -1.0)}) {
    phases.push_back(Split(Row(columns, At(0.0, 0.1, v)), ',').back());
  }
  EXPECT_THAT(phases, ::testing::ElementsAre("concentric", "isometric", "isometric", "eccentric"));
}

std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "run_csv_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(TrajectoryCsv, StreamedWriterWritesWhatTheWholeFormatterDoes) {
  // 3000 rows of ~200 bytes span several of the writer's 64 KiB blocks
  std::vector<Point> points;
  for (int i = 0; i < 3000; ++i) {
    points.push_back(At(1e-3 * i, 0.1 + 1e-6 * i, 2e-3 * std::sin(0.01 * i)));
  }
  const Scenario scenario = testing::ConcentricScenario();
  const std::string path = TempPath("streamed.csv");
  std::remove(path.c_str());
  {
    StreamedOutput output(path);
    RunCsvWriter writer(output, scenario, scenario.Build());
    for (const Point& p : points) writer.Record(p.t, p.sample);
    EXPECT_EQ(writer.rows(), 3000);
    EXPECT_EQ(writer.last().front(), points.back().t);  // column t
    writer.Flush();
    output.Commit();
  }
  EXPECT_EQ(ReadFile(path), FormatRunCsv(Recorded(ActuatorColumns(), points)));
}

TEST(TrajectoryCsv, StreamedWriterOfAnEmptyRunWritesTheHeader) {
  const std::string path = TempPath("empty.csv");
  const Scenario scenario = testing::ConcentricScenario();
  {
    StreamedOutput output(path);
    RunCsvWriter writer(output, scenario, scenario.Build());
    EXPECT_EQ(writer.rows(), 0);
    writer.Flush();
    output.Commit();
  }
  EXPECT_EQ(ReadFile(path), FormatRunCsv(Recorded(ActuatorColumns(), {})));
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
