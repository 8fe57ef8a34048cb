// A network simulation driven piece by piece from outside: a controller's loop (a user's
// C++ at 1 kHz, say) integrates to the next sample time, reads the state, sets the inputs of
// actuators no controller in the network drives, and integrates on.
//
// Each Advance is one piece of an IntegrationSession (solver/integration_session.h) from
// time() to t_next (breakpoints, kinks and limits as in a run, docs/solver.md). While nothing
// changes between two calls the integrator goes on with its history (order and step size): a
// piece costs the steps it needs plus the one its end cuts short, not a restart (about twice
// a one-shot run's steps at 1 ms pieces, tests/solver/stepper_test.cc). SetActivation changes
// the system, and the next Advance starts a new session at time(), as a run restarts where an
// input jumps.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/solver/integration_session.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// Where a Stepper starts.
struct StepperStart {
  double t_start = 0.0;               // [s], finite
  std::vector<double> initial_state;  // y(t_start) in NetworkSystem's state order; empty: the
                                      // system's own (NetworkSystem::InitialState)
  std::vector<LengthLimit> limits;    // reaching one ends the stepping (status kLimit)
};

class Stepper {
 public:
  // Owns a copy of `system`. Validates `options`, `start` and its limits against the initial
  // state (ParameterError, as Simulation::Run).
  Stepper(NetworkSystem system, SolverOptions options, StepperStart start = {});
  ~Stepper();
  Stepper(const Stepper&) = delete;
  Stepper& operator=(const Stepper&) = delete;

  // Integrates from time() to t_next and returns how that went: kCompleted (time() is then
  // t_next), kLimit (time() where the limit was reached), kFailed (time() where a length
  // reached zero, or unchanged after a solver failure); message() says why. Throws
  // ParameterError("t_next") unless t_next is finite and after time(), std::logic_error
  // after a limit or a failure.
  RunStatus Advance(double t_next);

  // Holds the activation of `actuator` (with activation dynamics, its excitation) at `value`
  // from time() on, a zero-order hold. Throws ParameterError for a name that is no element,
  // an element that is no actuator or is driven by a controller, a value outside [0, 1].
  void SetActivation(std::string_view actuator, double value);

  double time() const { return time_; }                          // [s]
  const std::vector<double>& state() const { return state_; }    // y(time())
  const NetworkSample& sample() const { return sample_; }        // observed at time()
  const NetworkSystem& system() const { return system_; }        // with the inputs held
  const RunStats& stats() const { return stats_; }               // summed over every Advance
  const std::string& message() const { return stats_.message; }  // the last Advance's

 private:
  class Recorder;

  NetworkSystem system_;
  SolverOptions options_;
  std::vector<LengthLimit> limits_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<Recorder> recorder_;           // takes each piece's row
  std::unique_ptr<IntegrationSession> session_;  // the integration under way
  double time_;
  std::vector<double> state_;
  NetworkSample sample_;
  RunStats stats_;
  bool restart_ = true;  // the next Advance starts a new session at time()
  bool ended_ = false;   // a limit or a failure: no further Advance
};

}  // namespace musclesim
