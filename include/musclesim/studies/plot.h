// Figures drawn by gnuplot (Debian's gnuplot-nox): musclesim writes a gnuplot script with
// the data inline and runs gnuplot on it. The script builders are pure functions, so what
// a figure contains can be checked as text; Render runs gnuplot.
#pragma once

#include <optional>
#include <string>

#include "musclesim/io/csv_table.h"
#include "musclesim/model/tension.h"

namespace musclesim {

struct PlotOptions {
  std::string output;   // file path, .png or .svg: the format follows the extension
  int width = 1000;     // figure width [pixels], 100..10000
  int height = 750;     // figure height [pixels], 100..10000
  std::string title;    // text; empty: a title made from the input
};

// Throws InputError unless `output` ends in .png or .svg and the size is 100..10000 px.
void Validate(const PlotOptions& options);

// A trajectory CSV of `musclesim run`: length, shortening velocity, activation and the
// tensions (with the load) against time in stacked panels sharing the time axis, with the
// concentric, eccentric and isometric intervals shaded. Throws InputError naming missing
// columns.
std::string TrajectoryPlotScript(const CsvTable& trajectory, const PlotOptions& options);

// The model's curves (the paper's Figures 1, 3 and 5): passive, active (u = 1, v = 0) and
// total tension against length with L_opt shaded and each Gaussian component drawn thin,
// and g(v) against shortening velocity.
std::string CurvesPlotScript(const TensionModel& model, const PlotOptions& options);

// A sweep summary: `y` (a metric; default the first) against the swept path `x`, a line per
// value of the swept path `color`; without `color`, a heat map over `x` and the other swept
// path when there are exactly two. Failed rows are left out.
std::string SweepPlotScript(const CsvTable& summary, const std::string& x,
                            const std::optional<std::string>& y,
                            const std::optional<std::string>& color, const PlotOptions& options);

// Runs gnuplot on `script`, whose output goes to a temporary file renamed to
// options.output when gnuplot succeeds. Throws std::runtime_error naming the Debian
// package when gnuplot is missing, and gnuplot's own message when it fails.
void Render(const std::string& script, const PlotOptions& options);

}  // namespace musclesim
