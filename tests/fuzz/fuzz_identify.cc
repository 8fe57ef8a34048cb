// libFuzzer target: the reader of identify's data file (the CSVs it names are read later,
// by the identification).
#include "fuzz_input.h"
#include "musclesim/io/readers/identify_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "identify.yaml");
  fuzz::ExpectOnlyInputErrors([&] { LoadIdentifySpec(path); });
  return 0;
}
