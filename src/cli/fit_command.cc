// musclesim fit FILE.yaml: runs model.active_length.fit and prints the result as YAML.
#include <iostream>
#include <sstream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/model_yaml.h"
#include "musclesim/io/writers/model_yaml_writer.h"
#include "musclesim/io/writers/file_roles.h"
#include "musclesim/io/writers/output_file.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp = R"(usage: musclesim fit FILE.yaml [-o PATH]

Runs the fit in FILE.yaml's model.active_length.fit and prints a `gaussians:` block ready to
paste into a scenario's active_length, followed by
  cost:               N, the least-squares cost at the result
  relative_residual:  N / integral(target^2) (or / sum of y^2 for samples)
  iterations:         cost evaluations of the best start (0 when the shapes were fixed)
  starts:             starting points tried
)";

}  // namespace

int FitCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2, {"-o"}, {"--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return 0;
  }
  if (args.positional.size() != 1) throw UsageError("expected one model file (see --help)");
  CheckOutputFiles({{args.positional[0], "the model file"}}, {{args.Value("-o", "-"), "-o"}});
  const ModelSpec loaded = LoadModelFit(args.positional[0]);
  const FitResult& fit = *loaded.fit_result;
  std::ostringstream out;
  out << "gaussians:\n";
  for (const Gaussian& g : fit.gaussians) {
    out << "  - " << FormatGaussianYaml(g) << "\n";
  }
  out << "cost: " << FormatFull(fit.cost) << "\n"
      << "relative_residual: " << FormatFull(fit.relative_residual) << "\n"
      << "iterations: " << fit.iterations << "\n"
      << "starts: " << fit.starts << "\n";
  WriteOutput(args.Value("-o", "-"), out.str());
  return 0;
}

}  // namespace musclesim::cli
