// Panels of CSV columns against time sharing one inline data block: a network's lengths,
// tensions and activations (private to the plot layer).
#pragma once

#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/io/readers/csv_table.h"

namespace musclesim::plot_text {

// The columns whose name ends in `.suffix` (and is longer than it), in the CSV's order.
std::vector<int> ColumnsEndingIn(const CsvTable& table, const std::string& suffix);

// One line of a panel: an inline data column (gnuplot counts from 1), its legend and the CSV
// column it came from (for messages).
struct Line {
  int column;
  std::string label;
  std::string source;
  bool dashed;  // thin and dashed: the excitations, the references
};

struct Panel {
  std::string ylabel;
  std::vector<Line> lines;
  std::string ylabel_source;  // the CSV column a ylabel made from a name came from ("": none)
};

// The inline data's CSV columns, time first, and the panels drawing them.
class TimePanels {
 public:
  explicit TimePanels(const CsvTable& table);

  // Adds CSV column `column` to the inline data as a line of `panel`.
  void Add(Panel& panel, int column, const std::string& label, bool dashed);
  // A line per column ending in `suffix`, labelled by its part's name and `label_end`.
  void AddKind(Panel& panel, const std::string& suffix, const std::string& label_end, bool dashed);
  const std::vector<int>& data() const { return data_; }

 private:
  const CsvTable& table_;
  std::vector<int> data_;
};

// A panel of more lines than this draws them as one curve of many pieces (a block of its own,
// a piece per line, each its own colour) with one key entry for them all: a titled curve per
// line costs gnuplot a pass over every column of the block, which for a lattice of 1000
// elements took minutes, and a key of hundreds of names hides the panel.
inline constexpr std::size_t kMostKeyedLines = 12;

// The rows of `data`'s columns as the inline block `name` ("$network").
void WriteDataBlock(const CsvTable& table, const std::vector<int>& data, const std::string& name,
                    std::ostringstream& s);

// The blocks NAME_P of the panels of more than kMostKeyedLines lines: each line's (t, value)
// rows, the lines apart by two blank lines (gnuplot's data sets), `data` the inline data's
// CSV columns (TimePanels::data()).
void WriteGroupedBlocks(const CsvTable& table, const std::vector<int>& data,
                        const std::vector<Panel>& panels, const std::string& name,
                        std::ostringstream& s);

// Each panel's `plot` of block `name` against time (a grouped panel of its block NAME_P),
// the last with the time axis labelled; `before` (if set) writes what a panel needs first
// (its origin and size).
void WritePanels(const std::vector<Panel>& panels, const std::string& name, std::ostringstream& s,
                 const std::function<void(std::size_t)>& before = {});

}  // namespace musclesim::plot_text
