// SUNDIALS' SUNLinearSolver test driver (test_sunlinsol.c, compiled from Debian's
// libsundials-dev examples) run on the small dense solver with small vectors, modelled on
// test_sunlinsol_dense.c: a random matrix plus the anti-identity (so rows must be swapped),
// solved to 100 unit roundoffs (the driver checks to 10 times that). Usage:
// small_dense_solver_driver <n 1..16> <print timing 0|1>. Exit status 1 if any check fails.
#include <sundials/sundials_math.h>
#include <sundials/sundials_nvector.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cstdio>
#include <cstdlib>

#include "solver/small_linear_solver.h"
#include "solver/small_vector.h"
#include "test_sunlinsol.h"

namespace {

int RunDriver(sunindextype n, SUNContext context) {
  SUNMatrix a = SUNDenseMatrix(n, n, context);
  N_Vector x = musclesim::NewSmallVector(static_cast<int>(n), context);
  N_Vector b = N_VClone(x);
  if (a == nullptr || x == nullptr || b == nullptr) {
    std::printf("FAIL: unable to create the matrix and vectors\n");
    return 1;
  }

  // A: uniform in [0, 1/n] plus the anti-identity; x: uniform in [0, 1]
  for (sunindextype j = 0; j < n; ++j) {
    for (sunindextype i = 0; i < n; ++i) {
      SM_ELEMENT_D(a, i, j) = static_cast<realtype>(std::rand()) / RAND_MAX / n;
    }
    SM_ELEMENT_D(a, n - 1 - j, j) += 1.0;
  }
  realtype* xd = N_VGetArrayPointer(x);
  for (sunindextype i = 0; i < n; ++i) xd[i] = static_cast<realtype>(std::rand()) / RAND_MAX;

  // b = A x by hand: SUNMatMatvec_Dense takes only SUNDIALS' own serial-like vectors
  realtype* bd = N_VGetArrayPointer(b);
  for (sunindextype i = 0; i < n; ++i) {
    bd[i] = 0.0;
    for (sunindextype j = 0; j < n; ++j) bd[i] += SM_ELEMENT_D(a, i, j) * xd[j];
  }

  int fails = 0;
  SUNLinearSolver solver = musclesim::NewSmallDenseSolver(x, a, context);
  if (solver == nullptr) {
    std::printf("FAIL: unable to create the solver\n");
    fails = 1;
  } else {
    fails += Test_SUNLinSolInitialize(solver, 0);
    fails += Test_SUNLinSolSetup(solver, a, 0);
    fails += Test_SUNLinSolSolve(solver, a, x, b, 100 * UNIT_ROUNDOFF, SUNTRUE, 0);
    fails += Test_SUNLinSolSolve(solver, a, x, b, 100 * UNIT_ROUNDOFF, SUNFALSE, 0);
    fails += Test_SUNLinSolGetType(solver, SUNLINEARSOLVER_DIRECT, 0);
    fails += Test_SUNLinSolGetID(solver, SUNLINEARSOLVER_CUSTOM, 0);
    fails += Test_SUNLinSolLastFlag(solver, 0);
    fails += Test_SUNLinSolSpace(solver, 0);
    SUNLinSolFree(solver);
  }
  SUNMatDestroy(a);
  N_VDestroy(x);
  N_VDestroy(b);
  return fails;
}

}  // namespace

int main(int argc, char* argv[]) {
  if (argc < 3) {
    std::printf("ERROR: two arguments required: matrix size, print timing\n");
    return 2;
  }
  const long n = std::atol(argv[1]);
  if (n < 1 || n > musclesim::kSmallVectorMaxLength) {
    std::printf("ERROR: the size must be in [1, %d]\n", musclesim::kSmallVectorMaxLength);
    return 2;
  }
  SetTiming(std::atoi(argv[2]));
  SUNContext context = nullptr;
  if (SUNContext_Create(nullptr, &context) != 0) return 1;
  std::printf("Small dense linear solver test: size %ld\n\n", n);

  const int fails = RunDriver(static_cast<sunindextype>(n), context);
  if (fails != 0) {
    std::printf("FAIL: the small dense solver failed %d tests\n\n", fails);
  } else {
    std::printf("SUCCESS: the small dense solver passed all tests\n\n");
  }
  SUNContext_Free(&context);
  // not the count itself: an exit status is taken modulo 256
  return fails != 0 ? 1 : 0;
}

// ---------------------------------------------------------------------------------------------
// what the driver asks of an implementation (declared in test_sunlinsol.h)

int check_vector(N_Vector X, N_Vector Y, realtype tol) {
  const realtype* xd = N_VGetArrayPointer(X);
  const realtype* yd = N_VGetArrayPointer(Y);
  const sunindextype length = N_VGetLength(X);
  int failures = 0;
  realtype max_error = 0.0;
  for (sunindextype i = 0; i < length; ++i) {
    failures += SUNRCompareTol(xd[i], yd[i], tol);
    max_error = SUNMAX(max_error, SUNRabs(xd[i] - yd[i]));
  }
  if (failures > 0) {
    std::printf("check err failure: maxerr = %g (tol = %g)\n", max_error, tol);
    return 1;
  }
  return 0;
}

// no device to wait for
void sync_device() {}
