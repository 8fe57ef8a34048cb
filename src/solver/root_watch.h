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
#include "musclesim/core/brent_minimum.h"
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
    FindDips(cb, t_before, t, interpolate, first);
    if (first < 0) before_.swap(after_);
    return first;
  }

  double crossing_time() const { return crossing_time_; }  // [s]
  const Root& root(int i) const { return roots_[static_cast<std::size_t>(i)]; }

 private:
  // A segment's length is never below 0, so one that shortens through its level and back
  // within a step changes no sign at the step's ends (docs/model.md 12.5). A minimum inside
  // the step shows as the length falling just after the step's start and rising just before
  // its end; where the tangents there reach the level within the step (a convex length, as
  // between two points moving straight, lies above its tangents) its depth is sought on the
  // interpolant, and a dip below the level is a crossing at the first time it reaches it.
  template <typename Interpolate>
  void FindDips(const Callbacks& cb, double t_before, double t, Interpolate interpolate,
                int& first) {
    const double step = t - t_before;
    const double delta = 1e-6 * step;  // [s]: one-sided slopes, far above the times' rounding
    bool near_ends_known = false;
    for (std::size_t i = 0; i < roots_.size(); ++i) {
      const Root& root = roots_[i];
      if (root.kind != Root::kShortSegment || !active_[i] || before_[i] <= 0.0 ||
          after_[i] <= 0.0) {
        continue;
      }
      if (!near_ends_known) {
        const double* y = interpolate(t_before + delta);
        start_state_.assign(y, y + system_->state_size());
        y = interpolate(t - delta);
        end_state_.assign(y, y + system_->state_size());
        near_ends_known = true;
      }
      const double falling =
          (RootValue(*system_, root, cb.InputTime(t_before + delta), start_state_.data()) -
           before_[i]) /
          delta;
      const double rising =
          (after_[i] - RootValue(*system_, root, cb.InputTime(t - delta), end_state_.data())) /
          delta;
      // a factor 2 on the tangents' reach for paths that bend (over via points)
      if (!(falling < 0.0 && rising > 0.0 && before_[i] + 2.0 * falling * step <= 0.0 &&
            after_[i] - 2.0 * rising * step <= 0.0)) {
        continue;
      }
      const auto g = [&](double at) {
        return RootValue(*system_, root, cb.InputTime(at), interpolate(at));
      };
      const double tolerance =
          100.0 * std::numeric_limits<double>::epsilon() * (std::abs(t) + std::abs(step));
      const auto [lowest_at, lowest] = BrentMinimum(g, t_before, t, tolerance);
      if (lowest > 0.0) continue;
      const double at = LocateCrossing(g, t_before, before_[i], lowest_at, lowest, tolerance);
      if (first < 0 || at < crossing_time_) {
        first = static_cast<int>(i);
        crossing_time_ = at;
      }
    }
  }

  void Evaluate(const Callbacks& cb, double t, const double* y, std::vector<double>& g) const {
    for (std::size_t i = 0; i < roots_.size(); ++i) {
      g[i] = RootValue(*system_, roots_[i], cb.InputTime(t), y);
    }
  }

  const NetworkSystem* system_ = nullptr;
  std::vector<Root> roots_;
  std::vector<double> before_, after_;
  std::vector<char> active_;
  std::vector<double> start_state_, end_state_;  // FindDips: just inside the step's ends
  bool armed_ = false;                           // before_ holds the values at the last step's end
  double crossing_time_ = 0.0;
};

}  // namespace musclesim
