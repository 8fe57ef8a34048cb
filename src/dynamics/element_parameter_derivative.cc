// df/dp and dT/dp of a spring's, tendon's or damper's parameter in closed form: each tension is
// a short expression of its length, rate and parameters (docs/model.md section 7). Evaluated on
// the base system's side of a tendon's slack length, where the integrator restarts, so no
// difference quotient smears the kink.
#include <algorithm>
#include <cmath>

#include "musclesim/dynamics/parameter_derivative.h"

namespace musclesim {

namespace {

enum class ElementParameter { kStiffness, kRestLength, kSlackLength, kScale, kRate, kDamping };

class ElementDerivative final : public ParameterDerivative {
 public:
  ElementDerivative(const NetworkSystem& system, int element, ElementParameter parameter)
      : system_(system), element_(element), parameter_(parameter) {}

  void RightHandSide(double t, const double* y, double* dfdp, NetworkScratch&) const override {
    std::fill(dfdp, dfdp + system_.state_size(), 0.0);
    system_.AddTension(element_, t, y, Partial(t, y), dfdp);
  }

  void Elements(double t, const double* y, NetworkSystem::ElementPartials* elements,
                NetworkScratch&) const override {
    elements[element_] = {0.0, Partial(t, y), 0.0, 0.0};
  }

  bool analytic() const override { return true; }

 private:
  // dT/dp at (t, y)
  double Partial(double t, const double* y) const {
    const Element& e = system_.elements()[static_cast<std::size_t>(element_)];
    const double l = system_.Length(element_, t, y);
    if (parameter_ == ElementParameter::kDamping) return system_.LengtheningRate(element_, t, y);
    if (e.kind == ElementKind::kSpring) {
      return parameter_ == ElementParameter::kStiffness ? l - e.rest_length : -e.stiffness;
    }
    const double stretch = l - e.slack_length;
    if (stretch <= 0.0 && !e.pushes_below_slack) return 0.0;  // slack: no tension at all
    if (!e.exponential()) {
      return parameter_ == ElementParameter::kStiffness ? stretch : -e.stiffness;
    }
    const double grow = std::exp(e.alpha * stretch);
    switch (parameter_) {
      case ElementParameter::kScale: return grow - 1.0;
      case ElementParameter::kRate: return e.k * stretch * grow;
      default: return -e.k * e.alpha * grow;  // the slack length
    }
  }

  const NetworkSystem& system_;
  int element_;
  ElementParameter parameter_;
};

}  // namespace

std::unique_ptr<ParameterDerivative> ElementParameterDerivative(const NetworkSystem& system,
                                                                int element,
                                                                const std::string& path) {
  const Element& e = system.elements().at(static_cast<std::size_t>(element));
  const auto make = [&](ElementParameter p) {
    return std::make_unique<ElementDerivative>(system, element, p);
  };
  switch (e.kind) {
    case ElementKind::kSpring:
      if (path == "stiffness") return make(ElementParameter::kStiffness);
      if (path == "rest_length") return make(ElementParameter::kRestLength);
      break;
    case ElementKind::kTendon:
      // De Groote's tendon: its rate follows its slack length (alpha = ln 6 / (strain l_s)),
      // which the closed form at fixed alpha leaves out: a difference quotient
      if (e.pushes_below_slack) break;
      if (path == "slack_length") return make(ElementParameter::kSlackLength);
      if (!e.exponential() && path == "stiffness") return make(ElementParameter::kStiffness);
      if (e.exponential() && path == "exponential.k") return make(ElementParameter::kScale);
      if (e.exponential() && path == "exponential.alpha") return make(ElementParameter::kRate);
      break;
    case ElementKind::kDamper:
      if (path == "damping") return make(ElementParameter::kDamping);
      break;
    case ElementKind::kActuator: break;
  }
  return nullptr;
}

}  // namespace musclesim
