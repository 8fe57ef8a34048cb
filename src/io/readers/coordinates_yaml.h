// Private: reading coordinates: a point as one number on a line or a list of 2 or 3 in the
// plane or in space, each coordinate within its range, with messages that name the
// coordinates ("[x, y]") and the scenario's dimensions.
#pragma once

#include <cstddef>
#include <string>

#include "io/readers/yaml_fields.h"
#include "musclesim/core/part_fields.h"

namespace musclesim {

// path + "[i]", built by appending (GCC 12 warns falsely on "[" + std::to_string(i)).
std::string Indexed(std::string path, std::size_t i);

// What a rule of the space says it follows from: "the scenario has dimensions: 2".
std::string HasDimensions(int dimensions);

// The coordinates of a list in messages, each name after `prefix`: "[x, y]", "[vx, vy, vz]".
std::string CoordinateNames(int dimensions, const char* prefix);

// A list of exactly `dimensions` numbers (2 or 3) at `node`, each within `range`; the
// coordinates past them 0. `prefix` names them in messages (CoordinateNames).
FieldPoint ReadCoordinateList(const yaml::Source& src, const Document& node,
                              const std::string& path, int dimensions, const InputRange& range,
                              const char* prefix);

// A point (a node's `fixed`, `position` or `velocity`): one number, x, on a line, a list of
// `dimensions` numbers otherwise.
FieldPoint ReadPoint(const yaml::Source& src, const Document& node, const std::string& path,
                     int dimensions, const InputRange& range, const char* prefix);

}  // namespace musclesim
