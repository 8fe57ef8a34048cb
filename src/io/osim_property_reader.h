// What the .osim readers share (io/osim_muscles.cc, io/osim_millard.cc): an OpenSim object's
// properties read with its own defaults, and the notes and checks every muscle class needs.
#pragma once

#include <tinyxml2.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/io/muscle_import.h"

namespace musclesim {

// The properties of one OpenSim object (a muscle, or one of its curves), each error naming
// the file and line, the object, the property and the rule.
class OsimPropertyReader {
 public:
  OsimPropertyReader(const tinyxml2::XMLElement& object, const std::string& path)
      : object_(object), path_(path) {}

  // The property's value, `fallback` when the file leaves it out.
  double Number(const char* property, double fallback) const;
  bool Flag(const char* property, bool fallback) const;
  // An optional property (OpenSim's empty `<curviness />`): none when absent or empty.
  std::optional<double> OptionalNumber(const char* property) const;

  // "Millard2012EquilibriumMuscle 'name' <property>", for messages
  std::string What(const char* property) const;
  // the object's name attribute, printable
  std::string Name() const;
  // "path:line" of the object
  std::string Where() const;

 private:
  const tinyxml2::XMLElement& object_;
  const std::string& path_;
};

// The note on a muscle's path, which the scenario does not carry (its points, wrap objects).
std::string GeometryNote(const tinyxml2::XMLElement& muscle);

// A compliant tendon's strain and slack length, set on `muscle` after De Groote's rules:
// InputError naming the property otherwise.
void SetCompliantTendon(ImportedMuscle& muscle, double strain_at_one_norm_force,
                        const char* strain_property);

// musclesim's key -> OpenSim's property, for the messages of ValidateImported
extern const std::vector<std::pair<std::string, std::string>> kOsimPropertyNames;

// The notes every OpenSim muscle's import adds: appliesForce, default_activation, the path.
void AddCommonNotes(const OsimPropertyReader& read, const tinyxml2::XMLElement& element,
                    ImportedMuscle& muscle);

// A Millard2012EquilibriumMuscle, converted to family degroote2016 (docs/model.md 14.5).
ImportedMuscle ReadMillard(const tinyxml2::XMLElement& element, const std::string& path);

}  // namespace musclesim
