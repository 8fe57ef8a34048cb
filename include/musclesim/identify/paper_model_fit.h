// The paper's model fitted to another family's curves (`musclesim import --to-gaussians N`,
// docs/guide/import.md): the curves of the model sampled densely along its line and
// identified as measured curves are (identify.h): the passive exponential, a sum of N
// Gaussians for the active tension at rest, the power law in velocity (with its eccentric
// branch) at the optimal length. Each fit's RMSE says how far the paper's forms are from the
// family's.
#pragma once

#include "musclesim/identify/identify.h"
#include "musclesim/model/tension.h"

namespace musclesim {

struct PaperModelFit {
  PassiveIdentification passive;    // T_p at rest [N]
  ActiveIdentification active;      // f_iso f_L [N], N Gaussians
  VelocityIdentification velocity;  // f_iso g(v) at the optimal length [N]
};

// `count` Gaussians (1..20); the lengths sampled span 0.3 to 2 optimal lengths (along the
// line: `optimal_line_length` [m]), the passive curve up to where it reaches f_iso (at most
// 3 optimal lengths), the velocities +-0.9 `max_speed` [m/s] (the family's v_max along the
// line). Throws InputError when a curve cannot be identified.
PaperModelFit FitPaperModel(const TensionModel& model, int count, double optimal_line_length,
                            double max_speed);

}  // namespace musclesim
