// A scenario's run with forward sensitivities (docs/model.md section 10): the trajectory's
// differentiated columns and their derivatives with respect to parameters named by their key
// paths (scenario/parameter.h), as data. Each parameter's df/dp is a closed form where one is
// known (a tension model's parameters, a spring's, tendon's or damper's coefficients), else a
// difference quotient of the right-hand side between copies of the scenario set at p +- h
// through the parameter's handle. `musclesim run --sensitivity` writes the same numbers as CSV
// (io/writers/run_csv.h).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/scenario/scenario.h"
#include "musclesim/solver/sensitivity.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// How a parameter's right-hand-side derivative df/dp is computed.
enum class DerivativeSource {
  kAnalytic,            // closed form
  kDifferenceQuotient,  // a difference quotient between the scenario set at p +- h
};
std::string_view ToString(DerivativeSource source);

// One parameter asked for: its key path, and who asked, for messages ("--sensitivity", or
// "FILE:LINE:COLUMN: sensitivities[0]"; empty: the path alone).
// `size` is the parameter's typical magnitude [its unit] where the caller knows one better
// than the value (an identification's start while its estimate nears 0): a difference
// quotient steps by a fraction of max(|value|, size) (1 where both are 0), so that a value
// near 0 is not differentiated by a step that moves nothing.
struct SensitivityRequest {
  std::string path;
  std::string where;
  double size = 0.0;
};

struct SensitivityTable {
  // The differentiated columns, by their CSV names. A single actuator: length,
  // shortening_velocity, activation (only with activation dynamics, where it is a state),
  // tension_passive, tension_active, tension_total. A network: NODE.position and
  // NODE.velocity of every free node (in 2 or 3 dimensions NODE.x, NODE.y (NODE.z), NODE.vx,
  // NODE.vy (NODE.vz), as the run's columns), ELEMENT.length and ELEMENT.tension of every
  // element, ACTUATOR.activation (with activation dynamics), ACTUATOR.tension_passive and
  // ACTUATOR.tension_active.
  std::vector<std::string> columns;
  std::vector<std::string> parameters;    // the paths, written one way
  std::vector<double> parameter_values;   // each parameter's value in the scenario
  std::vector<DerivativeSource> sources;  // per parameter
  std::vector<double> times;              // [s], one per row
  std::vector<double> values;             // rows x columns, row-major
  std::vector<double> derivatives;        // rows x parameters x columns, row-major
  RunStats stats;                         // a solver failure is a status, not a throw

  std::size_t rows() const { return times.size(); }
  double value(std::size_t row, std::size_t column) const {
    return values[row * columns.size() + column];
  }
  // d columns[column] / d parameters[parameter] at times[row].
  double derivative(std::size_t row, std::size_t parameter, std::size_t column) const {
    return derivatives[(row * parameters.size() + parameter) * columns.size() + column];
  }
  int FindColumn(const std::string& name) const;  // -1 if none
};

// Receives each row of a run with sensitivities: the time, the observed sample (what a plain
// run records), the differentiated columns' values and their derivatives (parameters x
// columns, row-major); valid only during the call.
class SensitivityRowSink {
 public:
  virtual ~SensitivityRowSink() = default;
  virtual void Record(double t, const NetworkSample& sample, const double* values,
                      const double* derivatives) = 0;
};

// A scenario prepared for runs with sensitivities: its system built, each parameter resolved
// into its df/dp and initial sensitivity. Immutable once made; Run may be called many times.
class SensitivityRun {
 public:
  // `parameters` first, then the scenario's own `sensitivities:` (repeats dropped). Throws
  // InputError ("WHERE PATH: rule") for a path that names no number of the dynamics, a
  // setting of the run, a value that cannot move (an integer, or the edge of its range on
  // both sides), a parameter that moves an input breakpoint, and sensitivities of a network
  // with controllers; ParameterError when the scenario's parts do not fit.
  // `system`, when given, is scenario.Build()'s (a LoadedScenario's), not built again.
  SensitivityRun(const Scenario& scenario, const std::vector<SensitivityRequest>& parameters,
                 std::shared_ptr<const NetworkSystem> system = nullptr);
  ~SensitivityRun();
  SensitivityRun(const SensitivityRun&) = delete;
  SensitivityRun& operator=(const SensitivityRun&) = delete;

  const Scenario& scenario() const;
  const NetworkSystem& system() const;
  const std::vector<std::string>& paths() const;  // written one way
  const std::vector<double>& values() const;      // in the scenario
  const std::vector<DerivativeSource>& sources() const;
  const std::vector<std::string>& columns() const;  // the differentiated columns

  // Integrates on `simulation` with rows at `output_times` (strictly increasing, within the
  // run; empty: the scenario's output grid), each to `sink`. A solver failure is a status.
  RunStats Run(Simulation& simulation, SensitivityRowSink& sink,
               const std::vector<double>& output_times = {}) const;

 private:
  struct Prepared;
  std::unique_ptr<Prepared> prepared_;
};

// A SensitivityRun of `parameters` (paths, as SensitivityRequest without `where`; `sizes`
// empty or one per parameter, as SensitivityRequest::size) on a new Simulation, collected
// into a table.
SensitivityTable RunWithSensitivities(const Scenario& scenario,
                                      const std::vector<std::string>& parameters,
                                      const std::vector<double>& output_times = {},
                                      const std::vector<double>& sizes = {});

}  // namespace musclesim
