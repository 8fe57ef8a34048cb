// Private: the functions of the state an integration watches (run_roots.h), by their sign at
// the end of every step; only a sign change asks for the crossing's time on the step's
// interpolant. A root exactly zero where the integration starts is inactive until it leaves
// zero, as in CVODE. At a restart the inputs are read a few ulps past the breakpoint (or the
// last advance's end), where the last step read them a few ulps before it: a limit crossed
// in that gap is reported at the restart.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "crossing.h"
#include "cvode_workspace.h"
#include "run_roots.h"

namespace musclesim {

class RootWatch {
 public:
  void Watch(const NetworkSystem& system, std::vector<Root> roots) {
    system_ = &system;
    roots_ = std::move(roots);
    before_.assign(roots_.size(), 0.0);
    after_.assign(roots_.size(), 0.0);
    active_.assign(roots_.size(), 0);
    armed_ = false;
  }

  // Takes the values at a (re)start (t, y) as the ones the next step is compared with; or,
  // when a watched limit (not a kink: the restart restarts anyway) reached zero or changed
  // sign since the last step's end, returns it, its crossing_time() t. -1 otherwise.
  int Arm(const Callbacks& cb, double t, const double* y) {
    Evaluate(cb, t, y, after_);
    for (std::size_t i = 0; armed_ && i < roots_.size(); ++i) {
      if (roots_[i].kind == Root::kKink || !active_[i]) continue;
      if (after_[i] == 0.0 || (after_[i] < 0.0) != (before_[i] < 0.0)) {
        crossing_time_ = t;
        return static_cast<int>(i);
      }
    }
    before_.swap(after_);
    for (std::size_t i = 0; i < roots_.size(); ++i) active_[i] = before_[i] != 0.0;
    armed_ = true;
    return -1;
  }

  // After a step from t_before to (t, y): the earliest root crossed within it (its time in
  // crossing_time()), or -1, the values at t then being those the next step is compared
  // with. `interpolate(at)` gives the state at `at` within the step.
  template <typename Interpolate>
  int Step(const Callbacks& cb, double t_before, double t, const double* y,
           Interpolate interpolate) {
    Evaluate(cb, t, y, after_);
    int first = -1;
    const double step = t - t_before;
    for (std::size_t i = 0; i < roots_.size(); ++i) {
      if (!active_[i]) {
        if (after_[i] != 0.0) active_[i] = 1;  // left zero: watched from here on
        continue;
      }
      if (after_[i] != 0.0 && (after_[i] < 0.0) == (before_[i] < 0.0)) continue;
      const Root& root = roots_[i];
      // CVODE's own location tolerance: 100 ulps of the time and the step
      const double tolerance =
          100.0 * std::numeric_limits<double>::epsilon() * (std::abs(t) + std::abs(step));
      const auto g = [&](double at) {
        return RootValue(*system_, root, cb.InputTime(at), interpolate(at));
      };
      const double at = LocateCrossing(g, t_before, before_[i], t, after_[i], tolerance);
      if (first < 0 || at < crossing_time_) {
        first = static_cast<int>(i);
        crossing_time_ = at;
      }
    }
    if (first < 0) before_.swap(after_);
    return first;
  }

  double crossing_time() const { return crossing_time_; }  // [s]
  const Root& root(int i) const { return roots_[static_cast<std::size_t>(i)]; }

 private:
  void Evaluate(const Callbacks& cb, double t, const double* y, std::vector<double>& g) const {
    for (std::size_t i = 0; i < roots_.size(); ++i) {
      g[i] = RootValue(*system_, roots_[i], cb.InputTime(t), y);
    }
  }

  const NetworkSystem* system_ = nullptr;
  std::vector<Root> roots_;
  std::vector<double> before_, after_;
  std::vector<char> active_;
  bool armed_ = false;  // before_ holds the values at the last step's end
  double crossing_time_ = 0.0;
};

}  // namespace musclesim
