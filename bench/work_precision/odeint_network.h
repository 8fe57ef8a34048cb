// A network's right-hand side and analytic Jacobian as Odeint's N-state peer takes them
// (odeint_peer.h), for the work-precision and chain benchmarks.
#pragma once

#include <algorithm>
#include <vector>

#include "musclesim/dynamics/network.h"

namespace musclesim {

// The network's analytic Jacobian, by pattern entry, scattered into Odeint's dense row-major
// matrix.
struct OdeintNetwork {
  const NetworkSystem* system;
  std::vector<double> values;  // one per entry of the Jacobian's pattern

  static void Rhs(void* context, double t, const double* y, double* dydt) {
    static_cast<OdeintNetwork*>(context)->system->RightHandSide(t, y, dydt);
  }
  static void DenseJacobian(void* context, double t, const double* y, double* jacobian) {
    OdeintNetwork& network = *static_cast<OdeintNetwork*>(context);
    const JacobianPattern& pattern = network.system->jacobian_pattern();
    network.system->Jacobian(t, y, network.values.data());
    const int n = pattern.size;
    std::fill(jacobian, jacobian + n * n, 0.0);
    for (int column = 0; column < n; ++column) {
      for (int k = pattern.column_starts[column]; k < pattern.column_starts[column + 1]; ++k) {
        jacobian[pattern.rows[k] * n + column] = network.values[k];
      }
    }
  }
};

}  // namespace musclesim
