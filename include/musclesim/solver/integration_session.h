// One integration of a network on a Simulation's CVODE memory (docs/solver.md), advanced piece
// by piece: Start, then AdvanceTo as far as the caller wants. Each piece stops at every input
// breakpoint in it (a CVODE stop time, then a restart), restarts the integrator at every kink
// crossed, ends the integration at a length limit or a collapsed element, and records the
// rows its OutputGrid asks for. Between pieces CVODE keeps its history (order and step size),
// so advancing in pieces costs the steps the pieces need plus the one each end cuts short.
//
// A run to the end (Simulation::Run) is one AdvanceTo; a Stepper (solver/stepper.h) is one
// AdvanceTo per sample time, with a row at each.
#pragma once

#include <memory>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/solver/sensitivity.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// Which rows a piece records: every `interval` from the integration's start, the last at the
// piece's end; the listed `times`; or one per internal step (`interval` 0).
struct OutputGrid {
  double interval = 0.0;      // [s], > 0; 0 (with `times` empty) records every step
  std::vector<double> times;  // [s], strictly increasing within the piece: these rows only
                              // (one at the start only if listed)

  // The grid a request asks for (its output_times, else its output_interval).
  static OutputGrid Of(const NetworkRunRequest& request);
};

// How many rows a piece from `start` to `end` records on `grid`, the one at `start`
// included: what a recorder may reserve. 0 for every step (unknown in advance).
std::size_t GridRows(const OutputGrid& grid, double start, double end);

class IntegrationSession {
 public:
  // An integration of `system` with `options` from `start` (its t_start, initial state and
  // limits; its span and grid are the pieces'), rows to `sink`; or with `parameters`, their
  // forward sensitivities (carried over every restart unchanged), rows to
  // `sensitivity_sink`. `simulation`, `system`, the sinks and the parameters must outlive the
  // session, and the simulation runs nothing else meanwhile. Validates `options`, the
  // initial state and the limits (ParameterError, as Simulation::Run).
  IntegrationSession(Simulation& simulation, const NetworkSystem& system,
                     const SolverOptions& options, const NetworkRunRequest& start,
                     NetworkSink* sink,
                     const std::vector<SensitivityParameter>* parameters = nullptr,
                     SensitivitySink* sensitivity_sink = nullptr);
  ~IntegrationSession();
  IntegrationSession(const IntegrationSession&) = delete;
  IntegrationSession& operator=(const IntegrationSession&) = delete;

  // Integrates from time() to `until` (finite, > time()), recording the rows of `rows` in
  // (time(), until], and at time() itself unless the grid lists times without it. Returns
  // this piece's counters: status kCompleted (time() is then `until`), kLimit or kFailed
  // (time() where it ended), with the message; after either, no further piece may be asked
  // for (std::logic_error).
  RunStats AdvanceTo(double until, const OutputGrid& rows);

  double time() const;  // [s]
  bool ended() const;   // a limit or a failure ended it

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace musclesim
