// The laws of the passive elements, each described once (core/part_fields.h): a spring, a
// linear, exponential or De Groote tendon, a damper, with their keys, units, ranges, defaults
// and meaning. The network reader, the elements' parameter handles, their closed-form
// derivatives, Validate(Element) and the table in docs/guide/networks.md derive from these.
// An actuator is no law of this list: its tension is its model's (model/tension.h).
#pragma once

#include <vector>

#include "musclesim/core/part_fields.h"
#include "musclesim/dynamics/network_parts.h"

namespace musclesim {

using ElementLaw = PartVariant<Element>;
using ElementField = NumberField<Element>;

// The tag of a field whose dT/dp has a closed form (dynamics/element_parameter_derivative.cc).
enum class ElementPartial : int { kStiffness, kRestLength, kSlackLength, kScale, kRate, kDamping };

// Every passive law, in the order of the reference table.
const std::vector<ElementLaw>& ElementLaws();

// The names every element has, an actuator's too: its own and the nodes it joins.
const std::vector<NameField<Element>>& ElementNames();

// The law `element` follows; null for an actuator (or a tendon marked pushes_below_slack that
// is not exponential, which Validate refuses).
const ElementLaw* LawOf(const Element& element);

}  // namespace musclesim
