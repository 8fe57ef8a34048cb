// The problem file's reader (optimize/problem_file.h): every key read into the problem with
// its default where it is left out, and each refusal carrying the key path, the value as
// written, the rule and the place of the offending value in the file (found here by
// searching the text, not by asking the reader).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/optimize/problem_file.h"
#include "optimize/flat_actuator.h"

namespace musclesim {
namespace {

using optimize_test::FlatActuatorOnALoad;

const char kBody[] = R"(intervals: 20
controls:
  - {actuator: muscle, bounds: [0.05, 0.9]}
final_values:
  - {column: mass.position, value: 0.08}
  - {column: mass.velocity, bounds: [-0.001, 0.001]}
optimizer: {tolerance: 1.0e-7, max_iterations: 40}
)";

TEST(ProblemFile, ReadsEveryKeyWithItsDefaults) {
  const ProblemFile file =
      ReadProblem(ParseDocument("problem", kBody), "problem", FlatActuatorOnALoad());
  const OptimalControlProblem& p = file.problem;
  EXPECT_EQ(p.intervals, 20);
  ASSERT_EQ(p.controls.size(), 1u);
  EXPECT_EQ(p.controls[0].actuator, "muscle");
  EXPECT_EQ(p.controls[0].lower, 0.05);
  EXPECT_EQ(p.controls[0].upper, 0.9);
  EXPECT_EQ(p.controls[0].effort_weight, 1.0);  // the defaults of an effort left out
  EXPECT_EQ(p.controls[0].effort_power, 2);
  ASSERT_EQ(p.final_values.size(), 2u);
  // a value fixes the column: its bounds equal
  EXPECT_EQ(p.final_values[0].column, "mass.position");
  EXPECT_EQ(p.final_values[0].lower, 0.08);
  EXPECT_EQ(p.final_values[0].upper, 0.08);
  EXPECT_EQ(p.final_values[1].lower, -0.001);
  EXPECT_EQ(p.final_values[1].upper, 0.001);
  EXPECT_EQ(file.options.tolerance, 1e-7);
  EXPECT_EQ(file.options.max_iterations, 40);
  EXPECT_TRUE(file.outputs.scenario.empty());  // a document writes nothing
}

TEST(ProblemFile, ABlockLeftOutTakesItsDescribedDefaults) {
  // the optimizer block absent: the defaults its description states, as for a block given
  // without those keys
  const std::string body = R"(controls:
  - {actuator: muscle}
final_time: {bounds: [0.1, 0.2]}
terminal:
  - {column: mass.position, target: 0.08}
)";
  const ProblemFile file =
      ReadProblem(ParseDocument("problem", body), "problem", FlatActuatorOnALoad());
  EXPECT_EQ(file.problem.intervals, 20);
  EXPECT_EQ(file.problem.controls[0].lower, 0.0);
  EXPECT_EQ(file.problem.controls[0].upper, 1.0);
  EXPECT_EQ(file.options.tolerance, 1e-8);
  EXPECT_EQ(file.options.max_iterations, 500);
  EXPECT_EQ(file.options.max_iterations, OptimizeOptions{}.max_iterations);
  EXPECT_EQ(file.options.derivatives, ShootingDerivatives::kSensitivities);
  EXPECT_TRUE(std::isinf(file.options.max_seconds));
  ASSERT_TRUE(file.problem.final_time);
  EXPECT_EQ(file.problem.final_time->lower, 0.1);
  EXPECT_EQ(file.problem.final_time->upper, 0.2);
  EXPECT_EQ(file.problem.final_time->weight, 0.0);
  ASSERT_EQ(file.problem.terminal.size(), 1u);
  EXPECT_EQ(file.problem.terminal[0].target, 0.08);
  EXPECT_EQ(file.problem.terminal[0].weight, 1.0);
  const ProblemFile given =
      ReadProblem(ParseDocument("problem", body + "optimizer: {derivatives: difference_quotients, "
                                                  "max_seconds: 60}\n"),
                  "problem", FlatActuatorOnALoad());
  EXPECT_EQ(given.options.tolerance, 1e-8);
  EXPECT_EQ(given.options.derivatives, ShootingDerivatives::kDifferenceQuotients);
  EXPECT_EQ(given.options.max_seconds, 60.0);
}

struct Refusal {
  std::string from, to;  // the edit of kBody's text
  std::string key, value, rule;
};

// "base: PATH" then kBody with one edit, written to a file of this test.
std::string WriteProblem(const Refusal& r, std::string& text) {
  const Scenario scenario = FlatActuatorOnALoad();
  text = "base: " + scenario.source + "\n" + kBody;
  const std::size_t at = text.find(r.from);
  EXPECT_NE(at, std::string::npos) << r.from;
  text.replace(at, r.from.size(), r.to);
  std::string name = r.key;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  const std::string path = ::testing::TempDir() + "problem_file_test_" + name + ".yaml";
  std::ofstream(path) << text;
  return path;
}

void PrintTo(const Refusal& r, std::ostream* out) { *out << r.to; }

class ProblemFileRefusal : public ::testing::TestWithParam<Refusal> {};

TEST_P(ProblemFileRefusal, NamesTheKeyTheValueTheRuleAndThePlace) {
  const Refusal& r = GetParam();
  std::string text;
  const std::string path = WriteProblem(r, text);
  try {
    LoadProblemFile(path);
    FAIL() << "accepted: " << r.to;
  } catch (const InputError& error) {
    const InputFault& fault = error.fault();
    EXPECT_EQ(fault.key, r.key) << error.what();
    ASSERT_TRUE(fault.value.has_value()) << error.what();
    EXPECT_EQ(*fault.value, r.value) << error.what();
    EXPECT_NE(fault.rule.find(r.rule), std::string::npos) << error.what();
    ASSERT_TRUE(fault.place.has_value()) << error.what();
    EXPECT_EQ(fault.place->file, path);
    // the line and column of the edited value in the text, counted from 1
    const std::size_t at = text.find(r.value, text.find(r.to));
    const std::size_t line_start = text.rfind('\n', at) + 1;
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    EXPECT_EQ(fault.place->line, line) << error.what();
    EXPECT_EQ(fault.place->column, static_cast<int>(at - line_start) + 1) << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryKind, ProblemFileRefusal,
    ::testing::Values(Refusal{"intervals: 20", "intervals: 0", "intervals", "0", "must be"},
                      Refusal{"actuator: muscle", "actuator: nobody", "controls[0].actuator",
                              "nobody", "no actuator"},
                      Refusal{"bounds: [0.05, 0.9]}", "bounds: [0.05, 0.9], effort: {power: 4}}",
                              "controls[0].effort.power", "4",
                              "must be an integer from 2 to 3 [-]: 2: integral of u^2"},
                      Refusal{"bounds: [0.05, 0.9]", "bounds: [0.05, 1.5]", "controls[0].bounds[1]",
                              "1.5", "must be"},
                      Refusal{"column: mass.position", "column: mass.speed",
                              "final_values[0].column", "mass.speed", "column"},
                      Refusal{"intervals: 20", "intervals: 2.5", "intervals", "2.5",
                              "must be an integer from 1 to 1e+05 [-]"},
                      Refusal{"bounds: [0.05, 0.9]", "bounds: [0.9, 0.05]", "controls[0].bounds",
                              "[0.9, 0.05]", "lower <= upper"},
                      Refusal{"bounds: [0.05, 0.9]}", "bounds: [0.05, 0.9], effort: {weight: -1}}",
                              "controls[0].effort.weight", "-1", "must be from 0 to 1e+12"},
                      Refusal{"value: 0.08}", "value: 0.08, bounds: [0, 1]}",
                              "final_values[0].bounds", "[0, 1]", "either value or bounds"},
                      Refusal{"tolerance: 1.0e-7", "tolerance: 0", "optimizer.tolerance", "0",
                              "must be from 1e-14 to 1"},
                      Refusal{"max_iterations: 40", "max_iterations: 0", "optimizer.max_iterations",
                              "0", "must be an integer from 1"},
                      Refusal{"max_iterations: 40", "max_iterations: 40, derivatives: guess",
                              "optimizer.derivatives", "guess",
                              "must be sensitivities or difference_quotients"},
                      Refusal{"max_iterations: 40}",
                              "max_iterations: 40}\nfinal_time: {bounds: [0.2, 0.1]}",
                              "final_time.bounds", "[0.2, 0.1]", "lower <= upper"},
                      Refusal{"max_iterations: 40}", "max_iterations: 40}\noutput: {summary: \"\"}",
                              "output.summary", "\"\"", "must not be empty"}),
    [](const ::testing::TestParamInfo<Refusal>& param) {
      std::string name = param.param.key;
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name + "_" + std::to_string(param.index);  // a key may be refused twice
    });

}  // namespace
}  // namespace musclesim
