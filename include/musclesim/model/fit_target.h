// The least-squares cost of a sum of Gaussians against a target (docs/model.md section 3.1),
// in closed form, with its gradient in every amplitude, width and centre.
//
// With unit-amplitude components phi_k (so psi_k = a_k phi_k) every target gives
//   N(a, b, d) = a^T G(b, d) a - 2 a^T r(b, d) + c,
// G the Gram matrix of the phi_k, r their products with the target, c the target's norm:
//   indicator / polygon: continuous L2 over the real line (G_ij and erf terms);
//   samples:             the discrete sum over measured points.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace musclesim {

enum class FitTargetKind { kIndicator, kPolygon, kSamples };
std::string_view ToString(FitTargetKind kind);
// Throws ParameterError("target", text, ...) for an unknown name.
FitTargetKind ParseFitTargetKind(std::string_view text);

struct TargetPoint {
  double x = 0.0;  // length [m]
  double y = 0.0;  // target value (f_L scale, dimensionless)
};

// Shapes of m components: width factors b (> 0) and centres d.
struct GaussianShapes {
  Eigen::VectorXd widths;
  Eigen::VectorXd centers;
};

// Gradient of N in all parameters.
struct CostGradient {
  Eigen::VectorXd amplitudes;
  Eigen::VectorXd widths;
  Eigen::VectorXd centers;
};

class FitTarget {
 public:
  virtual ~FitTarget() = default;

  // The normal equations at the given shapes: G (m x m) and r (m), resized here.
  virtual void Normal(const GaussianShapes& shapes, Eigen::MatrixXd& gram,
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

}  // namespace musclesim
