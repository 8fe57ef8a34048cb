// What a network observes at one instant (docs/model.md 7 and 12): the nodes' positions,
// velocities and loads, each element's length, rate and tension, each controller's signals.
// A network's CSV records these; NetworkSystem::Observe fills them.
#pragma once

#include <vector>

#include "musclesim/model/tension_sample.h"

namespace musclesim {

// What one element observes at one instant.
struct ElementSample {
  double length = 0.0;            // l = x_to - x_from [m]
  double lengthening_rate = 0.0;  // dl/dt [m/s]
  double tension = 0.0;           // T [N]
  double activation = 0.0;        // actuator: u [-], the state's with activation dynamics,
                                  // else u(t); other kinds 0
  double excitation = 0.0;        // actuator with activation dynamics: e(t) [-]; an actuator
                                  // without them: u(t) (e = u); other kinds 0
  TensionSample parts;            // actuator: T split into parts, with derivatives
};

// What one controller computes at one instant.
struct ControllerSample {
  double reference = 0.0;  // r(t) [unit measured]
  double measured = 0.0;   // y [unit measured]
  double error = 0.0;      // r - y
  double output = 0.0;     // driving one actuator: the activation or excitation it applies,
                           // clamped to [0, 1]; a co-contracting pair: the command c
};

// Everything the state observes at one instant: what a network's CSV records.
// In d dimensions the nodes' vectors hold d numbers per node, node after node (x, y of node 0,
// x, y of node 1, ...).
struct NetworkSample {
  std::vector<double> position;  // of every node [m]
  std::vector<double> velocity;  // of every node [m/s]
  std::vector<double> load;      // the sum of the loads on every node [N] (0 off free nodes;
                                 // gravity not included)
  std::vector<ElementSample> elements;
  std::vector<ControllerSample> controllers;
  // with a skeleton (docs/model.md 15): each coordinate's value q [rad or m] and speed u,
  // and each element's moment arm about each coordinate, r_k = -dl/dq_k [m, or - for a
  // sliding coordinate], element-major
  std::vector<double> coordinates, speeds, moment_arms;
};

}  // namespace musclesim
