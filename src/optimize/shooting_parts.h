// The pieces multiple shooting is made of: the sensitivity parameters of an interval (its
// initial state's components and its two control values), the sink that keeps the interval's
// end, the closed-form effort of a linear control segment and the problem's checks.
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
  void RightHandSide(double t, const double* y, double* dfdp) const override;
  void Elements(double, const double*, NetworkSystem::ElementPartials*) const override {}
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
  void RightHandSide(double t, const double* y, double* dfdp) const override;
  void Elements(double t, const double* y, NetworkSystem::ElementPartials* elements) const override;
  bool analytic() const override { return true; }

 private:
  double Weight(double t) const;
  double TensionSlope(double t, const double* y) const;  // dT/du * du/dp
  const NetworkSystem& system_;
  int element_;
  double t0_, t1_;
  bool at_end_;
};

// Keeps the one row an interval records, its end: the state and the sensitivities.
class IntervalEnd final : public SensitivitySink {
 public:
  IntervalEnd(int state_size, int parameters) : n_(state_size), parameters_(parameters) {}
  void Record(double t, const double* y, const double* const* s) override;
  bool recorded() const { return recorded_; }
  const std::vector<double>& state() const { return state_; }
  // column-major: parameter p's sensitivity in entries [p n, (p + 1) n)
  const std::vector<double>& sensitivities() const { return sensitivities_; }

 private:
  int n_, parameters_;
  bool recorded_ = false;
  std::vector<double> state_, sensitivities_;
};

// integral over [0, 1] of u^q for u linear from a to b (a, b >= 0), and its derivatives.
struct Effort {
  double value, by_start, by_end;
};
Effort SegmentEffort(double a, double b, int power);

// Checks `problem` (InputError naming the entry and the rule) and returns its system, each
// control's actuator element and each final value's state index.
NetworkSystem CheckProblem(const OptimalControlProblem& problem, std::vector<int>& elements,
                           std::vector<int>& final_states);

}  // namespace musclesim
