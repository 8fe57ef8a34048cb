// The Newton iteration's matrix and linear solver for one system size and pattern: SUNDIALS
// dense, band or KLU sparse, or musclesim's small dense one, and how a Jacobian in pattern
// order is written into each.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

#include <optional>
#include <vector>

#include "coloured_difference_quotient.h"
#include "musclesim/dynamics/jacobian_pattern.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// KLU's fill-reducing ordering: AMD (0), not its default COLAMD (1).
inline constexpr int kKluOrdering = 0;
// The most states a dense LU serves: its cost grows as n^3 (2000 states: 2.7e9 flops per
// factorisation, seconds each with SUNDIALS' own LU; a 4900-state lattice took 10 minutes
// for 35 steps where KLU took 2 s).
inline constexpr int kDenseMaxStates = 2000;

// Bytes of the matrices a solver of `kind` keeps for `pattern` (the Newton matrix and CVODE's
// saved Jacobian); what the process may allocate is core/memory.h's AllocatableBytes.
double MatrixBytes(LinearSolverKind kind, const JacobianPattern& pattern);
// The entries of KLU's L and U for the Newton matrix of `pattern` as its symbolic analysis
// estimates them (an upper bound: about twice those factored on planar lattices).
double SparseFactorEntries(const JacobianPattern& pattern);
// MatrixBytes, and for the sparse solver its LU factors (SparseFactorEntries).
double SolverBytes(LinearSolverKind kind, const JacobianPattern& pattern);
// Throws ParameterError("linear_solver") naming the size needed when the matrices and factors
// of `kind` exceed `allowed` bytes (SolverBytes): SUNDIALS does not check every allocation of
// a matrix, so one too large must be refused before it is asked for, or it ends in a signal
// rather than an error; and for a dense LU above kDenseMaxStates, naming its cost.
void RequireRoomFor(LinearSolverKind kind, const JacobianPattern& pattern, double allowed);

class LinearSystem {
 public:
  // `kind` is never kAuto. Throws std::runtime_error if SUNDIALS cannot allocate.
  LinearSystem(LinearSolverKind kind, const JacobianPattern& pattern, N_Vector state,
               SUNContext context);
  ~LinearSystem();
  LinearSystem(const LinearSystem&) = delete;
  LinearSystem& operator=(const LinearSystem&) = delete;

  // Whether this one serves a system of `pattern` with `kind`.
  bool Fits(LinearSolverKind kind, const JacobianPattern& pattern) const;
  // Writes `values` (one per pattern entry) into `matrix` (CVODE has zeroed it).
  void Fill(const double* values, SUNMatrix matrix) const;

  LinearSolverKind kind() const { return kind_; }
  // Whether the matrix is a SUNDIALS dense one (dense and small).
  bool dense() const {
    return kind_ == LinearSolverKind::kDense || kind_ == LinearSolverKind::kSmall;
  }
  SUNMatrix matrix() const { return matrix_; }
  SUNLinearSolver solver() const { return solver_; }
  // A buffer for the Jacobian's values, one per pattern entry.
  std::vector<double>& values() { return values_; }
  // The sparse solver's difference quotient (the other kinds use CVODE's own).
  const ColouredDifferenceQuotient& quotient() const { return *quotient_; }

 private:
  LinearSolverKind kind_;
  JacobianPattern pattern_;
  std::vector<int> columns_;  // the column of every entry
  std::vector<double> values_;
  std::optional<ColouredDifferenceQuotient> quotient_;  // sparse only
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver solver_ = nullptr;
};

}  // namespace musclesim
