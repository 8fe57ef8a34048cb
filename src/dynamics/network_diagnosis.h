// Private: what made a network's right-hand side non-finite (network_diagnosis.cc).
#pragma once

#include <string>

#include "musclesim/dynamics/network_model.h"

namespace musclesim::network {

std::string NonFiniteCause(const NetworkModel& m, double t, const double* y);

}  // namespace musclesim::network
