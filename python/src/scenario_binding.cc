// Scenarios from files or dicts, changed with set(), run to NumPy columns (cli_run.h: the
// very writers `musclesim run` uses, so the columns are its CSV's).
#include <pybind11/stl.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "bindings.h"
#include "cli_run.h"
#include "file_alias.h"
#include "overrides.h"
#include "temp_file.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/network_scenario.h"
#include "musclesim/io/scenario.h"
#include "musclesim/io/scenario_rewrite.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

// A scenario: the file it is read from, the overrides set() gave, and what it is.
struct Scenario {
  std::string path;                 // the file read (a temporary one for a dict)
  std::string display;              // the file's name in messages ("<dict>" for a dict)
  std::shared_ptr<TempFile> text;   // owns `path` when it is temporary
  std::vector<std::string> overrides;
  bool network = false;
  std::string name;

  // Runs `read`, its InputError naming the file as `display` (file_alias.h).
  template <typename Read>
  auto Located(Read read) const {
    return WithFileAlias(path, display, read);
  }

  // Reads and validates the file with the overrides, as `musclesim run` does before it runs.
  void Validate() {
    Located([&] {
      network = IsNetworkScenario(path);
      name = network ? LoadNetworkScenario(path, overrides).name
                     : LoadScenario(path, overrides).name;
      return 0;
    });
  }
};

Scenario Load(const py::object& given, const py::object& set) {
  const std::string path = PathText(given, "load_scenario(path)");
  Scenario scenario;
  // absolute: the scenario stays valid across os.chdir and in a sweep's temporary directory;
  // messages keep the name the user gave
  scenario.path = std::filesystem::absolute(path).lexically_normal().string();
  scenario.display = path;
  scenario.overrides = OverridesFrom(set);
  py::gil_scoped_release release;
  scenario.Validate();
  return scenario;
}

Scenario FromText(const std::string& text, const std::string& display) {
  Scenario scenario;
  scenario.text = std::make_shared<TempFile>(".yaml");
  {
    std::ofstream out(scenario.text->path(), std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + scenario.text->path());
  }
  scenario.path = scenario.text->path();
  scenario.display = display;
  py::gil_scoped_release release;
  scenario.Validate();
  return scenario;
}

Result Run(const Scenario& scenario, const py::object& sensitivities) {
  std::vector<std::string> parameters;
  if (!sensitivities.is_none()) {
    if (py::isinstance<py::str>(sensitivities)) {
      throw py::type_error("sensitivities must be a list of dotted paths, not one str");
    }
    for (const auto& item : sensitivities) parameters.push_back(py::str(item).cast<std::string>());
  }
  CsvColumns columns;
  std::string stats_json;
  const Scenario fixed = scenario;  // taken with the GIL: another thread may set() meanwhile
  {
    py::gil_scoped_release release;
    const RunText text =
        fixed.Located([&] { return RunLikeCli(fixed.path, fixed.overrides, parameters); });
    columns = SplitCsv(text.csv);
    stats_json = text.stats_json;
  }
  return MakeResult(columns, stats_json);
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

}  // namespace

void BindScenario(py::module_& m) {
  py::class_<Result>(
      m, "Result",
      "One run's trajectory and solver counters, as `musclesim run` writes them (its CSV and "
      "its --stats JSON). Rows are the output grid's times (output.interval) or every internal "
      "step (interval: steps). SI units: t in s, lengths and positions in m, velocities in m/s "
      "(shortening_velocity positive when the actuator shortens), tensions and loads in N, "
      "activations and excitations in [0, 1].")
      .def_property_readonly(
          "columns", [](const Result& r) { return r.columns; },
          "dict {name: 1-D NumPy array of len(result)}, exactly the CLI CSV's columns in its "
          "order: float64, except the text columns `phase` and `<actuator>.phase` "
          "('concentric', 'eccentric', 'isometric'), which are NumPy str arrays. With "
          "sensitivities, d_<column>/d_<path> after them.")
      .def_property_readonly(
          "times", [](const Result& r) { return r.columns[py::str("t")]; },
          "columns['t']: the rows' times [s], float64, shape (len(result),).")
      .def_property_readonly(
          "stats", [](const Result& r) { return r.stats; },
          "dict of the run's counters, as `musclesim run --stats` writes them: steps, "
          "rhs_evals, jac_evals, linear_setups, newton_iters, newton_conv_fails, "
          "error_test_fails, wall_seconds [s], final_time [s], linear_solver, status, message "
          "(and with sensitivities their counters and `sensitivities`, one {path, derivative} "
          "each).")
      .def_property_readonly(
          "status", [](const Result& r) { return r.stats["status"]; },
          "'completed', 'limit' (stopped at a length limit) or 'failed' (the solver failed; "
          "the rows up to the failure are kept).")
      .def("to_dataframe", &ToDataFrame,
           "The columns as a pandas.DataFrame (pandas imported only here; ImportError naming "
           "python3-pandas if it is missing).")
      .def("__len__", [](const Result& r) { return r.rows; }, "The number of rows.")
      .def(py::pickle(  // for multiprocessing and joblib: the columns and stats as they are
          [](const Result& r) { return py::make_tuple(r.columns, r.stats, r.rows); },
          [](const py::tuple& state) {
            if (state.size() != 3) throw std::runtime_error("not a pickled musclesim.Result");
            return Result{state[0].cast<py::dict>(), state[1].cast<py::dict>(),
                          state[2].cast<py::ssize_t>()};
          }))
      .def(
          "__getitem__",
          [](const Result& r, const std::string& name) -> py::object {
            if (!r.columns.contains(name)) throw py::key_error("no column '" + name + "'");
            return r.columns[py::str(name)];
          },
          py::arg("column"), "result['column'] is result.columns['column'].")
      .def("__repr__", [](const Result& r) {
        return "<musclesim.Result " + std::to_string(r.rows) + " rows, " +
               std::to_string(py::len(r.columns)) + " columns, " +
               py::str(r.stats["status"]).cast<std::string>() + ">";
      });

  py::class_<Scenario>(
      m, "Scenario",
      "A validated scenario (a single actuator or a network on a line, README \"Scenario "
      "files\"): a file or a dict with the overrides given since. SI units as in the files.")
      .def_property_readonly(
          "is_network", [](const Scenario& s) { return s.network; },
          "True for a network (a top-level `nodes:` key), False for a single actuator.")
      .def_property_readonly(
          "name", [](const Scenario& s) { return s.name; }, "The scenario's `name:` ('' if none).")
      .def_property_readonly(
          "overrides", [](const Scenario& s) { return s.overrides; },
          "The 'key=value' overrides applied to the file, in order.")
      .def_property_readonly(
          "_path", [](const Scenario& s) { return s.path; },
          "The file read (for a dict, a temporary file the scenario owns): run_many's job.")
      .def_property_readonly(
          "_display", [](const Scenario& s) { return s.display; },
          "The file's name in messages: the path, or the name given to scenario_from_dict.")
      .def(py::pickle(
          // a file's scenario as its path and overrides; a dict's as its text (its temporary
          // file is this process's)
          [](const Scenario& s) {
            if (s.text) {
              const Scenario fixed = s;  // taken with the GIL
              std::string text;
              {
                py::gil_scoped_release release;
                text = fixed.Located(
                    [&] { return RewriteScenario(fixed.path, fixed.overrides, {}); });
              }
              return py::make_tuple(py::none(), s.display, std::vector<std::string>{}, text);
            }
            return py::make_tuple(s.path, s.display, s.overrides, py::none());
          },
          [](const py::tuple& state) {
            if (state.size() != 4) throw std::runtime_error("not a pickled musclesim.Scenario");
            const std::string display = state[1].cast<std::string>();
            if (!state[3].is_none()) return FromText(state[3].cast<std::string>(), display);
            Scenario scenario;
            scenario.path = state[0].cast<std::string>();
            scenario.display = display;
            scenario.overrides = state[2].cast<std::vector<std::string>>();
            py::gil_scoped_release release;
            scenario.Validate();
            return scenario;
          }))
      .def(
          "copy", [](const Scenario& s) { return s; },
          "An independent copy: set() on one leaves the other as it is (copy.copy and "
          "copy.deepcopy give the same).")
      .def("__copy__", [](const Scenario& s) { return s; })
      .def("__deepcopy__", [](const Scenario& s, const py::object&) { return s; },
           py::arg("memo"))
      .def(
          "to_yaml",
          [](const Scenario& s) {
            const Scenario fixed = s;  // taken with the GIL
            py::gil_scoped_release release;
            return fixed.Located([&] { return RewriteScenario(fixed.path, fixed.overrides, {}); });
          },
          "The scenario as a YAML file's text, its set() values written in: what `musclesim "
          "run` runs alike (the original's comments are not kept).")
      .def(
          "_with_overrides",
          [](const Scenario& s, const std::vector<std::string>& more) {
            Scenario copy = s;  // shares a dict's temporary file, which lives while either does
            copy.overrides.insert(copy.overrides.end(), more.begin(), more.end());
            py::gil_scoped_release release;
            copy.Validate();
            return copy;
          },
          py::arg("overrides"),
          "A validated copy with the 'key=value' texts `overrides` applied after its own "
          "(identification's estimated scenario).")
      .def(
          "set",
          [](Scenario& s, const std::string& key, const py::object& value) -> Scenario& {
            // validated as a copy without the GIL, taken on only if valid: a rejected value
            // leaves the scenario as it was, and no other thread sees it half changed
            Scenario changed = s;
            changed.overrides.push_back(OverrideText(key, value));
            {
              py::gil_scoped_release release;
              changed.Validate();
            }
            s = std::move(changed);
            return s;
          },
          py::arg("key"), py::arg("value"), py::return_value_policy::reference_internal,
          "Overrides one value by its dotted key path as `musclesim run --set KEY=VALUE` does "
          "(e.g. 'load[0].after', 'model.velocity.n', 'elements[1].activation.after', in the "
          "file's units) and validates the scenario at once: InputError (with .key) for a key "
          "that is not there or a value that breaks a rule, leaving the scenario unchanged. "
          "Returns the scenario.")
      .def("run", &Run, py::arg("sensitivities") = py::none(),
           "Integrates the scenario (GIL released) as `musclesim run` does and returns a "
           "Result. `sensitivities`: dotted paths of numeric parameters ('model.f_iso', "
           "'load[0].value', 'models.muscle.f_iso', ...) whose forward sensitivities add the "
           "columns d_<column>/d_<path>, as `musclesim run --sensitivity PATH` writes them; a "
           "scenario's own `sensitivities:` list adds its own. A solver failure is a result "
           "(status 'failed'), not an exception.")
      .def("__repr__", [](const Scenario& s) {
        return "<musclesim.Scenario '" + s.name + "' from " + s.display +
               (s.network ? " (network)" : " (single actuator)") + ">";
      });

  m.def("load_scenario", &Load, py::arg("path"), py::arg("set") = py::none(),
        "Reads and validates the scenario file `path` (single actuator or network), applying "
        "`set` first: a list of 'key=value' texts as `musclesim run --set` takes them, or a "
        "dict {key: value}. InputError (with .key and .location 'file:line:column') for bad "
        "input.");
  m.def("_scenario_from_text", &FromText, py::arg("text"), py::arg("name"),
        "A scenario from YAML (or JSON) text; messages name the file `name`. "
        "scenario_from_dict is the public way.");
}

}  // namespace musclesim::python
