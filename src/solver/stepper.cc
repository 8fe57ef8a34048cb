#include "musclesim/solver/stepper.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/core/number_format.h"
#include "musclesim/solver/integration_session.h"
#include "run_roots.h"

namespace musclesim {

// Takes the one row of an Advance (or the row where a limit ended it): its time and state,
// then the sample observed there.
class Stepper::Recorder final : public NetworkSink {
 public:
  explicit Recorder(Stepper& stepper) : stepper_(stepper) {}
  bool RecordState(double t, const double* y) override {
    stepper_.time_ = t;
    stepper_.state_.assign(y, y + stepper_.state_.size());
    return false;  // and Record with the sample
  }
  void Record(double, const NetworkSample& sample) override { stepper_.sample_ = sample; }

 private:
  Stepper& stepper_;
};

Stepper::Stepper(NetworkSystem system, SolverOptions options, StepperStart start)
    : system_(std::move(system)),
      options_(options),
      limits_(std::move(start.limits)),
      simulation_(std::make_unique<Simulation>()),
      recorder_(std::make_unique<Recorder>(*this)),
      time_(start.t_start) {
  Validate(options_);
  Require(std::isfinite(time_), "t_start", time_, "must be finite [s]");
  const int n = system_.state_size();
  if (start.initial_state.empty()) {
    state_.resize(static_cast<std::size_t>(n));
    system_.InitialState(time_, state_.data());
  } else {
    if (static_cast<int>(start.initial_state.size()) != n) {
      throw ParameterError("initial_state", std::to_string(start.initial_state.size()) + " values",
                           "must hold the system's " + std::to_string(n) + " states");
    }
    for (double v : start.initial_state) {
      Require(std::isfinite(v), "initial_state", v, "must be finite");
    }
    state_ = std::move(start.initial_state);
  }
  system_.CheckInitialState(time_, state_.data());
  // the limits as a run checks them: elements named, bracketing the initial lengths
  NetworkRunRequest request;
  request.t_start = time_;
  request.limits = limits_;
  RootsOf(system_, request, state_.data());
  system_.Observe(time_, state_.data(), sample_);
  stats_.final_time = time_;
}

Stepper::~Stepper() = default;

RunStatus Stepper::Advance(double t_next) {
  if (ended_) {
    throw std::logic_error("advance after the stepping ended at t = " + FormatNumber(time_) +
                           " s (" + std::string(ToString(stats_.status)) + ": " + stats_.message +
                           "): a new stepper starts again");
  }
  Require(std::isfinite(t_next) && kTimeRange.Contains(t_next), "t_next", t_next,
          "must be finite and at most " + FormatNumber(kTimeRange.max) + " [s]: " + kTimeRange.why);
  // a step CVODE can take: many roundoffs of the time scale (as an output interval)
  const double shortest = kMinIntervalRelative * TimeScale(time_, t_next);
  Require(t_next - time_ >= shortest, "t_next", t_next,
          "must be after time() = " + FormatNumber(time_) + " [s] by at least " +
              FormatNumber(shortest) + " [s], 1e-12 of the time scale max(1 s, |t|)");
  if (restart_) {
    // a new integration from here: the inputs changed, or this is the first piece
    NetworkRunRequest start;
    start.t_start = time_;
    start.limits = limits_;
    start.initial_state = state_;
    session_.reset();
    session_ = std::make_unique<IntegrationSession>(*simulation_, system_, options_, start,
                                                    recorder_.get());
    restart_ = false;
  }
  const RunStats run = session_->AdvanceTo(t_next, OutputGrid{0.0, {t_next}});
  stats_.steps += run.steps;
  stats_.rhs_evals += run.rhs_evals;
  stats_.jac_evals += run.jac_evals;
  stats_.linear_setups += run.linear_setups;
  stats_.newton_iters += run.newton_iters;
  stats_.newton_conv_fails += run.newton_conv_fails;
  stats_.error_test_fails += run.error_test_fails;
  stats_.wall_seconds += run.wall_seconds;
  stats_.final_time = time_;
  stats_.linear_solver = run.linear_solver;
  stats_.status = run.status;
  stats_.message = run.message;
  ended_ = run.status != RunStatus::kCompleted;
  return run.status;
}

void Stepper::SetActivation(std::string_view actuator, double value) {
  const int e = system_.FindElement(actuator);
  if (e < 0) {
    throw ParameterError("actuator", std::string(actuator), "names no element of this network");
  }
  system_.HoldActivation(e, value);  // ParameterError: controlled, no actuator, out of range
  // the input jumps here: the integrator's history belongs to the old one
  restart_ = true;
  system_.Observe(time_, state_.data(), sample_);
}

}  // namespace musclesim
