// df/dp and dT/dp of a spring's, tendon's or damper's parameter in closed form: each tension is
// a short expression of its length, rate and parameters (docs/model.md section 7). Evaluated on
// the base system's side of a tendon's slack length, where the integrator restarts, so no
// difference quotient smears the kink.
#include <algorithm>
#include <cmath>

#include "musclesim/dynamics/element_laws.h"
#include "musclesim/dynamics/parameter_derivative.h"

namespace musclesim {

namespace {

class ElementDerivative final : public ParameterDerivative {
 public:
  ElementDerivative(const NetworkSystem& system, int element, ElementPartial parameter)
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
    if (parameter_ == ElementPartial::kDamping) return system_.LengtheningRate(element_, t, y);
    if (e.kind == ElementKind::kSpring) {
      return parameter_ == ElementPartial::kStiffness ? l - e.rest_length : -e.stiffness;
    }
    const double stretch = l - e.slack_length;
    if (stretch <= 0.0 && !e.pushes_below_slack) return 0.0;  // slack: no tension at all
    if (!e.exponential()) {
      return parameter_ == ElementPartial::kStiffness ? stretch : -e.stiffness;
    }
    const double grow = std::exp(e.alpha * stretch);
    switch (parameter_) {
      case ElementPartial::kScale: return grow - 1.0;
      case ElementPartial::kRate: return e.k * stretch * grow;
      default: return -e.k * e.alpha * grow;  // the slack length
    }
  }

  const NetworkSystem& system_;
  int element_;
  ElementPartial parameter_;
};

}  // namespace

std::unique_ptr<ParameterDerivative> ElementParameterDerivative(const NetworkSystem& system,
                                                                int element,
                                                                const std::string& path) {
  // the field's tag, if its law gives it one (De Groote's tendon gives none: its rate
  // follows its slack length, which the closed form at fixed alpha leaves out)
  const ElementLaw* law = LawOf(system.elements().at(static_cast<std::size_t>(element)));
  const ElementField* field = law == nullptr ? nullptr : FindField(*law, path);
  if (field != nullptr && field->partial >= 0) {
    return std::make_unique<ElementDerivative>(system, element,
                                               static_cast<ElementPartial>(field->partial));
  }
  return nullptr;
}

}  // namespace musclesim
