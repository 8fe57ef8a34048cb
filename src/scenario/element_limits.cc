#include "musclesim/scenario/element_limits.h"

#include <algorithm>
#include <cmath>

#include "musclesim/model/tension.h"

namespace musclesim {

double TensionAtRest(const Element& e, double l) {
  switch (e.kind) {
    case ElementKind::kActuator: return e.model->Evaluate(l, 0.0, 1.0).total;
    case ElementKind::kSpring: return e.stiffness * (l - e.rest_length);
    case ElementKind::kTendon: {
      const double stretch =
          e.pushes_below_slack ? l - e.slack_length : std::max(l - e.slack_length, 0.0);
      return e.exponential() ? e.k * (std::exp(e.alpha * stretch) - 1.0) : e.stiffness * stretch;
    }
    case ElementKind::kDamper: return 0.0;
  }
  return 0.0;
}

}  // namespace musclesim
