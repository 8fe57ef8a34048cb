// The loads other than a force, each described once (core/part_fields.h): a spring to an
// anchor and a hanging mass, with their keys, units, ranges, defaults and meaning. The load
// readers, the loads' parameter handles, Validate(Load) and the table in
// docs/guide/scenarios.md derive from these. A force is a waveform (dynamics/waveform.h).
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/loads.h"
#include "musclesim/dynamics/network_parts.h"

namespace musclesim {

using LoadVariant = PartVariant<Load>;

// The spring and the mass, in the order of the reference table.
const std::vector<LoadVariant>& LoadVariants();

// The name a network's load has, of any kind: the node it acts on.
const std::vector<NameField<NodeLoad>>& LoadNames();

}  // namespace musclesim
