#include "musclesim/model/fit_target.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "musclesim/model/active_length.h"
#include "musclesim/core/enum_names.h"
#include "musclesim/model/force_length_presets.h"

namespace musclesim {

std::string_view ToString(FitTargetKind kind) { return ToString(kFitTargetNames, kind); }

FitTargetKind ParseFitTargetKind(std::string_view text) {
  return Parse(kFitTargetNames, "target", text);
}

namespace {

constexpr double kInvSqrt2Pi = 0.398942280401432677939946059934;  // 1 / sqrt(2 pi)

// Standard normal probability between z1 < z2, computed on the tail side where both
// points lie in one tail, so that far-out pieces keep their relative precision.
double NormalMass(double z1, double z2) {
  constexpr double kInvSqrt2 = 0.707106781186547524400844362105;
  if (z1 > 0.0) return 0.5 * (std::erfc(z1 * kInvSqrt2) - std::erfc(z2 * kInvSqrt2));
  if (z2 < 0.0) return 0.5 * (std::erfc(-z2 * kInvSqrt2) - std::erfc(-z1 * kInvSqrt2));
  return 0.5 * (std::erf(z2 * kInvSqrt2) - std::erf(z1 * kInvSqrt2));
}

// integral over [x1, x2] of phi(x) * (y1 + slope (x - x1)), phi the unit-amplitude
// Gaussian of precision b and centre d, with its derivatives in b and d.
struct PieceIntegral {
  double value, d_precision, d_center;
};

PieceIntegral IntegratePiece(double x1, double x2, double y1, double slope, double b, double d,
                             double sigma) {
  const double spread = std::sqrt(sigma / b);  // standard deviation s
  const double z1 = (x1 - d) / spread;
  const double z2 = (x2 - d) / spread;
  const double n1 = kInvSqrt2Pi * std::exp(-0.5 * z1 * z1);
  const double n2 = kInvSqrt2Pi * std::exp(-0.5 * z2 * z2);
  const double mass = NormalMass(z1, z2);
  const double at_center = y1 + slope * (d - x1);  // the linear piece evaluated at d
  const double inv_sqrt_b = 1.0 / std::sqrt(b);

  // with x = d + s z: integral = (1/sqrt b) [ at_center * mass + slope * s * (n1 - n2) ]
  const double inner = at_center * mass + slope * spread * (n1 - n2);
  const double value = inv_sqrt_b * inner;
  const double d_center =
      inv_sqrt_b * (slope * mass - at_center * (n2 - n1) / spread + slope * (z1 * n1 - z2 * n2));
  // dz/db = z / (2b), ds/db = -s / (2b)
  const double d_inner =
      (at_center * (z2 * n2 - z1 * n1) + slope * spread * (n2 - n1 + z2 * z2 * n2 - z1 * z1 * n1)) /
      (2.0 * b);
  const double d_precision = -value / (2.0 * b) + inv_sqrt_b * d_inner;
  return {value, d_precision, d_center};
}

// The targets integrated over the real line: G in closed form, r_k (with its derivatives)
// from each target's Project, c from its NormSquared.
class ContinuousTarget : public FitTarget {
 public:
  explicit ContinuousTarget(double sigma) : sigma_(sigma) {}

  void NormalEquations(const GaussianShapes& shapes, Eigen::MatrixXd& gram,
                       Eigen::VectorXd& projection) const override {
    const Eigen::Index m = shapes.precisions.size();
    gram.resize(m, m);
    projection.resize(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      for (Eigen::Index j = 0; j <= i; ++j) {
        gram(i, j) = gram(j, i) = GramEntry(shapes, i, j);
      }
      projection(i) = Project(shapes.precisions(i), shapes.centers(i)).value;
    }
  }

  double Cost(const Eigen::VectorXd& a, const GaussianShapes& shapes,
              CostGradient* gradient) const override {
    Eigen::MatrixXd gram;
    Eigen::VectorXd projection;
    NormalEquations(shapes, gram, projection);
    const Eigen::VectorXd gram_a = gram * a;
    const double cost = a.dot(gram_a) - 2.0 * a.dot(projection) + NormSquared();
    if (gradient != nullptr) FillGradient(a, shapes, gram, gram_a, projection, *gradient);
    return cost;
  }

 protected:
  // r_k = integral of phi_k times the target, and its derivatives in b_k and d_k.
  virtual PieceIntegral Project(double b, double d) const = 0;

  double sigma_;

 private:
  // G_ij = exp(-b_i b_j (d_i - d_j)^2 / (2 sigma B)) / sqrt(2 pi sigma B), B = b_i + b_j
  double GramEntry(const GaussianShapes& shapes, Eigen::Index i, Eigen::Index j) const {
    const double bi = shapes.precisions(i), bj = shapes.precisions(j);
    const double sum = bi + bj;
    const double gap = shapes.centers(i) - shapes.centers(j);
    return std::exp(-bi * bj * gap * gap / (2.0 * sigma_ * sum)) /
           std::sqrt(2.0 * std::numbers::pi * sigma_ * sum);
  }

  void FillGradient(const Eigen::VectorXd& a, const GaussianShapes& shapes,
                    const Eigen::MatrixXd& gram, const Eigen::VectorXd& gram_a,
                    const Eigen::VectorXd& projection, CostGradient& out) const {
    const Eigen::Index m = a.size();
    out.amplitudes = 2.0 * (gram_a - projection);
    out.precisions.setZero(m);
    out.centers.setZero(m);
    for (Eigen::Index k = 0; k < m; ++k) {
      const double bk = shapes.precisions(k);
      // d/d(b_k, d_k) of sum_ij a_i a_j G_ij = 2 a_k sum_j a_j dG_kj / d(b_k, d_k)
      double by_precision = 0.0, by_center = 0.0;
      for (Eigen::Index j = 0; j < m; ++j) {
        const double bj = shapes.precisions(j);
        const double sum = bk + bj;
        const double gap = shapes.centers(k) - shapes.centers(j);
        by_precision +=
            a(j) * gram(k, j) * (-0.5 / sum - gap * gap * bj * bj / (2.0 * sigma_ * sum * sum));
        by_center += a(j) * gram(k, j) * (-bk * bj * gap / (sigma_ * sum));
      }
      const PieceIntegral r = Project(bk, shapes.centers(k));
      out.precisions(k) = 2.0 * a(k) * (by_precision - r.d_precision);
      out.centers(k) = 2.0 * a(k) * (by_center - r.d_center);
    }
  }
};

class PiecewiseLinearTarget final : public ContinuousTarget {
 public:
  PiecewiseLinearTarget(std::vector<TargetPoint> vertices, double sigma)
      : ContinuousTarget(sigma), vertices_(std::move(vertices)) {
    for (std::size_t i = 0; i + 1 < vertices_.size(); ++i) {
      const TargetPoint& p = vertices_[i];
      const TargetPoint& q = vertices_[i + 1];
      norm_squared_ += (q.x - p.x) * (p.y * p.y + p.y * q.y + q.y * q.y) / 3.0;
    }
  }

  double NormSquared() const override { return norm_squared_; }
  double SupportMin() const override { return vertices_.front().x; }
  double SupportMax() const override { return vertices_.back().x; }

 private:
  // r_k and its derivatives: the sum over the polygon's pieces.
  PieceIntegral Project(double b, double d) const override {
    PieceIntegral total{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i + 1 < vertices_.size(); ++i) {
      const TargetPoint& p = vertices_[i];
      const TargetPoint& q = vertices_[i + 1];
      const PieceIntegral piece =
          IntegratePiece(p.x, q.x, p.y, (q.y - p.y) / (q.x - p.x), b, d, sigma_);
      total.value += piece.value;
      total.d_precision += piece.d_precision;
      total.d_center += piece.d_center;
    }
    return total;
  }

  std::vector<TargetPoint> vertices_;
  double norm_squared_ = 0.0;
};

// 8-point Gauss-Legendre rule on [-1, 1]: nodes and weights, symmetric pairs.
constexpr double kLegendreNodes[4] = {
    0.183434642495649804939476142360, 0.525532409916328985817739049189,
    0.796666477413626739591553936476, 0.960289856497536231683560868569};
constexpr double kLegendreWeights[4] = {
    0.362683783378361982965150449277, 0.313706645877887287337962201987,
    0.222381034453374470544355994426, 0.101228536290376259152531354310};

// Calls visit(x, w) for the nodes and weights of the composite 8-point rule on [lo, hi],
// split into equal panels no wider than `panel`.
template <typename Visit>
void ForEachNode(double lo, double hi, double panel, Visit visit) {
  const double count = std::ceil((hi - lo) / panel);
  const int panels = std::max(1, static_cast<int>(count));
  const double width = (hi - lo) / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = lo + (p + 0.5) * width;
    const double half = 0.5 * width;
    for (int i = 0; i < 4; ++i) {
      visit(mid - half * kLegendreNodes[i], half * kLegendreWeights[i]);
      visit(mid + half * kLegendreNodes[i], half * kLegendreWeights[i]);
    }
  }
}

// A standard curve scaled to l_opt: C(x) = preset(x / l_opt). It is smooth between its breaks,
// so r_k is integrated by Gauss-Legendre on panels no wider than the curve's own panel nor than
// one spread of the Gaussian, over the Gaussian's +-10 spreads (beyond, it is below e^-50 of
// its peak): accurate to roundoff for any width the fit may try.
class PresetTarget final : public ContinuousTarget {
 public:
  PresetTarget(ForceLengthPreset preset, double optimal_length, double sigma)
      : ContinuousTarget(sigma), preset_(preset), optimal_length_(optimal_length) {
    const PresetPieces pieces = PiecesOf(preset);
    for (double s : pieces.breaks) breaks_.push_back(s * optimal_length);
    panel_ = pieces.panel * optimal_length;
    for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
      ForEachNode(breaks_[i], breaks_[i + 1], panel_, [&](double x, double w) {
        const double c = Curve(x);
        norm_squared_ += w * c * c;
      });
    }
  }

  double NormSquared() const override { return norm_squared_; }
  double SupportMin() const override { return breaks_.front(); }
  double SupportMax() const override { return breaks_.back(); }

 private:
  double Curve(double x) const { return EvaluatePreset(preset_, x / optimal_length_); }

  PieceIntegral Project(double b, double d) const override {
    const double spread = std::sqrt(sigma_ / b);
    const double rate = b / (2.0 * sigma_);
    const double peak = kInvSqrt2Pi / std::sqrt(sigma_);  // phi_k at its centre
    const double reach_lo = d - 10.0 * spread, reach_hi = d + 10.0 * spread;
    const double panel = std::min(panel_, spread);
    PieceIntegral total{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i + 1 < breaks_.size(); ++i) {
      const double lo = std::max(breaks_[i], reach_lo);
      const double hi = std::min(breaks_[i + 1], reach_hi);
      if (!(hi > lo)) continue;
      ForEachNode(lo, hi, panel, [&](double x, double w) {
        const double dx = x - d;
        const double weighted = w * peak * std::exp(-rate * dx * dx) * Curve(x);
        total.value += weighted;
        // dphi/db = -phi (x - d)^2 / (2 sigma), dphi/dd = phi b (x - d) / sigma
        total.d_precision -= weighted * dx * dx / (2.0 * sigma_);
        total.d_center += weighted * b * dx / sigma_;
      });
    }
    return total;
  }

  ForceLengthPreset preset_;
  double optimal_length_;
  std::vector<double> breaks_;
  double panel_ = 0.0;
  double norm_squared_ = 0.0;
};

class SampleTarget final : public FitTarget {
 public:
  SampleTarget(std::vector<TargetPoint> samples, double sigma)
      : samples_(std::move(samples)), sigma_(sigma) {
    for (const TargetPoint& s : samples_) {
      norm_squared_ += s.y * s.y;
      support_min_ = std::min(support_min_, s.x);
      support_max_ = std::max(support_max_, s.x);
    }
  }

  void NormalEquations(const GaussianShapes& shapes, Eigen::MatrixXd& gram,
                       Eigen::VectorXd& projection) const override {
    const Eigen::MatrixXd basis = Basis(shapes);
    gram = basis.transpose() * basis;
    projection = basis.transpose() * Values();
  }

  double Cost(const Eigen::VectorXd& a, const GaussianShapes& shapes,
              CostGradient* gradient) const override {
    const Eigen::MatrixXd basis = Basis(shapes);
    const Eigen::VectorXd residual = basis * a - Values();
    if (gradient != nullptr) {
      const Eigen::Index m = a.size();
      gradient->amplitudes = 2.0 * basis.transpose() * residual;
      gradient->precisions.setZero(m);
      gradient->centers.setZero(m);
      for (Eigen::Index k = 0; k < m; ++k) {
        for (std::size_t s = 0; s < samples_.size(); ++s) {
          const double dx = samples_[s].x - shapes.centers(k);
          const double weight = 2.0 * residual(s) * a(k) * basis(s, k);
          gradient->precisions(k) += weight * (-dx * dx / (2.0 * sigma_));
          gradient->centers(k) += weight * shapes.precisions(k) * dx / sigma_;
        }
      }
    }
    return residual.squaredNorm();
  }

  double NormSquared() const override { return norm_squared_; }
  double SupportMin() const override { return support_min_; }
  double SupportMax() const override { return support_max_; }

 private:
  // phi_k(x_s): the unit-amplitude components at the samples, one column each.
  Eigen::MatrixXd Basis(const GaussianShapes& shapes) const {
    Eigen::MatrixXd basis(samples_.size(), shapes.precisions.size());
    for (Eigen::Index k = 0; k < basis.cols(); ++k) {
      const GaussianTerm phi = GaussianTerm::Unit(shapes.precisions(k), shapes.centers(k), sigma_);
      for (std::size_t s = 0; s < samples_.size(); ++s) basis(s, k) = phi(samples_[s].x);
    }
    return basis;
  }

  Eigen::VectorXd Values() const {
    Eigen::VectorXd y(samples_.size());
    for (std::size_t s = 0; s < samples_.size(); ++s) y(s) = samples_[s].y;
    return y;
  }

  std::vector<TargetPoint> samples_;
  double sigma_;
  double norm_squared_ = 0.0;
  double support_min_ = INFINITY;
  double support_max_ = -INFINITY;
};

}  // namespace

std::unique_ptr<FitTarget> MakePiecewiseLinearTarget(std::vector<TargetPoint> vertices,
                                                     double sigma) {
  return std::make_unique<PiecewiseLinearTarget>(std::move(vertices), sigma);
}

std::unique_ptr<FitTarget> MakeSampleTarget(std::vector<TargetPoint> samples, double sigma) {
  return std::make_unique<SampleTarget>(std::move(samples), sigma);
}

std::unique_ptr<FitTarget> MakePresetTarget(ForceLengthPreset preset, double optimal_length,
                                            double sigma) {
  return std::make_unique<PresetTarget>(preset, optimal_length, sigma);
}

}  // namespace musclesim
