// libFuzzer target: the sensitivity reader, a scenario's `sensitivities:` list (its corpus:
// single actuators and networks that list parameters), with `--sensitivity` requests given as
// lines starting "#--sensitivity ". A scenario the reader accepted is prepared for a run with
// sensitivities (every path resolved into its df/dp), which may refuse a path only with an
// InputError or ParameterError.
#include <optional>
#include <sstream>
#include <vector>

#include "fuzz_input.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/sensitivity_run.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "sensitivity.yaml");
  std::vector<SensitivityRequest> requests;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("#--sensitivity ", 0) == 0) requests.push_back({line.substr(15), "fuzz"});
  }
  fuzz::ExpectOnlyInputErrors([&] {
    const Scenario scenario = LoadScenario(path);
    const SensitivityRun run(scenario, requests);
    (void)run.columns();
  });
  return 0;
}
