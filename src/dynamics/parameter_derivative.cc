#include "musclesim/dynamics/parameter_derivative.h"

#include <algorithm>

namespace musclesim {

DifferenceQuotientDerivative::DifferenceQuotientDerivative(Stencil stencil)
    : stencil_(std::move(stencil)) {
  scratch_.resize(static_cast<std::size_t>(stencil_.front().first->state_size()));
  elements_ = stencil_.front().first->elements().size();
  for (const auto& entry : stencil_) elements_ = std::min(elements_, entry.first->elements().size());
}

void DifferenceQuotientDerivative::RightHandSide(double t, const double* y, double* dfdp) const {
  std::fill(dfdp, dfdp + scratch_.size(), 0.0);
  for (const auto& [system, weight] : stencil_) {
    system->RightHandSide(t, y, scratch_.data());
    for (std::size_t i = 0; i < scratch_.size(); ++i) dfdp[i] += weight * scratch_[i];
  }
}

void DifferenceQuotientDerivative::Elements(double t, const double* y,
                                            NetworkSystem::ElementPartials* elements) const {
  const std::size_t count = elements_;
  std::fill(elements, elements + count, NetworkSystem::ElementPartials{});
  for (const auto& [system, weight] : stencil_) {
    system->Observe(t, y, sample_);
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
