// How `auto` chooses the linear solver from a system's real structure, and what it costs: a
// chain whose nodes are listed out of order has a band as wide as its matrix, and takes the
// sparse solver with a coloured difference quotient (solver/coloured_difference_quotient.h)
// whose values match the analytic Jacobian and whose runs match the in-order chain's; a
// solver whose matrices cannot fit in memory is refused with the size it needs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sunmatrix/sunmatrix_band.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/solver/simulation.h"
#include "solver/coloured_difference_quotient.h"
#include "solver/linear_system.h"
#include "support/canonical_networks.h"

namespace musclesim {
namespace {

using testing::NetworkExperiment;

// testing::Chain(n) with its free nodes listed in a shuffled order (the same chain: each node
// joined to the one before it by an actuator and a damper, the load on the last).
NetworkExperiment ShuffledChain(int n, JacobianKind jacobian) {
  NetworkExperiment in_order = testing::Chain(n);
  std::vector<Node> nodes = in_order.system.nodes();
  std::mt19937 generator(2026);
  std::shuffle(nodes.begin() + 1, nodes.end(), generator);  // the wall stays first
  NetworkExperiment shuffled{
      NetworkSystem(nodes, in_order.system.elements(), in_order.system.loads()), in_order.request,
      in_order.options};
  shuffled.options.jacobian = jacobian;
  return shuffled;
}

TEST(LinearSolverChoice, AChainListedOutOfOrderTakesTheSparseSolver) {
  const NetworkExperiment chain = ShuffledChain(200, JacobianKind::kDifferenceQuotient);
  const JacobianPattern& pattern = chain.system.jacobian_pattern();
  // the band spans most of the matrix, where the chain in order has 3 below and 2 above
  EXPECT_GT(pattern.lower_bandwidth + pattern.upper_bandwidth, pattern.size / 2);
  EXPECT_EQ(ChooseLinearSolver(pattern), LinearSolverKind::kSparse);
}

TEST(ColouredDifferenceQuotient, GroupsOnlyColumnsThatShareNoRow) {
  const NetworkExperiment chain = ShuffledChain(200, JacobianKind::kDifferenceQuotient);
  const JacobianPattern& pattern = chain.system.jacobian_pattern();
  const ColouredDifferenceQuotient quotient(pattern);
  // each node's two columns touch the rows of itself and its two neighbours: a handful of
  // groups, where the band's quotient perturbs one column of its width at a time
  EXPECT_LE(quotient.groups(), 12);
  // checked on the pattern itself: within a group no row is hit twice, and every column is in
  // exactly one group
  std::vector<int> groups_of_column(static_cast<std::size_t>(pattern.size), 0);
  std::vector<int> hit(static_cast<std::size_t>(pattern.size));
  for (int g = 0; g < quotient.groups(); ++g) {
    std::fill(hit.begin(), hit.end(), 0);
    for (int j : quotient.columns(g)) {
      ++groups_of_column[static_cast<std::size_t>(j)];
      for (int k = pattern.column_starts[j]; k < pattern.column_starts[j + 1]; ++k) {
        EXPECT_EQ(++hit[static_cast<std::size_t>(pattern.rows[k])], 1)
            << "group " << g << " row " << pattern.rows[k];
      }
    }
  }
  for (int count : groups_of_column) EXPECT_EQ(count, 1);
}

TEST(ColouredDifferenceQuotient, MatchesTheAnalyticJacobian) {
  const NetworkExperiment chain = ShuffledChain(60, JacobianKind::kDifferenceQuotient);
  const NetworkSystem& system = chain.system;
  const JacobianPattern& pattern = system.jacobian_pattern();
  const auto n = static_cast<std::size_t>(pattern.size);
  std::vector<double> y(n), rate(n), perturbed_rate(n), weights(n);
  system.InitialState(0.0, y.data());
  // away from rest, so the velocity terms are not all at their kinks
  for (std::size_t i = 1; i < n; i += 2) y[i] = 0.01 * std::sin(static_cast<double>(i));
  system.RightHandSide(0.1, y.data(), rate.data());
  for (std::size_t i = 0; i < n; ++i) weights[i] = 1.0 / (1e-8 * std::abs(y[i]) + 1e-12);
  std::vector<double> quotient_values(static_cast<std::size_t>(pattern.entries()));
  std::vector<double> analytic(quotient_values.size());
  ColouredDifferenceQuotient(pattern).Evaluate(
      [&](const double* state, double* out) { system.RightHandSide(0.1, state, out); }, y.data(),
      rate.data(), weights.data(), 1e-3, perturbed_rate.data(), quotient_values.data());
  system.Jacobian(0.1, y.data(), analytic.data());
  double largest = 0.0;
  for (double a : analytic) largest = std::max(largest, std::abs(a));
  for (std::size_t k = 0; k < analytic.size(); ++k) {
    // a one-sided quotient of relative step 1e-8: its error is about 1e-8 of the curvature,
    // the rounding 1e-8 of the right-hand side
    EXPECT_NEAR(quotient_values[k], analytic[k], 1e-5 * largest) << "entry " << k;
  }
}

TEST(ColouredDifferenceQuotient, MatchesTheAnalyticJacobianAtRest) {
  // every velocity exactly 0, as a chain starts: a step relative to the value alone (or to
  // the error test's negligible size times sqrt(uround), ~1e-20) moved nothing the right-hand
  // side resolves, and the Jacobian's velocity columns were noise; CVODE's floor (1000 |h|
  // uround n ||f||) keeps them
  const NetworkExperiment chain = ShuffledChain(60, JacobianKind::kDifferenceQuotient);
  const NetworkSystem& system = chain.system;
  const JacobianPattern& pattern = system.jacobian_pattern();
  const auto n = static_cast<std::size_t>(pattern.size);
  std::vector<double> y(n), rate(n), perturbed_rate(n), weights(n);
  system.InitialState(0.0, y.data());
  system.RightHandSide(0.1, y.data(), rate.data());
  for (std::size_t i = 0; i < n; ++i) weights[i] = 1.0 / (1e-6 * std::abs(y[i]) + 1e-9);
  std::vector<double> quotient_values(static_cast<std::size_t>(pattern.entries()));
  std::vector<double> analytic(quotient_values.size());
  ColouredDifferenceQuotient(pattern).Evaluate(
      [&](const double* state, double* out) { system.RightHandSide(0.1, state, out); }, y.data(),
      rate.data(), weights.data(), 1e-4, perturbed_rate.data(), quotient_values.data());
  system.Jacobian(0.1, y.data(), analytic.data());
  double largest = 0.0;
  for (double a : analytic) largest = std::max(largest, std::abs(a));
  for (std::size_t k = 0; k < analytic.size(); ++k) {
    // the quotient's truncation and rounding at the floor's step: well within 1e-4
    EXPECT_NEAR(quotient_values[k], analytic[k], 1e-4 * largest) << "entry " << k;
  }
}

TEST(LinearSolverChoice, TheShuffledChainRunsAsTheChainInOrder) {
  const NetworkExperiment in_order = testing::Chain(120);
  const NetworkRunResult reference = in_order.Run();
  for (JacobianKind jacobian : {JacobianKind::kDifferenceQuotient, JacobianKind::kAnalytic}) {
    const NetworkExperiment shuffled = ShuffledChain(120, jacobian);
    const NetworkRunResult run = shuffled.Run();
    ASSERT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
    EXPECT_EQ(run.stats.linear_solver, LinearSolverKind::kSparse);
    ASSERT_EQ(run.times.size(), reference.times.size());
    // the same chain: every node where the in-order run has it, to the tolerances' error
    for (std::size_t i = 1; i < shuffled.system.nodes().size(); ++i) {
      const std::string& name = shuffled.system.nodes()[i].name;
      const auto in_reference = static_cast<std::size_t>(in_order.system.FindNode(name));
      EXPECT_NEAR(run.samples.back().position[i], reference.samples.back().position[in_reference],
                  1e-8)
          << name;
    }
  }
}

TEST(LinearSolverChoice, MatricesTooLargeForMemoryAreRefusedWithTheirSize) {
  const NetworkExperiment chain = ShuffledChain(200, JacobianKind::kDifferenceQuotient);
  const JacobianPattern& pattern = chain.system.jacobian_pattern();
  const double dense = MatrixBytes(LinearSolverKind::kDense, pattern);
  EXPECT_DOUBLE_EQ(dense, 2.0 * 400.0 * 400.0 * sizeof(double));
  // the band's storage is SUNDIALS' own: its columns of ldata entries
  SUNContext context = nullptr;
  ASSERT_EQ(SUNContext_Create(nullptr, &context), 0);
  SUNMatrix band =
      SUNBandMatrix(pattern.size, pattern.upper_bandwidth, pattern.lower_bandwidth, context);
  EXPECT_DOUBLE_EQ(MatrixBytes(LinearSolverKind::kBand, pattern),
                   2.0 * SUNBandMatrix_LDim(band) * pattern.size * sizeof(double));
  SUNMatDestroy(band);
  SUNContext_Free(&context);
  try {
    RequireRoomFor(LinearSolverKind::kDense, pattern, dense - 1.0);
    ADD_FAILURE() << "accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "linear_solver");
    EXPECT_NE(std::string(e.what()).find(
                  "needs about 3 MiB for the matrices of this system's 400 states"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(RequireRoomFor(LinearSolverKind::kSparse, pattern, dense - 1.0));
  // a run asking for a dense matrix of 200000 states (640 GB) is refused before any
  // allocation, on any machine: a dense LU serves at most kDenseMaxStates
  const NetworkExperiment huge = testing::Chain(100000, LinearSolverKind::kDense);
  try {
    huge.Run();
    ADD_FAILURE() << "accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.path(), "linear_solver");
    EXPECT_THAT(e.what(), ::testing::HasSubstr("a dense LU of this system's 200000 states costs "
                                               "2.7e+15 flops per factorisation"));
  }
  // and just above that size too, where the matrices would fit in memory
  const NetworkExperiment above = testing::Chain(kDenseMaxStates / 2 + 1, LinearSolverKind::kDense);
  EXPECT_THROW(above.Run(), ParameterError);
  const NetworkExperiment at = testing::Chain(kDenseMaxStates / 2, LinearSolverKind::kDense);
  EXPECT_NO_THROW(RequireRoomFor(LinearSolverKind::kDense, at.system.jacobian_pattern(), 1e12));
}

TEST(LinearSolverChoice, KlusFactorsAreCountedAndTooManyAreRefused) {
  // KLU's symbolic analysis estimates its factors' entries: at least the Newton matrix's own
  // (the pattern and its diagonal), and for a chain in any order not much more (a chain's
  // LU fills nothing under a good ordering)
  const NetworkExperiment chain = ShuffledChain(200, JacobianKind::kAnalytic);
  const JacobianPattern& pattern = chain.system.jacobian_pattern();
  const double entries = SparseFactorEntries(pattern);
  EXPECT_GE(entries, pattern.entries());
  EXPECT_LT(entries, 3.0 * pattern.entries());
  // the factors are part of what a sparse solver needs, and refused with their count
  const double needed = SolverBytes(LinearSolverKind::kSparse, pattern);
  EXPECT_GT(needed, MatrixBytes(LinearSolverKind::kSparse, pattern));
  try {
    RequireRoomFor(LinearSolverKind::kSparse, pattern, needed - 1.0);
    ADD_FAILURE() << "accepted";
  } catch (const ParameterError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("for the matrices and LU factors of this system's "
                                               "400 states"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("factor entries"));
  }
  EXPECT_NO_THROW(RequireRoomFor(LinearSolverKind::kSparse, pattern, needed));
}

}  // namespace
}  // namespace musclesim
