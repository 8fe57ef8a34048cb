// Fitting a sum of Gaussians to a target by variable projection (docs/model.md section 3.2):
// amplitudes from the linear least-squares solve (optionally non-negative), precisions and
// centres by a gradient-based minimiser (NLopt's L-BFGS) of the reduced cost, from a
// fixed, deterministic set of well-spread starting points; the best result is kept.
#pragma once

#include <optional>
#include <vector>

#include "musclesim/model/active_length.h"
#include "musclesim/model/fit_target.h"

namespace musclesim {

struct FitSpec {
  int count = 2;                                     // number of Gaussians m [-], 1..12
  FitTargetKind target = FitTargetKind::kIndicator;  // what the sum approximates
  std::vector<TargetPoint> points;  // polygon vertices or samples ([m], [-]; x strictly
                                    // increasing for a polygon)
  bool nonnegative = false;         // keep every amplitude >= 0
  // When both are given (count entries each), the shapes are held fixed and only the
  // amplitudes are solved for: the paper's linear case.
  std::vector<double> precisions;  // b_k [1/m^2 when sigma = 1], > 0; YAML key `widths`
  std::vector<double> centers;     // d_k [m]
  // Target preset only, and then both required: the standard curve (YAML key `name`) and the
  // optimal length it is scaled to.
  std::optional<ForceLengthPreset> preset;
  std::optional<double> optimal_length;  // l_opt [m], finite and > 0
};

// Throws ParameterError ("count", "points", "points[i]", "widths[k]", "name",
// "optimal_length", ...), naming each field by its YAML key.
void Validate(const FitSpec& spec);

struct FitResult {
  std::vector<Gaussian> gaussians;  // the fitted components (a_k, b_k, d_k)
  double cost = 0.0;                // N at the result [m] (continuous targets) or [-] (samples)
  double relative_residual = 0.0;   // N / integral(target^2) (or / sum y^2) [-]
  int iterations = 0;               // cost evaluations of the winning start (0: shapes fixed)
  int starts = 0;                   // starting points tried
};

// The target that `spec` describes, with L_opt = [l1, l2] for the indicator (the other
// targets ignore l1 and l2).
std::unique_ptr<FitTarget> MakeFitTarget(const FitSpec& spec, double l1, double l2, double sigma);

// Validates `spec` (ParameterError) and fits. Deterministic: the same input gives the
// same result bit for bit.
FitResult FitGaussians(const FitSpec& spec, double l1, double l2, double sigma);

// Amplitudes minimising a^T G a - 2 a^T r: the minimum-norm least-squares solution, or with
// `nonnegative` the Lawson-Hanson active-set solution under a >= 0.
Eigen::VectorXd SolveAmplitudes(const Eigen::MatrixXd& gram, const Eigen::VectorXd& projection,
                                bool nonnegative);

}  // namespace musclesim
