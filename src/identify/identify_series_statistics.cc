#include "identify/identify_series_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace musclesim::identify_series_detail {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool Held(const std::vector<bool>& at_bound, Eigen::Index j) {
  return !at_bound.empty() && at_bound[static_cast<std::size_t>(j)];
}

// The columns not at a bound (seen) and, of those, the ones not negligible (estimable).
struct ColumnSets {
  std::vector<Eigen::Index> seen, estimable;
};

// The verdicts at a bound and of negligible columns (the rest identifiable, for now).
ColumnSets ClassifyColumns(const std::vector<bool>& at_bound, JacobianAnalysis& a) {
  const Eigen::Index p = a.column_ratios.size();
  a.verdicts.assign(static_cast<std::size_t>(p), Identifiability::kIdentifiable);
  ColumnSets sets;
  for (Eigen::Index j = 0; j < p; ++j) {
    auto& verdict = a.verdicts[static_cast<std::size_t>(j)];
    if (Held(at_bound, j)) {
      verdict = Identifiability::kAtBound;
      continue;
    }
    sets.seen.push_back(j);
    if (!(a.column_ratios[j] >= kNegligibleColumnRatio)) {
      verdict = Identifiability::kNegligibleColumn;
    } else {
      sets.estimable.push_back(j);
    }
  }
  return sets;
}

// The singular values over every column not at a bound (a negligible column gives a
// near-zero one); the unresolved directions, but those of negligible columns alone, whose
// parameters become dependent.
void FindWeakDirections(const Eigen::MatrixXd& s, const std::vector<Eigen::Index>& seen,
                        JacobianAnalysis& a) {
  const Eigen::Index p = s.cols();
  const Eigen::MatrixXd s_seen = s(Eigen::all, seen);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(s_seen, Eigen::ComputeThinV);
  a.singular_values = svd.singularValues();
  const double top = a.singular_values.size() ? a.singular_values[0] : 0.0;
  for (Eigen::Index k = 0; k < a.singular_values.size(); ++k) {
    const double ratio = top > 0.0 ? a.singular_values[k] / top : 0.0;
    if (ratio >= kDependentSingularValueRatio) continue;
    WeakDirection direction{ratio, std::vector<double>(static_cast<std::size_t>(p), 0.0)};
    int taking_part = 0;
    for (std::size_t i = 0; i < seen.size(); ++i) {
      const Eigen::Index j = seen[i];
      const double component = svd.matrixV()(static_cast<Eigen::Index>(i), k);
      direction.components[static_cast<std::size_t>(j)] = component;
      if (std::abs(component) >= kComponentFloor &&
          a.verdicts[static_cast<std::size_t>(j)] != Identifiability::kNegligibleColumn) {
        ++taking_part;
      }
    }
    if (taking_part == 0) continue;  // negligible columns alone: their ratios say it
    for (std::size_t i = 0; i < seen.size(); ++i) {
      auto& verdict = a.verdicts[static_cast<std::size_t>(seen[i])];
      if (std::abs(direction.components[static_cast<std::size_t>(seen[i])]) >= kComponentFloor &&
          verdict == Identifiability::kIdentifiable) {
        verdict = Identifiability::kDependent;
      }
    }
    a.weak_directions.push_back(std::move(direction));
  }
}

// The covariance over the estimable parameters, in relative terms: V diag(1/sigma^2) V^T
// over the resolved directions (a truncated SVD); a parameter taking part in an unresolved
// one has no standard error (NaN covariances, an infinite a.relative_standard_errors).
Eigen::MatrixXd RelativeCovariance(const Eigen::MatrixXd& s,
                                   const std::vector<Eigen::Index>& estimable,
                                   JacobianAnalysis& a) {
  const Eigen::Index p = s.cols();
  a.relative_standard_errors = Eigen::VectorXd::Constant(p, kInfinity);
  Eigen::MatrixXd relative_covariance = Eigen::MatrixXd::Constant(p, p, kNaN);
  if (estimable.empty()) return relative_covariance;
  const Eigen::MatrixXd s_est = s(Eigen::all, estimable);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(s_est, Eigen::ComputeThinV);
  const Eigen::VectorXd& sv = svd.singularValues();
  const Eigen::MatrixXd& v = svd.matrixV();
  const Eigen::Index m = static_cast<Eigen::Index>(estimable.size());
  Eigen::MatrixXd inner = Eigen::MatrixXd::Zero(m, m);
  std::vector<bool> unbounded(static_cast<std::size_t>(m), false);
  for (Eigen::Index k = 0; k < sv.size(); ++k) {
    if (sv[k] > 0.0 && sv[k] >= kDependentSingularValueRatio * sv[0]) {
      inner += v.col(k) * v.col(k).transpose() / (sv[k] * sv[k]);
      continue;
    }
    for (Eigen::Index i = 0; i < m; ++i) {
      if (std::abs(v(i, k)) >= kComponentFloor) unbounded[static_cast<std::size_t>(i)] = true;
    }
  }
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index k = 0; k < m; ++k) {
      const bool finite =
          !unbounded[static_cast<std::size_t>(i)] && !unbounded[static_cast<std::size_t>(k)];
      relative_covariance(estimable[static_cast<std::size_t>(i)],
                          estimable[static_cast<std::size_t>(k)]) = finite ? inner(i, k) : kNaN;
    }
    if (!unbounded[static_cast<std::size_t>(i)]) {
      a.relative_standard_errors[estimable[static_cast<std::size_t>(i)]] = std::sqrt(inner(i, i));
    }
  }
  return relative_covariance;
}

// The correlations of a covariance matrix; NaN where a variance is not finite and positive.
Eigen::MatrixXd Correlation(const Eigen::MatrixXd& covariance) {
  const Eigen::Index p = covariance.rows();
  Eigen::MatrixXd correlation = Eigen::MatrixXd::Constant(p, p, kNaN);
  for (Eigen::Index i = 0; i < p; ++i) {
    for (Eigen::Index k = 0; k < p; ++k) {
      const double d = covariance(i, i) * covariance(k, k);
      if (std::isfinite(covariance(i, k)) && d > 0.0) {
        correlation(i, k) = covariance(i, k) / std::sqrt(d);
      }
    }
  }
  return correlation;
}

}  // namespace

Eigen::VectorXd ParameterScales(const Eigen::VectorXd& estimate, const Eigen::VectorXd& start,
                                const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) {
  Eigen::VectorXd scales(estimate.size());
  for (Eigen::Index j = 0; j < estimate.size(); ++j) {
    double scale = std::max(std::abs(estimate[j]), std::abs(start[j]));
    for (const double bound : {lower[j], upper[j]}) {
      if (std::isfinite(bound) && estimate[j] == 0.0 && start[j] == 0.0) {
        scale = std::max(scale, std::abs(bound));
      }
    }
    scales[j] = scale > 0.0 ? scale : 1.0;
  }
  return scales;
}

JacobianAnalysis AnalyseJacobian(const Eigen::MatrixXd& weighted_jacobian,
                                 const Eigen::VectorXd& scales, bool noise_given,
                                 double weighted_rss, const std::vector<bool>& at_bound) {
  const Eigen::Index n = weighted_jacobian.rows(), p = weighted_jacobian.cols();
  JacobianAnalysis a;
  Eigen::Index estimated = 0;
  for (Eigen::Index j = 0; j < p; ++j) estimated += Held(at_bound, j) ? 0 : 1;
  a.degrees_of_freedom = static_cast<int>(n - estimated);
  a.variance_factor = noise_given                ? 1.0
                      : a.degrees_of_freedom > 0 ? weighted_rss / a.degrees_of_freedom
                                                 : kNaN;

  a.scales = scales;
  const Eigen::MatrixXd s =
      weighted_jacobian * a.scales.asDiagonal() / std::sqrt(a.variance_factor);
  const Eigen::VectorXd norms = s.colwise().norm().transpose();
  const double largest = norms.maxCoeff();
  a.column_ratios = largest > 0.0 ? Eigen::VectorXd(norms / largest) : Eigen::VectorXd::Zero(p);

  const ColumnSets columns = ClassifyColumns(at_bound, a);
  if (!columns.seen.empty()) FindWeakDirections(s, columns.seen, a);
  const Eigen::MatrixXd relative_covariance = RelativeCovariance(s, columns.estimable, a);
  a.covariance = a.scales.asDiagonal() * relative_covariance * a.scales.asDiagonal();
  a.standard_errors = a.relative_standard_errors.cwiseProduct(a.scales);
  a.correlation = Correlation(relative_covariance);
  for (Eigen::Index j = 0; j < p; ++j) {
    auto& verdict = a.verdicts[static_cast<std::size_t>(j)];
    if (verdict == Identifiability::kIdentifiable &&
        !(a.relative_standard_errors[j] <= kPoorRelativeError)) {
      verdict = Identifiability::kPoorlyDetermined;
    }
  }
  return a;
}

}  // namespace musclesim::identify_series_detail
