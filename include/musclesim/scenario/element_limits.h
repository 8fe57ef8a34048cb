// What an element's law gives at the lengths a run may reach, for the checks made when a
// scenario is read (a `max_length` limit is a length the run may reach).
#pragma once

#include "musclesim/dynamics/network_parts.h"

namespace musclesim {

// Element `e`'s tension held at length `l` [m], at rest and fully active: the largest its law
// gives there (the passive and tendon exponentials grow with the length). Not finite where
// the law overflows.
double TensionAtRest(const Element& e, double l);

}  // namespace musclesim
