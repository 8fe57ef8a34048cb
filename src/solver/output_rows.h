// Private: the rows one piece of an integration records (OutputGrid): the grid's times from
// the piece's start to its end, the listed times, or every internal step.
#pragma once

#include <cmath>
#include <vector>

#include "musclesim/solver/integration_session.h"

namespace musclesim {

class OutputRows {
 public:
  // The rows of `grid` over [start, end]; times within `merge` of `end` are `end`.
  void Plan(const OutputGrid& grid, double start, double end, double merge) {
    listed_ = &grid.times;
    start_ = start;
    end_ = end;
    interval_ = grid.interval;
    explicit_ = !grid.times.empty();
    every_step_ = !explicit_ && grid.interval == 0.0;
    row_at_start_ = !explicit_ || grid.times.front() == start;
    skipped_ = row_at_start_ && explicit_ ? 1 : 0;  // a listed start: recorded first
    if (explicit_) {
      count_ = static_cast<long>(grid.times.size()) - skipped_;
    } else if (every_step_) {
      count_ = 0;
    } else {
      count_ = static_cast<long>(std::ceil((end - start) / interval_ - 1e-9));
      // far from t = 0 the span itself carries rounding errors: a grid time within `merge` of
      // the end is the end, which the last row is anyway
      while (count_ > 1 && start + (count_ - 1) * interval_ >= end - merge) --count_;
    }
    next_ = 1;
  }

  bool every_step() const { return every_step_; }
  bool row_at_start() const { return row_at_start_; }
  bool pending() const { return next_ <= count_; }
  long remaining() const { return count_ - next_ + 1; }  // rows still to record
  double next_time() const { return Time(next_); }
  void Done() { ++next_; }
  // How many pending rows lie strictly before `until`.
  long Before(double until) const {
    long inside = 0;
    while (next_ + inside <= count_ && Time(next_ + inside) < until) ++inside;
    return inside;
  }

 private:
  // Row k (1-based) after the start: the last one at the end.
  double Time(long k) const {
    if (explicit_) return (*listed_)[static_cast<std::size_t>(k - 1 + skipped_)];
    return k >= count_ ? end_ : start_ + k * interval_;
  }

  const std::vector<double>* listed_ = nullptr;
  double start_ = 0.0, end_ = 0.0, interval_ = 0.0;
  bool explicit_ = false, every_step_ = false, row_at_start_ = false;
  long count_ = 0, skipped_ = 0, next_ = 1;
};

}  // namespace musclesim
