#include "plot/time_panels.h"

#include "plot/plot_text.h"

namespace musclesim::plot_text {

std::vector<int> ColumnsEndingIn(const CsvTable& table, const std::string& suffix) {
  std::vector<int> columns;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    const std::string& name = table.header[c];
    if (name.size() > suffix.size() && EndsWith(name, suffix))
      columns.push_back(static_cast<int>(c));
  }
  return columns;
}

TimePanels::TimePanels(const CsvTable& table) : table_(table), data_{table.Find("t")} {}

void TimePanels::Add(Panel& panel, int column, const std::string& label, bool dashed) {
  data_.push_back(column);
  panel.lines.push_back({static_cast<int>(data_.size()), label,
                         table_.header[static_cast<std::size_t>(column)], dashed});
}

void TimePanels::AddKind(Panel& panel, const std::string& suffix, const std::string& label_end,
                         bool dashed) {
  for (int column : ColumnsEndingIn(table_, suffix)) {
    const std::string& name = table_.header[static_cast<std::size_t>(column)];
    Add(panel, column, name.substr(0, name.size() - suffix.size()) + label_end, dashed);
  }
}

void WriteDataBlock(const CsvTable& table, const std::vector<int>& data, const std::string& name,
                    std::ostringstream& s) {
  s << name << " << EOD\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    for (std::size_t c = 0; c < data.size(); ++c) {
      s << (c ? " " : "") << Number(FiniteValue(table, r, data[c]));
    }
    s << "\n";
  }
  s << "EOD\n";
}

namespace {

bool Grouped(const Panel& panel) { return panel.lines.size() > kMostKeyedLines; }

std::string GroupName(const std::string& name, std::size_t panel) {
  return name + "_" + std::to_string(panel);
}

// A grouped panel's one curve: its data sets in turn, coloured by their index, the key
// saying how many lines there are.
void WriteGroupedPlot(const Panel& panel, const std::string& block, std::ostringstream& s) {
  const bool dashed = panel.lines.front().dashed;
  s << "plot " << block << " using 1:2:(column(-2) + 1) with lines lw 1" << (dashed ? " dt 2" : "")
    << " lc variable notitle, \\\n  keyentry with lines lw 1 lc 1 title "
    << GnuplotString(std::to_string(panel.lines.size()) + " lines", "a key") << "\n";
}

}  // namespace

void WriteGroupedBlocks(const CsvTable& table, const std::vector<int>& data,
                        const std::vector<Panel>& panels, const std::string& name,
                        std::ostringstream& s) {
  for (std::size_t p = 0; p < panels.size(); ++p) {
    if (!Grouped(panels[p])) continue;
    s << GroupName(name, p) << " << EOD\n";
    for (std::size_t i = 0; i < panels[p].lines.size(); ++i) {
      if (i > 0) s << "\n\n";
      const int column = data[static_cast<std::size_t>(panels[p].lines[i].column - 1)];
      for (std::size_t r = 0; r < table.rows.size(); ++r) {
        s << Number(FiniteValue(table, r, data[0])) << " " << Number(FiniteValue(table, r, column))
          << "\n";
      }
    }
    s << "EOD\n";
  }
}

void WritePanels(const std::vector<Panel>& panels, const std::string& name, std::ostringstream& s,
                 const std::function<void(std::size_t)>& before) {
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const Panel& panel = panels[p];
    if (before) before(p);
    if (p + 1 == panels.size()) s << "set format x '%g'\nset xlabel 'time [s]'\n";
    s << "set ylabel " << GnuplotString(panel.ylabel, "column " + Printable(panel.ylabel_source))
      << "\n";
    if (Grouped(panel)) {
      WriteGroupedPlot(panel, GroupName(name, p), s);
      continue;
    }
    s << "plot ";
    for (std::size_t i = 0; i < panel.lines.size(); ++i) {
      const Line& line = panel.lines[i];
      s << (i ? ", \\\n  " : "") << name << " using 1:" << line.column
        << (line.dashed ? " with lines lw 1 dt 2 title " : " with lines lw 2 title ")
        << GnuplotString(line.label, "column " + Printable(line.source));
    }
    s << "\n";
  }
}

}  // namespace musclesim::plot_text
