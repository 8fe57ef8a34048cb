// Reads a scenario's skeleton (docs/model.md 15, docs/guide/skeletons.md): `bodies:` and
// `joints:`, and the points of bodies an element's `from`, `to` or `via` may give in place of
// a node's name ({body: forearm, point: [0.0, -0.02]}).
#pragma once

#include <string>
#include <vector>

#include "io/readers/document_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/dynamics/network_parts.h"
#include "musclesim/dynamics/skeleton_parts.h"

namespace musclesim {

std::vector<Body> ReadBodies(const yaml::Source& src, const Document& node, int dimensions);
std::vector<Joint> ReadJoints(const yaml::Source& src, const Document& node, int dimensions);
std::vector<WrapCylinder> ReadWraps(const yaml::Source& src, const Document& node, int dimensions);
// A map {body, point} at `path`: the node `name` on that body, which must be one of `bodies`.
Node ReadBodyPoint(const yaml::Source& src, const Document& node, const std::string& path,
                   const std::string& name, const std::vector<Body>& bodies, int dimensions);

}  // namespace musclesim
