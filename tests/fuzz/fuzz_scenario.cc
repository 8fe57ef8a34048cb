// libFuzzer target: the scenario reader, with `--set` overrides. Lines of the input that
// start with "#--set " (YAML comments, so the file stays a scenario) are applied as overrides.
#include <optional>
#include <sstream>
#include <vector>

#include "fuzz_input.h"
#include "musclesim/io/readers/scenario_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "scenario.yaml");
  std::vector<std::string> overrides;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("#--set ", 0) == 0) overrides.push_back(line.substr(7));
  }
  std::optional<Scenario> scenario;
  fuzz::ExpectOnlyInputErrors([&] { scenario = LoadScenario(path, overrides); });
  // what the reader accepted (a single actuator: the network of docs/model.md 7.4) builds
  // and passes a run's checks: any exception here escapes to libFuzzer as a finding
  if (scenario) {
    scenario->Build();
    scenario->Validate();
  }
  return 0;
}
