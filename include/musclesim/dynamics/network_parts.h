// The parts of a network on a line (docs/model.md section 7): nodes, the elements joining
// them and the loads on free nodes. Make them with the validating factories
// (Element::Spring("spring", "wall", "load", 50.0, 0.1)); NetworkSystem checks how they fit.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "musclesim/dynamics/activation_dynamics.h"
#include "musclesim/dynamics/loads.h"
#include "musclesim/dynamics/waveform.h"
#include "musclesim/model/tension.h"

namespace musclesim {

enum class NodeKind { kFixed, kPrescribed, kFree };
std::string_view ToString(NodeKind kind);

// A point on the axis. Only the fields of its kind are used:
//   fixed:      position
//   prescribed: motion, a continuous waveform x(t) (its velocity is the waveform's slope)
//   free:       mass, and position and velocity at the start
struct Node {
  std::string name;
  NodeKind kind = NodeKind::kFree;
  double position = 0.0;  // fixed: x; free: x(t_start) [m]
  double velocity = 0.0;  // free: xdot(t_start) [m/s]
  double mass = 1.0;      // free: [kg], > 0 (mass loads add to it)
  Waveform motion;        // prescribed: x(t) [m]; constant, ramp, sine or table

  static Node Fixed(std::string name, double position);
  static Node Prescribed(std::string name, Waveform motion);
  static Node Free(std::string name, double mass, double position, double velocity = 0.0);
};

// Throws ParameterError (paths as the YAML keys of a node: "mass", "prescribed.type").
void Validate(const Node& node);

enum class ElementKind { kActuator, kSpring, kTendon, kDamper };
std::string_view ToString(ElementKind kind);
ElementKind ParseElementKind(std::string_view text);  // ParameterError("type")

// A two-node element: length l = x_to - x_from, a tension T pulling its nodes together
// (+T on `from`, -T on `to`). Only the fields of its kind are used:
//   actuator: T(l, v, u) of the model, v = -dl/dt, u = activation(t); or, with activation
//             dynamics (`excitation` set, docs/model.md section 8), u a state of the ODE
//             driven by excitation->signal, and `activation` unused; or, `controlled`, u (or
//             with activation dynamics its excitation) a controller's output (section 11),
//             and `activation` and excitation->signal unused
//   spring:   T = stiffness (l - rest_length), negative when compressed
//   tendon:   T = stiffness (l - slack_length) above slack_length, else 0 (linear), or
//             T = k (exp(alpha (l - slack_length)) - 1) above it (exponential: k > 0)
//   damper:   T = damping dl/dt
struct Element {
  std::string name;
  ElementKind kind = ElementKind::kSpring;
  std::string from, to;                       // node names
  std::shared_ptr<const TensionModel> model;  // actuator: its tension model
  Waveform activation;                        // actuator: u(t) in [0, 1]
  std::optional<ExcitationInput> excitation;  // actuator: set for activation dynamics
  bool controlled = false;                    // actuator: driven by a controller
  double stiffness = 0.0;                     // spring, linear tendon [N/m], >= 0
  double rest_length = 0.0;                   // spring [m]
  double slack_length = 0.0;                  // tendon [m]
  double k = 0.0;        // exponential tendon [N], > 0 (0: the tendon is linear)
  double alpha = 0.0;    // exponential tendon [1/m], > 0
  double damping = 0.0;  // damper [N s/m], >= 0

  static Element Actuator(std::string name, std::string from, std::string to,
                          std::shared_ptr<const TensionModel> model, Waveform activation);
  // An actuator with activation dynamics: its activation is a state driven by `excitation`.
  static Element Actuator(std::string name, std::string from, std::string to,
                          std::shared_ptr<const TensionModel> model, ExcitationInput excitation);
  // An actuator driven by a controller (docs/model.md 11): its activation, or with
  // `dynamics` its excitation (the activation then starting at `initial_activation`), is the
  // output of the controller that names it.
  static Element ControlledActuator(std::string name, std::string from, std::string to,
                                    std::shared_ptr<const TensionModel> model);
  static Element ControlledActuator(std::string name, std::string from, std::string to,
                                    std::shared_ptr<const TensionModel> model,
                                    ActivationDynamics dynamics, double initial_activation = 0.0);
  static Element Spring(std::string name, std::string from, std::string to, double stiffness,
                        double rest_length);
  static Element LinearTendon(std::string name, std::string from, std::string to,
                              double slack_length, double stiffness);
  static Element ExponentialTendon(std::string name, std::string from, std::string to,
                                   double slack_length, double k, double alpha);
  static Element Damper(std::string name, std::string from, std::string to, double damping);

  bool exponential() const { return kind == ElementKind::kTendon && k > 0.0; }
};

// Throws ParameterError (paths as the YAML keys of an element: "stiffness", "activation.to",
// "excitation.high", "activation_dynamics.tau_activation", "initial_activation").
void Validate(const Element& element);

// A load (dynamics/loads.h) on a free node.
struct NodeLoad {
  std::string node;
  Load load;
};

}  // namespace musclesim
