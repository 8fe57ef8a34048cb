// What a run with forward sensitivities (docs/model.md section 10, CVODES) needs beyond a plain
// run: the parameters' partial derivatives, their initial sensitivities and scales, and a sink
// that receives each row's state with its sensitivities.
#pragma once

#include <vector>

#include "musclesim/dynamics/parameter_derivative.h"

namespace musclesim {

// One parameter p of a run.
struct SensitivityParameter {
  const ParameterDerivative* derivative = nullptr;  // df/dp and dT/dp; not null
  std::vector<double> initial;                      // dy(t_start)/dp, state_size values
  double scale = 1.0;  // |p|, or 1 when p is 0: CVODES scales the sensitivity's
                       // absolute tolerance by it (pbar, CVodeSetSensParams)
};

// Receives each recorded row: the state y and the sensitivities s[0..k-1] (each state_size
// values), valid only during the call.
class SensitivitySink {
 public:
  virtual ~SensitivitySink() = default;
  virtual void Record(double t, const double* y, const double* const* s) = 0;
};

}  // namespace musclesim
