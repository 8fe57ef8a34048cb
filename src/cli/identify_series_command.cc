// musclesim identify DATA.yaml, for a data file of the time-series kind (a top-level
// `scenario` key): the fit, or with --design the experiment's check.
#include <iostream>
#include <memory>
#include <system_error>
#include <utility>
#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/identify_series_spec.h"
#include "musclesim/io/writers/file_roles.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/io/writers/scenario_rewrite.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/identify/identify_series.h"
#include "musclesim/identify/identify_series_warnings.h"

namespace musclesim::cli {

namespace {

constexpr const char* kSeriesHelp = R"(
usage: musclesim identify DATA.yaml [-o SCENARIO.yaml] [--report PATH] [--residuals PATH]
                          [--set KEY=VALUE]...
       musclesim identify DATA.yaml --design [-o PATH] [--set KEY=VALUE]...

A data file with a top-level `scenario:` key fits a scenario's parameters to measured time
series, by Levenberg-Marquardt on the exact Jacobian of forward sensitivities:
  scenario: quick_release.yaml          the experiment's known inputs (either form)
  series:                               one or more, each a CSV with t and output columns
    - csv: quick_release.csv            named as the trajectory CSV's (length, NODE.position,
      noise: {length: 2.0e-5}           ELEMENT.tension, ...); noise: optional SD per column
  parameters:                           dotted paths as --set takes them; start: optional
    - {path: model.f_iso, start: 80, bounds: [1, 1000]}    (the scenario's value), bounds:
    - {path: model.velocity.v_max, start: 0.5}               optional [lower, upper]
    - {path: "load[0].after"}           (a path with [index] is quoted inside {...})
(paths relative to DATA.yaml). Noise levels for every column, or for none (then every series
must measure one and the same column, and the standard errors come from s^2 = RSS/(N-P)).
It writes the scenario with the estimates applied, a complete file that runs, headed by each
estimate with its standard error and a verdict on which parameters the experiment determines.
  -o PATH            the estimated scenario (atomically) instead of standard output
  --report PATH      Markdown: estimates, standard errors, correlations, the singular values of
                     the scaled sensitivity matrix, the verdict, the fit's convergence
  --residuals PATH   CSV of every measured value beside the model's; `musclesim plot` draws it
  --set KEY=VALUE    change the scenario before anything (repeatable), as run --set does
  --design           no fit, no data needed: rank the parameters by their Cramer-Rao standard
                     errors at the start values with the stated noise (every column needs one;
                     a series without csv uses the scenario's output grid), with the singular
                     values and the verdict; Markdown to standard output or -o
Exit codes: 0 success, 2 invalid input or data, 1 anything else (a fit that did not converge
writes its results and exits 1).
)";

// The first positional argument, skipping the options that take a value in either kind.
std::optional<std::string> DataFile(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o" || arg == "--report" || arg == "--residuals" || arg == "--set") {
      ++i;
    } else if (arg == "-" || arg.empty() || arg[0] != '-') {
      return arg;
    }
  }
  return std::nullopt;
}

// Refuses (exit 2) an output that would overwrite an input of the fit, or another output.
void CheckOutputs(const Arguments& args, const IdentifySeriesSpec& spec) {
  std::vector<FileRole> inputs = {{args.positional[0], "the data file"},
                                  {spec.scenario, "the scenario"}};
  for (const SeriesSpec& series : spec.series) {
    if (series.csv) inputs.push_back({*series.csv, "a measured series"});
  }
  std::vector<FileRole> outputs;
  for (const char* option : {"-o", "--report", "--residuals"}) {
    if (args.Has(option)) outputs.push_back({args.Value(option), option});
  }
  CheckOutputFiles(inputs, outputs);
}

}  // namespace

const char* IdentifySeriesHelp() { return kSeriesHelp; }

bool NamesSeriesDataFile(int argc, char** argv) {
  const std::optional<std::string> data = DataFile(argc, argv);
  if (!data) return false;
  try {
    return IsIdentifySeriesFile(*data);
  } catch (const InputError&) {
    // a file that cannot be read or parsed: the reader of the kind the options ask for says
    // what is wrong with it (the measured curves' when no option is the time series' own)
    for (int i = 2; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--design" || arg == "--residuals" || arg == "--set" ||
          arg.rfind("--residuals=", 0) == 0 || arg.rfind("--set=", 0) == 0) {
        return true;
      }
    }
    return false;
  }
}

// The data file's scenario with --set applied, its errors naming the data file's entry.
Scenario LoadSeriesScenario(const IdentifySeriesSpec& spec, const std::vector<std::string>& sets) {
  try {
    return LoadScenario(spec.scenario, Overrides(sets, "--set"));
  } catch (const InputError& e) {
    throw InputError(
        spec.source + ": scenario " + spec.scenario + " (" + PlaceText(spec.scenario_at) + ")", e);
  }
}

int IdentifySeriesCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2, {"-o", "--report", "--residuals", "--set"},
                               {"--design", "--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kSeriesHelp + 1;  // without the blank line that separates it in identify --help
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("expected one data file (see --help)");
  const std::string& data_file = args.positional[0];
  const IdentifySeriesSpec spec = LoadIdentifySeriesSpec(data_file);
  const std::vector<std::string> sets = args.List("--set");
  const SensitivityRunner run = ScenarioSensitivityRunner(LoadSeriesScenario(spec, sets));

  if (args.Has("--design")) {
    if (args.Has("--report") || args.Has("--residuals")) {
      throw UsageError("--report and --residuals go with a fit, not --design");
    }
    CheckOutputs(args, spec);
    const SeriesIdentification design = DesignSeries(spec, ReadMeasuredSeries(spec, true), run);
    WriteOutput(args.Value("-o", "-"), FormatDesignReport(design, data_file));
    return kExitSuccess;
  }

  CheckOutputs(args, spec);
  const SeriesIdentification fit = FitSeries(spec, ReadMeasuredSeries(spec, false), run);
  std::vector<std::string> overrides = sets;
  for (const std::string& o : EstimateOverrides(fit)) overrides.push_back(o);
  // every output staged first and committed together: a failure to write one leaves every
  // earlier file as it was
  std::vector<std::unique_ptr<StreamedOutput>> outputs;
  const auto stage = [&](const std::string& path, const std::string& text) {
    outputs.push_back(std::make_unique<StreamedOutput>(path));
    outputs.back()->Write(text);
  };
  stage(args.Value("-o", "-"), RewriteScenario(spec.scenario, Overrides(overrides, "--set"),
                                               EstimatedScenarioHeader(fit, data_file)));
  if (args.Has("--report")) stage(args.Value("--report"), FormatSeriesReport(fit, data_file));
  if (args.Has("--residuals")) stage(args.Value("--residuals"), FormatResidualCsv(fit));
  for (const auto& output : outputs) output->Commit();
  // far above 1 the model does not describe the data at this optimum: say so, not silently
  if (const std::string warning = PoorFitWarning(fit); !warning.empty()) {
    std::cerr << "musclesim identify: warning: " << warning << "\n";
  }
  if (!fit.converged) {
    std::cerr << "musclesim identify: the fit did not converge: " << fit.stop_reason
              << "; the results written are its last point, not an optimum\n";
    return kExitFailure;
  }
  return kExitSuccess;
}

}  // namespace musclesim::cli
