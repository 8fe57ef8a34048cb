// Every reader's InputError carries its fault as fields: the file, line and column found here
// by searching the text written (an independent place), the key path, the value and the
// rule, for a value, an unknown key, a syntax error, an override, a CSV row, a problem file's
// entry checked against its scenario and a sweep's axis.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/csv_table.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/optimize/problem_file.h"
#include "support/fresh_directory.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

std::string Write(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

std::string Text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// The 1-based line and column of the first `needle` in `text`.
InputPlace Find(const std::string& file, const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  const std::size_t line_start = text.rfind('\n', at);
  const std::size_t begin = line_start == std::string::npos ? 0 : line_start + 1;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return {file, line, static_cast<int>(at - begin) + 1};
}

template <typename Call>
InputFault FaultOf(Call call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.fault();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

void ExpectPlace(const InputFault& fault, const InputPlace& expected) {
  ASSERT_TRUE(fault.place.has_value());
  EXPECT_EQ(fault.place->file, expected.file);
  EXPECT_EQ(fault.place->line, expected.line);
  EXPECT_EQ(fault.place->column, expected.column);
}

TEST(InputErrorFields, AValueBreakingARule) {
  const std::string dir = testing::FreshDirectory("fields_value");
  std::string text = Text(testing::ScenarioPath("concentric.yaml"));
  text.replace(text.find("n: 3,"), 5, "n: 0,");
  const std::string path = Write(dir + "/s.yaml", text);
  const InputFault fault = FaultOf([&] { LoadScenario(path); });
  EXPECT_EQ(fault.key, "model.velocity.n");
  EXPECT_EQ(fault.value, "0");
  InputPlace zero = Find(path, text, "n: 0,");
  zero.column += 3;  // the value, after "n: "
  ExpectPlace(fault, zero);
  EXPECT_FALSE(fault.rule.empty());
}

TEST(InputErrorFields, AnUnknownKeyIsPlacedAtTheKey) {
  const std::string dir = testing::FreshDirectory("fields_unknown");
  std::string text = Text(testing::ScenarioPath("concentric.yaml"));
  text.replace(text.find("f_iso:"), 6, "f_isoo:");
  const std::string path = Write(dir + "/s.yaml", text);
  const InputFault fault = FaultOf([&] { LoadScenario(path); });
  EXPECT_EQ(fault.key, "model.f_isoo");
  EXPECT_FALSE(fault.value.has_value());
  ExpectPlace(fault, Find(path, text, "f_isoo:"));
  EXPECT_EQ(fault.rule.rfind("unknown key", 0), 0u) << fault.rule;
}

TEST(InputErrorFields, ASyntaxErrorHasAPlaceAndNoKey) {
  const std::string dir = testing::FreshDirectory("fields_syntax");
  const std::string path = Write(dir + "/s.yaml", "name: x\nmodel: {f_iso: [1, 2}\n");
  const InputFault fault = FaultOf([&] { LoadScenario(path); });
  EXPECT_TRUE(fault.key.empty());
  ASSERT_TRUE(fault.place.has_value());
  EXPECT_EQ(fault.place->file, path);
  EXPECT_EQ(fault.place->line, 2);
  EXPECT_EQ(fault.rule.rfind("YAML syntax error", 0), 0u) << fault.rule;
}

TEST(InputErrorFields, AnOverrideNamesItsKeyAndValue) {
  const InputFault missing = FaultOf([] {
    LoadScenario(testing::ScenarioPath("concentric.yaml"),
                 Overrides({"model.nothing.n=3"}, "--set"));
  });
  EXPECT_EQ(missing.key, "model.nothing.n");
  EXPECT_EQ(missing.value, "3");
  ASSERT_TRUE(missing.place.has_value());
  EXPECT_EQ(missing.place->file, "--set");
  EXPECT_FALSE(missing.place->positioned());
  // a value an override gives that breaks a rule: the reader's own fault, at the label
  const InputFault bad = FaultOf([] {
    LoadScenario(testing::ScenarioPath("concentric.yaml"), Overrides({"model.f_iso=-1"}, "--set"));
  });
  EXPECT_EQ(bad.key, "model.f_iso");
  EXPECT_EQ(bad.value, "-1");
  EXPECT_EQ(bad.place->file, "--set");
}

TEST(InputErrorFields, ACsvRowIsPlacedAtItsLine) {
  const std::string dir = testing::FreshDirectory("fields_csv");
  const std::string path = Write(dir + "/d.csv", "t,length\n0,0.1\n0.1,abc\n");
  const InputFault fault = FaultOf([&] {
    const CsvTable table = ReadCsv(path);
    table.Number(1, table.Find("length"));
  });
  ASSERT_TRUE(fault.place.has_value());
  EXPECT_EQ(fault.place->file, path);
  EXPECT_EQ(fault.place->line, 3);
  EXPECT_EQ(fault.place->column, 0);
}

TEST(InputErrorFields, AProblemEntryCheckedAgainstItsScenarioIsPlacedInTheProblem) {
  const std::string dir = testing::FreshDirectory("fields_problem");
  std::filesystem::copy_file(testing::ScenarioPath("antagonist_move.yaml"),
                             dir + "/antagonist_move.yaml");
  const std::string text = "base: antagonist_move.yaml\ncontrols:\n  - {actuator: biceps}\n";
  const std::string path = Write(dir + "/problem.yaml", text);
  const InputFault fault = FaultOf([&] { LoadProblemFile(path); });
  EXPECT_EQ(fault.key, "controls[0].actuator");
  ExpectPlace(fault, Find(path, text, "biceps"));
}

}  // namespace
}  // namespace musclesim
