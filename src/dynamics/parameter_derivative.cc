#include "musclesim/dynamics/parameter_derivative.h"

#include <algorithm>

namespace musclesim {

DifferenceQuotientDerivative::DifferenceQuotientDerivative(Stencil stencil)
    : stencil_(std::move(stencil)) {
  scratch_.resize(static_cast<std::size_t>(stencil_.front().system->state_size()));
  shifted_.resize(scratch_.size());
  elements_ = stencil_.front().system->elements().size();
  for (const Point& point : stencil_) {
    elements_ = std::min(elements_, point.system->elements().size());
  }
}

void DifferenceQuotientDerivative::RightHandSide(double t, const double* y, double* dfdp) const {
  std::fill(dfdp, dfdp + scratch_.size(), 0.0);
  for (const Point& point : stencil_) {
    point.system->RightHandSide(t, y, scratch_.data());
    for (std::size_t i = 0; i < scratch_.size(); ++i) dfdp[i] += point.weight * scratch_[i];
  }
}

void DifferenceQuotientDerivative::RefineRate(double t, const double* y, const double* s,
                                              double* rate) const {
  const std::size_t n = scratch_.size();
  const std::size_t first =
      n - static_cast<std::size_t>(stencil_.front().system->activation_count());
  if (first == n) return;
  for (std::size_t i = first; i < n; ++i) rate[i] = 0.0;
  std::copy(y, y + n, shifted_.begin());
  for (const Point& point : stencil_) {
    // an activation's rate depends on its own state and the time only
    for (std::size_t i = first; i < n; ++i) shifted_[i] = y[i] + point.offset * s[i];
    point.system->RightHandSide(t, shifted_.data(), scratch_.data());
    for (std::size_t i = first; i < n; ++i) rate[i] += point.weight * scratch_[i];
  }
}

double DifferenceQuotientDerivative::NodeVelocity(double t, const double* y, int node) const {
  double derivative = 0.0;
  for (const Point& point : stencil_) {
    point.system->Observe(t, y, sample_);
    derivative += point.weight * sample_.velocity[static_cast<std::size_t>(node)];
  }
  return derivative;
}

void DifferenceQuotientDerivative::Elements(double t, const double* y,
                                            NetworkSystem::ElementPartials* elements) const {
  const std::size_t count = elements_;
  std::fill(elements, elements + count, NetworkSystem::ElementPartials{});
  for (const Point& point : stencil_) {
    const double weight = point.weight;
    point.system->Observe(t, y, sample_);
    for (std::size_t e = 0; e < count; ++e) {
      const ElementSample& element = sample_.elements[e];
      elements[e].length += weight * element.length;
      elements[e].total += weight * element.tension;
      elements[e].passive += weight * element.parts.passive;
      elements[e].active += weight * element.parts.active;
    }
  }
}

}  // namespace musclesim
