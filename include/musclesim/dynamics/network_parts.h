// The parts of a network (docs/model.md section 7; in the plane or in space, section 12):
// nodes, the elements joining them and the loads on free nodes. Make them with the validating
// factories (Element::Spring("spring", "wall", "load", 50.0, 0.1)); NetworkSystem checks how
// they fit.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/core/coordinates.h"
#include "musclesim/dynamics/activation_dynamics.h"
#include "musclesim/dynamics/loads.h"
#include "musclesim/dynamics/waveform.h"
#include "musclesim/model/tension.h"

namespace musclesim {

// A point or vector of a network's space (Coordinates): a planar network's z is 0, a line's y
// and z are.

// The space a network lives in (docs/model.md 12): `dimensions` 1 (a line, section 7
// exactly), 2 (the x-y plane) or 3, and the acceleration of gravity on every free node's mass.
struct Space {
  int dimensions = 1;
  Coordinates gravity{};  // [m/s^2]; only the first `dimensions` entries may be nonzero,
                          // and none on a line (a hanging mass there is a `mass` load)
};

// Throws ParameterError ("dimensions", "gravity").
void Validate(const Space& space);

enum class NodeKind { kFixed, kPrescribed, kFree, kOnBody };
std::string_view ToString(NodeKind kind);

// A point of the network. Only the fields of its kind are used:
//   fixed:      position
//   prescribed: motion, a continuous waveform x(t) (its velocity is the waveform's slope)
//   free:       mass, and position and velocity at the start
//   on_body:    body, and position: the point in the body's frame (docs/model.md 15.1); it
//               moves with the body and the forces on it act on the body
// In 2 or 3 dimensions `position`, `velocity` and `motion` are the x coordinate's and the
// `_yz` fields hold y and z (z unused in 2).
struct Node {
  std::string name;
  NodeKind kind = NodeKind::kFree;
  double position = 0.0;                // fixed: x; free: x(t_start) [m]
  double velocity = 0.0;                // free: xdot(t_start) [m/s]
  double mass = 1.0;                    // free: [kg], > 0 (mass loads add to it)
  Waveform motion;                      // prescribed: x(t) [m]; constant, ramp, sine or table
  std::array<double, 2> position_yz{};  // fixed, free: y, z [m]
  std::array<double, 2> velocity_yz{};  // free: ydot, zdot at t_start [m/s]
  std::array<Waveform, 2> motion_yz;    // prescribed: y(t), z(t) [m]
  std::string body;                     // on_body: a body of the network's skeleton

  // (x, y, z) of the position and velocity fields.
  Coordinates PositionCoordinates() const { return {position, position_yz[0], position_yz[1]}; }
  Coordinates VelocityCoordinates() const { return {velocity, velocity_yz[0], velocity_yz[1]}; }

  static Node Fixed(std::string name, double position);
  static Node Prescribed(std::string name, Waveform motion);
  static Node Free(std::string name, double mass, double position, double velocity = 0.0);
  // In the plane or in space.
  static Node Fixed(std::string name, const Coordinates& position);
  static Node Prescribed(std::string name, std::array<Waveform, 3> motion);
  static Node Free(std::string name, double mass, const Coordinates& position,
                   const Coordinates& velocity = {});
  // A point fixed in a body of the skeleton, at `point` in the body's frame.
  static Node OnBody(std::string name, std::string body, const Coordinates& point);
};

// Throws ParameterError (paths as the YAML keys of a node: "mass", "position[1]",
// "prescribed.type") unless every coordinate is finite, a mass >= 0 and a motion continuous.
// A file's ranges (node_kinds.h) are its reader's: a program may build past them.
void Validate(const Node& node);

// A point an element's path passes through between its ends (docs/model.md 12.1): a node of
// the network (a free one carries the pulley's force), or fixed coordinates.
// Or, in a network with a skeleton, a wrap surface of it (docs/model.md 15.3), over which the
// path between the points before and after it wraps.
struct ViaPoint {
  std::string node;        // a node's name; empty: the fixed point `position` (or a wrap)
  Coordinates position{};  // [m]
  std::string wrap;        // a wrap surface's name; empty: none

  static ViaPoint Node(std::string name);
  static ViaPoint Fixed(const Coordinates& position);
  static ViaPoint Wrap(std::string surface);
};

enum class ElementKind { kActuator, kSpring, kTendon, kDamper };
std::string_view ToString(ElementKind kind);
ElementKind ParseElementKind(std::string_view text);  // ParameterError("type")

// A two-node element: length l = x_to - x_from, a tension T pulling its nodes together
// (+T on `from`, -T on `to`). In 2 or 3 dimensions its length is its path's, from `from`
// over its `via` points to `to`, and T acts along each segment (docs/model.md 12.2). Only the
// fields of its kind are used:
//   actuator: T(l, v, u) of the model, v = -dl/dt, u = activation(t); or, with activation
//             dynamics (`excitation` set, docs/model.md section 8), u a state of the ODE
//             driven by excitation->signal, and `activation` unused; or, `controlled`, u (or
//             with activation dynamics its excitation) a controller's output (section 11),
//             and `activation` and excitation->signal unused
//   spring:   T = stiffness (l - rest_length), negative when compressed
//   tendon:   T = stiffness (l - slack_length) above slack_length, else 0 (linear), or
//             T = k (exp(alpha (l - slack_length)) - 1) above it (exponential: k > 0), and
//             below it too when `pushes_below_slack` (De Groote's tendon, as OpenSim's
//             DeGrooteFregly2016Muscle has it: negative there, docs/model.md 14.1)
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
  double k = 0.0;                   // exponential tendon [N], > 0 (0: the tendon is linear)
  double alpha = 0.0;               // exponential tendon [1/m], > 0
  bool pushes_below_slack = false;  // exponential tendon: its law continues below slack
  double damping = 0.0;             // damper [N s/m], >= 0
  std::vector<ViaPoint> via;  // in 2 or 3 dimensions: the points between from and to, in order

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
  // De Groote et al. (2016)'s tendon, as OpenSim's DeGrooteFregly2016Muscle evaluates it:
  // T = F0 (0.2 exp(kT (l / l_s - 1)) - 0.2), kT = ln(6) / strain (F0 at l_s (1 + strain)),
  // on both sides of the slack length: the exponential tendon with k = 0.2 F0 and
  // alpha = kT / l_s, pushing below l_s.
  static Element DeGrooteTendon(std::string name, std::string from, std::string to,
                                double slack_length, double max_isometric_force,
                                double strain_at_one_norm_force);

  bool exponential() const { return kind == ElementKind::kTendon && k > 0.0; }
};

// Throws ParameterError (paths as the YAML keys of an element: "stiffness", "activation.to",
// "excitation.high", "activation_dynamics.tau_activation", "initial_activation").
void Validate(const Element& element);

// A load (dynamics/loads.h) on a free node. In 2 or 3 dimensions it acts along `direction`
// (made a unit vector): its x is the node's position along it, its force points along it.
struct NodeLoad {
  std::string node;
  Load load;
  Coordinates direction{1.0, 0.0, 0.0};  // [-], not zero
};

}  // namespace musclesim
