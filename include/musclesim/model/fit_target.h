// The least-squares cost of a sum of Gaussians against a target (docs/model.md section 3.1),
// in closed form, with its gradient in every amplitude, precision b_k and centre.
//
// With unit-amplitude components phi_k (so psi_k = a_k phi_k) every target gives
//   N(a, b, d) = a^T G(b, d) a - 2 a^T r(b, d) + c,
// G the Gram matrix of the phi_k, r their products with the target, c the target's norm:
//   indicator / polygon: continuous L2 over the real line (G_ij and erf terms);
//   samples:             the discrete sum over measured points;
//   preset:              continuous L2 against a standard curve scaled to l_opt (G in
//                        closed form, r by Gauss-Legendre between the curve's breaks).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "musclesim/core/enum_names.h"
#include "musclesim/model/force_length_presets.h"

namespace musclesim {

enum class FitTargetKind { kIndicator, kPolygon, kSamples, kPreset };
// The targets' names, as a fit block's `target` gives them.
inline constexpr EnumName<FitTargetKind> kFitTargetNames[] = {
    {FitTargetKind::kIndicator, "indicator"},
    {FitTargetKind::kPolygon, "polygon"},
    {FitTargetKind::kSamples, "samples"},
    {FitTargetKind::kPreset, "preset"},
};

std::string_view ToString(FitTargetKind kind);
// Throws ParameterError("target", text, ...) for an unknown name.
FitTargetKind ParseFitTargetKind(std::string_view text);

struct TargetPoint {
  double x = 0.0;  // length [m]
  double y = 0.0;  // target value on the f_L scale [-]
};

// Shapes of m components.
struct GaussianShapes {
  Eigen::VectorXd precisions;  // b_k, inverse-variance factors [1/m^2 when sigma = 1], > 0
  Eigen::VectorXd centers;     // d_k [m]
};

// Gradient of the cost N in all parameters. N is in [m] for the continuous targets (the
// integral over length of a dimensionless square) and [-] for samples: "[N]" below.
struct CostGradient {
  Eigen::VectorXd amplitudes;  // dN/da_k [N]
  Eigen::VectorXd precisions;  // dN/db_k [N m^2 when sigma = 1]
  Eigen::VectorXd centers;     // dN/dd_k [N/m]
};

class FitTarget {
 public:
  virtual ~FitTarget() = default;

  // The normal equations at the given shapes: G (m x m) and r (m), resized here.
  virtual void NormalEquations(const GaussianShapes& shapes, Eigen::MatrixXd& gram,
                               Eigen::VectorXd& projection) const = 0;
  // N(a, b, d), and its gradient when `gradient` is not null.
  virtual double Cost(const Eigen::VectorXd& amplitudes, const GaussianShapes& shapes,
                      CostGradient* gradient) const = 0;
  // c: the integral of target^2 (continuous) or the sum of y_i^2 (samples).
  virtual double NormSquared() const = 0;
  // The interval of lengths where the target lives, used to place starting points.
  virtual double SupportMin() const = 0;
  virtual double SupportMax() const = 0;
};

// The piecewise-linear target through `vertices` (sorted by x), zero outside them: a
// polygon, or the indicator of [l1, l2] as the polygon (l1, 1), (l2, 1).
std::unique_ptr<FitTarget> MakePiecewiseLinearTarget(std::vector<TargetPoint> vertices,
                                                     double sigma);
// Discrete least squares on measured samples.
std::unique_ptr<FitTarget> MakeSampleTarget(std::vector<TargetPoint> samples, double sigma);
// The standard curve `preset` scaled to the optimal length l_opt [m] (> 0): the target is
// EvaluatePreset(preset, x / l_opt), zero outside the preset's support times l_opt.
std::unique_ptr<FitTarget> MakePresetTarget(ForceLengthPreset preset, double optimal_length,
                                            double sigma);

}  // namespace musclesim
