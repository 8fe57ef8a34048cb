// musclesim.Scenario's C++ side: the Scenario in memory, every set() value in it, and where
// it was read from (a file, or a document built from a dict), which to_yaml(), pickling and a
// set() of a word (a solver's method, a waveform's type) read again.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "musclesim/io/readers/document.h"
#include "musclesim/scenario/scenario.h"

namespace musclesim::python {

struct PyScenario {
  Scenario scenario;                            // as read, with every set() value
  std::shared_ptr<const NetworkSystem> system;  // scenario.Build()'s, kept from reading for
                                                // its runs; null once set() changed a number
  std::string path;                             // the file read, absolute; "" for a document
  std::shared_ptr<const Document> document;     // a dict's document; null for a file
  std::string display;                          // its name in messages
  std::vector<std::string> overrides;           // "key=value" since reading, one per key

  // The source read again with `more` overrides after the scenario's own (without the GIL).
  LoadedScenario Read(const std::vector<std::string>& more) const;
  // `loaded` as this scenario and its system.
  void Assign(LoadedScenario loaded);
  // The scenario as YAML text, its set() values written in (without the GIL).
  std::string ToYaml() const;
  // The same as a document in memory (without the GIL).
  Document ToDocument() const;
  // Sets `key` to `value` as set() does (with the GIL: it converts `value`).
  // All or nothing: a refused value leaves the scenario as it was.
  void Set(const std::string& key, const pybind11::object& value);
};

// A file's scenario: `given` (str or os.PathLike) read with `set` (a list of "key=value"
// strings, or a dict) applied first.
PyScenario LoadPyScenario(const pybind11::object& given, const pybind11::object& set);
// A dict's (or another document's) scenario.
PyScenario DocumentPyScenario(Document document, const std::string& name);

// `object` as a PyScenario, or TypeError naming `what`.
const PyScenario& ScenarioArgument(const pybind11::handle& object, const std::string& what);

}  // namespace musclesim::python
