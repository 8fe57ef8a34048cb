// libFuzzer target: the sweep reader. The shipped scenarios are copied beside the input once,
// so that a sweep's `base` (concentric.yaml, isometric.yaml, ...) is found and every point is
// validated as a scenario.
#include "fuzz_input.h"
#include "musclesim/sweep/sweep_file.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  musclesim::fuzz::CopyShippedScenarios();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "sweep.yaml");
  fuzz::ExpectOnlyInputErrors([&] { LoadSweep(path); });
  return 0;
}
