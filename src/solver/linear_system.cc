#include "linear_system.h"

#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <klu.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/memory.h"
#include "musclesim/core/number_format.h"
#include "small_linear_solver.h"

namespace musclesim {

double SparseFactorEntries(const JacobianPattern& pattern) {
  // the Newton matrix I - gamma J: the pattern with every diagonal entry
  std::vector<SuiteSparse_long> starts{0}, rows;
  rows.reserve(pattern.rows.size() + static_cast<std::size_t>(pattern.size));
  for (int j = 0; j < pattern.size; ++j) {
    bool diagonal = false;
    for (int k = pattern.column_starts[j]; k < pattern.column_starts[j + 1]; ++k) {
      if (!diagonal && pattern.rows[k] > j) rows.push_back(j);
      diagonal = diagonal || pattern.rows[k] >= j;
      rows.push_back(pattern.rows[k]);
    }
    if (!diagonal) rows.push_back(j);
    starts.push_back(static_cast<SuiteSparse_long>(rows.size()));
  }
  klu_l_common common;
  klu_l_defaults(&common);
  common.ordering = kKluOrdering;
  klu_l_symbolic* symbolic = klu_l_analyze(pattern.size, starts.data(), rows.data(), &common);
  if (symbolic == nullptr) return static_cast<double>(rows.size());
  const double entries = symbolic->lnz + symbolic->unz;
  klu_l_free_symbolic(&symbolic, &common);
  return entries;
}

double MatrixBytes(LinearSolverKind kind, const JacobianPattern& pattern) {
  const double n = pattern.size;
  const double per_matrix =
      kind == LinearSolverKind::kBand
          ? n * (2.0 * pattern.lower_bandwidth + pattern.upper_bandwidth + 1.0) * sizeof(double)
      : kind == LinearSolverKind::kSparse
          ? pattern.entries() * (sizeof(double) + sizeof(sunindextype)) + n * sizeof(sunindextype)
          : n * n * sizeof(double);
  return 2.0 * per_matrix;
}

double SolverBytes(LinearSolverKind kind, const JacobianPattern& pattern) {
  // KLU's factors: an entry and its row index each, with its workspace (measured: 20 bytes
  // per estimated entry at its peak on the planar lattices of 10 x 10 to 150 x 150 nodes)
  constexpr double kBytesPerFactorEntry = 20.0;
  const double factors =
      kind == LinearSolverKind::kSparse ? kBytesPerFactorEntry * SparseFactorEntries(pattern) : 0.0;
  return MatrixBytes(kind, pattern) + factors;
}

void RequireRoomFor(LinearSolverKind kind, const JacobianPattern& pattern, double allowed) {
  if (kind == LinearSolverKind::kDense && pattern.size > kDenseMaxStates) {
    const double n = pattern.size;
    throw ParameterError(
        "linear_solver", "dense",
        "a dense LU of this system's " + std::to_string(pattern.size) + " states costs " +
            FormatSignificant(n * n * n / 3.0, 2) + " flops per factorisation and " +
            MebibytesText(n * n * sizeof(double)) + " per matrix; above " +
            std::to_string(kDenseMaxStates) +
            " states use auto or sparse, which store only the structural entries (" +
            std::to_string(pattern.entries()) + ")");
  }
  const double needed = SolverBytes(kind, pattern);
  if (needed <= allowed) return;
  const bool sparse = kind == LinearSolverKind::kSparse;
  throw ParameterError(
      "linear_solver", std::string(ToString(kind)),
      "needs about " + MebibytesText(needed) + " for the " +
          (sparse ? "matrices and LU factors" : "matrices") + " of this system's " +
          std::to_string(pattern.size) + " states (bandwidths " +
          std::to_string(pattern.lower_bandwidth) + " below, " +
          std::to_string(pattern.upper_bandwidth) + " above" +
          (sparse ? ", " + FormatSignificant(SparseFactorEntries(pattern), 3) + " factor entries"
                  : std::string()) +
          "), more than the " + MebibytesText(allowed) + " this process may allocate: " +
          (sparse ? "a smaller network, or a machine with more memory"
                  : "use auto or sparse, which store only the structural entries (" +
                        std::to_string(pattern.entries()) + ")"));
}

LinearSystem::LinearSystem(LinearSolverKind kind, const JacobianPattern& pattern, N_Vector state,
                           SUNContext context)
    : kind_(kind), pattern_(pattern), values_(pattern.rows.size()) {
  for (int k = 0; k < pattern.entries(); ++k) columns_.push_back(pattern.ColumnOf(k));
  // CVODE's interface holds the Newton matrix and a saved Jacobian of the same shape
  RequireRoomFor(kind, pattern, AllocatableBytes());
  const sunindextype n = pattern.size;
  switch (kind) {
    case LinearSolverKind::kDense:
    case LinearSolverKind::kAuto:
      matrix_ = SUNDenseMatrix(n, n, context);
      if (matrix_ != nullptr) solver_ = SUNLinSol_Dense(state, matrix_, context);
      break;
    case LinearSolverKind::kBand:
      matrix_ = SUNBandMatrix(n, pattern.upper_bandwidth, pattern.lower_bandwidth, context);
      if (matrix_ != nullptr) solver_ = SUNLinSol_Band(state, matrix_, context);
      break;
    case LinearSolverKind::kSparse:
      matrix_ = SUNSparseMatrix(n, n, pattern.entries(), CSC_MAT, context);
      if (matrix_ != nullptr) solver_ = SUNLinSol_KLU(state, matrix_, context);
      // AMD fills less than KLU's default COLAMD, and factors faster, on every network
      // measured (planar lattices of 10 x 10 to 150 x 150 nodes: 35-55 % fewer entries,
      // 1.4-2.6 times faster; docs/solver.md)
      if (solver_ != nullptr) SUNLinSol_KLUSetOrdering(solver_, kKluOrdering);
      quotient_.emplace(pattern_);
      break;
    case LinearSolverKind::kSmall:
      matrix_ = SUNDenseMatrix(n, n, context);
      if (matrix_ != nullptr) solver_ = NewSmallDenseSolver(state, matrix_, context);
      break;
  }
  if (matrix_ == nullptr || solver_ == nullptr) {
    if (solver_ != nullptr) SUNLinSolFree(solver_);
    if (matrix_ != nullptr) SUNMatDestroy(matrix_);
    throw std::runtime_error("allocating the " + std::string(ToString(kind)) +
                             " linear solver failed");
  }
}

LinearSystem::~LinearSystem() {
  SUNLinSolFree(solver_);
  SUNMatDestroy(matrix_);
}

bool LinearSystem::Fits(LinearSolverKind kind, const JacobianPattern& pattern) const {
  return kind == kind_ && pattern.size == pattern_.size && pattern.rows == pattern_.rows &&
         pattern.column_starts == pattern_.column_starts;
}

void LinearSystem::Fill(const double* values, SUNMatrix matrix) const {
  switch (kind_) {
    case LinearSolverKind::kDense:
    case LinearSolverKind::kSmall:
    case LinearSolverKind::kAuto:
      for (int k = 0; k < pattern_.entries(); ++k) {
        SM_ELEMENT_D(matrix, pattern_.rows[k], columns_[k]) = values[k];
      }
      break;
    case LinearSolverKind::kBand:
      for (int k = 0; k < pattern_.entries(); ++k) {
        SM_ELEMENT_B(matrix, pattern_.rows[k], columns_[k]) = values[k];
      }
      break;
    case LinearSolverKind::kSparse: {
      // CVODE's zeroing clears the structure too: write it back with the values
      sunindextype* starts = SUNSparseMatrix_IndexPointers(matrix);
      sunindextype* rows = SUNSparseMatrix_IndexValues(matrix);
      std::copy(pattern_.column_starts.begin(), pattern_.column_starts.end(), starts);
      std::copy(pattern_.rows.begin(), pattern_.rows.end(), rows);
      std::copy(values, values + pattern_.entries(), SUNSparseMatrix_Data(matrix));
      break;
    }
  }
}

}  // namespace musclesim
