// The vector operations CVODE calls most, and a 2x2 setup + solve, on the small vector and
// solver against NVECTOR_SERIAL and SUNLinSol_Dense.
#include <benchmark/benchmark.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "solver/small_linear_solver.h"
#include "solver/small_vector.h"

namespace {

struct Context {
  Context() { SUNContext_Create(nullptr, &context); }
  ~Context() { SUNContext_Free(&context); }
  SUNContext context = nullptr;
};

N_Vector MakeVector(bool small, int n, SUNContext context) {
  N_Vector v = small ? musclesim::NewSmallVector(n, context) : N_VNew_Serial(n, context);
  for (int i = 0; i < n; ++i) N_VGetArrayPointer(v)[i] = 0.5 + i;
  return v;
}

// state.range(0): 1 for the small vector, 0 for NVECTOR_SERIAL; range(1): the length
void BM_SmallVectorLinearSum(benchmark::State& state) {
  Context context;
  const int n = static_cast<int>(state.range(1));
  N_Vector x = MakeVector(state.range(0) != 0, n, context.context);
  N_Vector y = N_VClone(x);
  N_VConst(0.25, y);
  for (auto _ : state) {
    N_VLinearSum(1.0, x, -1e-3, y, y);
    benchmark::DoNotOptimize(N_VGetArrayPointer(y));
  }
  state.SetItemsProcessed(state.iterations());
  N_VDestroy(x);
  N_VDestroy(y);
}
BENCHMARK(BM_SmallVectorLinearSum)->ArgsProduct({{0, 1}, {2, 3, 16}});

void BM_SmallVectorWrmsNorm(benchmark::State& state) {
  Context context;
  const int n = static_cast<int>(state.range(1));
  N_Vector x = MakeVector(state.range(0) != 0, n, context.context);
  N_Vector w = N_VClone(x);
  N_VConst(1e6, w);
  for (auto _ : state) benchmark::DoNotOptimize(N_VWrmsNorm(x, w));
  state.SetItemsProcessed(state.iterations());
  N_VDestroy(x);
  N_VDestroy(w);
}
BENCHMARK(BM_SmallVectorWrmsNorm)->ArgsProduct({{0, 1}, {2, 3, 16}});

// range(0): 1 for the small solver on small vectors, 0 for SUNLinSol_Dense on serial ones
void BM_SmallDenseSolverSetupSolve(benchmark::State& state) {
  Context context;
  const bool small = state.range(0) != 0;
  const int n = static_cast<int>(state.range(1));
  SUNMatrix a = SUNDenseMatrix(n, n, context.context);
  SUNMatrix original = SUNDenseMatrix(n, n, context.context);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) SM_ELEMENT_D(original, i, j) = (i == j ? n : 0.0) + 0.1 * (i - j);
  }
  N_Vector b = MakeVector(small, n, context.context);
  N_Vector x = N_VClone(b);
  SUNLinearSolver solver = small ? musclesim::NewSmallDenseSolver(x, a, context.context)
                                 : SUNLinSol_Dense(x, a, context.context);
  SUNLinSolInitialize(solver);
  for (auto _ : state) {
    SUNMatCopy(original, a);  // SUNLinSol_Dense factors in place
    SUNLinSolSetup(solver, a);
    SUNLinSolSolve(solver, a, x, b, 0.0);
    benchmark::DoNotOptimize(N_VGetArrayPointer(x));
  }
  state.SetItemsProcessed(state.iterations());
  SUNLinSolFree(solver);
  SUNMatDestroy(a);
  SUNMatDestroy(original);
  N_VDestroy(b);
  N_VDestroy(x);
}
BENCHMARK(BM_SmallDenseSolverSetupSolve)->ArgsProduct({{0, 1}, {2, 3, 16}});

}  // namespace
