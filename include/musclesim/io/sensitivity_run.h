// A scenario's run with forward sensitivities (docs/model.md section 10): the trajectory's
// differentiated columns and their derivatives with respect to parameters named by the dotted
// paths `--set` takes, as data. The CLI's `run --sensitivity` writes the same numbers as CSV.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "musclesim/io/output_file.h"
#include "musclesim/solver/simulation.h"

namespace musclesim {

// How a parameter's right-hand-side derivative df/dp is computed.
enum class DerivativeSource {
  kAnalytic,            // closed form (the tension model's parameters)
  kDifferenceQuotient,  // a difference quotient of the right-hand side between the scenario
                        // rebuilt at p +- h (every other parameter)
};
std::string_view ToString(DerivativeSource source);

struct SensitivityTable {
  // The differentiated columns, by their CSV names. A single actuator: length,
  // shortening_velocity, activation (only with activation dynamics, where it is a state),
  // tension_passive, tension_active, tension_total. A network: NODE.position and
  // NODE.velocity of every free node, ELEMENT.length and ELEMENT.tension of every element,
  // ACTUATOR.activation (with activation dynamics), ACTUATOR.tension_passive and
  // ACTUATOR.tension_active.
  std::vector<std::string> columns;
  std::vector<std::string> parameters;         // the paths, as given
  std::vector<double> parameter_values;        // each parameter's value in the scenario
  std::vector<DerivativeSource> sources;       // per parameter
  std::vector<double> times;                   // [s], one per row
  std::vector<double> values;                  // rows x columns, row-major
  std::vector<double> derivatives;             // rows x parameters x columns, row-major
  RunStats stats;                              // a solver failure is a status, not a throw

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

// Loads the scenario `path` (a single actuator or a network) with `overrides` applied, and
// runs it with the sensitivities to `parameters` (dotted paths as `--set` takes them: a
// numeric value of the model, the actuator, a load, the initial state, an element, a node,
// a models block). Rows at `output_times` when it is not empty (strictly increasing, within
// [t_start, t_end]), else at the scenario's output grid. Throws InputError for a bad file or
// override, and for a parameter that is not a number of the dynamics or moves an input
// breakpoint (naming `--sensitivity PATH` and the rule).
SensitivityTable RunWithSensitivities(const std::string& path,
                                      const std::vector<std::string>& overrides,
                                      const std::vector<std::string>& parameters,
                                      const std::vector<double>& output_times = {});

// Whether the scenario `path` lists `sensitivities:` (a look at its top level; false for a
// file that cannot be read, which the scenario's reader then reports).
bool HasSensitivities(const std::string& path);

struct SensitivitySetup;

// `musclesim run --sensitivity`: the trajectory CSV of a scenario with, after its own columns,
// d_<column>/d_<path> for every parameter (in order) and every differentiated column of
// SensitivityTable. Prepared first (errors before any output is opened), then run.
class SensitivityCsvRun {
 public:
  // As RunWithSensitivities; `parameters` come before the scenario's own `sensitivities:`.
  SensitivityCsvRun(const std::string& path, const std::vector<std::string>& overrides,
                    const std::vector<std::string>& parameters);
  ~SensitivityCsvRun();
  SensitivityCsvRun(const SensitivityCsvRun&) = delete;
  SensitivityCsvRun& operator=(const SensitivityCsvRun&) = delete;

  const std::string& output_file() const;  // the scenario's output.file
  const std::string& name() const;         // the scenario's name
  const std::vector<std::string>& parameters() const;
  const std::vector<DerivativeSource>& sources() const;
  // Integrates and streams the rows into `output` (flushed; not committed).
  RunStats Run(StreamedOutput& output);
  long rows() const { return rows_; }

 private:
  std::unique_ptr<SensitivitySetup> setup_;
  long rows_ = 0;
};

}  // namespace musclesim
