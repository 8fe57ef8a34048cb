// Handles on the numbers of a Scenario, each named by the key path its file form writes it
// at (docs/guide/cpp.md):
//   single actuator  model.f_iso, actuator.mass, initial.length, activation.after,
//                    load[0].value, excitation.high, activation_dynamics.tau_activation
//   network          models.muscle.velocity.v_max, nodes[1].mass, elements[0].activation.value,
//                    elements[2].exponential.alpha, loads[0].value, controllers[0].gains.kp;
//                    in 2 or 3 dimensions a coordinate by its index: nodes[1].position[1] (y),
//                    nodes[0].fixed[2], nodes[2].prescribed[1].amplitude, gravity[1]
//   either           time.end, solver.rtol, output.interval, limits (limits.max_length in the
//                    single-actuator form, limits[0].max_length in a network's)
// A handle is found once in a scenario and then reads and writes that value in any scenario
// with the same parts (a copy of it, say), in place and without text: `--set`-like changes
// from code, sweep axes, sensitivities and identification all move values through handles.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "musclesim/core/input_ranges.h"

namespace musclesim {

struct Scenario;
struct ModelSpec;

class Parameter {
 public:
  // The key path, written the one way the handle's form writes it ("load[0].after").
  const std::string& path() const { return path_; }
  // The path into the scenario's network: the same number under one name whatever the form
  // ("loads[0].value" for a single actuator's load.value and load[0].value alike).
  const std::string& network_path() const { return network_path_; }

  // The value in `scenario` [the key's unit].
  double Get(const Scenario& scenario) const;

  // Sets the value in `scenario` and checks it: against the key's range (as the file reader
  // does), for an integer key that it is one, and then the scenario as a whole, every rule a
  // run checks (Scenario::Validate; a model block is rebuilt, its Gaussians refitted when it
  // asks for a fit). Throws ParameterError naming the path (or the part of the scenario the
  // value breaks), the value and the rule, and leaves `scenario` as it was.
  void Set(Scenario& scenario, double value) const;

  // What Set checks of the value alone: finite, an integer for an integer key, within the
  // key's range. Throws ParameterError.
  void Check(double value) const;
  // Writes the value without checking anything (a model block's spec only, not rebuilt: see
  // SetParameters, which does both).
  void Assign(Scenario& scenario, double value) const;

  // A setting of the run (time, solver, output, limits), not a parameter of its dynamics: it
  // has no sensitivity.
  bool is_setting() const { return setting_; }
  // An integer (velocity.n, fit.count, solver.max_steps): it cannot change continuously.
  bool is_integer() const { return integer_; }
  // A parameter of a tension model: the block's name ("model" for the single actuator) and
  // the path within it ("velocity.v_max"); both empty otherwise.
  const std::string& model() const { return model_; }
  const std::string& model_path() const { return model_path_; }
  // An element's own coefficient (a spring's stiffness, a tendon's alpha, a damper's
  // damping): the element's index and the path within it ("exponential.alpha"); -1 otherwise.
  int element() const { return element_; }
  const std::string& element_path() const { return element_path_; }

 private:
  friend Parameter FindParameter(const Scenario& scenario, const std::string& path);
  friend class ParameterResolver;

  std::string path_, network_path_;
  std::function<double(const Scenario&)> get_;
  std::function<void(Scenario&, double)> set_;  // writes, without checking
  InputRange range_{};                          // [range_.min, range_.max] unless unbounded
  bool bounded_ = false;
  bool integer_ = false;
  bool setting_ = false;
  std::string model_, model_path_;
  std::function<double(const ModelSpec&)> model_get_;
  std::function<void(ModelSpec&, double)> model_set_;
  bool refits_ = false;  // a change re-runs the block's fit
  int element_ = -1;
  std::string element_path_;
};

// Sets values[i] at parameters[i] for every i at once: each value checked alone first
// (Parameter::Check), the model blocks they change rebuilt and the scenario validated once all
// are set, so that values valid only together (a longer initial length with a longer limit)
// are accepted. Throws ParameterError as Parameter::Set does, naming the first value that
// breaks its own rule or what the whole breaks, and leaves `scenario` as it was.
void SetParameters(Scenario& scenario, const std::vector<Parameter>& parameters,
                   const std::vector<double>& values);

// The handle on the number at `path` in `scenario`. Throws ParameterError(path, "", rule)
// when the path is malformed or names nothing numeric in this scenario (a key its form does
// not have, an index past a list's end, a field of another kind of waveform or element).
Parameter FindParameter(const Scenario& scenario, const std::string& path);

}  // namespace musclesim
