// Private: what one Simulation owns of CVODES, kept from run to run: the SUNDIALS context, the
// state vectors, the linear system and the CVODE memory, the callbacks' data, and the
// counters already added to a run's stats. An IntegrationSession integrates on it.
#pragma once

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "linear_system.h"
#include "musclesim/dynamics/network.h"
#include "musclesim/solver/sensitivity.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// What the C callbacks see through CVODE's user data.
struct Callbacks {
  const NetworkSystem* system = nullptr;
  NetworkScratch scratch;  // the buffers of every evaluation of `system` in this session
  LinearSystem* linear = nullptr;
  void* cvode = nullptr;        // for the error weights of a sparse difference quotient
  long quotient_rhs_evals = 0;  // the right-hand sides that quotient has evaluated
  std::string last_error;
  // the last right-hand side that was not finite: its time (NaN: none yet) and state, kept
  // so that a run failing on it can say which quantity it was
  double non_finite_time = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> non_finite_state;
  void NoteNonFinite(double t, const double* y, std::size_t n) {
    non_finite_time = t;
    non_finite_state.assign(y, y + n);
  }
  // The inputs (activation, excitation, loads) jump only at the stop times, and a step's
  // right-hand sides belong to the segment it is in: an implicit step ending on a stop
  // must see the input before the jump, a restart the input after it, whichever side of
  // the exact time the waveform puts its edge. The inputs are read at the time clamped into
  // [input_from, input_to], a few ulps inside the segment.
  double input_from = 0.0;
  double input_to = 0.0;
  double InputTime(double t) const { return std::clamp(t, input_from, input_to); }
  // a run with sensitivities: its parameters, and room for df/dy
  const std::vector<SensitivityParameter>* parameters = nullptr;
  std::vector<double> jacobian_values;
};

// CVODE's name for a return flag ("CV_TOO_MUCH_WORK").
std::string FlagName(int flag);

class CvodeWorkspace {
 public:
  CvodeWorkspace();
  ~CvodeWorkspace();
  CvodeWorkspace(const CvodeWorkspace&) = delete;
  CvodeWorkspace& operator=(const CvodeWorkspace&) = delete;

  // Makes the state vector and linear system fit `system` with `kind`, keeping the CVODE
  // memory when they already do (a sweep's runs of one scenario).
  void Fit(const NetworkSystem& system, LinearSolverKind kind);
  // Vectors for `count` sensitivities like the state (after Fit).
  void FitSensitivities(int count);
  // Creates the CVODE memory for `options`, or re-initialises the existing one at (t, state),
  // with the tolerances, Jacobian and step settings of `options` and `count` sensitivities
  // switched on (at the values in sensitivities()) or off.
  void Configure(const SolverOptions& options, double t, int count);
  // Adds CVODE's counters since the last (re)initialisation, less those already counted,
  // to `stats`.
  void Accumulate(RunStats& stats);
  // Throws std::runtime_error naming `call` and the flag when `flag` is an error.
  void Check(int flag, const char* call) const;

  void* cvode() const { return cvode_; }
  N_Vector state() const { return state_; }
  N_Vector between() const { return between_; }  // a state interpolated within the last step
  N_Vector* sensitivities() const { return sensitivities_; }  // at the last (re)start
  N_Vector* sensitivities_between() const { return sensitivities_between_; }
  Callbacks& callbacks() { return callbacks_; }
  NetworkSample& sample() { return sample_; }  // re-used by every record
  std::vector<double>& sensitivity_scales() { return sensitivity_scales_; }  // pbar

  // Where a run that completed without sensitivities ended: a later piece of the same
  // integration may go on from there with CVODE's history (IntegrationSession).
  const NetworkSystem* resumable_system = nullptr;
  double resumable_time = 0.0;

 private:
  void Start(IntegrationMethod method, double t);
  void ConfigureSensitivities(int count);
  void FreeSensitivities();

  SUNContext context_ = nullptr;
  N_Vector state_ = nullptr;
  N_Vector between_ = nullptr;
  std::unique_ptr<LinearSystem> linear_;
  void* cvode_ = nullptr;
  IntegrationMethod method_ = IntegrationMethod::kBdf;
  Callbacks callbacks_;
  NetworkSample sample_;
  N_Vector* sensitivities_ = nullptr;
  N_Vector* sensitivities_between_ = nullptr;
  int sensitivity_count_ = 0;
  int sensitivities_initialized_ = 0;  // the count CVodeSensInit1 was given; 0: none
  bool sensitivities_on_ = false;
  std::vector<double> sensitivity_scales_;  // pbar: CVODES keeps the pointer
  // CVODE's counters since the last (re)initialisation already added to a run's stats
  RunStats counted_;
};

}  // namespace musclesim
