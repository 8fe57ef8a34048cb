// The partial derivatives in one parameter p that forward sensitivity analysis needs
// (docs/model.md section 10): of a network's right-hand side, df/dp at fixed (t, y), and of
// its elements' lengths and tensions, dl/dp and dT/dp at fixed (t, y). The solver integrates
// s' = (df/dy) s + df/dp; the tensions' sensitivities are dT/dy s + dT/dp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "musclesim/dynamics/network.h"

namespace musclesim {

class ParameterDerivative {
 public:
  virtual ~ParameterDerivative() = default;
  // Each evaluation writes its working buffers into the caller's `scratch` (a difference
  // quotient's right-hand sides and observations; a closed form uses none).
  // df/dp at (t, y) into `dfdp` (state_size values, overwritten).
  virtual void RightHandSide(double t, const double* y, double* dfdp,
                             NetworkScratch& scratch) const = 0;
  // dl/dp and dT/dp at (t, y) of every element, into `elements` (one per element; overwritten,
  // or left as they are for an element it does not know).
  virtual void Elements(double t, const double* y, NetworkSystem::ElementPartials* elements,
                        NetworkScratch& scratch) const = 0;
  // d(node's velocity)/dp at fixed (t, y): nonzero only for a massless junction, whose
  // velocity solves a balance the parameter may move (the closed forms, which a network with a
  // junction does not use, return 0).
  virtual double NodeVelocity(double /*t*/, const double* /*y*/, int /*node*/,
                              NetworkScratch& /*scratch*/) const {
    return 0.0;
  }
  // Whether the derivatives are closed forms (else difference quotients).
  virtual bool analytic() const = 0;
  // Replaces rows of the sensitivity's rate `rate` = (df/dy) s + df/dp at (t, y), s the
  // sensitivity, by derivatives taken along s, where a parameter needs them (the default
  // replaces none).
  virtual void RefineRate(double /*t*/, const double* /*y*/, const double* /*s*/, double* /*rate*/,
                          NetworkScratch& /*scratch*/) const {}
};

// A difference quotient over the same network built at several values p + offset_i of p:
// df/dp = sum_i weight_i f_i(t, y), and the same for the tensions (a central quotient is
// {(p - h, -1/2h, -h), (p + h, 1/2h, h)}). The activation states' rows of the sensitivity's
// rate are taken along the sensitivity itself, sum_i weight_i f_i(t, y + offset_i s): the
// derivative of udot along the direction (s, 1) in (y, p), which stays on the kink e = u when
// the activation tracks its excitation, where udot has no derivative in p or u alone. (The
// mechanical rows stay at fixed y: along s a step offset_i s may be large next to the
// velocity curve's epsilon, and the quotient then inaccurate.)
class DifferenceQuotientDerivative final : public ParameterDerivative {
 public:
  struct Point {
    std::shared_ptr<const NetworkSystem> system;  // built at p + offset
    double weight;                                // [1/unit of p]
    double offset;                                // [unit of p]
  };
  using Stencil = std::vector<Point>;
  explicit DifferenceQuotientDerivative(Stencil stencil);
  void RightHandSide(double t, const double* y, double* dfdp,
                     NetworkScratch& scratch) const override;
  void Elements(double t, const double* y, NetworkSystem::ElementPartials* elements,
                NetworkScratch& scratch) const override;
  double NodeVelocity(double t, const double* y, int node, NetworkScratch& scratch) const override;
  bool analytic() const override { return false; }
  void RefineRate(double t, const double* y, const double* s, double* rate,
                  NetworkScratch& scratch) const override;

 private:
  Stencil stencil_;
  std::size_t states_ = 0;    // of every system
  std::size_t elements_ = 0;  // the fewest elements among the systems
};

// A parameter of the tension model `model` (`path` relative to its block, as
// "velocity.v_max"), in closed form through every actuator of `system` that holds that
// model; null when the path is no continuous parameter of a tension model. `system` and
// `model` must outlive the result.
std::unique_ptr<ParameterDerivative> ModelParameterDerivative(const NetworkSystem& system,
                                                              const TensionModel* model,
                                                              const std::string& path);

// A parameter of element `element` of `system` that is a spring's, a tendon's or a damper's
// (`path` relative to the element: "stiffness", "rest_length", "slack_length",
// "exponential.k", "exponential.alpha", "damping"), in closed form; null for any other.
// `system` must outlive the result.
std::unique_ptr<ParameterDerivative> ElementParameterDerivative(const NetworkSystem& system,
                                                                int element,
                                                                const std::string& path);

}  // namespace musclesim
