// libFuzzer target: the optimal control problem reader (it checks the problem against its base
// scenario, resolving columns and parameters, without solving). The shipped scenarios are
// copied beside the input once, so that a problem's `base` is found.
#include "fuzz_input.h"
#include "musclesim/optimize/problem_file.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  musclesim::fuzz::CopyShippedScenarios();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "problem.yaml");
  fuzz::ExpectOnlyInputErrors([&] { LoadProblemFile(path); });
  return 0;
}
