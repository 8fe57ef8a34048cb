#include "musclesim/solver/simulation.h"

#include <cmath>
#include <limits>

#include "cvode_workspace.h"
#include "musclesim/core/enum_names.h"
#include "musclesim/core/errors.h"
#include "musclesim/solver/integration_session.h"

namespace musclesim {

LinearSolverKind ChooseLinearSolver(const JacobianPattern& pattern) {
  // up to a few dozen states a dense LU costs less than band or sparse bookkeeping, and a
  // fixed-size one with its own vector least (docs/solver.md)
  // a band this narrow (a chain has 3 + 2) factors in O(n) with less overhead than KLU; a
  // wider one (nodes listed out of order) grows as n times its width, the sparse structure
  // as the entries, and its difference quotient needs a few right-hand sides per Jacobian
  // (coloured_difference_quotient.h) where the band's needs one per column of the band
  constexpr int kNarrowBand = 8;
  if (pattern.size <= kSmallSystemMaxSize) return LinearSolverKind::kSmall;
  if (pattern.lower_bandwidth + pattern.upper_bandwidth <= kNarrowBand) {
    return LinearSolverKind::kBand;
  }
  return LinearSolverKind::kSparse;
}

constexpr EnumName<RunStatus> kStatusNames[] = {
    {RunStatus::kCompleted, "completed"},
    {RunStatus::kLimit, "limit"},
    {RunStatus::kFailed, "failed"},
};

std::string_view ToString(RunStatus status) { return ToString(kStatusNames, status); }

namespace {

// The time span and the output grid, as both kinds of run request have them.
void ValidateSpan(double t_start, double t_end) {
  Require(std::isfinite(t_start), "t_start", t_start, "must be finite [s]");
  Require(std::isfinite(t_end) && t_end > t_start, "t_end", t_end,
          "must be finite and greater than t_start = " + FormatNumber(t_start) + " [s]");
}

void ValidateOutputInterval(double t_start, double t_end, double interval) {
  // 0 asks for every internal step; otherwise a positive grid of at most 1e8 rows
  Require(interval == 0.0 ||
              (std::isfinite(interval) && interval > 0.0 && (t_end - t_start) / interval <= 1e8),
          "output_interval", interval,
          "must be > 0 with at most 1e8 rows over the run, or 0 for every step [s]");
}

}  // namespace

void Validate(const RunRequest& r) {
  ValidateSpan(r.t_start, r.t_end);
  Require(std::isfinite(r.length) && r.length > 0.0, "length", r.length,
          "must be finite and > 0 [m]");
  Require(std::isfinite(r.lengthening_rate), "lengthening_rate", r.lengthening_rate,
          "must be finite [m/s]");
  ValidateOutputInterval(r.t_start, r.t_end, r.output_interval);
  if (r.min_length) {
    Require(std::isfinite(*r.min_length) && *r.min_length >= 0.0 && *r.min_length < r.length,
            "min_length", *r.min_length,
            "must be >= 0 and below the initial length = " + FormatNumber(r.length) + " [m]");
  }
  if (r.max_length) {
    Require(std::isfinite(*r.max_length) && *r.max_length > r.length, "max_length", *r.max_length,
            "must be above the initial length = " + FormatNumber(r.length) + " [m]");
  }
}

void Validate(const NetworkRunRequest& r) {
  ValidateSpan(r.t_start, r.t_end);
  ValidateOutputInterval(r.t_start, r.t_end, r.output_interval);
  for (double v : r.initial_state) Require(std::isfinite(v), "initial_state", v, "must be finite");
  for (std::size_t i = 0; i < r.output_times.size(); ++i) {
    const double t = r.output_times[i];
    const double previous =
        i == 0 ? -std::numeric_limits<double>::infinity() : r.output_times[i - 1];
    Require(std::isfinite(t) && t >= r.t_start && t <= r.t_end && t > previous, "output_times", t,
            "must be strictly increasing within [t_start, t_end] = [" + FormatNumber(r.t_start) +
                ", " + FormatNumber(r.t_end) + "] [s]");
  }
}

Simulation::Simulation() : workspace_(std::make_unique<CvodeWorkspace>()) {}
Simulation::~Simulation() = default;

namespace {

// Collects the points in a vector.
class VectorSink final : public TrajectorySink {
 public:
  explicit VectorSink(std::vector<TrajectoryPoint>& points) : points_(points) { points_.clear(); }
  void Record(const TrajectoryPoint& point) override { points_.push_back(point); }

 private:
  std::vector<TrajectoryPoint>& points_;
};

// The single actuator's view of its network's samples (element 0 the actuator, node 1 the tip).
class ActuatorView final : public NetworkSink {
 public:
  explicit ActuatorView(TrajectorySink& out) : out_(out) {}
  void Record(double t, const NetworkSample& s) override {
    const ElementSample& actuator = s.elements[0];
    ActuatorSample sample;
    sample.length = actuator.length;
    sample.shortening_velocity = 0.0 - actuator.lengthening_rate;  // +0 rather than -0 at rest
    sample.activation = actuator.activation;
    sample.excitation = actuator.excitation;
    sample.tension = actuator.parts;
    sample.load = s.load[1];
    out_.Record({t, sample});
  }

 private:
  TrajectorySink& out_;
};

class NetworkVectorSink final : public NetworkSink {
 public:
  explicit NetworkVectorSink(NetworkRunResult& result) : result_(result) {}
  void Record(double t, const NetworkSample& sample) override {
    result_.times.push_back(t);
    result_.samples.push_back(sample);
  }

 private:
  NetworkRunResult& result_;
};

}  // namespace

NetworkRunRequest NetworkRequestOf(const ActuatorSystem& system, const RunRequest& request) {
  NetworkRunRequest network_request;
  network_request.t_start = request.t_start;
  network_request.t_end = request.t_end;
  network_request.output_interval = request.output_interval;
  if (request.min_length || request.max_length) {
    network_request.limits.push_back({"actuator", request.min_length, request.max_length});
  }
  network_request.initial_state = {request.length, request.lengthening_rate};
  if (system.excitation()) {
    const double u0 = system.excitation()->InitialActivation(request.t_start);
    network_request.initial_state.push_back(u0);
  }
  return network_request;
}

RunResult Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                          const RunRequest& request) {
  RunResult result;
  result.stats = Run(system, options, request, result.trajectory);
  return result;
}

RunStats Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                         const RunRequest& request, std::vector<TrajectoryPoint>& trajectory) {
  VectorSink sink(trajectory);
  return Run(system, options, request, sink);
}

RunStats Simulation::Run(const ActuatorSystem& system, const SolverOptions& options,
                         const RunRequest& request, TrajectorySink& sink) {
  Validate(request);
  ActuatorView view(sink);
  return Run(system.network(), options, NetworkRequestOf(system, request), view);
}

NetworkRunResult Simulation::Run(const NetworkSystem& system, const SolverOptions& options,
                                 const NetworkRunRequest& request) {
  NetworkRunResult result;
  NetworkVectorSink sink(result);
  result.stats = Run(system, options, request, sink);
  return result;
}

RunStats Simulation::Run(const NetworkSystem& system, const SolverOptions& options,
                         const NetworkRunRequest& request, NetworkSink& sink) {
  Validate(options);
  Validate(request);
  IntegrationSession session(*this, system, options, request, &sink);
  return session.AdvanceTo(request.t_end, OutputGrid::Of(request));
}

RunStats Simulation::Run(const NetworkSystem& system, const SolverOptions& options,
                         const NetworkRunRequest& request,
                         const std::vector<SensitivityParameter>& parameters,
                         SensitivitySink& sink) {
  Validate(options);
  Validate(request);
  IntegrationSession session(*this, system, options, request, nullptr, &parameters, &sink);
  return session.AdvanceTo(request.t_end, OutputGrid::Of(request));
}

}  // namespace musclesim
