// musclesim curves FILE.yaml --length A:B:N | --velocity A:B:N [-o PATH]
// musclesim curves --preset NAME [--optimal-length L] [--length A:B:N] [-o PATH]
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/writers/curves_csv.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/io/readers/model_yaml.h"
#include "musclesim/io/writers/file_roles.h"
#include "musclesim/io/writers/output_file.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp =
    R"(usage: musclesim curves FILE.yaml (--length A:B:N | --velocity A:B:N) [-o PATH]
       musclesim curves --preset NAME [--optimal-length L] [--length A:B:N] [-o PATH]

Tabulates the model of FILE.yaml's `model:` block on N evenly spaced points from A to B
(a model file, or a scenario, which is then checked whole).
  --length A:B:N     CSV columns length,f_L,tension_passive   (length in m, tension in N;
                     A and B within [-1000, 1000] m)
  --velocity A:B:N   CSV columns shortening_velocity,g        (m/s, eps-regularised g;
                     A and B within [-1000, 1000] m/s)
  -o PATH            write to PATH (atomically) instead of standard output ("-")
Numbers carry 17 significant digits.

With --preset, no FILE: a standard active force-length curve, scaled so that its peak is 1
at the optimal length L (--optimal-length, in m, default 1: lengths are then normalised).
  --preset NAME      degroote2016, thelen2003, gordon1966 or mujoco (docs/guide/model.md)
  --length A:B:N     CSV columns length,normalized_length,f_L   (m, l / L, -); default
                     0:2L:201, from zero to twice the optimal length in steps of L / 100
)";

// The table of a standard curve: `musclesim curves --preset NAME ...`.
int PresetCurve(const Arguments& args) {
  if (!args.positional.empty()) {
    throw UsageError("--preset takes no model file (" + args.positional[0] +
                     "): give one or the other");
  }
  if (args.Has("--velocity")) {
    throw UsageError("--preset tabulates lengths: --velocity does not apply");
  }
  const ForceLengthPreset preset = ParsePreset("--preset", args.Value("--preset"));
  const double optimal_length =
      args.Has("--optimal-length")
          ? ParseNumber("--optimal-length", args.Value("--optimal-length"), kLengthRange)
          : 1.0;
  const UniformGrid grid = args.Has("--length")
                               ? ParseGrid("--length", args.Value("--length"), kPositionRange)
                               : UniformGrid{0.0, 2.0 * optimal_length, 201};
  WriteOutput(args.Value("-o", "-"), FormatPresetCurveCsv(preset, optimal_length, grid));
  return 0;
}

}  // namespace

int CurvesCommand(int argc, char** argv) {
  const Arguments args =
      Parse(argc, argv, 2, {"--length", "--velocity", "-o", "--preset", "--optimal-length"},
            {"--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return 0;
  }
  if (args.Has("--preset")) return PresetCurve(args);
  if (args.Has("--optimal-length")) throw UsageError("--optimal-length goes with --preset NAME");
  if (args.positional.size() != 1) throw UsageError("expected one model file (see --help)");
  if (args.Has("--length") == args.Has("--velocity")) {
    throw UsageError("give exactly one of --length A:B:N or --velocity A:B:N");
  }
  const bool lengths = args.Has("--length");
  const std::string option = lengths ? "--length" : "--velocity";
  const UniformGrid grid =
      ParseGrid(option, args.Value(option), lengths ? kPositionRange : kSpeedRange);
  CheckOutputFiles({{args.positional[0], "the model file"}}, {{args.Value("-o", "-"), "-o"}});
  const TensionModel model(LoadModelSpec(args.positional[0]).params);
  std::string csv;
  try {
    csv = lengths ? FormatLengthCurvesCsv(model, grid) : FormatVelocityCurveCsv(model, grid);
  } catch (const ParameterError& e) {
    // a value that overflows: name the flag that asked for it
    throw UsageError(option + " " + args.Value(option) + ": " + e.what());
  }
  WriteOutput(args.Value("-o", "-"), csv);
  return 0;
}

}  // namespace musclesim::cli
