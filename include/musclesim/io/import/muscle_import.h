// Reading the muscles of another tool's model file (docs/guide/import.md): OpenSim's .osim
// (DeGrooteFregly2016Muscle; Millard2012EquilibriumMuscle and Thelen2003Muscle, converted to
// the nearest family, degroote2016) and MuJoCo's MJCF (<muscle>, and <general> with the
// muscle gain and bias), each into a musclesim model of the matching curve family
// (docs/model.md 14). What a file holds that musclesim does not take (another muscle class,
// the path's geometry, MuJoCo's clamps) is listed, never dropped silently.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/dynamics/activation_dynamics.h"
#include "musclesim/model/tension.h"

namespace musclesim {

// One muscle, as musclesim runs it.
struct ImportedMuscle {
  std::string name;                     // the muscle's name in the file
  std::string source;                   // its class or element and line: "DeGrooteFregly2016Muscle
                                        // (arm.osim:41)"
  ModelParams params;                   // the family's model, validated
  double tendon_slack_length = 0.0;     // [m] the tendon's slack length (rigid: taken off the
                                        // muscle-tendon length)
  std::optional<double> tendon_strain;  // [-] a compliant tendon's strain at the maximum
                                        // isometric force (De Groote's); none: rigid
  std::optional<ActivationDynamics> activation_dynamics;  // the tool's (family degroote2016
                                                          // or mujoco); none: the control is
                                                          // the activation
  std::vector<std::string> notes;  // what of this muscle was not carried over, one sentence each
  std::vector<std::string> conversion;  // a muscle of another family: how far each of its
                                        // curves moved, one sentence each
};

struct ImportedModel {
  std::string tool;                      // "OpenSim" or "MuJoCo"
  std::vector<ImportedMuscle> muscles;   // in file order
  std::vector<std::string> unsupported;  // actuators not imported, each with its line and why
};

// Reads `path`, an .osim file (its root element <OpenSimDocument>) or an MJCF file (root
// <mujoco>), told apart by content. Throws InputError naming path:line, the element, the
// attribute or property, the value and the rule broken; or when no muscle of a supported
// class is found (the message lists what was found instead).
ImportedModel ImportMuscles(const std::string& path);

}  // namespace musclesim
