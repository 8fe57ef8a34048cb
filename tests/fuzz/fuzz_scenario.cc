// libFuzzer target: the scenario reader, with `--set` overrides. Lines of the input that
// start with "#--set " (YAML comments, so the file stays a scenario) are applied as overrides.
#include <sstream>
#include <vector>

#include "fuzz_input.h"
#include "musclesim/io/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "scenario.yaml");
  std::vector<std::string> overrides;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("#--set ", 0) == 0) overrides.push_back(line.substr(7));
  }
  fuzz::ExpectOnlyInputErrors([&] { LoadScenario(path, overrides); });
  return 0;
}
