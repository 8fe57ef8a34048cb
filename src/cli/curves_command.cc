// musclesim curves FILE.yaml --length A:B:N | --velocity A:B:N [-o PATH]
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "musclesim/errors.h"
#include "musclesim/io/curves_csv.h"
#include "musclesim/io/input_ranges.h"
#include "musclesim/io/model_yaml.h"
#include "musclesim/io/output_file.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp = R"(usage: musclesim curves FILE.yaml (--length A:B:N | --velocity A:B:N) [-o PATH]

Tabulates the model of FILE.yaml's `model:` block on N evenly spaced points from A to B
(a model file, or a scenario, which is then checked whole).
  --length A:B:N     CSV columns length,f_L,tension_passive   (length in m, tension in N;
                     A and B within [-1000, 1000] m)
  --velocity A:B:N   CSV columns shortening_velocity,g        (m/s, eps-regularised g;
                     A and B within [-1000, 1000] m/s)
  -o PATH            write to PATH (atomically) instead of standard output ("-")
Numbers carry 17 significant digits.
)";

}  // namespace

int CurvesCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2, {"--length", "--velocity", "-o"}, {"--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return 0;
  }
  if (args.positional.size() != 1) throw UsageError("expected one model file (see --help)");
  if (args.Has("--length") == args.Has("--velocity")) {
    throw UsageError("give exactly one of --length A:B:N or --velocity A:B:N");
  }
  const bool lengths = args.Has("--length");
  const std::string option = lengths ? "--length" : "--velocity";
  const UniformGrid grid =
      ParseGrid(option, args.Value(option), lengths ? kPositionRange : kSpeedRange);
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
