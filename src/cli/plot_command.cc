// musclesim plot: figures of trajectories, model curves and sweeps, drawn by gnuplot.
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/model_yaml.h"
#include "musclesim/io/file_roles.h"
#include "musclesim/io/output_file.h"
#include "musclesim/plot/plot.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp =
    R"(usage: musclesim plot RUN.csv -o run.png           a trajectory of musclesim run
  musclesim plot --curves SCENARIO.yaml -o curves.png     the model's curves
  musclesim plot RESIDUALS.csv -o fit.png    musclesim identify --residuals: data beside model
  musclesim plot SWEEP.csv --x PATH [--y METRIC] [--color PATH] -o sweep.png
common options:
  -o PATH          the figure: .png or .svg (required)
  --title TEXT     the figure's title (default: from the input)
  --size WxH       pixels (default 1000x750)
  --script PATH    also write the gnuplot script, to restyle the figure by hand
A trajectory: length, shortening velocity, activation and the tensions against time in
stacked panels, concentric, eccentric and isometric intervals shaded; a network's, its
positions, lengths, tensions and activations, and per controller its measured value against
its reference, over a panel of the controllers' errors. Curves: passive, active and total
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
      {"output", "-o"}, {"title", "--title"}, {"size", "--size"},
      {"x", "--x"},     {"y", "--y"},         {"color", "--color"}};
  const auto flag = kFlags.find(e.path());
  if (flag == kFlags.end()) throw InputError(e.what());
  throw InputError(flag->second + " " + e.value() + ": " + e.rule());
}

std::string Script(const Arguments& args, const PlotOptions& options) {
  if (args.Has("--curves")) {
    if (!args.positional.empty()) throw UsageError("--curves takes the model file; give no CSV");
    return CurvesPlotScript(TensionModel(LoadModelSpec(args.Value("--curves")).params), options);
  }
  if (args.positional.size() != 1) throw UsageError("expected one CSV file (see --help)");
  const CsvTable table = ReadCsv(args.positional[0]);
  if (args.Has("--x")) {
    const auto optional = [&](const char* name) {
      return args.Has(name) ? std::optional<std::string>(args.Value(name)) : std::nullopt;
    };
    return SweepPlotScript(table, args.Value("--x"), optional("--y"), optional("--color"), options);
  }
  if (args.Has("--y") || args.Has("--color")) throw UsageError("--y and --color go with --x");
  return IsResidualTable(table)       ? ResidualPlotScript(table, options)
         : IsNetworkTrajectory(table) ? NetworkPlotScript(table, options)
                                      : TrajectoryPlotScript(table, options);
}

}  // namespace

int PlotCommand(int argc, char** argv) {
  const Arguments args = Parse(
      argc, argv, 2, {"-o", "--title", "--size", "--script", "--curves", "--x", "--y", "--color"},
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
