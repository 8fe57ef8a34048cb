// Boost.Odeint's rosenbrock4 on the two-state actuator problem and on an N-state system, in a
// translation unit of its own: Boost 1.74's uBLAS needs C++17 (it uses std::allocator::construct,
// which C++20 removed), while musclesim's headers need C++20. The problem comes in through function
// pointers, as CVODE's right-hand side does.
#pragma once

#include <functional>
#include <vector>

struct TwoStateProblem {
  const void* system;
  double (*acceleration)(const void* system, double t, double x, double v);
  void (*jacobian)(const void* system, double t, double x, double v, double* by_length,
                   double* by_rate);
  // d acceleration / dt at fixed (x, v): rosenbrock4's stages use it, and a ramp or a sine
  // input makes it non-zero
  double (*time_derivative)(const void* system, double t, double x, double v);
};

struct OdeintCounts {
  long steps = 0;      // accepted steps: the dense-output stepper's do_step calls
  long rhs_evals = 0;  // right-hand-side evaluations
  long jac_evals = 0;  // Jacobian evaluations: one per attempted step, each followed by an LU
};

// Integrates y = (x, v) from times.front() through `times` (ascending) with rosenbrock4's
// error control and dense output, calling `observe` at each time. Adds what it did to
// `counts`.
void OdeintSegment(const TwoStateProblem& problem, double rtol, double atol, double y[2],
                   const std::vector<double>& times,
                   const std::function<void(double t, const double* y)>& observe,
                   OdeintCounts& counts);

// An N-state system y' = f(t, y) with its dense Jacobian df/dy, written row-major into
// `jacobian` (size * size values, every one of them: the matrix is not cleared first). Its
// inputs must be constant between the breakpoints the caller restarts at: df/dt is taken as 0.
struct NStateProblem {
  int size;
  void* context;  // the callbacks' own (they may keep scratch space in it)
  void (*rhs)(void* context, double t, const double* y, double* dydt);
  void (*jacobian)(void* context, double t, const double* y, double* jacobian);
};

// As OdeintSegment, for an N-state system, with dense ublas matrices: y holds problem.size
// values. Adds what it did to `counts`.
void OdeintSegmentN(const NStateProblem& problem, double rtol, double atol, double* y,
                    const std::vector<double>& times,
                    const std::function<void(double t, const double* y)>& observe,
                    OdeintCounts& counts);
