#include "musclesim/plot/plot.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>

#include "musclesim/core/errors.h"
#include "plot/gnuplot_process.h"
#include "plot/plot_text.h"

namespace musclesim {

using namespace plot_text;  // the script pieces every figure shares

namespace {

// Why `text` cannot be a gnuplot string ("" when it can): a control character (a newline
// would end the command, and no quoting carries it) or a byte that is not UTF-8.
std::string TextProblem(const std::string& text) {
  const auto control = std::find_if(
      text.begin(), text.end(), [](char c) { return IsControl(static_cast<unsigned char>(c)); });
  if (control != text.end()) {
    return "must not contain control characters (bytes below 0x20, and 0x7f); byte " +
           Hex(static_cast<unsigned char>(*control)) + " at offset " +
           std::to_string(control - text.begin());
  }
  if (const std::size_t bad = FirstInvalidUtf8(text); bad != std::string::npos) {
    return "must be valid UTF-8; byte " + Hex(static_cast<unsigned char>(text[bad])) +
           " at offset " + std::to_string(bad) + " starts no UTF-8 character";
  }
  return "";
}

std::string Quoted(const std::string& text) {
  // gnuplot 5.4's own '' escape fails at the start of a string and for two quotes in a row
  // (its scanner ends the string there), so each quote is sprintf's %c of 39 between quoted
  // pieces; a quote inside double quotes would mislead its macro expander about where the
  // single-quoted text is, so the pieces only ever sit between single quotes
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'.sprintf(\"%c\",39).'") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string GnuplotString(const std::string& text, const std::string& what) {
  if (const std::string problem = TextProblem(text); !problem.empty()) {
    throw InputError(what + " '" + Printable(text) + "': " + problem);
  }
  return Quoted(text);
}

std::string plot_text::OptionString(const std::string& text, const std::string& option) {
  if (const std::string problem = TextProblem(text); !problem.empty()) {
    throw ParameterError(option, "'" + Printable(text) + "'", problem);
  }
  return Quoted(text);
}

void Validate(const PlotOptions& options) {
  OptionString(options.output, "output");
  if (!options.title.empty()) OptionString(options.title, "title");
  if (!EndsWith(options.output, ".png") && !EndsWith(options.output, ".svg")) {
    throw ParameterError("output", options.output, "the figure's file must end in .png or .svg");
  }
  if (options.width < 100 || options.width > 10000 || options.height < 100 ||
      options.height > 10000) {
    throw ParameterError("size",
                         std::to_string(options.width) + "x" + std::to_string(options.height),
                         "width and height must be 100 to 10000 px");
  }
}

std::string TrajectoryPlotScript(const CsvTable& table, const PlotOptions& options) {
  const std::vector<std::string> needed = {"t",
                                           "length",
                                           "shortening_velocity",
                                           "activation",
                                           "tension_passive",
                                           "tension_active",
                                           "tension_total",
                                           "load",
                                           "phase"};
  table.Require(needed, "a trajectory CSV of musclesim run");
  if (table.rows.empty()) throw InputError(table.source + ": no rows to plot");
  std::vector<int> columns;
  for (std::size_t i = 0; i + 1 < needed.size(); ++i) columns.push_back(table.Find(needed[i]));
  const int phase = table.Find("phase");
  // a scenario with activation dynamics has its excitation too: the inline data's column 9
  const bool excitation = table.Find("excitation") >= 0;
  if (excitation) columns.push_back(table.Find("excitation"));

  std::ostringstream s;
  s << kFrame;
  s << "$trajectory << EOD\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      s << (c ? " " : "") << Number(FiniteValue(table, r, columns[c]));
    }
    s << "\n";
  }
  s << "EOD\n";

  // one shaded rectangle per run of equal phase, from its first record to the next run's
  const std::map<std::string, std::string> shade = {
      {"concentric", "#9ecae1"}, {"eccentric", "#fcae91"}, {"isometric", "#e5e5e5"}};
  int object = 1;
  for (std::size_t r = 0; r < table.rows.size();) {
    const std::string& label = table.rows[r][static_cast<std::size_t>(phase)];
    std::size_t end = r + 1;
    while (end < table.rows.size() && table.rows[end][static_cast<std::size_t>(phase)] == label)
      ++end;
    const double t0 = FiniteValue(table, r, columns[0]);
    const double t1 = FiniteValue(table, end < table.rows.size() ? end : end - 1, columns[0]);
    const auto color = shade.find(label);
    if (color == shade.end()) {
      throw InputError(table.source + ":" + std::to_string(table.lines[r]) + ": column phase = '" +
                       Printable(label) + "': must be concentric, eccentric or isometric");
    }
    if (t1 > t0) {
      s << "set object " << object++ << " rect from first " << Number(t0) << ", graph 0 to first "
        << Number(t1) << ", graph 1 fc rgb '" << color->second
        << "' fs solid 0.45 noborder behind\n";
    }
    r = end;
  }

  s << "set multiplot layout 4,1 title "
    << TitleOf(options, table.source, "the CSV file's name (the default title)") << "\n"
    << "set lmargin 12\nset rmargin 22\nset key outside right top\nset format x ''\n"
    << "set ylabel 'length [m]'\n"
    << "plot $trajectory using 1:2 with lines lw 2 lc rgb '#000000' title 'length', \\\n"
    << "  keyentry with boxes fs solid 0.45 fc rgb '#9ecae1' title 'concentric', \\\n"
    << "  keyentry with boxes fs solid 0.45 fc rgb '#fcae91' title 'eccentric', \\\n"
    << "  keyentry with boxes fs solid 0.45 fc rgb '#e5e5e5' title 'isometric'\n"
    << "set ylabel 'shortening velocity [m/s]'\n"
    << "plot $trajectory using 1:3 with lines lw 2 lc rgb '#08519c' title 'shortening velocity'\n"
    << "set ylabel 'activation [-]'\nset yrange [-0.05:1.05]\n"
    << "plot $trajectory using 1:4 with lines lw 2 lc rgb '#54278f' title 'activation'"
    << (excitation ? ", \\\n  $trajectory using 1:9 with lines lw 1 dt 2 lc rgb '#9e9ac8' "
                     "title 'excitation'\n"
                   : "\n")
    << "set autoscale y\nset format x '%g'\nset xlabel 'time [s]'\nset ylabel 'tension [N]'\n"
    << "plot $trajectory using 1:5 with lines lw 2 lc rgb '#31a354' title 'passive', \\\n"
    << "  $trajectory using 1:6 with lines lw 2 lc rgb '#de2d26' title 'active', \\\n"
    << "  $trajectory using 1:7 with lines lw 2 lc rgb '#000000' title 'total', \\\n"
    << "  $trajectory using 1:8 with lines lw 1 dt 2 lc rgb '#636363' title 'load'\n"
    << "unset multiplot\n";
  return s.str();
}

std::string CurvesPlotScript(const TensionModel& model, const PlotOptions& options) {
  const ModelParams& p = model.params();
  const ActiveLengthParams& a = p.active_length;
  // lengths where the components live, L_opt and the start of the passive rise
  double lo = a.optimal_min, hi = std::max(a.optimal_max, p.passive.slack_length);
  for (const Gaussian& g : a.gaussians) {
    const double spread = std::sqrt(a.sigma / g.precision);
    lo = std::min(lo, g.center - 3.0 * spread);
    hi = std::max(hi, g.center + 3.0 * spread);
  }
  // psi_k scaled as f_iso f_L is: f_iso psi_k / max f
  const double component_scale = p.f_iso / model.active_length().peak_value();

  std::ostringstream s;
  s << kFrame;
  s << "$length << EOD\n";
  double lowest = 0.0;
  const int samples = 400;
  for (int i = 0; i <= samples; ++i) {
    const double x = lo + (hi - lo) * i / samples;
    const TensionSample t = model.Evaluate(x, 0.0, 1.0);
    s << Number(x) << " " << Number(t.passive) << " " << Number(t.active) << " " << Number(t.total);
    for (const GaussianTerm& psi : model.active_length().sum().terms()) {
      const double component = component_scale * psi(x);
      lowest = std::min(lowest, component);
      s << " " << Number(component);
    }
    s << "\n";
  }
  s << "EOD\n$velocity << EOD\n";
  const double v_max = p.velocity.v_max;
  for (int i = 0; i <= samples; ++i) {
    const double v = -v_max + 2.2 * v_max * i / samples;
    s << Number(v) << " " << Number(model.velocity().Evaluate(v).value) << "\n";
  }
  s << "EOD\n";

  s << "set multiplot layout 1,2 title " << TitleOf(options, "model curves", "the default title")
    << "\n"
    << "set key top left\nset autoscale xfix\nset xlabel 'length [m]'\nset ylabel 'tension [N]'\n"
    << "set yrange [" << Number(1.1 * lowest) << ":" << Number(1.6 * p.f_iso) << "]\n"
    << "set object 1 rect from first " << Number(a.optimal_min) << ", graph 0 to first "
    << Number(a.optimal_max) << ", graph 1 fc rgb '#e5e5e5' fs solid 1.0 noborder behind\n"
    << "set label 1 'L_opt' at first " << Number(0.5 * (a.optimal_min + a.optimal_max))
    << ", graph 0.03 center\n"
    << "plot $length using 1:2 with lines lw 2 lc rgb '#31a354' title 'passive T_p', \\\n"
    << "  $length using 1:3 with lines lw 2 lc rgb '#de2d26' title 'active f_iso f_L (u = 1, v = "
       "0)', \\\n"
    << "  $length using 1:4 with lines lw 2 lc rgb '#000000' title 'total'";
  for (std::size_t k = 0; k < a.gaussians.size(); ++k) {
    s << ", \\\n  $length using 1:" << 5 + k << " with lines lw 1 dt 2 lc rgb '#fb6a4a' title '"
      << (k == 0 ? "Gaussian components" : "") << "'";
  }
  s << "\nunset object 1\nunset label 1\nset autoscale y\n"
    << "set xlabel 'shortening velocity v [m/s]'\nset ylabel 'g(v) [-]'\nset xzeroaxis\n"
    << "set key bottom left\n"
    << "set arrow 1 from " << Number(v_max) << ", graph 0 to " << Number(v_max)
    << ", graph 1 nohead dt 3\nset label 2 'v_max' at " << Number(v_max)
    << ", graph 0.95 right offset -0.5,0\n"
    << "plot $velocity using 1:2 with lines lw 2 lc rgb '#08519c' title 'g(v), n = " << p.velocity.n
    << ", eps = " << Number(p.velocity.epsilon) << " m/s'\n"
    << "unset multiplot\n";
  return s.str();
}

namespace {

constexpr const char* kSummaryLayout =
    "a summary CSV of musclesim sweep has the columns index, the swept paths, status, the "
    "metrics, steps, rhs_evals, wall_seconds, message";

// Where the parts of a sweep summary are; throws InputError naming what is missing or out of
// place when the header is not a summary's.
struct SummaryColumns {
  int status = -1;                   // index of the status column [-]
  int message = -1;                  // index of the message column, the last [-]
  std::vector<std::string> swept;    // the swept paths, in column order [-]
  std::vector<std::string> metrics;  // the metrics, in column order [-]
};

SummaryColumns FindSummaryColumns(const CsvTable& table) {
  table.Require({"index", "status", "steps", "rhs_evals", "wall_seconds", "message"},
                kSummaryLayout);
  const std::vector<std::string>& h = table.header;
  const std::size_t n = h.size();
  SummaryColumns c;
  c.status = table.Find("status");
  c.message = static_cast<int>(n) - 1;
  std::string problem;
  if (h[0] != "index") {
    problem = "index is not the first column";
  } else if (c.status < 2) {
    problem = "no swept path between index and status";
  } else if (h[n - 4] != "steps" || h[n - 3] != "rhs_evals" || h[n - 2] != "wall_seconds" ||
             h[n - 1] != "message" || c.status > static_cast<int>(n) - 5) {
    problem = "steps, rhs_evals, wall_seconds, message are not the last columns, after status";
  }
  if (!problem.empty()) {
    throw InputError(table.source + ": " + problem + " (" + kSummaryLayout + ")");
  }
  c.swept.assign(h.begin() + 1, h.begin() + c.status);
  c.metrics.assign(h.begin() + c.status + 1, h.end() - 4);
  return c;
}

std::string List(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + Printable(name);
  return out.empty() ? "none" : out;
}

}  // namespace

namespace {

// What a sweep figure plots, its columns resolved and its texts checked before any row.
struct SweepFigure {
  int status = -1, x_column = -1, y_column = -1, other_column = -1;  // -1: no other [-]
  std::string y_name;                                                // the metric plotted [-]
  std::optional<std::string> other;        // the colour's swept path, or the heat map's y [-]
  bool heat_map = false;                   // two swept paths and no colour: a heat map [-]
  std::string x_text, y_text, other_text;  // gnuplot strings of the column names [-]
};

SweepFigure ResolveSweepFigure(const CsvTable& table, const std::string& x,
                               const std::optional<std::string>& y,
                               const std::optional<std::string>& color) {
  const SummaryColumns summary = FindSummaryColumns(table);
  const std::vector<std::string>& swept = summary.swept;
  const auto is_swept = [&](const std::string& path) {
    return std::find(swept.begin(), swept.end(), path) != swept.end();
  };
  if (!is_swept(x)) {
    throw ParameterError(
        "x", Printable(x),
        "not a swept path of " + table.source + " (it sweeps " + List(swept) + ")");
  }
  if (color && (!is_swept(*color) || *color == x)) {
    throw ParameterError("color", Printable(*color),
                         "must be a swept path other than the x axis's (" + table.source +
                             " sweeps " + List(swept) + ")");
  }
  SweepFigure f;
  f.status = summary.status;
  f.y_name = y ? *y : (summary.metrics.empty() ? "steps" : summary.metrics.front());
  f.y_column = table.Find(f.y_name);
  // a metric, or one of the run's counts (steps, rhs_evals, wall_seconds)
  if (f.y_column <= f.status || f.y_column >= summary.message) {
    throw ParameterError("y", Printable(f.y_name),
                         "not a metric of " + table.source + " (its metrics: " +
                             List(summary.metrics) + "; also steps, rhs_evals, wall_seconds)");
  }
  f.x_column = table.Find(x);
  f.other = color;
  f.heat_map = !color && swept.size() == 2;
  if (f.heat_map) f.other = swept[0] == x ? swept[1] : swept[0];
  f.other_column = f.other ? table.Find(*f.other) : -1;
  // every column name that reaches the script, checked before any row
  f.x_text = OptionString(x, "x");
  f.y_text = y ? OptionString(f.y_name, "y")
               : GnuplotString(f.y_name, table.source + ": the first metric's name");
  f.other_text = !f.other ? ""
                 : color  ? OptionString(*f.other, "color")
                          : GnuplotString(*f.other, table.source + ": the other swept path");
  return f;
}

// A line of the figure: one value of the colour's path.
struct Group {
  std::string title;                              // gnuplot string of the legend entry [-]
  std::vector<std::pair<double, double>> points;  // (x, y) in the CSV's units
};

// The usable rows (status ok and a value for y): the lines by the colour's value as written
// in the CSV, or the heat map's cells; every x either way.
struct SweepPoints {
  std::map<std::string, Group> groups;
  std::vector<double> xs, others;
  std::vector<std::tuple<double, double, double>> cells;  // (x, other, y)
};

SweepPoints CollectSweepPoints(const CsvTable& table, const SweepFigure& f) {
  SweepPoints p;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    if (table.rows[r][static_cast<std::size_t>(f.status)] != "ok") continue;
    if (table.rows[r][static_cast<std::size_t>(f.y_column)].empty()) continue;
    const double xv = FiniteValue(table, r, f.x_column), yv = FiniteValue(table, r, f.y_column);
    p.xs.push_back(xv);
    if (f.heat_map) {
      const double ov = FiniteValue(table, r, f.other_column);
      p.others.push_back(ov);
      p.cells.emplace_back(xv, ov, yv);
      continue;
    }
    const std::string label =
        f.other ? table.rows[r][static_cast<std::size_t>(f.other_column)] : "";
    Group& group = p.groups[label];
    if (group.title.empty()) {
      group.title = f.other ? GnuplotString(*f.other + " = " + label,
                                            table.source + ":" + std::to_string(table.lines[r]) +
                                                ": the legend entry")
                            : f.y_text;
    }
    group.points.emplace_back(xv, yv);
  }
  if (p.xs.empty()) {
    throw InputError(table.source + ": no successful row with a value of " + Printable(f.y_name));
  }
  return p;
}

// Each heat-map cell's extent: halfway to its neighbours (geometrically on a log axis).
std::map<double, std::pair<double, double>> CellBounds(std::vector<double> values, bool log) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::map<double, std::pair<double, double>> out;
  const auto mid = [log](double a, double b) { return log ? std::sqrt(a * b) : 0.5 * (a + b); };
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double left = i > 0 ? mid(values[i - 1], values[i]) : values[i];
    const double right = i + 1 < values.size() ? mid(values[i], values[i + 1]) : values[i];
    const double half_left = i > 0 ? left : values[i] - (right - values[i]);
    const double half_right = i + 1 < values.size() ? right : values[i] + (values[i] - left);
    double lo = values.size() == 1 ? values[i] * 0.9 : half_left;
    double hi = values.size() == 1 ? values[i] * 1.1 : half_right;
    if (log && values.size() > 1) {
      if (i == 0) lo = values[i] * values[i] / right;
      if (i + 1 == values.size()) hi = values[i] * values[i] / left;
    }
    out[values[i]] = {lo, hi};
  }
  return out;
}

void WriteHeatMap(const SweepFigure& f, const SweepPoints& p, std::ostringstream& s) {
  const bool log_y = WantsLogScale(p.others);
  const auto x_cells = CellBounds(p.xs, WantsLogScale(p.xs)), y_cells = CellBounds(p.others, log_y);
  if (log_y) s << "set logscale y\nset format y '%g'\n";
  s << "set autoscale xfix\nset autoscale yfix\n";
  s << "set ylabel " << f.other_text << "\nset cblabel " << f.y_text << "\n"
    << "set palette rgb 33,13,10\nset key off\n$cells << EOD\n";
  for (const auto& [xv, ov, yv] : p.cells) {
    const auto [x0, x1] = x_cells.at(xv);
    const auto [y0, y1] = y_cells.at(ov);
    s << Number(xv) << " " << Number(ov) << " " << Number(x0) << " " << Number(x1) << " "
      << Number(y0) << " " << Number(y1) << " " << Number(yv) << "\n";
  }
  s << "EOD\n"
    << "plot $cells using 1:2:3:4:5:6:7 with boxxyerror fs solid 1.0 noborder lc palette title "
    << f.y_text << "\n";
}

void WriteLines(const SweepFigure& f, SweepPoints& p, std::ostringstream& s) {
  s << "set ylabel " << f.y_text << "\nset key outside right top\nset autoscale xfix\n";
  std::ostringstream plots;
  int block = 0;
  for (auto& entry : p.groups) {
    Group& group = entry.second;
    std::vector<std::pair<double, double>>& points = group.points;
    std::sort(points.begin(), points.end());
    s << "$group" << block << " << EOD\n";
    for (const auto& [xv, yv] : points) s << Number(xv) << " " << Number(yv) << "\n";
    s << "EOD\n";
    plots << (block ? ", \\\n  " : "plot ") << "$group" << block
          << " using 1:2 with linespoints lw 2 pt 7 title " << group.title;
    ++block;
  }
  s << plots.str() << "\n";
}

}  // namespace

std::string SweepPlotScript(const CsvTable& table, const std::string& x,
                            const std::optional<std::string>& y,
                            const std::optional<std::string>& color, const PlotOptions& options) {
  const SweepFigure figure = ResolveSweepFigure(table, x, y, color);
  SweepPoints points = CollectSweepPoints(table, figure);
  std::ostringstream s;
  s << kFrame;
  s << "set title " << TitleOf(options, figure.y_name + " against " + x, "the default title")
    << "\n"
    << "set xlabel " << figure.x_text << "\n";
  if (WantsLogScale(points.xs)) s << "set logscale x\nset format x '%g'\n";
  if (figure.heat_map) {
    WriteHeatMap(figure, points, s);
  } else {
    WriteLines(figure, points, s);
  }
  return s.str();
}

namespace {

// A file removed when this goes out of scope unless kept, so that no temporary file
// outlives a failure, whichever way the failure leaves.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::string path) : path_(std::move(path)) {}
  ~TemporaryFile() {
    if (kept_) return;
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return path_; }
  void Keep() { kept_ = true; }

 private:
  std::string path_;
  bool kept_ = false;
};

}  // namespace

void Render(const std::string& script, const PlotOptions& options) {
  Validate(options);
  const bool svg = EndsWith(options.output, ".svg");
  const std::filesystem::path folder = std::filesystem::path(options.output).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder)) {
    throw std::runtime_error(options.output + ": cannot write the figure (no folder " +
                             folder.string() + ")");
  }
  // the figure goes beside its target, so that the rename is atomic; a relative name starts
  // with ./ because gnuplot's `set output` reads '|command' as a pipe and '~' as $HOME
  std::string figure_path =
      options.output + ".tmp." + std::to_string(::getpid()) + (svg ? ".svg" : ".png");
  if (std::filesystem::path(options.output).is_relative()) figure_path = "./" + figure_path;
  TemporaryFile figure(figure_path);
  const std::string terminal =
      svg ? "set terminal svg size " + std::to_string(options.width) + "," +
                std::to_string(options.height) + " noenhanced font 'sans,12' background '#ffffff'\n"
          : "set terminal pngcairo size " + std::to_string(options.width) + "," +
                std::to_string(options.height) + " noenhanced font 'sans,10'\n";
  std::string messages;
  const bool ran = RunGnuplot(terminal + "set output " + OptionString(figure.path(), "output") +
                                  "\n" + script + "unset output\n",
                              messages);
  std::error_code error;
  if (!ran || std::filesystem::file_size(figure.path(), error) == 0 || error) {
    throw std::runtime_error("gnuplot failed: " + messages);
  }
  std::filesystem::rename(figure.path(), options.output, error);
  if (error) {
    throw std::runtime_error(options.output + ": cannot replace the file (" + error.message() +
                             ")");
  }
  figure.Keep();
}

std::string RunPlotScript(const CsvTable& table, const PlotOptions& options) {
  return IsResidualTable(table)       ? ResidualPlotScript(table, options)
         : IsNetworkTrajectory(table) ? NetworkPlotScript(table, options)
         : IsSpatialTrajectory(table) ? SpatialPathPlotScript(table, options)
                                      : TrajectoryPlotScript(table, options);
}

}  // namespace musclesim
