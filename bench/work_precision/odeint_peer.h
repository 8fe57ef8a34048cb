// Boost.Odeint's rosenbrock4 on the two-state actuator problem, in a translation unit of its
// own: Boost 1.74's uBLAS needs C++17 (it uses std::allocator::construct, which C++20
// removed), while musclesim's headers need C++20. The problem comes in through function
// pointers, as CVODE's right-hand side does.
#pragma once

#include <functional>
#include <vector>

struct TwoStateProblem {
  const void* system;
  double (*acceleration)(const void* system, double t, double x, double v);
  void (*jacobian)(const void* system, double t, double x, double v, double* by_length,
                   double* by_rate);
};

// Integrates y = (x, v) from times.front() through `times` (ascending) with rosenbrock4's
// error control and dense output, calling `observe` at each time; returns the number of
// right-hand-side evaluations.
long OdeintSegment(const TwoStateProblem& problem, double rtol, double atol, double y[2],
                   const std::vector<double>& times,
                   const std::function<void(double t, const double* y)>& observe);
