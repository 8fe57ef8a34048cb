#include "musclesim/io/import/muscle_import.h"

#include <tinyxml2.h>

#include "io/import/muscle_import_readers.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/printable_text.h"
#include "musclesim/io/readers/input_file.h"

namespace musclesim {

void ValidateImported(const ImportedMuscle& muscle,
                      const std::vector<std::pair<std::string, std::string>>& key_names) {
  try {
    Validate(muscle.params);
    if (muscle.activation_dynamics) Validate(*muscle.activation_dynamics);
  } catch (const ParameterError& e) {
    std::string key = e.path();
    for (const auto& [ours, theirs] : key_names) {
      if (key == ours) key = theirs;
    }
    throw InputError(muscle.source + " '" + muscle.name + "': " + key + " = " + e.value() + ": " +
                     e.rule());
  }
}

ImportedModel ImportMuscles(const std::string& path) {
  const std::string text = ReadInputFile(path, "an OpenSim (.osim) or MuJoCo (MJCF) model file");
  tinyxml2::XMLDocument document;
  const tinyxml2::XMLError status = document.Parse(text.data(), text.size());
  if (status != tinyxml2::XML_SUCCESS) {
    throw InputError(PrintableText(path) + ":" + std::to_string(document.ErrorLineNum()) +
                     ": not well-formed XML (" + PrintableText(document.ErrorStr()) + ")");
  }
  // A document holding only comments or declarations parses, yet has no root element.
  const tinyxml2::XMLElement* root_element = document.RootElement();
  if (root_element == nullptr) {
    throw InputError(PrintableText(path) +
                     ": no root element (expected OpenSim's <OpenSimDocument> or MuJoCo's "
                     "<mujoco>)");
  }
  const std::string root = root_element->Name();
  ImportedModel model;
  if (root == "OpenSimDocument") {
    model = ReadOpenSimMuscles(document, path);
  } else if (root == "mujoco") {
    model = ReadMjcfMuscles(document, path);
  } else {
    throw InputError(PrintableText(path) + ": root element <" + PrintableText(root) +
                     "> is neither OpenSim's <OpenSimDocument> nor MuJoCo's <mujoco>");
  }
  if (model.muscles.empty()) {
    std::string found;
    for (const std::string& line : model.unsupported) found += "\n  " + line;
    throw InputError(PrintableText(path) +
                     ": no muscle musclesim imports (OpenSim: DeGrooteFregly2016Muscle, "
                     "Millard2012EquilibriumMuscle, Thelen2003Muscle; MuJoCo: "
                     "<muscle>, <general> with the muscle gain and bias)" +
                     (found.empty() ? std::string(": no actuator found") : "; found:" + found));
  }
  return model;
}

}  // namespace musclesim
