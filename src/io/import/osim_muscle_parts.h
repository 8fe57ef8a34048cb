// The parts every imported OpenSim muscle is made of, whatever its class
// (io/import/osim_muscles.cc, io/import/osim_millard.cc, io/import/osim_thelen.cc): its size, its
// tendon, its activation lag, and the notes on what the scenario does not carry.
#pragma once

#include <tinyxml2.h>

#include <string>
#include <utility>
#include <vector>

#include "io/import/osim_property_reader.h"
#include "musclesim/io/import/muscle_import.h"

namespace musclesim {

// An OpenSim muscle of class `class_name` as a degroote2016 model: its name and source, and
// the properties every OpenSim muscle has (f_iso, l_opt, v_max, pennation, the tendon's slack
// length), at OpenSim 4.6's defaults (the same for each class imported) when left out.
ImportedMuscle StartMuscle(const OsimPropertyReader& read, const char* class_name);

// A compliant tendon's strain and slack length, set on `muscle` after De Groote's rules:
// InputError naming the property and where it is (`where`, "path:line") otherwise.
void SetCompliantTendon(ImportedMuscle& muscle, double strain_at_one_norm_force,
                        const char* strain_property, const std::string& where);

// Millard's or Thelen's first-order activation lag as family thelen2003, time constant for
// constant, unless the file ignores it; its floor `minimum_activation` noted (refused outside
// [0, 1], OpenSim's range, either way).
void SetFirstOrderActivation(const OsimPropertyReader& read, double tau_activation,
                             double tau_deactivation, ImportedMuscle& muscle);

// musclesim's key -> OpenSim's property, for the messages of ValidateImported
extern const std::vector<std::pair<std::string, std::string>> kOsimPropertyNames;

// The note on a muscle's path, which the scenario does not carry (its points, wrap objects).
std::string GeometryNote(const tinyxml2::XMLElement& muscle);

// The notes every OpenSim muscle's import adds: appliesForce, default_activation, the path.
void AddCommonNotes(const OsimPropertyReader& read, const tinyxml2::XMLElement& element,
                    ImportedMuscle& muscle);

// A pennate Millard or Thelen muscle's note on OpenSim's clamp at maximum_pennation_angle
// (refused outside [0, pi/2], OpenSim's range, pennate or not).
void AddPennationClampNote(const OsimPropertyReader& read, ImportedMuscle& muscle);

}  // namespace musclesim
