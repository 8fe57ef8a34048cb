// Student's t distribution with an integer number of degrees of freedom, for the F test of a
// profile likelihood with one parameter (F(1, dof) is t(dof) squared).
#pragma once

namespace musclesim {

// P(|T| <= t) [-] for T ~ t(dof), t >= 0 [-], dof >= 1: the finite sums of Abramowitz and
// Stegun 26.7.3 (odd dof) and 26.7.4 (even dof), O(dof) operations.
double StudentTCentralProbability(double t, int dof);

// The t [-] with P(|T| <= t) = probability, 0 < probability < 1, found by bisection to
// rounding; its square is the `probability` quantile of F(1, dof).
double StudentTCentralQuantile(double probability, int dof);

}  // namespace musclesim
