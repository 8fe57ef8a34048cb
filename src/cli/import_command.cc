// musclesim import MODEL.osim|MODEL.xml [-o DIR]
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/identify/identified_model.h"
#include "musclesim/identify/paper_model_fit.h"
#include "musclesim/io/writers/model_yaml_writer.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/writers/file_roles.h"
#include "musclesim/io/import/imported_scenario.h"
#include "musclesim/io/import/muscle_import.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/io/readers/scenario_yaml.h"

namespace musclesim::cli {

namespace {

constexpr const char* kHelp =
    R"(usage: musclesim import MODEL.osim|MODEL.xml [-o DIR] [--to-gaussians N]

Reads the muscles of an OpenSim model (.osim: DeGrooteFregly2016Muscle, and
Millard2012EquilibriumMuscle and Thelen2003Muscle converted to it) or a MuJoCo model (MJCF:
<muscle>, and <general> with gaintype and biastype muscle), and writes for each a scenario
DIR/NAME.yaml: its model of the matching curve family (family degroote2016 or mujoco,
docs/model.md 14) and an experiment to edit, the muscle on a line holding a hanging mass of
half its isometric force. Properties a file leaves out take the tool's defaults. A converted muscle's report
gives each curve's largest and RMS departure from the file's, in units of f_iso.
  -o DIR             the directory to write into (default: the current one); it must exist
  --to-gaussians N   also write DIR/NAME_gaussians.yaml: the same experiment with the paper's
                     model (passive exponential, N Gaussians, power-law velocity) fitted to
                     the muscle's curves, each fit's RMSE in its comments and on standard error
What is not imported (another actuator or muscle class, MuJoCo's force and activation
clamps, an <include>, the path's geometry) is listed on standard error and in each
scenario's header, never dropped silently.
Exit codes: 0 imported (some actuators may be listed as not imported), 2 invalid input (a
malformed file or value, or no muscle of a supported class), 1 anything else.
)";

// The file name for a muscle: its name with anything but letters, digits, '-', '_' and '.'
// replaced by '_', cut to 100 characters (a file name may hold 255 bytes), made unique among
// the muscles of the run.
std::string FileStem(const std::string& name, std::set<std::string>& taken) {
  constexpr std::size_t kLongest = 100;
  std::string stem;
  for (const char c : name.substr(0, kLongest)) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '-' || c == '_' || c == '.';
    stem += plain ? c : '_';
  }
  if (stem.empty() || stem[0] == '.') stem = "muscle" + stem;
  std::string unique = stem;
  for (int n = 2; taken.count(unique) > 0; ++n) unique = stem + "_" + std::to_string(n);
  taken.insert(unique);
  return unique;
}

// --to-gaussians N: a whole number from 1 to 20.
int GaussianCount(const std::string& text) {
  const bool digits = !text.empty() && text.size() <= 2 &&
                      text.find_first_not_of("0123456789") == std::string::npos;
  const int count = digits ? std::stoi(text) : 0;
  if (count < 1 || count > 20) {
    throw UsageError("--to-gaussians " + text + ": must be a whole number from 1 to 20");
  }
  return count;
}

// The paper's model fitted to `muscle`'s curves, as a model block with its header, and the
// line that reports the fit.
struct GaussianModel {
  std::string block;
  std::string report;
};

GaussianModel FitGaussians(const ImportedMuscle& muscle, int count) {
  const ModelParams& p = muscle.params;
  // a fit that cannot be made names its muscle: the file may hold several
  const PaperModelFit fit = [&] {
    try {
      return FitPaperModel(TensionModel(p), count, OptimalLineLength(p), MaxLineSpeed(p));
    } catch (const InputError& e) {
      throw InputError(muscle.source + " '" + muscle.name + "': " + e.what());
    }
  }();
  const std::string source = std::string("the ") + ToString(p.family) + " curves of '" +
                             muscle.name + "' (musclesim import --to-gaussians " +
                             std::to_string(count) + ")";
  const auto percent = [&](double rmse) {
    return FormatNumber(rmse) + " N (" + FormatNumber(100.0 * rmse / p.f_iso) + " % of f_iso)";
  };
  // a converted muscle's fit is to the curves it was converted to, which its report gives
  std::string report =
      std::string(muscle.conversion.empty() ? "" : "of its degroote2016 curves: ") +
      "RMSE passive " + percent(fit.passive.rmse) + ", active " + percent(fit.active.rmse) +
      ", velocity " + percent(fit.velocity.best.rmse) + " shortening";
  const std::optional<EccentricIdentification>& eccentric = fit.velocity.eccentric;
  if (eccentric && eccentric->identified) {
    report += ", " + percent(eccentric->best.rmse) + " lengthening";
  }
  // the paper's model has no fiber damping: say so, with the line damping nearest to it
  const DeGrooteParams& degroote = p.degroote2016;
  if (p.family == CurveFamily::kDeGroote2016 && degroote.fiber_damping > 0) {
    report += "; not fitted: fiber_damping " + FormatNumber(degroote.fiber_damping) +
              " (about actuator.damping " +
              FormatNumber(p.f_iso * degroote.fiber_damping /
                           (degroote.max_contraction_velocity * degroote.optimal_fiber_length)) +
              " N s/m along an unpennated fiber)";
  }
  return {FormatModelYaml(DraftIdentifiedModel(source, fit.passive, fit.active, fit.velocity)),
          report};
}

}  // namespace

int ImportCommand(int argc, char** argv) {
  const Arguments args = Parse(argc, argv, 2, {"-o", "--to-gaussians"}, {"--help", "-h"});
  if (args.Has("--help") || args.Has("-h")) {
    std::cout << kHelp;
    return 0;
  }
  if (args.positional.size() != 1) throw UsageError("expected one model file (see --help)");
  const std::string& source = args.positional[0];
  const std::string directory = args.Value("-o", ".");
  const int gaussians =
      args.Has("--to-gaussians") ? GaussianCount(args.Value("--to-gaussians")) : 0;
  const ImportedModel model = ImportMuscles(source);

  // every file composed and read back before the first is written
  std::vector<OutputText> outputs;
  std::vector<FileRole> roles;
  std::set<std::string> taken;
  std::vector<std::string> reports;
  const auto add = [&](const std::string& stem, const std::string& text, const std::string& what) {
    OutputText out{(std::filesystem::path(directory) / (stem + ".yaml")).string(), text};
    ReadScenario(ParseDocument(out.path, out.text), out.path);
    roles.push_back({out.path, what});
    outputs.push_back(std::move(out));
  };
  for (const ImportedMuscle& muscle : model.muscles) {
    const std::string stem = FileStem(muscle.name, taken);
    add(stem, FormatImportedScenario(muscle, source, stem + ".csv"),
        "the scenario of " + muscle.name);
    std::string report = "musclesim import: " + muscle.name + ": " + muscle.source + " -> " +
                         outputs.back().path + "\n";
    for (const std::string& line : muscle.conversion) report += "  converted: " + line + "\n";
    for (const std::string& note : muscle.notes) report += "  not carried over: " + note + "\n";
    const double damping = muscle.params.degroote2016.fiber_damping;
    if (muscle.tendon_strain && damping < kJunctionFiberDamping) {
      report += "  note: " + JunctionDampingNote(muscle) + "\n";
    }
    if (gaussians > 0) {
      const GaussianModel paper = FitGaussians(muscle, gaussians);
      // unique too: another muscle may be named after this one's fit
      const std::string fitted = FileStem(stem + "_gaussians", taken);
      add(fitted, FormatImportedScenario(muscle, source, fitted + ".csv", paper.block),
          "the paper's model of " + muscle.name);
      report += "  the paper's model, " + std::to_string(gaussians) + " Gaussians -> " +
                outputs.back().path + ": " + paper.report + "\n";
      if (muscle.tendon_strain) report += "  note: " + RigidTendonNote(muscle) + "\n";
    }
    reports.push_back(report);
  }
  CheckOutputFiles({{source, "the model file"}}, roles);
  // all or none: a file that cannot be written leaves every earlier one as it was
  WriteOutputs(outputs);

  for (const std::string& report : reports) std::cerr << report;
  for (const std::string& line : model.unsupported) {
    std::cerr << "musclesim import: not imported: " << line << "\n";
  }
  return 0;
}

}  // namespace musclesim::cli
