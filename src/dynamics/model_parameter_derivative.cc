// df/dp and dT/dp of a tension model's parameter, in closed form (model/tension_parameter.h),
// through every actuator of a network that holds the model.
#include <algorithm>

#include "musclesim/dynamics/parameter_derivative.h"
#include "musclesim/model/tension_parameter.h"

namespace musclesim {

namespace {

class ModelDerivative final : public ParameterDerivative {
 public:
  ModelDerivative(const NetworkSystem& system, const TensionModel& model,
                  TensionParameter parameter)
      : system_(system), derivative_(model, parameter) {
    for (std::size_t e = 0; e < system.elements().size(); ++e) {
      const Element& element = system.elements()[e];
      if (element.kind == ElementKind::kActuator && element.model.get() == &model) {
        actuators_.push_back(static_cast<int>(e));
      }
    }
  }

  void RightHandSide(double t, const double* y, double* dfdp, NetworkScratch&) const override {
    std::fill(dfdp, dfdp + system_.state_size(), 0.0);
    for (int e : actuators_) system_.AddTension(e, t, y, Partial(e, t, y).total, dfdp);
  }

  void Elements(double t, const double* y, NetworkSystem::ElementPartials* elements,
                NetworkScratch&) const override {
    for (int e : actuators_) {
      const TensionPartials partial = Partial(e, t, y);
      elements[e] = {0.0, partial.total, partial.passive, partial.active};
    }
  }

  bool analytic() const override { return true; }

 private:
  TensionPartials Partial(int e, double t, const double* y) const {
    const double l = system_.Length(e, t, y);
    const double v = -system_.LengtheningRate(e, t, y);
    const int state = system_.ActivationStateIndex(e);
    const double u = state >= 0 ? y[state] : system_.elements()[e].activation.Evaluate(t);
    return derivative_(l, v, u);
  }

  const NetworkSystem& system_;
  TensionParameterDerivative derivative_;
  std::vector<int> actuators_;  // the elements holding the model
};

}  // namespace

std::unique_ptr<ParameterDerivative> ModelParameterDerivative(const NetworkSystem& system,
                                                              const TensionModel* model,
                                                              const std::string& path) {
  // the closed forms are the paper's curves' along the line; another family's parameters, or
  // a pennate fiber's, take the difference quotient (docs/model.md 10)
  if (model->params().family != CurveFamily::kPaper || model->params().pennation_angle != 0.0) {
    return nullptr;
  }
  const std::optional<TensionParameter> parameter = ParseTensionParameter(path);
  if (!parameter) return nullptr;
  return std::make_unique<ModelDerivative>(system, *model, *parameter);
}

}  // namespace musclesim
