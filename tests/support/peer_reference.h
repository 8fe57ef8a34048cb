// Test helper: a table the peers wrote (bench/peers/reference/*.csv: '#' comment lines, a
// header, rows of numbers), as its columns by name.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace musclesim::testing {

using PeerTable = std::map<std::string, std::vector<double>>;

inline PeerTable ReadPeerTable(const std::string& name) {
  const std::string path = std::string(MUSCLESIM_SOURCE_DIR) + "/bench/peers/reference/" + name;
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  PeerTable table;
  std::vector<std::string> names;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream fields(line);
    std::string field;
    if (names.empty()) {
      while (std::getline(fields, field, ',')) names.push_back(field);
      continue;
    }
    for (const std::string& column : names) {
      std::getline(fields, field, ',');
      table[column].push_back(std::stod(field));
    }
  }
  EXPECT_FALSE(table.empty()) << path;
  return table;
}

}  // namespace musclesim::testing
