// What every figure's script builder shares: how numbers and user text enter a gnuplot
// script, and the frame every figure starts from (private to the studies layer).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "musclesim/io/readers/csv_table.h"
#include "musclesim/plot/plot.h"

namespace musclesim::plot_text {

bool EndsWith(const std::string& text, const std::string& end);
// A control byte: below 0x20, or 0x7f.
bool IsControl(unsigned char byte);
// Offset of the first byte that does not start well-formed UTF-8, or npos.
std::size_t FirstInvalidUtf8(const std::string& text);
std::string Hex(unsigned char byte);  // "0x1b"
// Text echoed in a message: control bytes as \xNN, cut after 80 bytes.
std::string Printable(const std::string& text);
// A plotted number in the shortest exact form.
std::string Number(double value);
// Cell (row, column) as a finite number; InputError naming file, line, column and cell.
double FiniteValue(const CsvTable& table, std::size_t row, int column);
// The start of every script: UTF-8, no enhanced-text markup, a light grid.
extern const char* const kFrame;
// Whether positive values spanning two decades or more read better on a log scale.
bool WantsLogScale(const std::vector<double>& values);
// GnuplotString of the text given as option `option` (PlotOptions' or SweepPlotScript's
// name: "title", "x"), refused with ParameterError(option, quoted text, rule).
std::string OptionString(const std::string& text, const std::string& option);
// The title as a gnuplot string: the user's, or `fallback` (named `fallback_source`).
std::string TitleOf(const PlotOptions& options, const std::string& fallback,
                    const std::string& fallback_source);

}  // namespace musclesim::plot_text
