// A feedback controller of a network (docs/model.md section 11): a PID law computing an
// actuator's activation (or, with activation dynamics, its excitation) from the state,
//   err = r(t) - y(state),   c = u_ff(t) + kp err + ki z + kd d(err)/dt,   zdot = err,
// y an element's length or tension or a free node's position (in 2 or 3 dimensions one
// coordinate of it, and an element's length and tension its path's). One actuator takes u =
// clamp(c, 0, 1); an antagonist pair under co-contraction takes u_first = clamp(level + c, 0, 1)
// and u_second = clamp(level - c, 0, 1), so c steers the pair while the level (the paper's
// co-activation) sets how stiff it is. Make one with the validating factories; NetworkSystem
// checks how it fits the network.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "musclesim/dynamics/waveform.h"

namespace musclesim {

// What a controller measures: an element's length or tension, or a free node's position.
enum class MeasuredQuantity { kLength, kTension, kPosition };
std::string_view ToString(MeasuredQuantity quantity);
MeasuredQuantity ParseMeasuredQuantity(std::string_view text);  // ParameterError("quantity")

struct Measurement {
  std::string element;  // an element's name, or empty when `node` is set
  std::string node;     // a free node's name, or empty when `element` is set
  MeasuredQuantity quantity = MeasuredQuantity::kLength;
  // A node's measured coordinate: 0 (x), 1 (y) or 2 (z); kNoCoordinate leaves it unnamed,
  // which on a line means x and in 2 or 3 dimensions is refused (NetworkSystem).
  int coordinate = kNoCoordinate;
  static constexpr int kNoCoordinate = -1;
};

// "x", "y", "z"; and its inverse, throwing ParameterError("coordinate") for any other text.
std::string_view CoordinateName(int coordinate);
int ParseCoordinate(std::string_view text);

struct PidGains {
  double kp = 0.0;  // [1/unit measured]; negative where more activation lowers the error
  double ki = 0.0;  // [1/(unit s)]: 0 gives the controller no integral state
  double kd = 0.0;  // [s/unit]: 0 on a tension (its rate would need the accelerations)
};

// Two actuators pulling against each other, both driven by one command.
struct CoContraction {
  std::string first;   // takes level + c
  std::string second;  // takes level - c
  Waveform level;      // within [0, 1]
};

struct Controller {
  std::string name;
  Measurement measure;
  Waveform reference;  // r(t) [unit measured]
  PidGains gains;
  Waveform feedforward;  // u_ff(t) [-]; by default 0
  std::string drives;    // the actuator driven; empty with co_contraction
  std::optional<CoContraction> co_contraction;

  static Controller Pid(std::string name, Measurement measure, Waveform reference, PidGains gains,
                        std::string drives);
  static Controller CoContracting(std::string name, Measurement measure, Waveform reference,
                                  PidGains gains, CoContraction pair);
};

// The largest gain magnitude accepted [per unit measured]: beyond it the loop is a switch
// (io/input_ranges.h kGainRange says why), and gains times errors stay finite.
inline constexpr double kMaxGain = 1e9;

// Throws ParameterError with paths as the YAML keys of a controller ("gains.kd",
// "measure.element", "measure.coordinate", "co_contraction.level.value", "drives").
void Validate(const Controller& controller);

// The width of the band below an output's bound over which the integral fades out [-]: the
// integral stops growing as c reaches the bound, continuously, so that the output can slide
// along a bound without the integrator restarting at every step (docs/model.md 11).
inline constexpr double kIntegralFadeBand = 1e-3;

}  // namespace musclesim
