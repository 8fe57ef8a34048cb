// The step polynomial (src/solver/step_polynomial.h) against CVODE's own interpolation: both
// evaluate the last step's interpolant, one from its derivatives at t_n, the other through
// CVodeGetDky at each time, so they agree to rounding at every order CVODE uses.
#include "solver/step_polynomial.h"

#include <cvodes/cvodes.h>
#include <gtest/gtest.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace musclesim {
namespace {

// y0' = y1, y1' = -4 y0 - 0.4 y1: smooth, so BDF climbs to its higher orders
int OscillatorRhs(sunrealtype, N_Vector y, N_Vector ydot, void*) {
  const double* state = N_VGetArrayPointer(y);
  double* rate = N_VGetArrayPointer(ydot);
  rate[0] = state[1];
  rate[1] = -4.0 * state[0] - 0.4 * state[1];
  return 0;
}

TEST(StepPolynomial, AgreesWithCvodesInterpolationInsideEveryStepAtEveryOrder) {
  for (const int method : {CV_BDF, CV_ADAMS}) {
    SUNContext context = nullptr;
    ASSERT_EQ(SUNContext_Create(nullptr, &context), 0);
    N_Vector y = N_VNew_Serial(2, context);
    N_Vector by_cvode = N_VClone(y), scratch = N_VClone(y);
    N_VGetArrayPointer(y)[0] = 1.0;
    N_VGetArrayPointer(y)[1] = 0.0;
    void* cvode = CVodeCreate(method, context);
    ASSERT_EQ(CVodeInit(cvode, OscillatorRhs, 0.0, y), CV_SUCCESS);
    ASSERT_EQ(CVodeSStolerances(cvode, 1e-8, 1e-10), CV_SUCCESS);
    SUNMatrix matrix = SUNDenseMatrix(2, 2, context);
    SUNLinearSolver solver = SUNLinSol_Dense(y, matrix, context);
    ASSERT_EQ(CVodeSetLinearSolver(cvode, solver, matrix), CVLS_SUCCESS);

    std::set<int> orders;
    double t = 0.0, worst = 0.0;
    StepPolynomial polynomial;
    for (int step = 0; step < 400; ++step) {
      const double t_before = t;
      ASSERT_GE(CVode(cvode, 10.0, y, &t, CV_ONE_STEP), 0);
      ASSERT_TRUE(polynomial.Fetch(cvode, scratch, 2));
      orders.insert(polynomial.terms() - 1);
      double out[2];
      for (int k = 1; k <= 7; ++k) {
        const double at = t_before + (t - t_before) * k / 8.0;
        polynomial.Evaluate(at, out);
        ASSERT_EQ(CVodeGetDky(cvode, at, 0, by_cvode), CV_SUCCESS);
        for (int i = 0; i < 2; ++i) {
          worst = std::max(worst, std::abs(out[i] - N_VGetArrayPointer(by_cvode)[i]));
        }
      }
      // at the step's end the polynomial is the state CVODE returned
      polynomial.Evaluate(t, out);
      EXPECT_NEAR(out[0], N_VGetArrayPointer(y)[0], 1e-15);
    }
    // the same polynomial summed two ways: a few ulps of the state's size (1)
    EXPECT_LT(worst, 1e-14) << (method == CV_BDF ? "BDF" : "Adams");
    // orders 1 to 4 or more were used, so every term count was exercised
    EXPECT_GE(orders.size(), 4u);
    CVodeFree(&cvode);
    SUNLinSolFree(solver);
    SUNMatDestroy(matrix);
    N_VDestroy(scratch);
    N_VDestroy(by_cvode);
    N_VDestroy(y);
    SUNContext_Free(&context);
  }
}

}  // namespace
}  // namespace musclesim
