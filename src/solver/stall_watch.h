// Private: ends a run that crawls. A controller whose gain makes its command switch between
// the activation's bounds at every step (a sliding mode), or a right-hand side nearly
// discontinuous, makes CVODE take ever smaller steps; left alone the run spends max_steps
// (ten million) of them before failing. Every window of steps, the pace of the last one is
// projected to the end: a run that cannot arrive within max_steps at that pace ends now, with
// what it was crossing at every step.
#pragma once

#include <map>
#include <string>

#include "musclesim/dynamics/network.h"

namespace musclesim {

class StallWatch {
 public:
  // Steps per window: long enough that a burst of short steps at a jump in the inputs, which
  // a run recovers from, does not count as a stall.
  static constexpr long kWindow = 1L << 16;

  void Start(double t, long calls) {
    window_start_time_ = t;
    window_start_calls_ = calls;
    crossings_.clear();
  }
  // A kink (NetworkSystem::kinks()) crossed by the last step.
  void Crossed(int kink) { ++crossings_[kink]; }

  // After a step: the reason the run cannot reach `until` within `max_steps` at the pace of
  // the last window, or "" (always "" within a window). `explained` tells whether the reason
  // names what the steps kept crossing.
  std::string Check(const NetworkSystem& system, double t, long calls, double until, long max_steps,
                    bool& explained);

 private:
  double window_start_time_ = 0.0;
  long window_start_calls_ = 0;
  std::map<int, long> crossings_;  // kink -> crossings within the window
};

}  // namespace musclesim
