// The pieces multiple shooting is made of: the sensitivity parameters of an interval (its
// initial state's components and its two control values) and the closed-form effort of a
// linear control segment.
#pragma once

#include <vector>

#include "musclesim/dynamics/parameter_derivative.h"
#include "musclesim/optimize/optimal_control.h"
#include "musclesim/solver/sensitivity.h"

namespace musclesim {

// IPOPT's infinity: a bound beyond it is no bound.
constexpr double kNoBound = 1e20;

// A component of the interval's initial state: df/dp = 0, its initial sensitivity a unit
// vector (given with the parameter).
class InitialStateDerivative final : public ParameterDerivative {
 public:
  explicit InitialStateDerivative(int state_size) : state_size_(state_size) {}
  void RightHandSide(double t, const double* y, double* dfdp, NetworkScratch&) const override;
  void Elements(double, const double*, NetworkSystem::ElementPartials*,
                NetworkScratch&) const override {}
  bool analytic() const override { return true; }

 private:
  int state_size_;
};

// The control value at the start (or the end) of interval [t0, t1]: the actuator's activation
// is linear between the two, so du/dp is the hat (t1 - t) / (t1 - t0) (or (t - t0) / (t1 - t0))
// and df/dp is dT/du times it, acting as the tension does.
class ControlValueDerivative final : public ParameterDerivative {
 public:
  ControlValueDerivative(const NetworkSystem& system, int element, double t0, double t1,
                         bool at_end)
      : system_(system), element_(element), t0_(t0), t1_(t1), at_end_(at_end) {}
  void RightHandSide(double t, const double* y, double* dfdp, NetworkScratch&) const override;
  void Elements(double t, const double* y, NetworkSystem::ElementPartials* elements,
                NetworkScratch&) const override;
  bool analytic() const override { return true; }

 private:
  double Weight(double t) const;
  double TensionSlope(double t, const double* y) const;  // dT/du * du/dp
  const NetworkSystem& system_;
  int element_;
  double t0_, t1_;
  bool at_end_;
};

// The same for an actuator with activation dynamics, whose excitation e is the control: e
// enters only the activation's rate, so df/dp is d(udot)/de times the hat, in that state's row.
class ExcitationValueDerivative final : public ParameterDerivative {
 public:
  ExcitationValueDerivative(const NetworkSystem& system, int element, double t0, double t1,
                            bool at_end)
      : system_(system), element_(element), t0_(t0), t1_(t1), at_end_(at_end) {}
  void RightHandSide(double t, const double* y, double* dfdp, NetworkScratch&) const override;
  void Elements(double, const double*, NetworkSystem::ElementPartials*,
                NetworkScratch&) const override {}
  bool analytic() const override { return true; }

 private:
  const NetworkSystem& system_;
  int element_;
  double t0_, t1_;
  bool at_end_;
};

// The hat of a control value: 1 at its end of [t0, t1], 0 at the other, linear between.
double HatWeight(double t, double t0, double t1, bool at_end);

// integral over [0, 1] of u^q for u linear from a to b (a, b >= 0), and its derivatives.
struct Effort {
  double value, by_start, by_end;
};
Effort SegmentEffort(double a, double b, int power);

}  // namespace musclesim
