// Test helper: runs the built `musclesim` program (MUSCLESIM_BINARY) and reads what it wrote:
// its exit code, standard error, and CSV and JSON files, for end-to-end tests of the CLI.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace musclesim::testing {

struct CliOutcome {
  int exit_code = -1;
  std::string err;  // standard error
};

// `musclesim ARGUMENTS` with standard output discarded; standard error goes to a file named
// after the running test (ctest runs tests in parallel processes).
inline CliOutcome RunMusclesim(const std::string& arguments) {
  const std::string err_path = ::testing::TempDir() +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                               "_stderr.txt";
  const std::string command =
      std::string(MUSCLESIM_BINARY) + " " + arguments + " >/dev/null 2>" + err_path;
  const int status = std::system(command.c_str());
  std::ifstream in(err_path);
  std::stringstream err;
  err << in.rdbuf();
  return {WEXITSTATUS(status), err.str()};
}

// A path in the test's temporary directory, named after the running test and `name`.
inline std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
         "_" + name;
}

// A CSV file as its header line and its rows of fields (text, as written).
struct CsvText {
  std::string header;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;

  int Column(const std::string& name) const {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i] == name) return static_cast<int>(i);
    }
    return -1;
  }
};

inline std::vector<std::string> SplitCommas(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

inline CsvText ReadCsv(const std::string& path) {
  CsvText csv;
  std::ifstream in(path);
  std::getline(in, csv.header);
  csv.columns = SplitCommas(csv.header);
  for (std::string line; std::getline(in, line);) csv.rows.push_back(SplitCommas(line));
  return csv;
}

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace musclesim::testing
