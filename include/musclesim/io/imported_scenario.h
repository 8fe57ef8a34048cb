// The scenario file `musclesim import` writes for one imported muscle (docs/guide/import.md):
// its model block, and an experiment to start from: the muscle-tendon unit on a line between
// a fixed end and a hanging mass of half its isometric force, released at rest at the
// muscle's optimal length and fully activated. The text reads back with LoadScenario.
#pragma once

#include <string>

#include "musclesim/io/muscle_import.h"

namespace musclesim {

// The `model:` block of a model of any curve family, two-space indented, each number the
// shortest text that reads back to it.
std::string FormatModelBlock(const ModelParams& params);

// The whole scenario; `source` names the imported file in its header, `output` its CSV.
// `model_block` replaces the muscle's own model block when given (--to-gaussians: the
// paper's model fitted to it, whose header says so), in the same experiment.
std::string FormatImportedScenario(const ImportedMuscle& muscle, const std::string& source,
                                   const std::string& output, const std::string& model_block = "");

// The actuator length at the muscle's optimal fiber length [m], along its line.
double OptimalLineLength(const ModelParams& params);
// The family's maximum shortening speed along the line [m/s] (DeGroote's v_max l_opt,
// MuJoCo's vmax L0, each seen through the pennation at the optimal length).
double MaxLineSpeed(const ModelParams& params);

}  // namespace musclesim
