// Scenarios from files or dicts, their parameter handles, set(), run() to NumPy columns filled
// from the run's recorder (run_data.h: no file, no text), and the solver's options and
// counters as types.
#include <pybind11/stl.h>

#include <chrono>
#include <string>
#include <vector>

#include "bindings.h"
#include "document.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/actuator_scenario.h"
#include "musclesim/solver/solver_fields.h"
#include "part_attributes.h"
#include "py_scenario.h"
#include "run_data.h"
#include "typed_objects.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

std::vector<std::string> Paths(const py::object& sensitivities) {
  std::vector<std::string> paths;
  if (sensitivities.is_none()) return paths;
  if (py::isinstance<py::str>(sensitivities)) {
    throw py::type_error("sensitivities must be a list of dotted paths, not one str");
  }
  for (const auto& item : sensitivities) paths.push_back(py::str(item).cast<std::string>());
  return paths;
}

Result Run(const PyScenario& s, const py::object& sensitivities) {
  const std::vector<std::string> paths = Paths(sensitivities);
  // taken with the GIL: another thread may set() meanwhile
  const Scenario scenario = s.scenario;
  const std::shared_ptr<const NetworkSystem> system = s.system;
  RunData data;
  {
    py::gil_scoped_release release;
    data = RunData::Of(scenario, paths, system);
  }
  return MakeResult(std::move(data));
}

py::object ToDataFrame(const Result& result) {
  py::module_ pandas;
  try {
    pandas = py::module_::import("pandas");
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ImportError)) throw;
    throw py::import_error(
        "Result.to_dataframe() needs pandas, which is not installed (Debian: apt install "
        "python3-pandas; elsewhere: pip install pandas); Result.columns holds the same "
        "columns as NumPy arrays");
  }
  return pandas.attr("DataFrame")(result.columns);
}

// A parameter handle bound to its Scenario: reading and writing its value in place.
struct BoundParameter {
  py::object scenario;  // the musclesim.Scenario
  std::string path;
};

void BindResult(py::module_& m) {
  py::class_<Result>(
      m, "Result",
      "One run's trajectory and solver counters, as `musclesim run` writes them (its CSV and "
      "its --stats JSON), recorded straight into NumPy arrays. Rows are the output grid's "
      "times (output.interval) or every internal step (interval: steps). SI units: t in s, "
      "lengths and positions in m, velocities in m/s (shortening_velocity positive when the "
      "actuator shortens), tensions and loads in N, activations and excitations in [0, 1].")
      .def_property_readonly(
          "columns", [](const Result& r) { return ArrayDict(r.columns); },
          "dict {name: 1-D NumPy array of len(result)}, exactly the CLI CSV's columns in its "
          "order: float64, except the text columns `phase` and `<actuator>.phase` "
          "('concentric', 'eccentric', 'isometric'), which are NumPy str arrays. With "
          "sensitivities, d_<column>/d_<path> after them.")
      .def_property_readonly(
          "times", [](const Result& r) { return FloatArray(r.columns[py::str("t")]); },
          "columns['t']: the rows' times [s], float64, shape (len(result),).")
      .def_property_readonly(
          "stats", [](const Result& r) { return AnyDict(r.stats); },
          "dict of the run's counters, as `musclesim run --stats` writes them: steps, "
          "rhs_evals, jac_evals, linear_setups, newton_iters, newton_conv_fails, "
          "error_test_fails, wall_seconds [s], final_time [s], linear_solver, status, message "
          "(and with sensitivities their counters and `sensitivities`, one {path, derivative} "
          "each).")
      .def_readonly("run_stats", &Result::run_stats, "The counters as a RunStats.")
      .def_property_readonly(
          "status", [](const Result& r) -> py::str { return r.stats["status"]; },
          "'completed', 'limit' (stopped at a length limit) or 'failed' (the solver failed; "
          "the rows up to the failure are kept).")
      .def("to_dataframe", &ToDataFrame,
           "The columns as a pandas.DataFrame (pandas imported only here; ImportError naming "
           "python3-pandas if it is missing).")
      .def(
          "__len__", [](const Result& r) { return r.rows; }, "The number of rows.")
      .def(py::pickle(  // for multiprocessing and joblib: the columns and stats as they are
          [](const Result& r) {
            return AnyTuple(py::make_tuple(r.columns, r.stats, r.rows, r.run_stats));
          },
          [](const AnyTuple& state) {
            if (state.size() != 4) throw std::runtime_error("not a pickled musclesim.Result");
            return Result{state[0].cast<py::dict>(), state[1].cast<py::dict>(),
                          state[2].cast<py::ssize_t>(), state[3].cast<RunStats>()};
          }))
      .def(
          "__getitem__",
          [](const Result& r, const std::string& name) {
            if (!r.columns.contains(name)) throw py::key_error("no column '" + name + "'");
            return AnyArray(r.columns[py::str(name)]);
          },
          py::arg("column"), "result['column'] is result.columns['column'].")
      .def("__repr__", [](const Result& r) {
        return "<musclesim.Result " + std::to_string(r.rows) + " rows, " +
               std::to_string(py::len(r.columns)) + " columns, " +
               py::str(r.stats["status"]).cast<std::string>() + ">";
      });
}

void BindSolverTypes(py::module_& m) {
  py::class_<SolverOptions> solver(
      m, "SolverOptions",
      "How CVODES integrates a scenario (its `solver:` block): method 'bdf' or 'adams', rtol "
      "[-], atol [m and m/s], jacobian 'analytic' or 'difference_quotient', max_step [s] (0: "
      "no limit), max_steps, linear_solver 'auto', 'small', 'dense', 'band' or 'sparse'. "
      "Scenario.solver gives a copy; Scenario.set('solver.rtol', ...) changes a scenario's.");
  solver.def(py::init<>(), "The defaults: bdf, rtol 1e-6, atol 1e-9, analytic Jacobian, auto.")
      .def("__repr__", [](const SolverOptions& o) {
        return "<musclesim.SolverOptions " + std::string(ToString(o.method)) + " rtol " +
               FormatNumber(o.rtol) + " atol " + FormatNumber(o.atol) + ">";
      });
  // its attributes, one per key of the solver block
  DefFieldAttributes(solver, SolverBlock().front());
  py::class_<RunStats>(
      m, "RunStats",
      "A run's solver counters (Result.run_stats; the same as the dict Result.stats): steps, "
      "rhs_evals, jac_evals, linear_setups, newton_iters, newton_conv_fails, error_test_fails, "
      "wall_seconds [s], final_time [s], linear_solver, status, message.")
      .def_readonly("steps", &RunStats::steps, "Internal steps taken [-].")
      .def_readonly("rhs_evals", &RunStats::rhs_evals,
                    "Right-hand side evaluations, a difference-quotient Jacobian's included [-].")
      .def_readonly("jac_evals", &RunStats::jac_evals, "Jacobian evaluations [-].")
      .def_readonly("linear_setups", &RunStats::linear_setups, "Newton matrix factorisations [-].")
      .def_readonly("newton_iters", &RunStats::newton_iters, "Newton iterations [-].")
      .def_readonly("newton_conv_fails", &RunStats::newton_conv_fails,
                    "Newton convergence failures [-].")
      .def_readonly("error_test_fails", &RunStats::error_test_fails,
                    "Steps the local error test rejected [-].")
      .def_readonly("wall_seconds", &RunStats::wall_seconds, "Wall-clock time of the run [s].")
      .def_readonly("final_time", &RunStats::final_time, "Where the run ended [s].")
      .def_property_readonly(
          "linear_solver", [](const RunStats& s) { return std::string(ToString(s.linear_solver)); },
          "The linear solver used (never 'auto').")
      .def_property_readonly(
          "status", [](const RunStats& s) { return std::string(ToString(s.status)); },
          "'completed', 'limit' (a length limit reached) or 'failed'.")
      .def_readonly("message", &RunStats::message,
                    "Why the run ended early (a limit or a failure); '' when it completed.")
      .def(py::pickle(
          [](const RunStats& s) {
            return AnyTuple(py::make_tuple(
                s.steps, s.rhs_evals, s.jac_evals, s.linear_setups, s.newton_iters,
                s.newton_conv_fails, s.error_test_fails, s.wall_seconds, s.final_time,
                static_cast<int>(s.linear_solver), static_cast<int>(s.status), s.message));
          },
          [](const AnyTuple& t) {
            if (t.size() != 12) throw std::runtime_error("not a pickled musclesim.RunStats");
            RunStats s;
            s.steps = t[0].cast<long>();
            s.rhs_evals = t[1].cast<long>();
            s.jac_evals = t[2].cast<long>();
            s.linear_setups = t[3].cast<long>();
            s.newton_iters = t[4].cast<long>();
            s.newton_conv_fails = t[5].cast<long>();
            s.error_test_fails = t[6].cast<long>();
            s.wall_seconds = t[7].cast<double>();
            s.final_time = t[8].cast<double>();
            s.linear_solver = static_cast<LinearSolverKind>(t[9].cast<int>());
            s.status = static_cast<RunStatus>(t[10].cast<int>());
            s.message = t[11].cast<std::string>();
            return s;
          }));
}

void BindParameter(py::module_& m) {
  py::class_<BoundParameter>(
      m, "Parameter",
      "A handle on one number of a Scenario (Scenario.parameter(path)), named by its key path "
      "in the scenario's file form ('model.f_iso', 'load[0].value', 'nodes[1].mass', ...): "
      "`value` reads it and, assigned, sets it as Scenario.set does (checked at once; a "
      "refused value leaves the scenario unchanged). In the key's unit.")
      .def_readonly("path", &BoundParameter::path, "The key path, written one way.")
      .def_property(
          "value",
          [](const BoundParameter& p) {
            const PyScenario& s = ScenarioArgument(p.scenario, "parameter");
            return s.scenario.parameter(p.path).Get(s.scenario);
          },
          [](BoundParameter& p, const py::object& value) { p.scenario.attr("set")(p.path, value); },
          "The value in the scenario [the key's unit]; assigning sets it.")
      .def("__repr__", [](const BoundParameter& p) {
        const PyScenario& s = ScenarioArgument(p.scenario, "parameter");
        return "<musclesim.Parameter " + p.path + " = " +
               FormatNumber(s.scenario.parameter(p.path).Get(s.scenario)) + ">";
      });
}

// What a scenario is: its form, name, values set, solver, and its parameters' handles.
void DefineScenarioProperties(py::class_<PyScenario>& scenario_class) {
  scenario_class
      .def_property_readonly(
          "is_network", [](const PyScenario& s) { return !IsSingleActuator(s.scenario); },
          "True for a network (a top-level `nodes:` key), False for a single actuator.")
      .def_property_readonly(
          "name", [](const PyScenario& s) { return s.scenario.name; },
          "The scenario's `name:` ('' if none).")
      .def_property_readonly(
          "overrides", [](const PyScenario& s) { return s.overrides; },
          "The 'key=value' values set since the file or dict was read: one per key, its last "
          "value, in "
          "the order the keys were first set.")
      .def_property_readonly(
          "solver", [](const PyScenario& s) { return s.scenario.solver; },
          "A copy of the solver's options (SolverOptions).")
      .def_property_readonly(
          "_path", [](const PyScenario& s) { return s.path; },
          "The file read (absolute), or '' for a dict.")
      .def_property_readonly(
          "_display", [](const PyScenario& s) { return s.display; },
          "The scenario's name in messages: the path as given, or the dict's name.")
      .def(
          "parameter",
          [](const py::object& self, const std::string& path) {
            const PyScenario& s = ScenarioArgument(self, "parameter");
            const Parameter handle = s.scenario.parameter(path);  // ParameterError if none
            return BoundParameter{self, handle.path()};
          },
          py::arg("path"),
          "The handle on the number at key path `path` (ParameterError when it names no "
          "number of this scenario): handle.value reads it, handle.value = v sets it.");
}

// Pickling and copies.
void DefineScenarioCopies(py::class_<PyScenario>& scenario_class) {
  scenario_class
      .def(py::pickle(
          // a file's scenario as its path and values; a dict's as its YAML text
          [](const PyScenario& s) -> AnyTuple {
            if (s.document) {
              const PyScenario fixed = s;  // taken with the GIL
              std::string text;
              {
                py::gil_scoped_release release;
                text = fixed.ToYaml();
              }
              return py::make_tuple(py::none(), s.display, std::vector<std::string>{}, text);
            }
            return py::make_tuple(s.path, s.display, s.overrides, py::none());
          },
          [](const AnyTuple& state) {
            if (state.size() != 4) throw std::runtime_error("not a pickled musclesim.Scenario");
            const std::string display = state[1].cast<std::string>();
            if (!state[3].is_none()) {
              return DocumentPyScenario(ParseDocument(display, state[3].cast<std::string>()),
                                        display);
            }
            PyScenario s;
            s.path = state[0].cast<std::string>();
            s.display = display;
            s.overrides = state[2].cast<std::vector<std::string>>();
            py::gil_scoped_release release;
            s.Assign(s.Read({}));
            return s;
          }))
      .def(
          "copy", [](const PyScenario& s) { return s; },
          "An independent copy: set() on one leaves the other as it is (copy.copy and "
          "copy.deepcopy give the same).")
      .def("__copy__", [](const PyScenario& s) { return s; })
      .def(
          "__deepcopy__", [](const PyScenario& s, const py::object&) { return s; },
          py::arg("memo"));
}

// The YAML text, set() and run().
void DefineScenarioUse(py::class_<PyScenario>& scenario_class) {
  scenario_class
      .def(
          "to_yaml",
          [](const PyScenario& s) {
            const PyScenario fixed = s;  // taken with the GIL
            py::gil_scoped_release release;
            return fixed.ToYaml();
          },
          "The scenario as a YAML file's text, its set() values written in: what `musclesim "
          "run` runs alike (the original's comments are not kept).")
      .def(
          "set",
          [](PyScenario& s, const std::string& key, const py::object& value) -> PyScenario& {
            s.Set(key, value);  // all or nothing: a rejected value leaves it as it was
            return s;
          },
          py::arg("key"), py::arg("value"), py::return_value_policy::reference_internal,
          "Sets one value by its dotted key path as `musclesim run --set KEY=VALUE` does (e.g. "
          "'load[0].after', 'model.velocity.n', 'elements[1].activation.after', in the file's "
          "units) and validates the scenario at once: a number goes in place through the key's "
          "parameter handle, a word (a method, a waveform's type) reads the scenario again. "
          "InputError (with .key) for a key that is not there or a value that breaks a rule, "
          "leaving the scenario unchanged. Returns the scenario.")
      .def("run", &Run, py::arg("sensitivities") = py::none(),
           "Integrates the scenario (GIL released) as `musclesim run` does and returns a "
           "Result, its columns filled in memory. `sensitivities`: dotted paths of numeric "
           "parameters ('model.f_iso', 'load[0].value', 'models.muscle.f_iso', ...) whose "
           "forward sensitivities add the columns d_<column>/d_<path>, as `musclesim run "
           "--sensitivity PATH` writes them; a scenario's own `sensitivities:` list adds its "
           "own. A solver failure is a result (status 'failed'), not an exception.")
      .def("__repr__", [](const PyScenario& s) {
        return "<musclesim.Scenario '" + s.scenario.name + "' from " + s.display +
               (IsSingleActuator(s.scenario) ? " (single actuator)" : " (network)") + ">";
      });
}

void BindScenarioClass(py::module_& m) {
  py::class_<PyScenario> scenario_class(
      m, "Scenario",
      "A validated scenario in memory (a single actuator, docs/guide/scenarios.md, or a "
      "network on a line, docs/guide/networks.md), read from a file or a dict, with the values "
      "set() since. SI units as in the files.");
  DefineScenarioProperties(scenario_class);
  DefineScenarioCopies(scenario_class);
  DefineScenarioUse(scenario_class);
}

// The module's functions: run timing for the overhead benchmark, reading a file or a dict.
void BindScenarioFunctions(py::module_& m) {
  m.def(
      "_cpp_run_seconds",
      [](const PyScenario& s, int repeats) {
        const Scenario scenario = s.scenario;
        const std::shared_ptr<const NetworkSystem> system = s.system;  // as Scenario.run()'s
        std::vector<double> seconds;
        py::gil_scoped_release release;
        for (int k = 0; k < repeats; ++k) {
          const auto start = std::chrono::steady_clock::now();
          const RecordedRun run = system ? RunScenario(scenario, *system) : RunScenario(scenario);
          seconds.push_back(
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        return seconds;
      },
      py::arg("scenario"), py::arg("repeats"),
      "The reference for Scenario.run()'s overhead (bench/python_run_overhead.py): the same "
      "run, recorded in memory by C++ alone `repeats` times; each one's wall time [s].");
  m.def("load_scenario", &LoadPyScenario, py::arg("path"), py::arg("set") = py::none(),
        "Reads and validates the scenario file `path` (single actuator or network), applying "
        "`set` first: a list of 'key=value' texts as `musclesim run --set` takes them, or a "
        "dict {key: value}. InputError (with .key and .location 'file:line:column') for bad "
        "input.");
  m.def(
      "_scenario_from_dict",
      [](const py::object& dict, const std::string& name) {
        return DocumentPyScenario(DocumentFrom(dict, ""), name);
      },
      py::arg("dict"), py::arg("name"),
      "A scenario from a dict read as a file's document (no text in between); messages name "
      "it `name`. scenario_from_dict is the public way.");
}

}  // namespace

void BindScenario(py::module_& m) {
  // RunStats before Result, whose run_stats returns one: signatures (and the .pyi stubs made
  // from them) name the Python type, not the C++ one
  BindSolverTypes(m);
  BindResult(m);
  BindParameter(m);
  BindScenarioClass(m);
  BindScenarioFunctions(m);
}

}  // namespace musclesim::python
