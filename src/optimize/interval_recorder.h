// Private: what one shooting interval's integration keeps. Its rows are the Gauss points of
// the tracking integrals (5-point Gauss-Legendre on every piece between the grid's points and
// the references' samples, where the integrand is smooth) and its end; at each, the
// differentiated columns and their sensitivities (scenario/sensitivity_columns.h) give the
// tracking integral's value and gradient, and at the end the state, its sensitivities and
// the columns the problem's terms read.
#pragma once

#include <vector>

#include "optimize/problem_checks.h"
#include "musclesim/solver/sensitivity.h"
#include "scenario/sensitivity_columns.h"

namespace musclesim {

// One tracking term's share of a row: weight (the term's times the quadrature's) and r(t).
struct TrackingPoint {
  int term = 0;
  double weight = 0.0;
  double reference = 0.0;
};

// The rows of one interval: their times, strictly increasing, the last its end.
struct IntervalPlan {
  std::vector<double> times;
  std::vector<std::vector<TrackingPoint>> points;  // per row
};

// The plans of the grid `times` (t_0 .. t_N) for `terms`.
std::vector<IntervalPlan> PlanIntervals(const std::vector<double>& times,
                                        const std::vector<TrackingTerm>& terms);

// An interval's results; derivatives by the interval's sensitivity parameters, K of them
// (its initial state's n components, its control values, the free parameters).
struct IntervalResult {
  std::vector<double> state;              // Phi_i, at the interval's end
  std::vector<double> sensitivities;      // d Phi_i / d parameter k in [k n, (k + 1) n)
  std::vector<double> columns;            // the problem's columns at the end (ProblemIndex)
  std::vector<double> column_gradients;   // d column u / d parameter k at [k U + u]
  double tracking = 0.0;                  // the interval's share of the tracking terms
  std::vector<double> tracking_gradient;  // by parameter
};

class IntervalRecorder final : public SensitivitySink {
 public:
  IntervalRecorder(const IntervalPlan& plan, SensitivityColumns& columns, const ProblemIndex& index,
                   int state_size, int parameters, IntervalResult& result);
  void Record(double t, const double* y, const double* const* s) override;
  bool complete() const { return row_ == plan_.times.size(); }

 private:
  const IntervalPlan& plan_;
  SensitivityColumns& columns_;
  const ProblemIndex& index_;
  int n_, parameters_;
  IntervalResult& result_;
  std::size_t row_ = 0;
  std::vector<double> values_, derivatives_;
};

}  // namespace musclesim
