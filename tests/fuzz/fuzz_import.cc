// libFuzzer target: the reader of other tools' model files (ImportMuscles, as `musclesim
// import` uses it), and the scenario written for each muscle read back (LoadScenario's rules).
#include "fuzz_input.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/import/imported_scenario.h"
#include "musclesim/io/import/muscle_import.h"
#include "musclesim/io/readers/scenario_yaml.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace musclesim;
  const std::string path = fuzz::WriteInput(data, size, "model.xml");
  fuzz::ExpectOnlyInputErrors([&] {
    for (const ImportedMuscle& muscle : ImportMuscles(path).muscles) {
      const std::string text = FormatImportedScenario(muscle, path, "out.csv");
      ReadScenario(ParseDocument("imported", text), "imported");
    }
  });
  return 0;
}
