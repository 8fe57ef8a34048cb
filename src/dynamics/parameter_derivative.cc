#include "musclesim/dynamics/parameter_derivative.h"

#include <algorithm>

namespace musclesim {

DifferenceQuotientDerivative::DifferenceQuotientDerivative(Stencil stencil)
    : stencil_(std::move(stencil)) {
  states_ = static_cast<std::size_t>(stencil_.front().system->state_size());
  elements_ = stencil_.front().system->elements().size();
  for (const Point& point : stencil_) {
    elements_ = std::min(elements_, point.system->elements().size());
  }
}

void DifferenceQuotientDerivative::RightHandSide(double t, const double* y, double* dfdp,
                                                 NetworkScratch& scratch) const {
  std::vector<double>& rate = scratch.rate;
  rate.resize(states_);
  std::fill(dfdp, dfdp + states_, 0.0);
  for (const Point& point : stencil_) {
    point.system->RightHandSide(t, y, rate.data(), scratch);
    for (std::size_t i = 0; i < states_; ++i) dfdp[i] += point.weight * rate[i];
  }
}

void DifferenceQuotientDerivative::RefineRate(double t, const double* y, const double* s,
                                              double* rate, NetworkScratch& scratch) const {
  const std::size_t n = states_;
  const std::size_t first =
      n - static_cast<std::size_t>(stencil_.front().system->activation_count());
  if (first == n) return;
  for (std::size_t i = first; i < n; ++i) rate[i] = 0.0;
  std::vector<double>& shifted = scratch.shifted;
  std::vector<double>& term = scratch.rate;
  shifted.assign(y, y + n);
  term.resize(n);
  for (const Point& point : stencil_) {
    // an activation's rate depends on its own state and the time only
    for (std::size_t i = first; i < n; ++i) shifted[i] = y[i] + point.offset * s[i];
    point.system->RightHandSide(t, shifted.data(), term.data(), scratch);
    for (std::size_t i = first; i < n; ++i) rate[i] += point.weight * term[i];
  }
}

double DifferenceQuotientDerivative::NodeVelocity(double t, const double* y, int node,
                                                  NetworkScratch& scratch) const {
  double derivative = 0.0;
  for (const Point& point : stencil_) {
    point.system->Observe(t, y, scratch.sample);
    derivative += point.weight * scratch.sample.velocity[static_cast<std::size_t>(node)];
  }
  return derivative;
}

void DifferenceQuotientDerivative::Elements(double t, const double* y,
                                            NetworkSystem::ElementPartials* elements,
                                            NetworkScratch& scratch) const {
  const std::size_t count = elements_;
  std::fill(elements, elements + count, NetworkSystem::ElementPartials{});
  for (const Point& point : stencil_) {
    const double weight = point.weight;
    point.system->Observe(t, y, scratch.sample);
    for (std::size_t e = 0; e < count; ++e) {
      const ElementSample& element = scratch.sample.elements[e];
      elements[e].length += weight * element.length;
      elements[e].total += weight * element.tension;
      elements[e].passive += weight * element.parts.passive;
      elements[e].active += weight * element.parts.active;
    }
  }
}

}  // namespace musclesim
