// `musclesim VERB ...`: dispatches to a verb and maps errors to the documented exit codes
// (0 success, 1 other failure, 2 invalid input, 3 solver failure).
#include <cstring>
#include <iostream>
#include <new>
#include <string>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/printable_text.h"

namespace {

constexpr const char* kUsage = R"(musclesim: muscle-like actuator tension model and simulator

usage: musclesim VERB [ARGS...]      (musclesim VERB --help for each verb)
       musclesim --version           print the version

verbs:
  run      integrate a scenario (actuator/load dynamics on CVODE); write the trajectory CSV
  sweep    run many scenarios made from one by overriding values; one summary CSV
  plot     draw a trajectory, the model's curves or a sweep with gnuplot (PNG or SVG)
  identify fit the model's parameters to measured curves (compare with splines), or a
           scenario's parameters to measured time series (with --design: plan the experiment)
  curves   tabulate f_L and passive tension over length, g over velocity, or a standard
           force-length curve (--preset NAME), as CSV
  fit      fit the sum of Gaussians that a model file asks for; print the components
  optimize the activations that reach a problem's final values with the least effort
           (multiple shooting, IPOPT); write the optimum as a scenario, a summary and a CSV
  import   write a scenario for each muscle of an OpenSim (.osim) or MuJoCo (MJCF) model
  reference print a part's keys with their units, defaults, ranges and meaning (Markdown)

exit codes: 0 success, 1 other failure, 2 invalid input, 3 solver failure,
            130 sweep interrupted
)";

}  // namespace

int main(int argc, char** argv) {
  using namespace musclesim;
  if (argc < 2) {
    std::cerr << kUsage;
    return kExitInvalidInput;
  }
  if (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    std::cout << kUsage;
    return kExitSuccess;
  }
  if (std::strcmp(argv[1], "--version") == 0) {
    std::cout << "musclesim " << MUSCLESIM_VERSION << "\n";
    return kExitSuccess;
  }
  const std::string verb = argv[1];
  try {
    if (verb == "run") return cli::RunCommand(argc, argv);
    if (verb == "sweep") return cli::SweepCommand(argc, argv);
    if (verb == "plot") return cli::PlotCommand(argc, argv);
    if (verb == "identify") return cli::IdentifyCommand(argc, argv);
    if (verb == "curves") return cli::CurvesCommand(argc, argv);
    if (verb == "fit") return cli::FitCommand(argc, argv);
    if (verb == "optimize") return cli::OptimizeCommand(argc, argv);
    if (verb == "import") return cli::ImportCommand(argc, argv);
    if (verb == "reference") return cli::ReferenceCommand(argc, argv);
    std::cerr << "musclesim: unknown verb '" << PrintableText(verb) << "' (see musclesim --help)\n";
    return kExitInvalidInput;
  } catch (const cli::UsageError& e) {
    // a usage error quotes the command line as given: its control characters escaped
    std::cerr << "musclesim " << PrintableText(verb) << ": " << PrintableText(e.what()) << "\n";
    return kExitInvalidInput;
  } catch (const InputError& e) {
    std::cerr << "musclesim " << verb << ": " << e.what() << "\n";
    return kExitInvalidInput;
  } catch (const ParameterError& e) {
    std::cerr << "musclesim " << verb << ": " << e.what() << "\n";
    return kExitInvalidInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "musclesim " << verb
              << ": error: out of memory: the input is larger than this process may allocate "
                 "(the machine's memory, or a limit such as ulimit -v)\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << "musclesim " << verb << ": error: " << PrintableText(e.what()) << "\n";
    return kExitFailure;
  }
}
