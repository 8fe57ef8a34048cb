// libFuzzer target: the network scenario reader (nodes, elements, loads, controllers), with
// `--set` overrides given as lines starting "#--set ", as for the single-actuator reader.
#include <sstream>
#include <vector>

#include "fuzz_input.h"
#include "musclesim/io/network_scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "network.yaml");
  std::vector<std::string> overrides;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("#--set ", 0) == 0) overrides.push_back(line.substr(7));
  }
  fuzz::ExpectOnlyInputErrors([&] { LoadNetworkScenario(path, overrides).Build(); });
  return 0;
}
