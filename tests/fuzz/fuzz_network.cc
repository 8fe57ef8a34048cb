// libFuzzer target: the network form of the scenario reader (nodes, elements, loads,
// controllers; its corpus holds networks), with `--set` overrides given as lines starting
// "#--set ", as for the single-actuator form. The scenario read is then built and checked as
// a run would (Scenario::Validate), which must refuse nothing the reader accepted.
#include <optional>
#include <sstream>
#include <vector>

#include "fuzz_input.h"
#include "musclesim/io/readers/scenario_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "network.yaml");
  std::vector<std::string> overrides;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("#--set ", 0) == 0) overrides.push_back(line.substr(7));
  }
  std::optional<Scenario> scenario;
  fuzz::ExpectOnlyInputErrors([&] { scenario = LoadScenario(path, overrides); });
  // a scenario the reader accepted builds and passes a run's checks: any exception here
  // escapes to libFuzzer as a finding
  if (scenario) {
    scenario->Build();
    scenario->Validate();
  }
  return 0;
}
