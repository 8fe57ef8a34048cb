#include "solver/small_linear_solver.h"

#include <sunmatrix/sunmatrix_dense.h>

#include <array>
#include <cassert>
#include <cmath>
#include <new>
#include <utility>

#include "solver/small_vector.h"

namespace musclesim {
namespace {

// The factor P A = L U of the last setup, rows in pivot order: lu[i][j] holds U on and above
// the diagonal and L's multipliers below it (L's unit diagonal is implied); row i of P A is
// row pivot[i] of A.
template <int N>
struct SmallDenseContent {
  sunrealtype lu[N][N] = {};
  int pivot[N] = {};
  bool factored = false;
  sunindextype last_flag = SUNLS_SUCCESS;
};

template <int N>
SmallDenseContent<N>* Content(SUNLinearSolver solver) {
  return static_cast<SmallDenseContent<N>*>(solver->content);
}

SUNLinearSolver_Type GetType(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }

SUNLinearSolver_ID GetId(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }

template <int N>
int Initialize(SUNLinearSolver solver) {
  Content<N>(solver)->last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

// Factors `a` (column-major, N x N) into `content`; 0, or the 1-based column of a zero pivot.
template <int N>
sunindextype Factor(const sunrealtype* a, SmallDenseContent<N>& content) {
  auto& lu = content.lu;
  if constexpr (N == 2) {
    // the n = 2 case of the loop below, written out: the larger entry of column 0 leads
    const bool swap = std::abs(a[1]) > std::abs(a[0]);
    const int top = swap ? 1 : 0;
    const int bottom = 1 - top;
    content.pivot[0] = top;
    content.pivot[1] = bottom;
    lu[0][0] = a[top];
    lu[0][1] = a[2 + top];
    if (lu[0][0] == 0.0) return 1;
    lu[1][0] = a[bottom] / lu[0][0];
    lu[1][1] = a[2 + bottom] - lu[1][0] * lu[0][1];
    if (lu[1][1] == 0.0) return 2;
    return 0;
  } else {
    for (int i = 0; i < N; ++i) {
      content.pivot[i] = i;
      for (int j = 0; j < N; ++j) lu[i][j] = a[j * N + i];
    }
    for (int k = 0; k < N; ++k) {
      // partial pivoting: the first largest magnitude in column k, as SUNDIALS' denseGETRF
      int p = k;
      for (int i = k + 1; i < N; ++i) {
        if (std::abs(lu[i][k]) > std::abs(lu[p][k])) p = i;
      }
      if (lu[p][k] == 0.0) return k + 1;
      if (p != k) {
        std::swap(lu[p], lu[k]);
        std::swap(content.pivot[p], content.pivot[k]);
      }
      for (int i = k + 1; i < N; ++i) {
        const sunrealtype multiplier = lu[i][k] / lu[k][k];
        lu[i][k] = multiplier;
        for (int j = k + 1; j < N; ++j) lu[i][j] -= multiplier * lu[k][j];
      }
    }
    return 0;
  }
}

template <int N>
int Setup(SUNLinearSolver solver, SUNMatrix a) {
  if (solver == nullptr || a == nullptr) return SUNLS_MEM_NULL;
  SmallDenseContent<N>& content = *Content<N>(solver);
  content.factored = false;
  if (SUNMatGetID(a) != SUNMATRIX_DENSE || SM_ROWS_D(a) != N || SM_COLUMNS_D(a) != N) {
    content.last_flag = SUNLS_ILL_INPUT;
    return SUNLS_ILL_INPUT;
  }
  content.last_flag = Factor<N>(SM_DATA_D(a), content);
  if (content.last_flag > 0) return SUNLS_LUFACT_FAIL;
  content.factored = true;
  return SUNLS_SUCCESS;
}

template <int N>
int Solve(SUNLinearSolver solver, SUNMatrix, N_Vector x, N_Vector b, sunrealtype) {
  if (solver == nullptr || x == nullptr || b == nullptr) return SUNLS_MEM_NULL;
  SmallDenseContent<N>& content = *Content<N>(solver);
  sunrealtype* xd = N_VGetArrayPointer(x);
  const sunrealtype* bd = N_VGetArrayPointer(b);
  if (xd == nullptr || bd == nullptr) {
    content.last_flag = SUNLS_MEM_FAIL;
    return SUNLS_MEM_FAIL;
  }
  if (!content.factored) {
    // no successful setup to solve with
    content.last_flag = SUNLS_ILL_INPUT;
    return SUNLS_ILL_INPUT;
  }
  assert(N_VGetLength(x) == N && N_VGetLength(b) == N);
  const auto& lu = content.lu;
  sunrealtype y[N];
  if constexpr (N == 2) {
    y[0] = bd[content.pivot[0]];
    y[1] = bd[content.pivot[1]] - lu[1][0] * y[0];
    y[1] /= lu[1][1];
    y[0] = (y[0] - lu[0][1] * y[1]) / lu[0][0];
  } else {
    // L y = P b, then U x = y; through a local copy, so x and b may be one vector
    for (int i = 0; i < N; ++i) {
      y[i] = bd[content.pivot[i]];
      for (int j = 0; j < i; ++j) y[i] -= lu[i][j] * y[j];
    }
    for (int i = N - 1; i >= 0; --i) {
      for (int j = i + 1; j < N; ++j) y[i] -= lu[i][j] * y[j];
      y[i] /= lu[i][i];
    }
  }
  for (int i = 0; i < N; ++i) xd[i] = y[i];
  content.last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

template <int N>
sunindextype LastFlag(SUNLinearSolver solver) {
  return Content<N>(solver)->last_flag;
}

template <int N>
int Space(SUNLinearSolver, long int* real_words, long int* integer_words) {
  // the factor's copy; the pivots, the flag and the size
  *real_words = N * N;
  *integer_words = N + 2;
  return SUNLS_SUCCESS;
}

template <int N>
int Free(SUNLinearSolver solver) {
  if (solver == nullptr) return SUNLS_SUCCESS;
  delete Content<N>(solver);
  solver->content = nullptr;
  SUNLinSolFreeEmpty(solver);
  return SUNLS_SUCCESS;
}

template <int N>
SUNLinearSolver NewSolver(SUNContext context) {
  SUNLinearSolver solver = SUNLinSolNewEmpty(context);
  if (solver == nullptr) return nullptr;
  solver->ops->gettype = GetType;
  solver->ops->getid = GetId;
  solver->ops->initialize = Initialize<N>;
  solver->ops->setup = Setup<N>;
  solver->ops->solve = Solve<N>;
  solver->ops->lastflag = LastFlag<N>;
  solver->ops->space = Space<N>;
  solver->ops->free = Free<N>;
  solver->content = new (std::nothrow) SmallDenseContent<N>;
  if (solver->content == nullptr) {
    SUNLinSolFreeEmpty(solver);
    return nullptr;
  }
  return solver;
}

using Creator = SUNLinearSolver (*)(SUNContext);

// entry k makes a solver of size k + 1
template <int... I>
constexpr std::array<Creator, sizeof...(I)> MakeCreators(std::integer_sequence<int, I...>) {
  return {&NewSolver<I + 1>...};
}

constexpr std::array<Creator, kSmallVectorMaxLength> kCreators =
    MakeCreators(std::make_integer_sequence<int, kSmallVectorMaxLength>{});

}  // namespace

SUNLinearSolver NewSmallDenseSolver(N_Vector y, SUNMatrix matrix, SUNContext context) {
  if (y == nullptr || matrix == nullptr) return nullptr;
  if (SUNMatGetID(matrix) != SUNMATRIX_DENSE) return nullptr;
  const sunindextype n = SM_ROWS_D(matrix);
  if (SM_COLUMNS_D(matrix) != n || n < 1 || n > kSmallVectorMaxLength) return nullptr;
  if (y->ops->nvgetarraypointer == nullptr || y->ops->nvgetlength == nullptr) return nullptr;
  if (N_VGetLength(y) != n) return nullptr;
  return kCreators[n - 1](context);
}

}  // namespace musclesim
