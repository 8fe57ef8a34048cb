// musclesim curves FILE.yaml --length A:B:N | --velocity A:B:N [-o PATH]
#include <iostream>
#include <sstream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "musclesim/io/model_yaml.h"
#include "musclesim/io/output_file.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp = R"(usage: musclesim curves FILE.yaml (--length A:B:N | --velocity A:B:N) [-o PATH]

Tabulates the model of FILE.yaml's `model:` block on N evenly spaced points from A to B.
  --length A:B:N     CSV columns length,f_L,tension_passive   (length in m, tension in N)
  --velocity A:B:N   CSV columns shortening_velocity,g        (m/s, eps-regularised g)
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
  const ModelSpec loaded = LoadModelSpec(args.positional[0]);
  const TensionModel model(loaded.params);

  std::ostringstream csv;
  if (args.Has("--length")) {
    const Range range = ParseRange("--length", args.Value("--length"));
    csv << "length,f_L,tension_passive\n";
    for (int i = 0; i < range.count; ++i) {
      const double x = range.At(i);
      csv << FormatFull(x) << ',' << FormatFull(model.active_length().Evaluate(x).value) << ','
          << FormatFull(PassiveTension(model.params().passive, x).value) << '\n';
    }
  } else {
    const Range range = ParseRange("--velocity", args.Value("--velocity"));
    csv << "shortening_velocity,g\n";
    for (int i = 0; i < range.count; ++i) {
      const double v = range.At(i);
      csv << FormatFull(v) << ',' << FormatFull(model.velocity().Evaluate(v).value) << '\n';
    }
  }
  WriteOutput(args.Value("-o", "-"), csv.str());
  return 0;
}

}  // namespace musclesim::cli
