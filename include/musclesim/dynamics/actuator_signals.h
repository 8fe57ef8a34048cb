// An actuator's input signals described once (dynamics/signal_fields.h): its activation u(t),
// or its excitation e(t) driving u through activation dynamics. `Part` is what holds them: a
// network's actuator element, or the reader's pair for one (members `activation`, a Waveform,
// and `excitation`, an optional ExcitationInput). Which of the two a file gives is the
// reader's rule; a part has the one it was made with.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "musclesim/dynamics/activation_dynamics.h"
#include "musclesim/dynamics/signal_fields.h"

namespace musclesim {

inline void CheckExcitation(const Waveform& w) { ValidateExcitation(w); }

template <typename Part>
const std::vector<SignalField<Part>>& ActuatorSignals() {
  static const std::vector<SignalField<Part>> signals = [] {
    SignalField<Part> activation = Signal<Part>(
        "activation", "-",
        "u(t) itself; give it or excitation, unless a controller drives the actuator",
        [](auto& part, std::size_t) { return part.excitation ? nullptr : &part.activation; },
        nullptr, CheckActivation);
    SignalField<Part> excitation = Signal<Part>(
        "excitation", "-", "e(t), driving u through activation_dynamics beside it",
        [](auto& part, std::size_t) {
          return part.excitation ? &part.excitation->signal : nullptr;
        },
        nullptr, CheckExcitation);
    for (SignalField<Part>* signal : {&activation, &excitation}) {
      signal->required = false;  // the one or the other: the reader's rule
      signal->accepted = ActivationValues();
    }
    return std::vector{std::move(activation), std::move(excitation)};
  }();
  return signals;
}

}  // namespace musclesim
