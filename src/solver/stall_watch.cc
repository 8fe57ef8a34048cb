#include "stall_watch.h"

#include <cmath>
#include <limits>

#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

// The controller driving actuator `element`, or -1.
int ControllerDriving(const NetworkSystem& system, int element) {
  const std::string& name = system.elements()[static_cast<std::size_t>(element)].name;
  const std::vector<Controller>& controllers = system.controllers();
  for (std::size_t k = 0; k < controllers.size(); ++k) {
    const Controller& c = controllers[k];
    const bool drives = c.co_contraction
                            ? c.co_contraction->first == name || c.co_contraction->second == name
                            : c.drives == name;
    if (drives) return static_cast<int>(k);
  }
  return -1;
}

// What the window's steps kept crossing, when one kink took a good share of them.
std::string CrossingCause(const NetworkSystem& system, const std::map<int, long>& crossings,
                          long steps) {
  int most = -1;
  long count = 0;
  for (const auto& [kink, times] : crossings) {
    if (times > count) most = kink, count = times;
  }
  // a kink crossed at one step in a hundred or more is what the steps are spent on
  if (most < 0 || count * 100 < steps) return "";
  const NetworkSystem::Kink& kink = system.kinks()[static_cast<std::size_t>(most)];
  const std::string& element = system.elements()[static_cast<std::size_t>(kink.element)].name;
  const std::string times =
      std::string(" ").append(std::to_string(count)) + " times in those steps";
  if (kink.kind == NetworkSystem::Kink::kCommand) {
    const int k = ControllerDriving(system, kink.element);
    if (k >= 0) {
      const Controller& c = system.controllers()[static_cast<std::size_t>(k)];
      return ": controller " + c.name + " drove " + element + " across its bound " +
             FormatNumber(kink.level) + times +
             ", its command switching between the bounds at every step (gains kp = " +
             FormatNumber(c.gains.kp) + ", ki = " + FormatNumber(c.gains.ki) +
             ", kd = " + FormatNumber(c.gains.kd) +
             "): smaller gains let the loop settle instead of chattering";
    }
  }
  std::string what = kink.kind == NetworkSystem::Kink::kLength            ? "a length"
                     : kink.kind == NetworkSystem::Kink::kLengtheningRate ? "a lengthening rate"
                     : kink.kind == NetworkSystem::Kink::kExcitation      ? "an excitation"
                                                                          : "a command";
  std::string cause = ": ";
  cause += element;
  cause += " crossed " + what + " of " + FormatNumber(kink.level) + " where its law has a kink";
  return cause + times;
}

}  // namespace

std::string StallWatch::Check(const NetworkSystem& system, double t, long calls, double until,
                              long max_steps, bool& explained) {
  const long steps = calls - window_start_calls_;
  if (steps < kWindow) return "";
  const double advanced = t - window_start_time_;
  const double needed = advanced > 0.0 ? (until - t) / advanced * static_cast<double>(steps)
                                       : std::numeric_limits<double>::infinity();
  std::string reason;
  explained = false;
  if (needed > static_cast<double>(max_steps - calls)) {
    reason = "the integration stalled at t = " + FormatNumber(t) + " s: its last " +
             std::to_string(steps) + " steps advanced " + FormatNumber(advanced) +
             " s, and at that pace reaching t = " + FormatNumber(until) + " s needs " +
             FormatNumber(std::round(needed)) +
             " more, beyond max_steps = " + std::to_string(max_steps);
    const std::string cause = CrossingCause(system, crossings_, steps);
    explained = !cause.empty();
    reason += cause;
  }
  Start(t, calls);
  return reason;
}

}  // namespace musclesim
