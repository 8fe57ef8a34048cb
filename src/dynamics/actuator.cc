#include "musclesim/dynamics/actuator.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/dynamics/actuator_fields.h"

namespace musclesim {

namespace {

// docs/model.md 7.4. The elements' order (actuator, damper, spring) makes the network's sum
// of forces the same floating-point operations as Acceleration's, so both runs agree exactly.
NetworkSystem AsNetwork(const std::shared_ptr<const TensionModel>& model,
                        const ActuatorParams& actuator, const Waveform& activation,
                        const std::optional<ExcitationInput>& excitation,
                        const std::vector<Load>& loads) {
  std::vector<Node> nodes = {Node::Fixed("ground", 0.0),
                             Node::Free("tip", actuator.mass, 0.0)};  // state set by each run
  std::vector<Element> elements = {
      excitation ? Element::Actuator("actuator", "ground", "tip", model, *excitation)
                 : Element::Actuator("actuator", "ground", "tip", model, activation)};
  // a damper or spring of zero coefficient subtracts a signed zero from a force that is
  // never -0 (F - T is +0 at worst): leaving it out changes no bit and saves its evaluation
  if (actuator.damping != 0.0) {
    elements.push_back(Element::Damper("damper", "ground", "tip", actuator.damping));
  }
  if (actuator.stiffness != 0.0) {
    elements.push_back(
        Element::Spring("spring", "ground", "tip", actuator.stiffness, actuator.rest_length));
  }
  std::vector<NodeLoad> node_loads;
  for (const Load& load : loads) node_loads.push_back({"tip", load});
  return NetworkSystem(std::move(nodes), std::move(elements), std::move(node_loads));
}

// Validate(ExcitationInput) with the single-actuator scenario's key for the initial state.
const ExcitationInput& CheckedExcitation(const ExcitationInput& input) {
  try {
    Validate(input);
  } catch (const ParameterError& e) {
    if (e.path() != "initial_activation") throw;
    throw ParameterError("initial.activation", e.value(), e.rule());
  }
  return input;
}

}  // namespace

void Validate(const ActuatorParams& p) { ValidateFields(ActuatorBlock().front(), p); }

ActuatorSystem::ActuatorSystem(std::shared_ptr<const TensionModel> model,
                               const ActuatorParams& actuator, Waveform activation,
                               std::vector<Load> loads)
    : model_((assert(model != nullptr), std::move(model))),
      actuator_((Validate(actuator), actuator)),
      activation_((ValidateActivation(activation), std::move(activation))),
      loads_(std::move(loads)),
      inverse_mass_(1.0 / (actuator.mass + loads_.AddedMass())),
      network_(AsNetwork(model_, actuator_, activation_, excitation_, loads_.loads())) {}

ActuatorSystem::ActuatorSystem(const ModelParams& model, const ActuatorParams& actuator,
                               Waveform activation, std::vector<Load> loads)
    : ActuatorSystem(std::make_shared<const TensionModel>(model), actuator, std::move(activation),
                     std::move(loads)) {}

ActuatorSystem::ActuatorSystem(std::shared_ptr<const TensionModel> model,
                               const ActuatorParams& actuator, ExcitationInput excitation,
                               std::vector<Load> loads)
    : model_((assert(model != nullptr), std::move(model))),
      actuator_((Validate(actuator), actuator)),
      excitation_(CheckedExcitation(excitation)),
      loads_(std::move(loads)),
      inverse_mass_(1.0 / (actuator.mass + loads_.AddedMass())),
      network_(AsNetwork(model_, actuator_, activation_, excitation_, loads_.loads())) {}

ActuatorSystem::ActuatorSystem(const ModelParams& model, const ActuatorParams& actuator,
                               ExcitationInput excitation, std::vector<Load> loads)
    : ActuatorSystem(std::make_shared<const TensionModel>(model), actuator, std::move(excitation),
                     std::move(loads)) {}

ActuatorSample ActuatorSystem::Observe(double t, double x, double xdot) const {
  ActuatorSample s;
  s.length = x;
  s.shortening_velocity = 0.0 - xdot;  // +0 rather than -0 at rest
  s.activation = s.excitation = activation_.Evaluate(t);
  s.tension = model_->Evaluate(x, -xdot, s.activation);
  s.load = loads_.Force(t, x);
  return s;
}

ActuatorSample ActuatorSystem::Observe(double t, double x, double xdot, double u) const {
  assert(excitation_);
  ActuatorSample s;
  s.length = x;
  s.shortening_velocity = 0.0 - xdot;  // +0 rather than -0 at rest
  s.activation = u;
  s.excitation = excitation_->signal.Evaluate(t);
  s.tension = model_->Evaluate(x, -xdot, u);
  s.load = loads_.Force(t, x);
  return s;
}

std::vector<double> ActuatorSystem::Breakpoints(double t0, double t1) const {
  std::vector<double> times =
      excitation_ ? excitation_->signal.Breakpoints(t0, t1) : activation_.Breakpoints(t0, t1);
  const std::vector<double> load_times = loads_.Breakpoints(t0, t1);
  times.insert(times.end(), load_times.begin(), load_times.end());
  SortUnique(times);
  return times;
}

}  // namespace musclesim
