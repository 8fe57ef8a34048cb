// One evaluation of a tension model: the tension split into its parts, with the derivatives
// the simulator's analytic Jacobian uses.
#pragma once

namespace musclesim {

// Tension at one state, split into its parts, with derivatives.
struct TensionSample {
  double passive = 0.0;       // T_p [N]
  double active = 0.0;        // T_a [N]
  double total = 0.0;         // T [N]
  double d_length = 0.0;      // dT/dx [N/m]
  double d_velocity = 0.0;    // dT/dv, v the shortening velocity [N s/m]
  double d_activation = 0.0;  // dT/du [N]
};

}  // namespace musclesim
