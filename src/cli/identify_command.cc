// musclesim identify DATA.yaml [-o MODEL.yaml] [--report PATH]
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/identify_spec.h"
#include "musclesim/io/writers/model_yaml_writer.h"
#include "musclesim/io/writers/file_roles.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/identify/curve_data.h"
#include "musclesim/identify/identified_model.h"
#include "musclesim/identify/identify.h"
#include "musclesim/identify/identify_comparisons.h"
#include "musclesim/identify/identify_report.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp = R"(usage: musclesim identify DATA.yaml [-o MODEL.yaml] [--report PATH]

Fits the model's parameters to measured curves and prints a complete `model:` block, each
parameter with its standard error and each curve's RMSE in comments, and the slack length's
95% profile-likelihood interval with the range of k_p and alpha across it (the slack length
can be weakly determined: see the README). DATA.yaml holds any of:
  passive:  {csv: passive.csv}                                columns length,tension
  active:   {csv: active.csv, count: 3, nonnegative: true}    columns length,tension
  velocity: {csv: velocity.csv, f_iso: 100}                   columns shortening_velocity,tension
(CSV paths relative to DATA.yaml; f_iso optional, held fixed when given.) Velocity data with
points v < 0 give the eccentric branch too (v_max, n and a limit under `eccentric:`), the
concentric one then coming from v >= 0; what the data cannot determine is said so and left out.
  -o PATH         write the model block there (atomically) instead of standard output
  --report PATH   also write a Markdown report comparing each fit with a natural cubic spline
                  and polynomials of degree 3 and 4 (RMSE, leave-one-out RMSE, behaviour outside
                  the data, ns per evaluation), and the passive notes of the model block
Exit codes: 0 success, 2 invalid input or data, 1 anything else.
)";

// Runs `step` on the curve of `spec`'s block `key` (its CSV `csv`, named at `at`): an input
// error in that data says which entry of which data file led to it.
template <typename Step>
auto InData(const std::string& key, const std::string& csv, const InputPlace& at, Step step) {
  try {
    return step();
  } catch (const InputError& e) {
    throw InputError(key + ".csv = " + csv + " (" + PlaceText(at) + ")", e);
  }
}

}  // namespace

int IdentifyCommand(int argc, char** argv) {
  if (NamesSeriesDataFile(argc, argv)) return IdentifySeriesCommand(argc, argv);
  const Arguments args = Parse(argc, argv, 2, {"-o", "--report"}, {"--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp << IdentifySeriesHelp();
    return kExitSuccess;
  }
  if (args.positional.size() != 1) throw UsageError("expected one data file (see --help)");
  const IdentifySpec spec = LoadIdentifySpec(args.positional[0]);
  std::vector<FileRole> inputs = {{args.positional[0], "the data file"}};
  for (const auto& [csv, name] :
       {std::pair{spec.passive_csv, "passive.csv"}, std::pair{spec.active_csv, "active.csv"},
        std::pair{spec.velocity_csv, "velocity.csv"}}) {
    if (csv) inputs.push_back({*csv, name});
  }
  CheckOutputFiles(inputs, {{args.Value("-o", "-"), "-o"},
                            {args.Has("--report") ? args.Value("--report") : "", "--report"}});

  std::optional<PassiveIdentification> passive;
  std::optional<ActiveIdentification> active;
  std::optional<VelocityIdentification> velocity;
  std::vector<CurveComparison> comparisons;
  const bool report = args.Has("--report");
  if (spec.passive_csv) {
    const auto data = InData("passive", *spec.passive_csv, spec.passive_csv_at, [&] {
      return ReadCurveCsv(*spec.passive_csv, "length", "tension", kMinPassivePoints);
    });
    passive = InData("passive", *spec.passive_csv, spec.passive_csv_at,
                     [&] { return IdentifyPassive(data); });
    if (report) comparisons.push_back(ComparePassiveFit(data, *passive));
  }
  if (spec.active_csv) {
    const auto data = InData("active", *spec.active_csv, spec.active_csv_at, [&] {
      return ReadCurveCsv(*spec.active_csv, "length", "tension",
                          MinActivePoints(spec.active_count));
    });
    active = InData("active", *spec.active_csv, spec.active_csv_at, [&] {
      return IdentifyActive(data, spec.active_count, spec.active_nonnegative);
    });
    if (report) {
      comparisons.push_back(CompareActiveFit(data, spec.active_count, spec.active_nonnegative));
    }
  }
  if (spec.velocity_csv) {
    const auto data = InData("velocity", *spec.velocity_csv, spec.velocity_csv_at, [&] {
      return ReadCurveCsv(*spec.velocity_csv, "shortening_velocity", "tension",
                          MinVelocityPoints(spec.velocity_f_iso.has_value()));
    });
    velocity = InData("velocity", *spec.velocity_csv, spec.velocity_csv_at,
                      [&] { return IdentifyVelocity(data, spec.velocity_f_iso); });
    if (report) comparisons.push_back(CompareVelocityFit(data, spec.velocity_f_iso, *velocity));
  }

  WriteOutput(args.Value("-o", "-"),
              FormatModelYaml(DraftIdentifiedModel(spec.source, passive, active, velocity)));
  if (report) WriteOutput(args.Value("--report"), FormatReport(comparisons));
  return kExitSuccess;
}

}  // namespace musclesim::cli
