#include "py_scenario.h"

#include <filesystem>

#include "musclesim/core/errors.h"
#include "musclesim/io/writers/scenario_rewrite.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "overrides.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

// A number set() sets through its key's parameter handle; anything else goes to the document.
bool IsNumber(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return false;
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) return true;
  const py::object numpy = py::module_::import("numpy");
  return py::isinstance(value, numpy.attr("number")) && !py::isinstance(value, numpy.attr("bool_"));
}

// `text` ("key=value") among `overrides`, in place of an earlier value of `key`.
void Record(std::vector<std::string>& overrides, const std::string& key, const std::string& text) {
  // a key set again replaces its earlier value: overrides set single values, so the document
  // they make is the same, and a loop of set() stays linear in its length
  const std::string prefix = key + "=";
  for (std::string& earlier : overrides) {
    if (earlier.compare(0, prefix.size(), prefix) == 0) {
      earlier = text;
      return;
    }
  }
  overrides.push_back(text);
}

}  // namespace

LoadedScenario PyScenario::Read(const std::vector<std::string>& more) const {
  std::vector<std::string> all = overrides;
  all.insert(all.end(), more.begin(), more.end());
  if (document) return ReadBuiltScenario(*document, display, Overrides(all, kOverrideLabel));
  // messages name the file as the user gave it
  return LoadBuiltScenario(path, Overrides(all, kOverrideLabel), display);
}

void PyScenario::Assign(LoadedScenario loaded) {
  scenario = std::move(loaded.scenario);
  system = std::move(loaded.system);
}

std::string PyScenario::ToYaml() const {
  const Overrides set(overrides, kOverrideLabel);
  return document ? RewriteScenario(*document, display, set, {}) : RewriteScenario(path, set, {});
}

Document PyScenario::ToDocument() const {
  const Overrides set(overrides, kOverrideLabel);
  return document ? RewrittenDocument(*document, display, set) : RewrittenDocument(path, set);
}

void PyScenario::Set(const std::string& key, const py::object& value) {
  const std::string text = OverrideText(key, value);  // TypeError for a list, say
  // a number at a key that holds one: in place, through its handle, without reading again
  if (IsNumber(value)) {
    std::optional<Parameter> handle;
    try {
      handle = scenario.parameter(key);
    } catch (const ParameterError&) {
      // no number there: the document's reader says what is wrong, as for --set
    }
    if (handle) {
      const double number = value.attr("__float__")().cast<double>();
      Scenario changed = scenario;
      {
        py::gil_scoped_release release;
        try {
          handle->Set(changed, number);
        } catch (const ParameterError& error) {
          throw InputError(
              InputFault{InputPlace{"set"}, error.path(), error.value(), error.rule()});
        }
      }
      scenario = std::move(changed);
      system.reset();  // of the scenario before: the next run builds anew
      Record(overrides, key, text);
      return;
    }
  }
  // a word (a method, a waveform's type), or a key with no number: read again with it
  LoadedScenario changed;
  {
    py::gil_scoped_release release;
    changed = Read({text});
  }
  Assign(std::move(changed));
  Record(overrides, key, text);
}

PyScenario LoadPyScenario(const py::object& given, const py::object& set) {
  const std::string path = PathText(given, "load_scenario(path)");
  PyScenario s;
  // absolute: the scenario stays valid across os.chdir; messages keep the user's name
  s.path = std::filesystem::absolute(path).lexically_normal().string();
  s.display = path;
  s.overrides = OverridesFrom(set);
  py::gil_scoped_release release;
  s.Assign(LoadBuiltScenario(path, Overrides(s.overrides, kOverrideLabel), path));
  return s;
}

PyScenario DocumentPyScenario(Document document, const std::string& name) {
  PyScenario s;
  s.document = std::make_shared<const Document>(std::move(document));
  s.display = name;
  py::gil_scoped_release release;
  s.Assign(ReadBuiltScenario(*s.document, name));
  return s;
}

const PyScenario& ScenarioArgument(const py::handle& object, const std::string& what) {
  try {
    return object.cast<const PyScenario&>();
  } catch (const py::cast_error&) {
    throw py::type_error(what +
                         " must be a musclesim.Scenario (load_scenario or "
                         "scenario_from_dict), not " +
                         py::str(py::type::of(object).attr("__name__")).cast<std::string>());
  }
}

}  // namespace musclesim::python
