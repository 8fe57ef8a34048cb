// NonFiniteCause (network_diagnosis.h): which quantity of the network made its right-hand side
// non-finite, so that a failed run names the element, the quantity and the time rather than
// only CVODE's flag.
#include "dynamics/network_diagnosis.h"

#include <cmath>
#include <string>
#include <vector>

#include "dynamics/network_evaluation.h"
#include "dynamics/network_junction.h"
#include "dynamics/network_space.h"
#include "musclesim/core/number_format.h"

namespace musclesim::network {

std::string NonFiniteCause(const NetworkModel& m, double t, const double* y) {
  const std::string at = " at t = " + FormatNumber(t) + " s";
  // a junction's velocity first: every tension at it depends on it
  for (std::size_t k = 0; k < m.junctions.size(); ++k) {
    const std::string failure = JunctionFailure(m, static_cast<int>(k), t, y);
    if (!failure.empty()) return failure + at;
  }
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const int node = static_cast<int>(i);
    for (int c = 0; c < m.space.dimensions; ++c) {
      const double position = NodeCoordinate(m, node, c, t, y);
      const double velocity = NodeCoordinateRate(m, node, c, t, y);
      if (!std::isfinite(position) || !std::isfinite(velocity)) {
        return "node " + m.nodes[i].name + "'s position " + FormatNumber(position) +
               " m, velocity " + FormatNumber(velocity) + " m/s" + at;
      }
    }
  }
  ElementSample sample;
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    ObserveElement(m, static_cast<int>(e), t, y, sample);
    if (!std::isfinite(sample.tension)) {
      return "elements[" + std::to_string(e) + "] (" + m.elements[e].name + ")'s tension is " +
             FormatNumber(sample.tension) + " N at length " + FormatNumber(sample.length) +
             " m and lengthening rate " + FormatNumber(sample.lengthening_rate) + " m/s" + at +
             ": its law's parameters overflow at that length";
    }
  }
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const double load = LoadOn(m, static_cast<int>(i), t, y);
    if (!std::isfinite(load)) {
      return "the load on node " + m.nodes[i].name + " is " + FormatNumber(load) + " N" + at;
    }
  }
  // every part finite, the sum over a node's mass is not: its acceleration overflowed
  std::vector<double> rate(static_cast<std::size_t>(StateSize(m)));
  NetworkScratch scratch;
  RightHandSide(m, t, y, rate.data(), scratch);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    // the first velocity's rate (a junction has none: its velocity was checked above)
    const int v = m.ends[i].rate;
    const std::size_t a = static_cast<std::size_t>(v);
    if (v >= 0 && !std::isfinite(rate[a])) {
      return "node " + m.nodes[i].name + "'s acceleration is " + FormatNumber(rate[a]) +
             " m/s^2: the forces on it, each finite, over its mass of " +
             FormatNumber(m.nodes[i].mass) + " kg overflow" + at;
    }
  }
  return "a rate of the state (an activation or a controller's integral) is not finite" + at;
}

}  // namespace musclesim::network
