// libFuzzer target: the reader of a time-series identification's data file (the scenario and
// CSVs it names are read when they exist: the seeds name the shipped ones).
#include "fuzz_input.h"
#include "musclesim/io/readers/identify_series_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "identify_series.yaml");
  fuzz::ExpectOnlyInputErrors([&] { LoadIdentifySeriesSpec(path); });
  return 0;
}
