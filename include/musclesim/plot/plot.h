// Figures drawn by gnuplot (Debian's gnuplot-nox): musclesim builds a gnuplot script with
// the data inline, in memory, and gives it to gnuplot on its standard input. The script
// builders are pure functions, so what a figure contains can be checked as text; Render runs
// gnuplot.
//
// Titles, labels, column names and file names come from the user and from CSV files, and a
// gnuplot script is a program: every such string enters the script only through
// GnuplotString, every number only as a finite number, and text is drawn literally
// (enhanced-text markup such as ^{} and @ is switched off).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/io/readers/csv_table.h"
#include "musclesim/model/tension.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {

struct PlotOptions {
  std::string output;  // file path, .png or .svg: the format follows the extension
  int width = 1000;    // figure width [pixels], 100..10000
  int height = 750;    // figure height [pixels], 100..10000
  std::string title;   // text; empty: a title made from the input
};

// `text` as a gnuplot string expression: pieces in single quotes, inside which gnuplot
// interprets nothing (no backslash escapes, no `command` substitution, no @macros), each
// quote of the text joined in as sprintf("%c",39): "it's" is 'it'.sprintf("%c",39).'s'.
// Throws InputError naming `what` (the file or column the text came from) when the
// text holds a control character (a byte below 0x20, or 0x7f: a newline would end the
// command, and no quoting carries it) or is not valid UTF-8 (an SVG must be).
std::string GnuplotString(const std::string& text, const std::string& what);

// Throws ParameterError naming the option ("output", "size", "title") unless `output` ends
// in .png or .svg, the size is 100..10000 px and `output` and `title` pass GnuplotString's
// rules.
void Validate(const PlotOptions& options);

// A trajectory CSV of `musclesim run`: length, shortening velocity, activation (with the
// excitation dashed, when the CSV has that column) and the tensions (with the load) against
// time in stacked panels sharing the time axis, with the concentric, eccentric and isometric
// intervals shaded; the title defaults to the file's name. Throws InputError naming missing
// columns, a table without rows, or the row and column of a cell that is not a finite number.
std::string TrajectoryPlotScript(const CsvTable& trajectory, const PlotOptions& options);

// A network's trajectory CSV of `musclesim run` (columns <node>.position, <element>.length,
// <element>.tension, <actuator>.activation): one panel per quantity kind (node positions,
// element lengths, tensions, activations when there are actuators, with any
// <actuator>.excitation dashed beside them), one line per node or element, sharing the time
// axis; with controllers (<controller>.reference, .measured, .error), a panel per controller
// of its measured value with its reference dashed, and a panel of every controller's error.
// Throws InputError as TrajectoryPlotScript does.
std::string NetworkPlotScript(const CsvTable& trajectory, const PlotOptions& options);

// Whether `table` is a network's trajectory (it has a <node>.position column).
bool IsNetworkTrajectory(const CsvTable& table);

// Whether `table` is the run of a network in the plane or in space: it has a NODE.x column
// with NODE.y beside it (and in space NODE.z for every such node).
bool IsSpatialTrajectory(const CsvTable& table);

// A spatial network's run (columns NODE.x, NODE.y [, NODE.z], ELEMENT.length, .tension,
// .activation, ...): on the left every node's path in the x-y plane (x across, y up, equal
// scales; a 3-D run's x-y projection), a line per node keyed by its name (no key beyond 20
// nodes); on the right, sharing the time axis, the panels of NetworkPlotScript but the
// positions: lengths, tensions and activations (with excitations dashed). Throws InputError
// as NetworkPlotScript does.
std::string SpatialPathPlotScript(const CsvTable& trajectory, const PlotOptions& options);

// The most frames SpatialFramesPlotScript draws.
inline constexpr int kMaxFrames = 36;

// `count` times (1..kMaxFrames) evenly spaced from the first row's time to the last's (the
// first alone for 1). Throws ParameterError("frame-count") for another count, InputError
// for a table without rows or a time that is not a finite number.
std::vector<double> EvenlySpacedFrameTimes(const CsvTable& trajectory, int count);

// A spatial network's shape at each of `times` (1..kMaxFrames, each within the run's first
// and last row's times): a panel per time, side by side in rows of up to 4, all on the same
// x-y axes with equal scales, each titled with the time of the row drawn, the row nearest
// the time asked for (the earlier of two as near; no interpolation). The nodes are points;
// with `scenario` (the one the run ran; may be null) each element is a polyline from its
// `from` node over its via points (fixed ones at their coordinates, nodes where the row has
// them) to its `to` node. A 3-D run is drawn in its x-y projection. Throws
// ParameterError("frames") for a time outside the run or too many times, InputError when the
// scenario's dimensions or nodes differ from the CSV's (naming both files and the node) and
// as NetworkPlotScript does.
std::string SpatialFramesPlotScript(const CsvTable& trajectory, const std::vector<double>& times,
                                    const Scenario* scenario, const PlotOptions& options);

// The residual CSV of `musclesim identify --residuals` (columns series, output, t, measured,
// model, residual, standardised): a panel per measured series and output, the measured
// values as points and the model as a line, over a last panel of the standardised residuals
// against time. Throws InputError as TrajectoryPlotScript does.
std::string ResidualPlotScript(const CsvTable& residuals, const PlotOptions& options);

// Whether `table` is such a residual CSV (it has the columns measured, model, standardised).
bool IsResidualTable(const CsvTable& table);

// The figure of a run's table, chosen by its form as `musclesim plot RUN.csv` chooses it: a
// residual table's, a network's on a line, a network's in the plane or in space (its
// nodes' paths), else a single actuator's trajectory. Throws InputError as each does.
std::string RunPlotScript(const CsvTable& table, const PlotOptions& options);

// The frames of a run in the plane or in space (SpatialFramesPlotScript) at `times`, or at
// `count` evenly spaced ones when `times` is empty. Throws InputError naming `flag` (the
// caller's word: "--frames") when the table is no such run, and as the two functions do.
std::string FramesPlotScript(const CsvTable& table, const std::vector<double>& times, int count,
                             const Scenario* scenario, const std::string& flag,
                             const PlotOptions& options);

// The model's curves (the paper's Figures 1, 3 and 5): passive, active (u = 1, v = 0) and
// total tension against length with L_opt shaded and each Gaussian component drawn thin,
// and g(v) against shortening velocity.
std::string CurvesPlotScript(const TensionModel& model, const PlotOptions& options);

// A sweep summary (columns index, the swept paths, status, the metrics, steps, rhs_evals,
// wall_seconds, message): `y` (a metric; default the first) against the swept path `x`, a
// line per value of the swept path `color`; without `color`, a heat map over `x` and the
// other swept path when there are exactly two. Failed rows and empty metrics are left out.
// Throws InputError for another layout (naming the missing columns), an unknown path or
// metric, a plotted cell that is not a finite number, or no row left to plot.
std::string SweepPlotScript(const CsvTable& summary, const std::string& x,
                            const std::optional<std::string>& y,
                            const std::optional<std::string>& color, const PlotOptions& options);

// Runs gnuplot on `script`, whose output goes to a temporary file beside options.output,
// renamed over it only when gnuplot succeeds: a failure leaves an earlier figure as it was
// and no temporary file behind. Throws InputError as Validate does, std::runtime_error
// naming the Debian package when gnuplot is missing, and gnuplot's own message when it
// fails.
void Render(const std::string& script, const PlotOptions& options);

}  // namespace musclesim
