// The residual figure of a time-series identification: each measured series beside the
// model's run, and the standardised residuals.
#include <algorithm>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/plot/plot.h"
#include "plot/plot_text.h"

namespace musclesim {

using namespace plot_text;  // the script pieces every figure shares

namespace {

constexpr const char* kResidualLayout =
    "a residual CSV of a time-series identification: series, output, t, measured, model, "
    "residual, standardised";

}  // namespace

bool IsResidualTable(const CsvTable& table) {
  return table.Find("measured") >= 0 && table.Find("model") >= 0 && table.Find("standardised") >= 0;
}

std::string ResidualPlotScript(const CsvTable& table, const PlotOptions& options) {
  table.Require({"series", "output", "t", "measured", "model", "standardised"}, kResidualLayout);
  if (table.rows.empty()) throw InputError(table.source + ": no rows to plot");
  const int series = table.Find("series"), output = table.Find("output"), t = table.Find("t");
  const int measured = table.Find("measured"), model = table.Find("model");
  const int standardised = table.Find("standardised");

  // one panel per (series, output), in the order they first appear
  std::vector<std::pair<std::string, std::string>> panels;
  std::vector<std::vector<std::size_t>> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::pair<std::string, std::string> key = {
        table.rows[r][static_cast<std::size_t>(series)],
        table.rows[r][static_cast<std::size_t>(output)]};
    std::size_t k = 0;
    while (k < panels.size() && panels[k] != key) ++k;
    if (k == panels.size()) {
      panels.push_back(key);
      rows.emplace_back();
    }
    rows[k].push_back(r);
  }

  // every panel on the same time axis
  double t_min = FiniteValue(table, 0, t), t_max = t_min;
  for (std::size_t r = 1; r < table.rows.size(); ++r) {
    t_min = std::min(t_min, FiniteValue(table, r, t));
    t_max = std::max(t_max, FiniteValue(table, r, t));
  }

  std::ostringstream s;
  s << kFrame;
  if (t_max > t_min) s << "set xrange [" << Number(t_min) << ":" << Number(t_max) << "]\n";
  for (std::size_t k = 0; k < panels.size(); ++k) {
    s << "$d" << k << " << EOD\n";
    for (std::size_t r : rows[k]) {
      s << Number(FiniteValue(table, r, t)) << " " << Number(FiniteValue(table, r, measured)) << " "
        << Number(FiniteValue(table, r, model)) << " "
        << Number(FiniteValue(table, r, standardised)) << "\n";
    }
    s << "EOD\n";
  }
  s << "set multiplot layout " << panels.size() + 1 << ",1 title "
    << TitleOf(options, table.source, "the CSV file's name (the default title)") << "\n"
    << "set lmargin 14\nset rmargin 22\nset key outside right top\nset format x ''\n";
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const std::string label = "series " + panels[k].first + ": " + panels[k].second;
    s << "set ylabel " << GnuplotString(label, "a series or output name of " + table.source)
      << "\nplot $d" << k
      << " using 1:2 with points pt 7 ps 0.5 lc rgb '#636363' title 'measured', "
      << "\\\n  $d" << k << " using 1:3 with lines lw 2 lc rgb '#de2d26' title 'model'\n";
  }
  s << "set format x '%g'\nset xlabel 'time [s]'\nset ylabel 'standardised residual [-]'\n"
    << "set xzeroaxis lt -1\nplot ";
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const std::string label = panels[k].first + ": " + panels[k].second;
    s << (k ? ", \\\n  " : "") << "$d" << k << " using 1:4 with points pt 7 ps 0.5 title "
      << GnuplotString(label, "a series or output name of " + table.source);
  }
  s << "\nunset multiplot\n";
  return s.str();
}

}  // namespace musclesim
