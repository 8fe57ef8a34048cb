// The two readers behind ImportMuscles (io/import/muscle_import.h), one per tool's file format.
#pragma once

#include <tinyxml2.h>

#include <string>

#include "musclesim/io/import/muscle_import.h"

namespace musclesim {

// An .osim document: every force of its ForceSet (and of any nested one).
ImportedModel ReadOpenSimMuscles(const tinyxml2::XMLDocument& document, const std::string& path);

// The OpenSim muscles converted to family degroote2016 (docs/model.md 14.5), one element each.
ImportedMuscle ReadMillard(const tinyxml2::XMLElement& element, const std::string& path);
ImportedMuscle ReadThelen(const tinyxml2::XMLElement& element, const std::string& path);

// An MJCF document: every actuator of its <actuator> sections.
ImportedModel ReadMjcfMuscles(const tinyxml2::XMLDocument& document, const std::string& path);

// Validates the muscle's model; a ParameterError becomes an InputError naming the muscle, its
// place and the tool's own name for the value (`key_names`: musclesim key -> the tool's).
void ValidateImported(const ImportedMuscle& muscle,
                      const std::vector<std::pair<std::string, std::string>>& key_names);

}  // namespace musclesim
