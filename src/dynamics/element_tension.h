// Private: the tension law of each kind of element (docs/model.md 7.1) with its derivatives,
// defined inline so that the right-hand side, which needs only the value, inlines it and
// computes no derivative for nothing. Included by the evaluations
// that need it.
#pragma once

#include <cmath>

#include "dynamics/network_control.h"
#include "musclesim/dynamics/network_model.h"

namespace musclesim::network {

// T, dT/dl, dT/d(dl/dt) and dT/du of element e at length l and lengthening rate ldot (an
// actuator's u read from y when it is a state, else its waveform's or its controller's at t).
struct Tension {
  double value, by_length, by_rate, by_activation;
};

inline Tension TensionOf(const NetworkModel& m, int e, double t, double l, double ldot,
                         const double* y) {
  const Element& element = m.elements[e];
  switch (element.kind) {
    case ElementKind::kActuator: {
      const int state = m.links[e].activation;
      const double u = state >= 0             ? y[state]
                       : m.links[e].loop >= 0 ? ControlOutput(m, e, t, y)
                                              : element.activation.Evaluate(t);
      const TensionSample s = element.model->Evaluate(l, -ldot, u);
      return {s.total, s.d_length, -s.d_velocity, s.d_activation};  // v = -ldot
    }
    case ElementKind::kSpring:
      return {element.stiffness * (l - element.rest_length), element.stiffness, 0.0, 0.0};
    case ElementKind::kTendon: {
      const double stretch = l - element.slack_length;
      if (stretch <= 0.0 && !element.pushes_below_slack) return {0.0, 0.0, 0.0, 0.0};
      if (!element.exponential()) {
        return {element.stiffness * stretch, element.stiffness, 0.0, 0.0};
      }
      const double grow = std::exp(element.alpha * stretch);
      return {element.k * (grow - 1.0), element.k * element.alpha * grow, 0.0, 0.0};
    }
    case ElementKind::kDamper: return {element.damping * ldot, 0.0, element.damping, 0.0};
  }
  return {0.0, 0.0, 0.0, 0.0};
}

}  // namespace musclesim::network
