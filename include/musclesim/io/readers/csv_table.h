// Reading the CSV files musclesim writes (trajectories, summaries): a header and rows of
// text fields, with RFC 4180 quoting.
#pragma once

#include <string>
#include <vector>

namespace musclesim {

// Numbers stay text until asked for (Number), so no field here has a physical unit: "[-]".
struct CsvTable {
  std::string source;                          // the file's path, for messages [-]
  std::vector<std::string> header;             // column names [-]
  std::vector<std::vector<std::string>> rows;  // fields as text, each row as long as header [-]
  std::vector<std::size_t> lines;              // the file's line number of each row, 1-based [-]

  // Index of `name` in the header, or -1.
  int Find(const std::string& name) const;
  // Throws InputError naming every one of `names` the header lacks.
  void Require(const std::vector<std::string>& names, const std::string& what) const;
  // The field as a number; throws InputError naming the file, row and column if it is not.
  double Number(std::size_t row, int column) const;
};

// Throws InputError for a missing file, an empty file or a row of the wrong length. Blank
// lines and lines starting with # (comments, such as a data file's source) are skipped.
CsvTable ReadCsv(const std::string& path);

}  // namespace musclesim
