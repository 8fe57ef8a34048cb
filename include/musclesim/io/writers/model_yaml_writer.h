// Writing a `model:` block (docs/guide/model.md) that LoadModelSpec reads back to the
// same parameters, with comments beside each part: how `musclesim identify` reports what the
// data determined and what it could not.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "musclesim/model/tension.h"

namespace musclesim {

// One part of the block: its parameters when the data determined them, or nullopt for the
// part's stand-in from StandInModelParams(); and the comments to write with it.
template <typename Params>
struct ModelYamlPart {
  std::optional<Params> params;       // units as in Params ([N] for f_iso)
  std::vector<std::string> comments;  // one line each [-], without the leading "# "
};

// The block to write. Known parameters carry 17 significant digits; a stand-in is written
// short (1.0, 1.0e-6). Comments go where they read best: f_iso's and a stand-in's on the
// value's line (joined by "; "), a known passive or velocity part's on lines below it,
// active_length's on lines above its optimal_range.
struct ModelYamlDraft {
  std::vector<std::string> header;                  // comment lines above `model:` [-]
  ModelYamlPart<double> f_iso;                      // [N]
  ModelYamlPart<PassiveParams> passive;             // units as in PassiveParams
  ModelYamlPart<ActiveLengthParams> active_length;  // as in ActiveLengthParams; sigma
                                                    // written only when not 1
  std::vector<std::string> gaussian_comments;       // none, or one per known component [-]
  ModelYamlPart<VelocityParams> velocity;           // units as in VelocityParams
};

// The draft as YAML text, every line ending in '\n'. Throws std::invalid_argument when
// gaussian_comments is neither empty nor one per known component.
std::string FormatModelYaml(const ModelYamlDraft& draft);

// One component as a flow map, "{amplitude: A, width: B, center: D}", 17 significant digits:
// an item of a `gaussians:` list.
std::string FormatGaussianYaml(const Gaussian& gaussian);

// What is written for a part no data determined: valid and neutral, so that the model loads
// and its other parts act alone. f_iso 1 N; no passive tension (k_p = 0); a flat f_L (one
// Gaussian a kilometre wide on L_opt = [-1, 1] m); g close to 1 (v_max = 1e6 m/s, n = 1,
// epsilon = 1 m/s).
ModelParams StandInModelParams();

// epsilon [m/s] for an identified v_max [m/s]: tension-velocity data cannot determine the
// regularisation width, so it is set to 1e-3 v_max, small against the velocities measured.
double StandInEpsilon(double v_max);

}  // namespace musclesim
