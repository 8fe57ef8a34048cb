// A network's nodes described once (core/part_fields.h): fixed, free and prescribed, each with
// its keys, units, ranges, defaults and meaning; a node's points are one number on a line and
// a list of 2 or 3 coordinates in the plane or in space. The node reader, the nodes' parameter
// handles, the points Validate(Node) checks (finite only: a program may build past a file's
// ranges) and the table in docs/guide/networks.md derive from these. A prescribed node's
// motion is a signal (dynamics/signal_fields.h), a waveform per coordinate.
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/network_parts.h"
#include "musclesim/dynamics/signal_fields.h"

namespace musclesim {

using NodeVariant = PartVariant<Node>;

// Fixed, prescribed and free, in the order of the reference table. A file names none by a
// `type:`; the key only that kind has (its `selector`: fixed, prescribed or mass) tells them
// apart.
const std::vector<NodeVariant>& NodeKinds();

// A prescribed node's motion, `prescribed`: one waveform on a line, a list of one per
// coordinate in 2 or 3 dimensions, each continuous in time.
const std::vector<SignalField<Node>>& NodeSignals();

// The name every node has: its own.
const std::vector<NameField<Node>>& NodeNames();

}  // namespace musclesim
