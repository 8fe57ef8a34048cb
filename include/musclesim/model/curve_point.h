// A curve's value together with its first derivative, the unit every model function returns.
#pragma once

namespace musclesim {

struct CurvePoint {
  double value = 0.0;  // the function's value
  double slope = 0.0;  // its first derivative in the function's argument
};

}  // namespace musclesim
