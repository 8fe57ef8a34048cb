// The columns a scenario's run records, in the order of its CSV (docs/guide/scenarios.md), as the
// scenario's form chooses them: one list, which the CSV writer (io/writers/run_csv.h) turns into
// text and the Python module into NumPy arrays, so both hold the same numbers.
//
// A single actuator (ScenarioForm::kActuator):
//   t, length, shortening_velocity, activation, [excitation], tension_passive, tension_active,
//   tension_total, load, phase
// (`excitation` only with activation dynamics). A network:
//   t; NODE.position, NODE.velocity of every node; ELEMENT.length, ELEMENT.tension of every
//   element, an actuator adding .shortening_velocity, .activation, [.excitation],
//   .tension_passive, .tension_active, .phase; NODE.load of every free node;
//   CONTROLLER.reference, .measured, .error, .output of every controller. With a skeleton
//   (docs/model.md 15), after the nodes' columns: COORDINATE.q, COORDINATE.u of every
//   coordinate; after an element's length and tension: ELEMENT.moment_arm.COORDINATE for
//   each coordinate it spans.
// A phase column holds text: concentric if the shortening velocity v > v_tol, eccentric if
// v < -v_tol, isometric otherwise (docs/model.md section 6); every other column a number.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim {

enum class Phase { kConcentric, kEccentric, kIsometric };
std::string_view ToString(Phase phase);

// docs/model.md section 6: concentric if v > tolerance, eccentric if v < -tolerance.
inline Phase ClassifyPhase(double shortening_velocity, double tolerance) {
  if (shortening_velocity > tolerance) return Phase::kConcentric;
  if (shortening_velocity < -tolerance) return Phase::kEccentric;
  return Phase::kIsometric;
}

class RunColumns {
 public:
  // The columns of `scenario`'s runs; `system` must be scenario.Build()'s (or one with the
  // same parts). Keeps no reference to either.
  RunColumns(const Scenario& scenario, const NetworkSystem& system);
  // The same in the view of `form` rather than the scenario's own (a single actuator seen as
  // its network, say).
  RunColumns(const Scenario& scenario, const NetworkSystem& system, ScenarioForm form);

  std::size_t size() const { return names_.size(); }
  const std::vector<std::string>& names() const { return names_; }
  // Whether column c holds a phase (text) rather than a number.
  bool is_phase(std::size_t c) const { return columns_[c].kind == Kind::kPhase; }
  // The row at time t [s] of `sample` into `row` (size() values): each column's number, and
  // for a phase column the shortening velocity [m/s] its phase is classified from.
  void Fill(double t, const NetworkSample& sample, double* row) const;
  // The same row straight from the state y at t of `system` (the one the columns were made
  // for), observing only the elements and nodes the columns read, each once into `scratch`
  // (one sample per element): what a single actuator's few columns need. Returns false,
  // writing nothing, when a column needs the whole sample (a controller's); otherwise equals
  // Fill of system.Observe's sample to the last bit.
  bool FillFromState(const NetworkSystem& system, double t, const double* y, double* row,
                     std::vector<ElementSample>& scratch) const;
  // The phase-column flags, one per column, for a writer's loop.
  const std::vector<char>& phase_flags() const { return phase_flags_; }
  // The phase of phase column c whose Fill value is `shortening_velocity` [m/s].
  Phase PhaseOf(std::size_t c, double shortening_velocity) const {
    return ClassifyPhase(shortening_velocity, columns_[c].tolerance);
  }

 private:
  // a node's or the time, an element's (kLength to kPhase), a controller's
  enum class Kind {
    kTime,
    kPosition,
    kVelocity,
    kLoad,
    kLength,
    kTension,
    kShortening,
    kActivation,
    kExcitation,
    kPassive,
    kActive,
    kTotal,
    kPhase,
    kReference,
    kMeasured,
    kError,
    kOutput,
    kCoordinate,
    kSpeed,
    kMomentArm,
  };
  static bool OfElement(Kind kind) { return kind >= Kind::kLength && kind <= Kind::kPhase; }
  struct Column {
    Kind kind;
    int index = 0;  // the node, element, controller, coordinate or (moment arm) element-major
                    // pair
    double tolerance = 0.0;  // a phase column's v_tol [m/s]
  };
  void Add(std::string name, Kind kind, int index = 0, double tolerance = 0.0);
  void AddActuatorView(const Scenario& scenario, const NetworkSystem& system);
  void AddNetworkView(const Scenario& scenario, const NetworkSystem& system);

  std::vector<std::string> names_;
  std::vector<Column> columns_;
  std::vector<char> phase_flags_;   // per column: a phase
  std::vector<int> elements_read_;  // the elements some column reads, ascending
  bool whole_sample_ = false;       // a column reads a controller's sample
  bool actuator_view_ = false;      // the single actuator's columns, in their fixed order
  bool excitation_ = false;         // ... with the excitation column
};

}  // namespace musclesim
