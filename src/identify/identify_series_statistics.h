// Private: what the Jacobian of a time-series fit says about its parameters: their
// standard errors and correlations (the inverse Fisher information), and whether this
// experiment determines each of them (the singular values of the scaled sensitivity matrix).
// The same analysis at the start values with the stated noise is `identify --design`.
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

#include "musclesim/identify/identify_series.h"  // the verdicts and their thresholds

namespace musclesim::identify_series_detail {

struct JacobianAnalysis {
  // the statistics: covariance = variance_factor (J_w^T J_w)^-1 over the parameters not at a
  // bound and not negligible, from the resolved directions (a truncated SVD); the others, and
  // those in an unresolved direction, have infinite standard errors and NaN correlations
  double variance_factor = 1.0;     // 1 with the noise given; s^2 = RSS / dof without
  int degrees_of_freedom = 0;       // values - parameters not at a bound
  Eigen::VectorXd standard_errors;  // P [the parameters' units]
  Eigen::MatrixXd covariance;       // P x P
  Eigen::MatrixXd correlation;      // P x P [-]
  // the identifiability: the sensitivity matrix S = J_w diag(scales) / sqrt(variance_factor),
  // each column the outputs' change, in noise standard deviations, for a relative change of
  // its parameter
  Eigen::VectorXd scales;                      // P: ParameterScales [the parameters' units]
  Eigen::VectorXd column_ratios;               // P: |S_j| / max_k |S_k| [-]
  Eigen::VectorXd singular_values;             // of S without the columns at a bound, descending
  Eigen::VectorXd relative_standard_errors;    // P: standard error / scale [-]
  std::vector<Identifiability> verdicts;       // P
  std::vector<WeakDirection> weak_directions;  // ratio < kDependentSingularValueRatio, but
                                               // those of negligible columns alone
};

// Each parameter's size, against which its sensitivity and standard error are relative: the
// larger of |estimate| and |start|, so that an estimate at or near 0 (a node fixed at the
// origin) is judged at the scale the experiment was set up for, and the design (estimate =
// start) and the fit agree; where both are 0, the larger finite bound's size, else 1.
Eigen::VectorXd ParameterScales(const Eigen::VectorXd& estimate, const Eigen::VectorXd& start,
                                const Eigen::VectorXd& lower, const Eigen::VectorXd& upper);

// Analyses the weighted Jacobian `weighted_jacobian` (N x P: row i is weight_i d prediction_i
// / d p) with the parameters' sizes `scales` (ParameterScales). With `noise_given` the weights are
// 1/sigma_i and the covariance is (J_w^T J_w)^-1; without, the weights are 1 and the covariance is
// s^2 (J^T J)^-1 with s^2 = weighted_rss / (N - P) (P: the parameters not at a bound). `at_bound`
// (P entries, or empty) marks parameters held at a bound.
JacobianAnalysis AnalyseJacobian(const Eigen::MatrixXd& weighted_jacobian,
                                 const Eigen::VectorXd& scales, bool noise_given,
                                 double weighted_rss, const std::vector<bool>& at_bound);

}  // namespace musclesim::identify_series_detail
