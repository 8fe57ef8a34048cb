#include "linear_system.h"

#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
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

void RequireRoomFor(LinearSolverKind kind, const JacobianPattern& pattern, double allowed) {
  const double needed = MatrixBytes(kind, pattern);
  if (needed <= allowed) return;
  constexpr double kMiB = 1024.0 * 1024.0;
  throw ParameterError(
      "linear_solver", std::string(ToString(kind)),
      "needs " + FormatNumber(std::ceil(needed / kMiB)) +
          " MiB for the matrices of this system's " + std::to_string(pattern.size) +
          " states (bandwidths " + std::to_string(pattern.lower_bandwidth) + " below, " +
          std::to_string(pattern.upper_bandwidth) + " above), more than the " +
          FormatNumber(std::floor(allowed / kMiB)) +
          " MiB this process may allocate: use auto or sparse, which store only the "
          "structural entries (" +
          std::to_string(pattern.entries()) + ")");
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
