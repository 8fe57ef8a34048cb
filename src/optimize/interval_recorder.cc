#include "optimize/interval_recorder.h"

#include <algorithm>
#include <cmath>

namespace musclesim {

namespace {

// r(t), linear between the points (t within their span).
double Interpolate(const std::vector<TablePoint>& points, double t) {
  const auto after = std::upper_bound(points.begin(), points.end(), t,
                                      [](double at, const TablePoint& p) { return at < p.t; });
  if (after == points.begin()) return points.front().value;
  if (after == points.end()) return points.back().value;
  const TablePoint& a = *(after - 1);
  const TablePoint& b = *after;
  return a.value + (b.value - a.value) * (t - a.t) / (b.t - a.t);
}

}  // namespace

std::vector<IntervalPlan> PlanIntervals(const std::vector<double>& times,
                                        const std::vector<TrackingTerm>& terms) {
  // 5-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree 9 (a mass driven by
  // a linear force moves as a cubic, its squared miss a sextic)
  const double inner = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
  const double outer = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
  const double w_inner = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
  const double w_outer = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
  const double nodes[] = {-outer, -inner, 0.0, inner, outer};
  const double kWeights[] = {w_outer, w_inner, 128.0 / 225.0, w_inner, w_outer};
  std::vector<IntervalPlan> plans(times.size() - 1);
  for (std::size_t i = 0; i + 1 < times.size(); ++i) {
    const double a = times[i], b = times[i + 1];
    IntervalPlan& plan = plans[i];
    if (!terms.empty()) {
      // the pieces: split at every reference sample inside (a, b), where r has a kink
      std::vector<double> cuts{a, b};
      const double tiny = 1e-9 * (b - a);
      for (const TrackingTerm& term : terms) {
        for (const TablePoint& p : term.reference) {
          if (p.t > a + tiny && p.t < b - tiny) cuts.push_back(p.t);
        }
      }
      std::sort(cuts.begin(), cuts.end());
      cuts.erase(
          std::unique(cuts.begin(), cuts.end(), [&](double x, double y) { return y - x <= tiny; }),
          cuts.end());
      for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
        const double middle = 0.5 * (cuts[c] + cuts[c + 1]);
        const double half = 0.5 * (cuts[c + 1] - cuts[c]);
        for (int g = 0; g < 5; ++g) {
          const double t = middle + half * nodes[g];
          std::vector<TrackingPoint> points;
          for (std::size_t k = 0; k < terms.size(); ++k) {
            points.push_back({static_cast<int>(k), terms[k].weight * half * kWeights[g],
                              Interpolate(terms[k].reference, t)});
          }
          plan.times.push_back(t);
          plan.points.push_back(std::move(points));
        }
      }
    }
    plan.times.push_back(b);
    plan.points.emplace_back();
  }
  return plans;
}

IntervalRecorder::IntervalRecorder(const IntervalPlan& plan, SensitivityColumns& columns,
                                   const ProblemIndex& index, int state_size, int parameters,
                                   IntervalResult& result)
    : plan_(plan),
      columns_(columns),
      index_(index),
      n_(state_size),
      parameters_(parameters),
      result_(result),
      values_(columns.names().size()),
      derivatives_(columns.names().size() * static_cast<std::size_t>(parameters)) {
  result_.tracking = 0.0;
  result_.tracking_gradient.assign(static_cast<std::size_t>(parameters), 0.0);
}

void IntervalRecorder::Record(double t, const double* y, const double* const* s) {
  if (row_ >= plan_.times.size()) return;
  const std::size_t row = row_++;
  const bool end = row + 1 == plan_.times.size();
  const std::vector<TrackingPoint>& points = plan_.points[row];
  if (points.empty() && !end) return;
  columns_.Evaluate(t, y, s, values_.data(), derivatives_.data());
  const std::size_t count = values_.size();
  const auto K = static_cast<std::size_t>(parameters_);
  for (const TrackingPoint& point : points) {
    const auto c = static_cast<std::size_t>(index_.columns[static_cast<std::size_t>(
        index_.tracked[static_cast<std::size_t>(point.term)])]);
    const double residual = values_[c] - point.reference;
    result_.tracking += point.weight * residual * residual;
    for (std::size_t k = 0; k < K; ++k) {
      result_.tracking_gradient[k] += 2.0 * point.weight * residual * derivatives_[k * count + c];
    }
  }
  if (!end) return;
  const auto n = static_cast<std::size_t>(n_);
  result_.state.assign(y, y + n);
  result_.sensitivities.resize(K * n);
  for (std::size_t k = 0; k < K; ++k) {
    std::copy(s[k], s[k] + n, result_.sensitivities.begin() + static_cast<std::ptrdiff_t>(k * n));
  }
  const std::size_t used = index_.columns.size();
  result_.columns.resize(used);
  result_.column_gradients.resize(K * used);
  for (std::size_t u = 0; u < used; ++u) {
    const auto c = static_cast<std::size_t>(index_.columns[u]);
    result_.columns[u] = values_[c];
    for (std::size_t k = 0; k < K; ++k)
      result_.column_gradients[k * used + u] = derivatives_[k * count + c];
  }
}

}  // namespace musclesim
