#include "musclesim/studies/plot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "musclesim/errors.h"
#include "musclesim/io/output_file.h"

namespace musclesim {

namespace {

bool EndsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// A gnuplot string literal: single quotes, with '' for a quote inside.
std::string Quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// Plot data in the shortest exact form, as messages print numbers.
std::string Number(double value) { return FormatNumber(value); }

// What every figure shares.
constexpr const char* kFrame = "set encoding utf8\nset grid lc rgb '#dddddd'\n";

// A wide axis of positive values reads better on a log scale.
bool WantsLogScale(const std::vector<double>& values) {
  if (values.empty()) return false;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  return *lo > 0.0 && *hi / *lo >= 100.0;
}

std::string TitleOf(const PlotOptions& options, const std::string& fallback) {
  return Quoted(options.title.empty() ? fallback : options.title);
}

}  // namespace

void Validate(const PlotOptions& options) {
  if (!EndsWith(options.output, ".png") && !EndsWith(options.output, ".svg")) {
    throw InputError("-o " + options.output + ": the figure's file must end in .png or .svg");
  }
  if (options.width < 100 || options.width > 10000 || options.height < 100 ||
      options.height > 10000) {
    throw InputError("--size " + std::to_string(options.width) + "x" +
                     std::to_string(options.height) + ": width and height must be 100 to 10000 px");
  }
}

std::string TrajectoryPlotScript(const CsvTable& table, const PlotOptions& options) {
  const std::vector<std::string> needed = {"t", "length", "shortening_velocity", "activation",
                                           "tension_passive", "tension_active", "tension_total",
                                           "load", "phase"};
  table.Require(needed, "a trajectory CSV of musclesim run");
  if (table.rows.empty()) throw InputError(table.source + ": no rows to plot");
  std::vector<int> columns;
  for (std::size_t i = 0; i + 1 < needed.size(); ++i) columns.push_back(table.Find(needed[i]));
  const int phase = table.Find("phase");

  std::ostringstream s;
  s << kFrame;
  s << "$trajectory << EOD\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      s << (c ? " " : "") << Number(table.Number(r, columns[c]));
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
    while (end < table.rows.size() && table.rows[end][static_cast<std::size_t>(phase)] == label) ++end;
    const double t0 = table.Number(r, columns[0]);
    const double t1 = table.Number(end < table.rows.size() ? end : end - 1, columns[0]);
    const auto color = shade.find(label);
    if (color != shade.end() && t1 > t0) {
      s << "set object " << object++ << " rect from first " << Number(t0) << ", graph 0 to first "
        << Number(t1) << ", graph 1 fc rgb '" << color->second << "' fs solid 0.45 noborder behind\n";
    }
    r = end;
  }

  s << "set multiplot layout 4,1 title " << TitleOf(options, table.source) << "\n"
    << "set lmargin 12\nset rmargin 22\nset key outside right top\nset format x ''\n"
    << "set ylabel 'length [m]'\n"
    << "plot $trajectory using 1:2 with lines lw 2 lc rgb '#000000' title 'length', \\\n"
    << "  keyentry with boxes fs solid 0.45 fc rgb '#9ecae1' title 'concentric', \\\n"
    << "  keyentry with boxes fs solid 0.45 fc rgb '#fcae91' title 'eccentric', \\\n"
    << "  keyentry with boxes fs solid 0.45 fc rgb '#e5e5e5' title 'isometric'\n"
    << "set ylabel 'shortening velocity [m/s]'\n"
    << "plot $trajectory using 1:3 with lines lw 2 lc rgb '#08519c' title 'shortening velocity'\n"
    << "set ylabel 'activation [-]'\nset yrange [-0.05:1.05]\n"
    << "plot $trajectory using 1:4 with lines lw 2 lc rgb '#54278f' title 'activation'\n"
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

  s << "set multiplot layout 1,2 title " << TitleOf(options, "model curves") << "\n"
    << "set key top left\nset autoscale xfix\nset xlabel 'length [m]'\nset ylabel 'tension [N]'\n"
    << "set yrange [" << Number(1.1 * lowest) << ":" << Number(1.6 * p.f_iso) << "]\n"
    << "set object 1 rect from first " << Number(a.optimal_min) << ", graph 0 to first "
    << Number(a.optimal_max) << ", graph 1 fc rgb '#e5e5e5' fs solid 1.0 noborder behind\n"
    << "set label 1 'L_opt' at first " << Number(0.5 * (a.optimal_min + a.optimal_max))
    << ", graph 0.03 center\n"
    << "plot $length using 1:2 with lines lw 2 lc rgb '#31a354' title 'passive T_p', \\\n"
    << "  $length using 1:3 with lines lw 2 lc rgb '#de2d26' title 'active f_iso f_L (u = 1, v = 0)', \\\n"
    << "  $length using 1:4 with lines lw 2 lc rgb '#000000' title 'total'";
  for (std::size_t k = 0; k < a.gaussians.size(); ++k) {
    s << ", \\\n  $length using 1:" << 5 + k << " with lines lw 1 dt 2 lc rgb '#fb6a4a' title '"
      << (k == 0 ? "Gaussian components" : "") << "'";
  }
  s << "\nunset object 1\nunset label 1\nset autoscale y\n"
    << "set xlabel 'shortening velocity v [m/s]'\nset ylabel 'g(v) [-]'\nset xzeroaxis\n"
    << "set key bottom left\n"
    << "set arrow 1 from " << Number(v_max) << ", graph 0 to " << Number(v_max)
    << ", graph 1 nohead dt 3\nset label 2 'v_max' at " << Number(v_max) << ", graph 0.95 right offset -0.5,0\n"
    << "plot $velocity using 1:2 with lines lw 2 lc rgb '#08519c' title 'g(v), n = "
    << p.velocity.n << ", eps = " << Number(p.velocity.epsilon) << " m/s'\n"
    << "unset multiplot\n";
  return s.str();
}

std::string SweepPlotScript(const CsvTable& table, const std::string& x,
                            const std::optional<std::string>& y,
                            const std::optional<std::string>& color, const PlotOptions& options) {
  table.Require({"index", "status", "steps"}, "a summary CSV of musclesim sweep");
  const int status = table.Find("status"), steps = table.Find("steps");
  std::vector<std::string> swept(table.header.begin() + 1, table.header.begin() + status);
  std::vector<std::string> metrics(table.header.begin() + status + 1, table.header.begin() + steps);
  std::string swept_list;
  for (const std::string& path : swept) swept_list += (swept_list.empty() ? "" : ", ") + path;
  const auto is_swept = [&](const std::string& path) {
    return std::find(swept.begin(), swept.end(), path) != swept.end();
  };
  if (!is_swept(x)) {
    throw InputError("--x " + x + ": not a swept path of " + table.source + " (it sweeps " +
                     swept_list + ")");
  }
  if (color && (!is_swept(*color) || *color == x)) {
    throw InputError("--color " + *color + ": must be a swept path other than --x (" +
                     table.source + " sweeps " + swept_list + ")");
  }
  const std::string y_name = y ? *y : (metrics.empty() ? "steps" : metrics.front());
  const int y_column = table.Find(y_name);
  if (y_column < 0 || y_column <= status) {
    throw InputError("--y " + y_name + ": not a metric of " + table.source);
  }
  const int x_column = table.Find(x);
  std::optional<std::string> other = color;
  const bool heat_map = !color && swept.size() == 2;
  if (heat_map) other = swept[0] == x ? swept[1] : swept[0];
  const int other_column = other ? table.Find(*other) : -1;

  // the usable rows: status ok and a value for y
  std::map<std::string, std::vector<std::pair<double, double>>> groups;  // other value -> points
  std::vector<double> xs, others;
  std::vector<std::tuple<double, double, double>> cells;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    if (table.rows[r][static_cast<std::size_t>(status)] != "ok") continue;
    if (table.rows[r][static_cast<std::size_t>(y_column)].empty()) continue;
    const double xv = table.Number(r, x_column), yv = table.Number(r, y_column);
    xs.push_back(xv);
    if (heat_map) {
      const double ov = table.Number(r, other_column);
      others.push_back(ov);
      cells.emplace_back(xv, ov, yv);
    } else {
      groups[other ? table.rows[r][static_cast<std::size_t>(other_column)] : ""].emplace_back(xv, yv);
    }
  }
  if (xs.empty()) throw InputError(table.source + ": no successful row with a value of " + y_name);

  std::ostringstream s;
  s << kFrame;
  s << "set title " << TitleOf(options, y_name + " against " + x) << "\n"
    << "set xlabel " << Quoted(x) << "\n";
  if (WantsLogScale(xs)) s << "set logscale x\nset format x '%g'\n";

  if (heat_map) {
    // each cell reaches halfway to its neighbours (geometrically on a log axis)
    const bool log_x = WantsLogScale(xs), log_y = WantsLogScale(others);
    const auto bounds = [](std::vector<double> values, bool log) {
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
    };
    const auto x_cells = bounds(xs, log_x), y_cells = bounds(others, log_y);
    if (log_y) s << "set logscale y\nset format y '%g'\n";
    s << "set autoscale xfix\nset autoscale yfix\n";
    s << "set ylabel " << Quoted(*other) << "\nset cblabel " << Quoted(y_name) << "\n"
      << "set palette rgb 33,13,10\nset key off\n$cells << EOD\n";
    for (const auto& [xv, ov, yv] : cells) {
      const auto [x0, x1] = x_cells.at(xv);
      const auto [y0, y1] = y_cells.at(ov);
      s << Number(xv) << " " << Number(ov) << " " << Number(x0) << " " << Number(x1) << " "
        << Number(y0) << " " << Number(y1) << " " << Number(yv) << "\n";
    }
    s << "EOD\n"
      << "plot $cells using 1:2:3:4:5:6:7 with boxxyerror fs solid 1.0 noborder lc palette title "
      << Quoted(y_name) << "\n";
    return s.str();
  }

  s << "set ylabel " << Quoted(y_name) << "\nset key outside right top\nset autoscale xfix\n";
  std::ostringstream plots;
  int block = 0;
  for (auto& [label, points] : groups) {
    std::sort(points.begin(), points.end());
    s << "$group" << block << " << EOD\n";
    for (const auto& [xv, yv] : points) s << Number(xv) << " " << Number(yv) << "\n";
    s << "EOD\n";
    plots << (block ? ", \\\n  " : "plot ") << "$group" << block
          << " using 1:2 with linespoints lw 2 pt 7 title "
          << Quoted(other ? *other + " = " + label : y_name);
    ++block;
  }
  s << plots.str() << "\n";
  return s.str();
}

namespace {

bool OnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path != nullptr ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

}  // namespace

void Render(const std::string& script, const PlotOptions& options) {
  Validate(options);
  if (!OnPath("gnuplot")) {
    throw std::runtime_error(
        "gnuplot is not installed (or not on PATH): install the Debian package gnuplot-nox "
        "(scripts/install-deps.sh does)");
  }
  const std::string temporary = options.output + ".tmp." + std::to_string(::getpid()) +
                                (EndsWith(options.output, ".svg") ? ".svg" : ".png");
  const std::string terminal =
      EndsWith(options.output, ".svg")
          ? "set terminal svg size " + std::to_string(options.width) + "," +
                std::to_string(options.height) + " noenhanced font 'sans,12' background '#ffffff'\n"
          : "set terminal pngcairo size " + std::to_string(options.width) + "," +
                std::to_string(options.height) + " noenhanced font 'sans,10'\n";
  const std::string full = terminal + "set output " + Quoted(temporary) + "\n" + script +
                           "unset output\n";

  char script_path[] = "/tmp/musclesim_plot_XXXXXX";
  const int fd = ::mkstemp(script_path);
  if (fd < 0) throw std::runtime_error("cannot create a temporary gnuplot script");
  if (::write(fd, full.data(), full.size()) != static_cast<ssize_t>(full.size())) {
    ::close(fd);
    ::unlink(script_path);
    throw std::runtime_error("cannot write the temporary gnuplot script");
  }
  ::close(fd);
  FILE* pipe = ::popen(("gnuplot " + std::string(script_path) + " 2>&1").c_str(), "r");
  std::string messages;
  char buffer[512];
  while (pipe != nullptr && std::fgets(buffer, sizeof buffer, pipe) != nullptr) messages += buffer;
  const int status = pipe != nullptr ? ::pclose(pipe) : -1;
  ::unlink(script_path);
  if (status != 0 || !std::filesystem::exists(temporary)) {
    std::filesystem::remove(temporary);
    throw std::runtime_error("gnuplot failed: " + messages);
  }
  std::filesystem::rename(temporary, options.output);
}

}  // namespace musclesim
