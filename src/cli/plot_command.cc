// musclesim plot: figures of trajectories, model curves and sweeps, drawn by gnuplot.
#include <charconv>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/model_yaml.h"
#include "musclesim/io/writers/file_roles.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/plot/plot.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp =
    R"(usage: musclesim plot RUN.csv -o run.png           a trajectory of musclesim run
  musclesim plot --curves SCENARIO.yaml -o curves.png     the model's curves
  musclesim plot RESIDUALS.csv -o fit.png    musclesim identify --residuals: data beside model
  musclesim plot SWEEP.csv --x PATH [--y METRIC] [--color PATH] -o sweep.png
  musclesim plot RUN.csv -o path.png      a network in the plane (or space): the nodes' paths
  musclesim plot RUN.csv --frames T1,T2,... [--scenario SCENARIO.yaml] -o frames.png
  musclesim plot RUN.csv --frame-count N [--scenario SCENARIO.yaml] -o frames.png
common options:
  -o PATH          the figure: .png or .svg (required)
  --title TEXT     the figure's title (default: from the input)
  --size WxH       pixels (default 1000x750)
  --script PATH    also write the gnuplot script, to restyle the figure by hand
A trajectory: length, shortening velocity, activation and the tensions against time in
stacked panels, concentric, eccentric and isometric intervals shaded; a network's, its
positions, lengths, tensions and activations, and per controller its measured value against
its reference, over a panel of the controllers' errors; a network's in the plane or in space
(columns NODE.x, NODE.y), the nodes' paths in the x-y plane (equal scales; in space the x-y
projection) beside its lengths, tensions and activations. Frames: the network's shape at
each time of --frames (seconds, within the run; each frame shows the row nearest the time,
titled with that row's time) or at --frame-count N times evenly spaced from the first row to
the last (N = 1..36), the nodes as points and, with --scenario (the file that made the run:
its nodes must be the CSV's), each element's path from its from node over its via points to
its to node; frames need a run in the plane or in space. Curves: passive, active and total
tension against length (L_opt shaded, each Gaussian thin) and g(v). A sweep: METRIC
(default the first) against the swept path PATH, a line per value of --color; without
--color and with two swept paths, a heat map. Failed rows are left out.
Text is drawn as written (no gnuplot markup); titles, file names and the CSV's column names
must be UTF-8 without control characters, and plotted cells finite numbers.
Needs gnuplot (Debian package gnuplot-nox; scripts/install-deps.sh installs it).
)";

void ParseSize(const std::string& text, PlotOptions& options) {
  int width = 0, height = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || x != 'x') {
    throw UsageError("--size " + text + ": expected WIDTHxHEIGHT in pixels, e.g. 1200x900");
  }
  options.width = width;
  options.height = height;
}

// The library names a refused option as PlotOptions and SweepPlotScript do; this program
// says the flag that gave it ("--x mass: not a swept path of ...").
[[noreturn]] void ThrowWithFlag(const ParameterError& e) {
  static const std::map<std::string, std::string> kFlags = {
      {"output", "-o"},       {"title", "--title"},
      {"size", "--size"},     {"x", "--x"},
      {"y", "--y"},           {"color", "--color"},
      {"frames", "--frames"}, {"frame-count", "--frame-count"}};
  const auto flag = kFlags.find(e.path());
  if (flag == kFlags.end()) throw InputError(e.what());
  throw InputError(flag->second + " " + e.value() + ": " + e.rule());
}

// "0,0.5,1" as times [s].
std::vector<double> ParseTimes(const std::string& text) {
  std::vector<double> times;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    double t = 0.0;
    const char* first = text.data() + start;
    const char* last = text.data() + end;
    const auto read = std::from_chars(first, last, t);
    if (first == last || read.ec != std::errc() || read.ptr != last || !std::isfinite(t)) {
      throw UsageError("--frames " + text +
                       ": expected times in seconds separated by commas, e.g. 0,0.5,1");
    }
    times.push_back(t);
    if (end == text.size()) return times;
    start = end + 1;
  }
}

int ParseCount(const std::string& text) {
  int count = 0;
  const auto read = std::from_chars(text.data(), text.data() + text.size(), count);
  if (text.empty() || read.ec != std::errc() || read.ptr != text.data() + text.size()) {
    throw UsageError("--frame-count " + text + ": expected a whole number of frames, 1 to " +
                     std::to_string(kMaxFrames));
  }
  return count;
}

// A strip of frames (--frames, --frame-count) of a run in the plane or in space.
std::string FramesScript(const Arguments& args, const CsvTable& table, const PlotOptions& options) {
  const char* flag = args.Has("--frames") ? "--frames" : "--frame-count";
  if (args.Has("--frames") && args.Has("--frame-count")) {
    throw UsageError("give --frames (the times) or --frame-count (how many), not both");
  }
  const std::vector<double> times =
      args.Has("--frames") ? ParseTimes(args.Value("--frames")) : std::vector<double>{};
  const int count = args.Has("--frames") ? 0 : ParseCount(args.Value("--frame-count"));
  std::optional<Scenario> scenario;
  if (args.Has("--scenario")) scenario = LoadScenario(args.Value("--scenario"));
  return FramesPlotScript(table, times, count, scenario ? &*scenario : nullptr, flag, options);
}

std::string Script(const Arguments& args, const PlotOptions& options) {
  if (args.Has("--curves")) {
    if (!args.positional.empty()) throw UsageError("--curves takes the model file; give no CSV");
    if (args.Has("--frames") || args.Has("--frame-count") || args.Has("--scenario")) {
      throw UsageError("--frames, --frame-count and --scenario go with a run's CSV, not --curves");
    }
    const ModelParams params = LoadModelSpec(args.Value("--curves")).params;
    if (params.family != CurveFamily::kPaper || params.pennation_angle != 0.0) {
      // the figure shows the Gaussian components, which only the paper's curves have
      throw InputError(args.Value("--curves") + ": model.family " + ToString(params.family) +
                       (params.pennation_angle != 0.0 ? " with a pennation_angle" : "") +
                       ": plot --curves draws the paper's curves and their Gaussians; tabulate "
                       "this model's with `musclesim curves` instead");
    }
    return CurvesPlotScript(TensionModel(params), options);
  }
  if (args.positional.size() != 1) throw UsageError("expected one CSV file (see --help)");
  const CsvTable table = ReadCsv(args.positional[0]);
  if (args.Has("--x")) {
    const auto optional = [&](const char* name) {
      return args.Has(name) ? std::optional<std::string>(args.Value(name)) : std::nullopt;
    };
    if (args.Has("--frames") || args.Has("--frame-count") || args.Has("--scenario")) {
      throw UsageError("--frames, --frame-count and --scenario go with a run's CSV, not --x");
    }
    return SweepPlotScript(table, args.Value("--x"), optional("--y"), optional("--color"), options);
  }
  if (args.Has("--y") || args.Has("--color")) throw UsageError("--y and --color go with --x");
  const bool frames = args.Has("--frames") || args.Has("--frame-count");
  if (frames) return FramesScript(args, table, options);
  if (args.Has("--scenario")) {
    throw UsageError("--scenario goes with --frames or --frame-count (it draws the elements)");
  }
  return RunPlotScript(table, options);
}

}  // namespace

int PlotCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2,
                               {"-o", "--title", "--size", "--script", "--curves", "--x", "--y",
                                "--color", "--frames", "--frame-count", "--scenario"},
                               {"--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return kExitSuccess;
  }
  PlotOptions options;
  options.output = args.Value("-o");
  if (options.output.empty()) throw UsageError("-o PATH (a .png or .svg file) is required");
  options.title = args.Value("--title");
  if (args.Has("--size")) ParseSize(args.Value("--size"), options);
  try {
    Validate(options);
    std::vector<FileRole> inputs;
    for (const std::string& file : args.positional) inputs.push_back({file, "the plotted CSV"});
    if (args.Has("--curves")) inputs.push_back({args.Value("--curves"), "the model file"});
    if (args.Has("--scenario")) inputs.push_back({args.Value("--scenario"), "the scenario"});
    CheckOutputFiles(inputs, {{options.output, "-o"},
                              {args.Has("--script") ? args.Value("--script") : "", "--script"}});
    const std::string script = Script(args, options);
    if (args.Has("--script")) WriteOutput(args.Value("--script"), script);
    Render(script, options);
  } catch (const ParameterError& e) {
    ThrowWithFlag(e);
  }
  return kExitSuccess;
}

}  // namespace musclesim::cli
