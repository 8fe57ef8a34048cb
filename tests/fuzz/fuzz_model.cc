// libFuzzer target: the model reader (LoadModelSpec, as curves and plot --curves use it,
// and LoadModelFit, as fit does).
#include "fuzz_input.h"
#include "musclesim/io/readers/model_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "model.yaml");
  fuzz::ExpectOnlyInputErrors([&] { LoadModelSpec(path); });
  fuzz::ExpectOnlyInputErrors([&] { LoadModelFit(path); });
  return 0;
}
