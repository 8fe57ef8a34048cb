#include "musclesim/solver/integration_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "cvode_workspace.h"
#include "stall_watch.h"
#include "stiffness_note.h"
#include "musclesim/core/errors.h"
#include "output_rows.h"
#include "root_watch.h"
#include "step_polynomial.h"

namespace musclesim {

namespace {

// For a failure on a right-hand side that was not finite: which quantity made it so, and when.
std::string NonFiniteNote(int flag, const Callbacks& cb, const NetworkSystem& system) {
  const bool right_hand_side = flag == CV_RHSFUNC_FAIL || flag == CV_FIRST_RHSFUNC_ERR ||
                               flag == CV_REPTD_RHSFUNC_ERR || flag == CV_UNREC_RHSFUNC_ERR ||
                               flag == CV_CONV_FAILURE || flag == CV_ERR_FAILURE;
  if (!right_hand_side || std::isnan(cb.non_finite_time)) return "";
  return "; the right-hand side was not finite: " +
         system.NonFiniteCause(cb.non_finite_time, cb.non_finite_state.data());
}

// For a failure of the corrector or the error test at a finite right-hand side: the stiffest
// part of the system where the last step began.
std::string StiffnessFailureNote(int flag, void* cvode, const Callbacks& cb,
                                 const NetworkSystem& system, double t, const double* y) {
  if (flag != CV_CONV_FAILURE && flag != CV_ERR_FAILURE) return "";
  double step = 0.0;
  CVodeGetCurrentStep(cvode, &step);
  return StiffnessNote(system, cb.InputTime(t), y, step);
}

// Times a rounding error apart (a pulse edge computed as start + k period + width and an
// output time k interval, say) are one time: CVODE refuses to step over less than a few
// ulps (CV_TOO_CLOSE), so nothing closer than this is integrated over.
double MergeDistance(double start, double end) {
  return 16.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(start), std::abs(end));
}

}  // namespace

OutputGrid OutputGrid::Of(const NetworkRunRequest& request) {
  return {request.output_interval, request.output_times};
}

std::size_t GridRows(const OutputGrid& grid, double start, double end) {
  OutputRows rows;
  rows.Plan(grid, start, end, MergeDistance(start, end));
  if (rows.every_step()) return 0;
  return static_cast<std::size_t>(rows.remaining() + (rows.row_at_start() ? 1 : 0));
}

struct IntegrationSession::Impl {
  Impl(CvodeWorkspace& workspace, const NetworkSystem& network, const SolverOptions& settings,
       NetworkSink* row_sink, const std::vector<SensitivityParameter>* sensitivity_parameters,
       SensitivitySink* sensitivity_rows)
      : ws(workspace),
        system(network),
        options(settings),
        sink(row_sink),
        parameters(sensitivity_parameters),
        sensitivity_sink(sensitivity_rows),
        n(network.state_size()),
        sensitivity_count(parameters == nullptr ? 0 : static_cast<int>(parameters->size())),
        rows_sensitivities(static_cast<std::size_t>(sensitivity_count)) {}

  void Prepare(const NetworkRunRequest& start);
  RunStats Advance(double until, const OutputGrid& grid);

  // One segment [t, stop] between breakpoints; a status once the integration ends in it.
  std::optional<RunStatus> Segment(double stop);
  // The root `hit` reached at (t, y): a limit ends the run, a kink restarts the integrator.
  std::optional<RunStatus> Reached(int hit, double stop);
  // The step just taken crossed root `hit`: go on from the crossing, or end there.
  std::optional<RunStatus> Crossed(int hit, double stop);
  RunStatus Finish(RunStatus status, double at, std::string message);
  // A row labelled `at` of the state `state` at time `state_time` (a rounding error from at).
  void Record(double at, const double* state, double state_time);
  void Record(double at, const double* state) { Record(at, state, at); }
  // The grid's rows up to `until` within the last step, the state there `at_until`;
  // `through_until`: also a row at `until` (or a rounding error past it).
  void RecordRows(double until, const double* at_until, bool through_until);
  const double* const* SensitivitiesAt(double at);
  // The sensitivities at `at` become those the integrator restarts with.
  void CarrySensitivities(double at);
  const double* Interpolate(double at);
  void Restart(double at);

  CvodeWorkspace& ws;
  const NetworkSystem& system;
  SolverOptions options;
  NetworkSink* sink;
  const std::vector<SensitivityParameter>* parameters;
  SensitivitySink* sensitivity_sink;
  int n;
  int sensitivity_count;
  LinearSolverKind kind = LinearSolverKind::kDense;
  double t = 0.0;
  double* y = nullptr;
  bool configured = false;  // CVODE started for this integration
  bool fresh = false;       // no step taken since the last (re)initialisation
  bool ended = false;
  RootWatch roots;
  OutputRows rows;
  StepPolynomial polynomial;
  std::vector<const double*> rows_sensitivities;
  // the piece under way
  RunStats stats;
  long calls = 0;        // CVode calls, one internal step each: the max_steps guard
  double run_end = 0.0;  // [s]: the time this Advance integrates to
  StallWatch stall;
  double merge = 0.0;  // [s]: times closer than this are one
  double last_row = std::numeric_limits<double>::quiet_NaN();  // [s] the last row recorded
  std::chrono::steady_clock::time_point wall_start;
};

void IntegrationSession::Impl::Prepare(const NetworkRunRequest& start) {
  if (!start.initial_state.empty() && static_cast<int>(start.initial_state.size()) != n) {
    throw ParameterError("initial_state", std::to_string(start.initial_state.size()) + " values",
                         "must hold " + std::to_string(n) +
                             " values (x, xdot of every free node, x alone of a massless "
                             "junction, then the activation of every actuator with activation "
                             "dynamics)");
  }
  std::vector<double> initial(static_cast<std::size_t>(n));
  if (start.initial_state.empty()) {
    system.InitialState(start.t_start, initial.data());
  } else {
    initial = start.initial_state;
  }
  system.CheckInitialState(start.t_start, initial.data());
  roots.Watch(system, RootsOf(system, start, initial.data()));

  kind = options.linear_solver == LinearSolverKind::kAuto
             ? ChooseLinearSolver(system.jacobian_pattern())
             : options.linear_solver;
  if (kind == LinearSolverKind::kSmall && n > kSmallSystemMaxSize) {
    throw ParameterError("linear_solver", "small",
                         "serves at most " + std::to_string(kSmallSystemMaxSize) +
                             " states and this system has " + std::to_string(n) +
                             ": use auto, dense, band or sparse");
  }
  if (sensitivity_count > 0) {
    if (!system.controllers().empty()) {
      // df/dp and the activation rows' refinement assume inputs that no state feeds back into
      throw std::invalid_argument(
          "sensitivities of a network with controllers are not supported yet");
    }
    for (std::size_t i = 0; i < parameters->size(); ++i) {
      const SensitivityParameter& p = (*parameters)[i];
      if (p.derivative == nullptr || static_cast<int>(p.initial.size()) != n) {
        throw std::invalid_argument("sensitivity parameter " + std::to_string(i) +
                                    ": needs a derivative and " + std::to_string(n) +
                                    " initial values");
      }
    }
  }
  ws.Fit(system, kind);
  Callbacks& cb = ws.callbacks();
  cb.system = &system;
  cb.last_error.clear();
  cb.non_finite_time = std::numeric_limits<double>::quiet_NaN();
  cb.parameters = parameters;
  if (sensitivity_count > 0) {
    ws.FitSensitivities(sensitivity_count);
    cb.jacobian_values.resize(static_cast<std::size_t>(system.jacobian_pattern().entries()));
    ws.sensitivity_scales().clear();
    for (int i = 0; i < sensitivity_count; ++i) {
      const SensitivityParameter& p = (*parameters)[static_cast<std::size_t>(i)];
      std::copy(p.initial.begin(), p.initial.end(), N_VGetArrayPointer(ws.sensitivities()[i]));
      ws.sensitivity_scales().push_back(p.scale);
    }
  }
  y = N_VGetArrayPointer(ws.state());
  std::copy(initial.begin(), initial.end(), y);
  t = start.t_start;
}

const double* const* IntegrationSession::Impl::SensitivitiesAt(double at) {
  // those the run (re)started with until a step is taken, then the last step's interpolant's
  for (int i = 0; i < sensitivity_count; ++i) {
    rows_sensitivities[static_cast<std::size_t>(i)] =
        N_VGetArrayPointer(fresh ? ws.sensitivities()[i] : ws.sensitivities_between()[i]);
  }
  if (!fresh && sensitivity_count > 0) {
    ws.Check(CVodeGetSensDky(ws.cvode(), at, 0, ws.sensitivities_between()), "CVodeGetSensDky");
  }
  return rows_sensitivities.data();
}

void IntegrationSession::Impl::Record(double at, const double* state, double state_time) {
  last_row = at;
  if (sensitivity_sink != nullptr) {
    sensitivity_sink->Record(at, state, SensitivitiesAt(state_time));
    return;
  }
  if (sink->RecordState(at, state)) return;
  system.Observe(at, state, ws.sample());
  sink->Record(at, ws.sample());
}

void IntegrationSession::Impl::CarrySensitivities(double at) {
  if (sensitivity_count == 0 || fresh) return;
  ws.Check(CVodeGetSensDky(ws.cvode(), at, 0, ws.sensitivities()), "CVodeGetSensDky");
}

const double* IntegrationSession::Impl::Interpolate(double at) {
  ws.Check(CVodeGetDky(ws.cvode(), at, 0, ws.between()), "CVodeGetDky");
  return N_VGetArrayPointer(ws.between());
}

RunStatus IntegrationSession::Impl::Finish(RunStatus status, double at, std::string message) {
  ws.Accumulate(stats);
  stats.status = status;
  stats.final_time = at;
  stats.message = std::move(message);
  stats.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  ended = status != RunStatus::kCompleted;
  return status;
}

void IntegrationSession::Impl::RecordRows(double until, const double* at_until,
                                          bool through_until) {
  if (rows.every_step()) return;
  // rows strictly inside: more than the interpolant has terms (order + 1 derivatives to
  // fetch), and one polynomial serves them all; fewer, and CVodeGetDky per row costs less
  const long inside = rows.Before(until);
  int order = 0;
  const bool by_polynomial = sensitivity_count == 0 && CVodeGetLastOrder(ws.cvode(), &order) >= 0 &&
                             inside > order + 1 && polynomial.Fetch(ws.cvode(), ws.between(), n);
  double* between = N_VGetArrayPointer(ws.between());
  while (rows.pending()) {
    const double out = rows.next_time();
    if (through_until ? out - until > merge : out >= until - merge) break;
    if (out >= until) {
      Record(out, at_until, until);
    } else if (by_polynomial) {
      polynomial.Evaluate(out, between);
      Record(out, between);
    } else {
      Record(out, Interpolate(out));
    }
    rows.Done();
  }
}

void IntegrationSession::Impl::Restart(double at) {
  CarrySensitivities(at);
  ws.Accumulate(stats);
  ws.Configure(options, at, sensitivity_count);
  fresh = true;
}

std::optional<RunStatus> IntegrationSession::Impl::Crossed(int hit, double stop) {
  // a crossing inside the step: the run goes on from there, on the interpolant's state
  t = roots.crossing_time();
  const double* at_crossing = Interpolate(t);
  std::copy(at_crossing, at_crossing + n, y);
  return Reached(hit, stop);
}

std::optional<RunStatus> IntegrationSession::Impl::Reached(int hit, double stop) {
  const Root& root = roots.root(hit);
  if (root.kind == Root::kKink) stall.Crossed(root.element);
  RecordRows(t, y, root.kind == Root::kKink);
  if (root.kind != Root::kKink) {
    const std::string& name = system.elements()[root.element].name;
    if (last_row != t) Record(t, y);  // (a limit reached at a restart: the row may be there)
    if (root.kind == Root::kShortSegment) {
      return Finish(
          RunStatus::kLimit, t,
          "segment " + std::to_string(root.segment) + " of " + name + "'s path shortened to " +
              FormatNumber(root.level) + " m at t = " + FormatNumber(t) +
              " s: its direction is undefined at 0, the run ends " + "there (docs/model.md 12.5)");
    }
    if (root.kind == Root::kZeroLength) {
      return Finish(
          RunStatus::kFailed, t,
          "the length of " + name + " reached zero at t = " + FormatNumber(t) + " s: it collapsed");
    }
    return Finish(RunStatus::kLimit, t,
                  std::string(root.kind == Root::kMinLength ? "min_length" : "max_length") + " = " +
                      FormatNumber(root.level) + " reached by " + name + ": length " +
                      FormatNumber(system.Length(root.element, t, y)) +
                      " m at t = " + FormatNumber(t) + " s");
  }
  // a kink: restart the integrator on its far side, the sensitivities carried over (the
  // right-hand side is continuous there: no jump, docs/model.md 10)
  Restart(t);
  ws.Check(CVodeSetStopTime(ws.cvode(), stop), "CVodeSetStopTime");
  if (const int limit = roots.Arm(ws.callbacks(), t, y); limit >= 0) return Reached(limit, stop);
  if (rows.every_step()) Record(t, y);
  return std::nullopt;
}

std::optional<RunStatus> IntegrationSession::Impl::Segment(double stop) {
  // the segment [t, stop]: its inputs read a few ulps inside it (Callbacks::InputTime)
  Callbacks& cb = ws.callbacks();
  const double middle = 0.5 * (t + stop);
  cb.input_from = std::min(t + merge, middle);
  cb.input_to = std::max(stop - merge, middle);
  // a limit reached between the last step's end and this restart ends the run here
  if (const int hit = roots.Arm(ws.callbacks(), t, y); hit >= 0) return Reached(hit, stop);
  ws.Check(CVodeSetStopTime(ws.cvode(), stop), "CVodeSetStopTime");
  while (t < stop) {
    if (fresh && stop - t <= merge) {
      // a rounding error past a restart, too close for CVODE's first step (CV_TOO_CLOSE):
      // the state there is the state here
      t = stop;
      RecordRows(t, y, true);
      break;
    }
    const double t_before = t;
    // CVODE bounds its first step by the distance to the time asked for: the next row, as
    // when it integrated row by row, so a restart starts as cautiously
    const double toward =
        fresh && !rows.every_step() && rows.pending() ? std::min(rows.next_time(), stop) : stop;
    fresh = false;
    bool explained = false;
    if (std::string stalled = stall.Check(system, t, calls, run_end, options.max_steps, explained);
        !stalled.empty()) {
      double step = 0.0;
      CVodeGetCurrentStep(ws.cvode(), &step);
      if (!explained) stalled += StiffnessNote(system, cb.InputTime(t), y, step);
      return Finish(RunStatus::kFailed, t, std::move(stalled));
    }
    if (calls == options.max_steps) {
      // CVODE's own name for the condition, which the driver checks itself: one step per call
      return Finish(RunStatus::kFailed, t,
                    "CVODE failed at t = " + FormatNumber(t) +
                        " s with CV_TOO_MUCH_WORK (more than max_steps = " +
                        std::to_string(options.max_steps) + " internal steps)");
    }
    ++calls;
    const int flag = CVode(ws.cvode(), toward, ws.state(), &t, CV_ONE_STEP);
    if (flag < 0) {
      return Finish(RunStatus::kFailed, t,
                    "CVODE failed at t = " + FormatNumber(t) + " s with " + FlagName(flag) +
                        (cb.last_error.empty() ? "" : " (" + cb.last_error + ")") +
                        NonFiniteNote(flag, cb, system) +
                        (std::isnan(cb.non_finite_time)
                             ? StiffnessFailureNote(flag, ws.cvode(), cb, system, t, y)
                             : ""));
    }
    const int hit = roots.Step(cb, t_before, t, y, [&](double at) { return Interpolate(at); });
    if (hit >= 0) {
      if (const std::optional<RunStatus> ended_here = Crossed(hit, stop)) return ended_here;
      continue;
    }
    RecordRows(t, y, true);
    if (rows.every_step()) Record(t, y);
  }
  return std::nullopt;
}

RunStats IntegrationSession::Impl::Advance(double until, const OutputGrid& grid) {
  if (ended) {
    throw std::logic_error("advance after the integration ended at t = " + FormatNumber(t) + " s");
  }
  Require(std::isfinite(until) && until > t, "t_end", until,
          "must be finite and after the integration's time = " + FormatNumber(t) + " [s]");
  wall_start = std::chrono::steady_clock::now();
  stats = RunStats{};
  stats.linear_solver = kind;
  stats.sensitivities = sensitivity_count;
  calls = 0;
  run_end = until;
  stall.Start(t, calls);
  merge = MergeDistance(t, until);
  std::vector<double> stops;
  for (double b : system.Breakpoints(t, until)) {
    const double previous = stops.empty() ? t : stops.back();
    if (b - previous > merge && until - b > merge) stops.push_back(b);
  }
  stops.push_back(until);
  rows.Plan(grid, t, until, merge);
  // the first piece starts CVODE; a later one goes on from the last, with its history (its
  // tolerances and settings are the same options)
  fresh = !configured;
  if (!configured) ws.Configure(options, t, sensitivity_count);
  configured = true;
  if (rows.row_at_start()) Record(t, y);
  for (double stop : stops) {
    if (Segment(stop)) return stats;
    if (stop < until) {
      // an input jumps at `stop`: restart with fresh history (a time that depends on no
      // parameter, so the sensitivities carry over unchanged)
      Restart(t);
    }
  }
  Finish(RunStatus::kCompleted, t, "");
  return stats;
}

IntegrationSession::IntegrationSession(Simulation& simulation, const NetworkSystem& system,
                                       const SolverOptions& options, const NetworkRunRequest& start,
                                       NetworkSink* sink,
                                       const std::vector<SensitivityParameter>* parameters,
                                       SensitivitySink* sensitivity_sink)
    : impl_(std::make_unique<Impl>(simulation.workspace(), system, options, sink, parameters,
                                   sensitivity_sink)) {
  Validate(options);
  Require(std::isfinite(start.t_start), "t_start", start.t_start, "must be finite [s]");
  for (double v : start.initial_state)
    Require(std::isfinite(v), "initial_state", v, "must be finite");
  impl_->Prepare(start);
}

IntegrationSession::~IntegrationSession() = default;

RunStats IntegrationSession::AdvanceTo(double until, const OutputGrid& rows) {
  return impl_->Advance(until, rows);
}

double IntegrationSession::time() const { return impl_->t; }
bool IntegrationSession::ended() const { return impl_->ended; }

}  // namespace musclesim
