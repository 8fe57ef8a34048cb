#include "cli/progress_report.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace musclesim::cli {

namespace {

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

ProgressReport::ProgressReport(bool quiet) : quiet_(quiet), terminal_(::isatty(2) != 0) {}

void ProgressReport::Update(long done, long total) {
  done_ = done;
  total_ = total;
  if (!started_) {
    started_ = true;
    start_done_ = done;
    start_ = Now();
    return;
  }
  Print(false);
}

void ProgressReport::Finish() {
  if (started_) Print(true);
}

void ProgressReport::Print(bool final) {
  if (quiet_) return;
  const double now = Now();
  if (!final && now - last_print_ < (terminal_ ? 0.2 : 10.0)) return;
  last_print_ = now;
  const double elapsed = now - start_;
  const double rate = elapsed > 0 ? (done_ - start_done_) / elapsed : 0.0;
  const double eta = rate > 0 ? (total_ - done_) / rate : 0.0;
  char text[160];
  if (terminal_) {
    const int width = 30;
    const int filled = total_ > 0 ? static_cast<int>(width * done_ / total_) : width;
    std::snprintf(text, sizeof text, "\r[%.*s%*s] %ld/%ld  %.1f runs/s  ETA %.0f s ", filled,
                  "##############################", width - filled, "", done_, total_, rate, eta);
    std::cerr << text << (final ? "\n" : "") << std::flush;
  } else {
    std::snprintf(text, sizeof text, "sweep: %ld/%ld points, %.1f runs/s, ETA %.0f s\n", done_,
                  total_, rate, eta);
    std::cerr << text << std::flush;
  }
}

}  // namespace musclesim::cli
