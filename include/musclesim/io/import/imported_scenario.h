// The scenario file `musclesim import` writes for one imported muscle (docs/guide/import.md):
// its model block, and an experiment to start from: the muscle-tendon unit on a line between
// a fixed end and a hanging mass of half its isometric force, released at rest at the
// muscle's optimal length and fully activated. The text reads back with LoadScenario.
#pragma once

#include <string>

#include "musclesim/io/import/muscle_import.h"

namespace musclesim {

// The `model:` block of a model of any curve family, two-space indented, each number the
// shortest text that reads back to it.
std::string FormatModelBlock(const ModelParams& params);

// The whole scenario; `source` names the imported file in its header, `output` its CSV.
// `model_block` replaces the muscle's own model block when given (--to-gaussians: the
// paper's model fitted to it, whose header says so), in the same experiment. A muscle with a
// compliant tendon is a network: the fiber from a fixed origin to a massless junction, the
// tendon from there to the hanging body (with `model_block`, whose paper model cannot hold a
// massless junction, the tendon is taken rigid and the header says so).
std::string FormatImportedScenario(const ImportedMuscle& muscle, const std::string& source,
                                   const std::string& output, const std::string& model_block = "");

// The fiber damping [-] a compliant muscle's scenario gives a fiber whose file has none: the
// massless junction needs a rate term at zero activation (docs/model.md 14.4); it moves
// OpenSim's trajectories by about 7 times this, relative (tests/scenario/
// opensim_reference_test.cc).
inline constexpr double kJunctionFiberDamping = 1e-8;

// Said on standard error and in the header when a compliant muscle's scenario gives its fiber
// kJunctionFiberDamping (its own damping is below it); and when --to-gaussians takes its
// tendon rigid.
std::string JunctionDampingNote(const ImportedMuscle& muscle);
std::string RigidTendonNote(const ImportedMuscle& muscle);

// The actuator length at the muscle's optimal fiber length [m], along its line.
double OptimalLineLength(const ModelParams& params);
// The family's maximum shortening speed along the line [m/s] (DeGroote's v_max l_opt,
// MuJoCo's vmax L0, each seen through the pennation at the optimal length).
double MaxLineSpeed(const ModelParams& params);

}  // namespace musclesim
