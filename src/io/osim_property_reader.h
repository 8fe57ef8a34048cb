// What the .osim readers share (io/osim_muscles.cc, io/osim_millard.cc): an OpenSim object's
// properties read with its own defaults, and the notes and checks every muscle class needs.
#pragma once

#include <tinyxml2.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/io/muscle_import.h"
#include "musclesim/model/degroote_conversion.h"

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
  // "path:line" of the object, and of its property (the object's when the file leaves it out)
  std::string Where() const;
  std::string WhereOf(const std::string& property) const;

 private:
  const tinyxml2::XMLElement& object_;
  const std::string& path_;
};

// An OpenSim muscle of class `class_name` as a degroote2016 model: its name and source, and
// the properties every OpenSim muscle has (f_iso, l_opt, v_max, pennation, the tendon's slack
// length), at OpenSim 4.6's defaults (the same for each class imported) when left out.
ImportedMuscle StartMuscle(const OsimPropertyReader& read, const char* class_name);

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

// A pennate Millard or Thelen muscle's note on OpenSim's clamp at maximum_pennation_angle.
void AddPennationClampNote(const OsimPropertyReader& read, ImportedMuscle& muscle);

// A muscle converted to family degroote2016 (docs/model.md 14.5): its curves' conversion,
// one line per curve into `muscle.conversion` (the tendon's when `compliant`), and the
// De Groote parameters it sets.
void ApplyConversion(const DeGrooteConversion& converted, bool compliant, ImportedMuscle& muscle);

// Millard's or Thelen's first-order activation lag as family thelen2003, time constant for
// constant, unless the file ignores it; its floor `minimum_activation` noted.
void SetFirstOrderActivation(const OsimPropertyReader& read, double tau_activation,
                             double tau_deactivation, ImportedMuscle& muscle);

// A Millard2012EquilibriumMuscle and a Thelen2003Muscle, converted to family degroote2016.
ImportedMuscle ReadMillard(const tinyxml2::XMLElement& element, const std::string& path);
ImportedMuscle ReadThelen(const tinyxml2::XMLElement& element, const std::string& path);

}  // namespace musclesim
