// musclesim.Stepper: a scenario (a network, or a single actuator as one) stepped piece by
// piece from a Python loop (solver/stepper.h). advance() converts nothing but a float and returns
// one of three prebuilt status strings, so that a 1 kHz loop spends its time integrating.
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "musclesim/scenario/run_columns.h"
#include "musclesim/solver/stepper.h"
#include "overrides.h"
#include "py_scenario.h"
#include "run_data.h"
#include "typed_objects.h"

namespace musclesim::python {

namespace py = pybind11;

namespace {

// `scenario` (either form), ready to step from its time.start with its limits; `rtol` and
// `atol` replace its tolerances.
std::unique_ptr<Stepper> MakeStepper(Scenario scenario, std::optional<double> rtol,
                                     std::optional<double> atol) {
  if (rtol) scenario.solver.rtol = *rtol;
  if (atol) scenario.solver.atol = *atol;
  // a single actuator steps as its network (docs/model.md 7.4: node `tip`, element
  // `actuator`), from its initial state
  return std::make_unique<Stepper>(scenario.Build(), scenario.solver,
                                   StepperStart{scenario.t_start, {}, scenario.limits});
}

class PyStepper {
 public:
  PyStepper(const Scenario& scenario, std::optional<double> rtol, std::optional<double> atol) {
    {
      py::gil_scoped_release release;
      stepper_ = MakeStepper(scenario, rtol, atol);
    }
    const RunColumns layout(scenario, stepper_->system(), ScenarioForm::kNetwork);
    for (std::size_t c = 1; c < layout.size(); ++c) {
      if (!layout.is_phase(c)) {
        columns_.append(py::str(layout.names()[c]));
        numeric_.push_back(c);
      }
    }
    layout_.emplace(layout);
    row_.resize(layout.size());
    statuses_[static_cast<int>(RunStatus::kCompleted)] = py::str("completed");
    statuses_[static_cast<int>(RunStatus::kLimit)] = py::str("limit");
    statuses_[static_cast<int>(RunStatus::kFailed)] = py::str("failed");
  }

  py::str Advance(double t_next) {
    RunStatus status;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      status = stepper_->Advance(t_next);
    }
    return statuses_[static_cast<int>(status)];
  }

  // The reference for the overhead of advance(): the same calls, looped in C++.
  py::str AdvanceEach(const py::array_t<double, py::array::c_style | py::array::forcecast>& times) {
    const auto view = times.unchecked<1>();
    RunStatus status = RunStatus::kCompleted;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      for (py::ssize_t k = 0; k < view.shape(0) && status == RunStatus::kCompleted; ++k) {
        status = stepper_->Advance(view(k));
      }
    }
    return statuses_[static_cast<int>(status)];
  }

  void SetActivation(const std::string& actuator, double value) {
    const auto lock = Exclusive();
    stepper_->SetActivation(actuator, value);
  }

  double time() const {
    const auto lock = Exclusive();
    return stepper_->time();
  }

  py::array_t<double> state() const {
    const auto lock = Exclusive();
    const std::vector<double>& y = stepper_->state();
    return py::array_t<double>(static_cast<py::ssize_t>(y.size()), y.data());
  }

  FloatDict Sample() const {
    const auto lock = Exclusive();
    layout_->Fill(stepper_->time(), stepper_->sample(), row_.data());
    FloatDict sample;
    sample["t"] = stepper_->time();
    for (std::size_t k = 0; k < numeric_.size(); ++k) sample[columns_[k]] = row_[numeric_[k]];
    return sample;
  }

  AnyDict Stats() const {
    const auto lock = Exclusive();
    return StatsDict(stepper_->stats());
  }

  std::string message() const {
    const auto lock = Exclusive();
    return stepper_->message();
  }
  StrList columns() const { return columns_; }

 private:
  // The stepper to this thread alone: advance() runs without the GIL, so two Python threads
  // could otherwise step one integrator at once. The GIL is let go while waiting, so that
  // the thread holding the stepper never waits for a thread that waits for it.
  std::unique_lock<std::mutex> Exclusive() const {
    py::gil_scoped_release release;
    return std::unique_lock<std::mutex>(mutex_);
  }

  mutable std::mutex mutex_;
  std::unique_ptr<Stepper> stepper_;
  StrList columns_;                   // names of sample()'s values after t, in the CSV's order
  std::vector<std::size_t> numeric_;  // their columns in layout_
  std::optional<RunColumns> layout_;  // the network's columns
  py::str statuses_[3];               // by RunStatus
  mutable std::vector<double> row_;   // sample()'s scratch
};

}  // namespace

void BindStepper(py::module_& m) {
  py::class_<PyStepper>(m, "Stepper",
                        "A scenario integrated piece by piece from Python (the C++ Stepper): "
                        "advance to the next sample time, read the state, set the activation "
                        "of actuators no controller drives, advance again. A single-actuator "
                        "scenario steps as its network (docs/model.md 7.4): node `ground` "
                        "fixed at 0, node `tip` (its position is the length), element "
                        "`actuator`, `damper` and `spring` (the last two of coefficient 0 when the "
                        "scenario gives none). Times in s, lengths "
                        "in m, tensions in N, activations in [0, 1].")
      .def(py::init([](const py::object& scenario, const py::object& overrides,
                       std::optional<double> rtol, std::optional<double> atol) {
             // a Scenario (load_scenario, scenario_from_dict) with its set() values, then
             // `set`; or a file's path
             PyScenario s = py::isinstance<PyScenario>(scenario)
                                ? scenario.cast<PyScenario>()
                                : LoadPyScenario(scenario, py::none());
             if (!overrides.is_none()) {
               if (py::isinstance<py::dict>(overrides)) {
                 for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(overrides)) {
                   s.Set(py::str(key).cast<std::string>(),
                         py::reinterpret_borrow<py::object>(value));
                 }
               } else {
                 const std::vector<std::string> more = OverridesFrom(overrides);
                 py::gil_scoped_release release;
                 s.Assign(s.Read(more));
               }
             }
             return std::make_unique<PyStepper>(s.scenario, rtol, atol);
           }),
           py::arg("scenario"), py::arg("set") = py::none(), py::arg("rtol") = py::none(),
           py::arg("atol") = py::none(),
           "A stepper of `scenario`: a Scenario (load_scenario or scenario_from_dict, with the "
           "values set() on it) or a scenario file's path (str or pathlib.Path), `set` applied "
           "after them: a list of \"key=value\" strings as --set takes them, or a dict {key: "
           "value}. `rtol` and `atol` (m, m/s) replace the scenario's solver tolerances. Starts "
           "at the scenario's time.start with its limits; its time.end and output are not used.")
      .def("advance", &PyStepper::Advance, py::arg("t"),
           "Integrates from `time` to `t` [s] (GIL released) and returns \"completed\" (time "
           "is then t), \"limit\" (a length limit was reached; no further advance) or "
           "\"failed\" (see `message`). Raises ValueError unless t is finite and after time.")
      .def("advance_each", &PyStepper::AdvanceEach, py::arg("times"),
           "advance(t) for every t of the 1-D array `times` [s], looped in C++ with the GIL "
           "released; stops at the first that does not complete and returns its status.")
      .def("set_activation", &PyStepper::SetActivation, py::arg("actuator"), py::arg("u"),
           "Holds the activation of `actuator` (with activation dynamics, its excitation) at "
           "`u` in [0, 1] from `time` on (zero-order hold); the next advance restarts the "
           "integrator. Raises ValueError for an unknown name, a non-actuator, an actuator a "
           "controller drives, or u outside [0, 1].")
      .def_property_readonly("time", &PyStepper::time, "Where the integration stands [s].")
      .def_property_readonly("state", &PyStepper::state,
                             "A copy of the state y(time) as a 1-D float64 array, in the "
                             "network's state order (positions [m] and velocities [m/s] of "
                             "the free nodes, then activations of actuators with dynamics).")
      .def("sample", &PyStepper::Sample,
           "What the network CSV would record at `time`: a dict {column: float} with the "
           "CSV's column names (t, <node>.position, <node>.velocity, <element>.length, "
           "<element>.tension, <actuator>.shortening_velocity, .activation, .excitation, "
           ".tension_passive, .tension_active, <node>.load, <controller>.reference, "
           ".measured, .error, .output), without the text column <actuator>.phase.")
      .def_property_readonly("columns", &PyStepper::columns,
                             "The keys of sample() after \"t\", in the CSV's order.")
      .def_property_readonly("stats", &PyStepper::Stats,
                             "Solver counters summed over every advance (steps, rhs_evals, "
                             "...), wall_seconds [s], final_time [s], status and message.")
      .def_property_readonly("message", &PyStepper::message,
                             "Why the last advance ended early (empty if it completed).");
}

}  // namespace musclesim::python
