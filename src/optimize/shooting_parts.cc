#include "optimize/shooting_parts.h"

#include <algorithm>
#include <cmath>

namespace musclesim {

void InitialStateDerivative::RightHandSide(double, const double*, double* dfdp,
                                           NetworkScratch&) const {
  std::fill(dfdp, dfdp + state_size_, 0.0);
}

double HatWeight(double t, double t0, double t1, bool at_end) {
  const double rising = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
  return at_end ? rising : 1.0 - rising;
}

double ControlValueDerivative::Weight(double t) const { return HatWeight(t, t0_, t1_, at_end_); }

void ExcitationValueDerivative::RightHandSide(double t, const double* y, double* dfdp,
                                              NetworkScratch&) const {
  std::fill(dfdp, dfdp + system_.state_size(), 0.0);
  const int state = system_.ActivationStateIndex(element_);
  const ExcitationInput& input = *system_.elements()[static_cast<std::size_t>(element_)].excitation;
  const double e = input.signal.Evaluate(t);  // no controller drives a control
  dfdp[state] = EvaluateActivationRate(input.dynamics, e, y[state]).by_excitation *
                HatWeight(t, t0_, t1_, at_end_);
}

double ControlValueDerivative::TensionSlope(double t, const double* y) const {
  ElementSample sample;
  system_.ObserveElement(element_, t, y, sample);
  return sample.parts.d_activation * Weight(t);
}

void ControlValueDerivative::RightHandSide(double t, const double* y, double* dfdp,
                                           NetworkScratch&) const {
  std::fill(dfdp, dfdp + system_.state_size(), 0.0);
  system_.AddTension(element_, t, y, TensionSlope(t, y), dfdp);
}

void ControlValueDerivative::Elements(double t, const double* y,
                                      NetworkSystem::ElementPartials* elements,
                                      NetworkScratch&) const {
  const double slope = TensionSlope(t, y);
  elements[element_] = {0.0, slope, 0.0, slope};
}

Effort SegmentEffort(double a, double b, int power) {
  if (power == 2) {
    return {(a * a + a * b + b * b) / 3.0, (2.0 * a + b) / 3.0, (a + 2.0 * b) / 3.0};
  }
  // q = 3, a and b within [0, 1]
  return {(a * a * a + a * a * b + a * b * b + b * b * b) / 4.0,
          (3.0 * a * a + 2.0 * a * b + b * b) / 4.0, (a * a + 2.0 * a * b + 3.0 * b * b) / 4.0};
}

}  // namespace musclesim
