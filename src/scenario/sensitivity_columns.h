// Private: the trajectory columns a run with sensitivities differentiates, and their values
// and derivatives at one row by the chain rule (docs/model.md 10):
// d column/dp = d column/dy s_p + d column/dp at fixed y.
#pragma once

#include <string>
#include <vector>

#include "musclesim/dynamics/network.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/solver/sensitivity.h"

namespace musclesim {

class SensitivityColumns {
 public:
  // The columns of a scenario of `form` built as `system`, differentiated with respect to
  // `parameters`; keeps references to both.
  SensitivityColumns(ScenarioForm form, const NetworkSystem& system,
                     const std::vector<SensitivityParameter>& parameters);
  // The columns' CSV names (scenario/sensitivity_run.h lists them).
  const std::vector<std::string>& names() const { return names_; }
  // The columns at (t, y) into `values` (names().size()), and into `derivatives`
  // (parameters x columns) d column / d parameter, s[p] the state's sensitivity to p.
  void Evaluate(double t, const double* y, const double* const* s, double* values,
                double* derivatives);
  // The state component column c reads, and the sign it reads it with (-1 for a shortening
  // velocity); -1 for a column that is a function of the state rather than one of it.
  int StateOf(std::size_t c, double& sign) const;
  // The sample observed at the last Evaluate's (t, y).
  const NetworkSample& sample() const { return sample_; }

 private:
  enum class Kind {
    kPosition,
    kVelocity,
    kShortening,
    kActivation,
    kLength,
    kTension,
    kPassive,
    kActive,
    kJunctionVelocity
  };
  struct Column {
    Kind kind;
    int index;  // a state (position, velocity, shortening, activation), an element, or a
                // junction's node
  };
  // A free node's columns in 2 or 3 dimensions, its states from `state` on.
  void AddCoordinates(const std::string& node, int d, int state);

  const NetworkSystem& system_;
  const std::vector<SensitivityParameter>& parameters_;
  std::vector<std::string> names_;
  std::vector<Column> columns_;
  NetworkSample sample_;
  std::vector<NetworkSystem::ElementPartials> partials_;  // per element, one parameter's
  NetworkScratch scratch_;                                // the parameters' derivatives' buffers
};

}  // namespace musclesim
