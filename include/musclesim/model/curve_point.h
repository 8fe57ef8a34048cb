// A curve's value together with its first derivative, the unit every model function returns.
#pragma once

namespace musclesim {

struct CurvePoint {
  double value = 0.0;  // the function's value [its unit: N for tensions, - for factors]
  double slope = 0.0;  // its first derivative in the argument [value's unit / argument's]
};

}  // namespace musclesim
