// LoadProblemFile: the problem file read with io's YAML helpers (file:line:column messages).
#include "musclesim/optimize/problem_file.h"

#include <filesystem>
#include <limits>

#include "io/readers/part_fields_yaml.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/core/errors.h"
#include "optimize/problem_checks.h"
#include "musclesim/io/readers/csv_table.h"
#include "musclesim/io/writers/output_file.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/optimize/problem_fields.h"

namespace musclesim {

namespace {

std::string Item(const char* list, std::size_t i) {
  std::string path = list;
  path.append("[").append(std::to_string(i)).append("]");
  return path;
}

// The entry or block at `node` read by its description (problem_fields.h), its keys checked.
template <typename Part>
Part ReadDescribed(const yaml::Source& src, const Document& node, const std::string& path,
                   const std::vector<PartVariant<Part>>& described) {
  std::vector<std::string> keys;
  AddVariantKeys(described.front(), keys);
  yaml::RequireMap(src, node, path, keys);
  Part part;
  ReadFields(src, node, path, described.front(), part);
  return part;
}

// A described pair bounds[0], bounds[1] in order, lower <= upper, where `node` gives it.
void RequireOrdered(const yaml::Source& src, const Document& node, const std::string& path,
                    double lower, double upper) {
  if (const Document& bounds = node["bounds"]; bounds && lower > upper) {
    yaml::Fail(src, bounds, yaml::Join(path, "bounds"), yaml::Describe(bounds),
               "must be [lower, upper] with lower <= upper");
  }
}

ControlSpec ReadControl(const yaml::Source& src, const Document& node, const std::string& path) {
  const ControlSpec control = ReadDescribed(src, node, path, ControlEntry());
  RequireOrdered(src, node, path, control.lower, control.upper);
  return control;
}

FinalValue ReadFinal(const yaml::Source& src, const Document& node, const std::string& path) {
  if (node.IsMap() && node["value"] && node["bounds"]) {
    yaml::Fail(src, node["bounds"], yaml::Join(path, "bounds"), yaml::Describe(node["bounds"]),
               "give either value or bounds, not both");
  }
  if (node.IsMap() && !node["value"] && !node["bounds"]) {
    throw InputError(InputFault{yaml::Place(src, node), path, std::nullopt,
                                "missing required key: value (an equality) or bounds [lower, "
                                "upper]"});
  }
  const FinalValue final = ReadDescribed(src, node, path, FinalValueEntry());
  RequireOrdered(src, node, path, final.lower, final.upper);
  return final;
}

// `entries` as a list of maps, each read by `read(node, path)`.
template <typename Read>
void ReadList(const yaml::Source& src, const Document& entries, const char* key, const char* form,
              Read read) {
  if (!entries.IsSequence()) {
    yaml::Fail(src, entries, key, yaml::Describe(entries),
               std::string("must be a list of ") + form);
  }
  for (std::size_t k = 0; k < entries.size(); ++k) read(entries[k], Item(key, k));
}

PathBound ReadPathBound(const yaml::Source& src, const Document& node, const std::string& path) {
  const PathBound bound = ReadDescribed(src, node, path, PathBoundEntry());
  RequireOrdered(src, node, path, bound.lower, bound.upper);
  return bound;
}

// A tracking term's reference: `points: [[t, r], ...]`, or `csv: FILE` (relative to the
// problem file) with `column: NAME` and the time column `time: NAME` (default t).
std::vector<TablePoint> ReadReference(const yaml::Source& src, const Document& node,
                                      const std::string& path, std::vector<std::string>& inputs) {
  yaml::RequireMap(src, node, path, {"points", "csv", "column", "time"});
  std::vector<TablePoint> points;
  if (node["points"] && node["csv"]) {
    yaml::Fail(src, node["csv"], yaml::Join(path, "csv"), yaml::Describe(node["csv"]),
               "give either points or csv, not both");
  }
  if (const Document& listed = node["points"]) {
    const std::string at = yaml::Join(path, "points");
    if (!listed.IsSequence()) {
      yaml::Fail(src, listed, at, yaml::Describe(listed), "must be a list of [t, value] pairs");
    }
    for (std::size_t i = 0; i < listed.size(); ++i) {
      const std::vector<double> pair = yaml::ReadNumbers(src, listed[i], Item(at.c_str(), i), 2);
      points.push_back({pair[0], pair[1]});
    }
    return points;
  }
  const std::string file =
      yaml::ReadString(src, yaml::Required(src, node, path, "csv"), yaml::Join(path, "csv"));
  const std::string resolved =
      (std::filesystem::path(src.file).parent_path() / file).lexically_normal().string();
  const std::string value =
      yaml::ReadString(src, yaml::Required(src, node, path, "column"), yaml::Join(path, "column"));
  const std::string time =
      node["time"] ? yaml::ReadString(src, node["time"], yaml::Join(path, "time")) : "t";
  inputs.push_back(resolved);
  const CsvTable table = ReadCsv(resolved);
  table.Require({time, value}, path + " (" + yaml::Location(src, node) + ")");
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    points.push_back({table.Number(r, table.Find(time)), table.Number(r, table.Find(value))});
  }
  return points;
}

TrackingTerm ReadTracking(const yaml::Source& src, const Document& node, const std::string& path,
                          std::vector<std::string>& inputs) {
  TrackingTerm term = ReadDescribed(src, node, path, TrackingEntry());
  term.reference = ReadReference(src, yaml::Required(src, node, path, "reference"),
                                 yaml::Join(path, "reference"), inputs);
  return term;
}

FreeParameter ReadParameter(const yaml::Source& src, const Document& node,
                            const std::string& path) {
  const FreeParameter free = ReadDescribed(src, node, path, ParameterEntry());
  RequireOrdered(src, node, path, free.lower, free.upper);
  return free;
}

FreeFinalTime ReadFinalTime(const yaml::Source& src, const Document& node) {
  const FreeFinalTime time = ReadDescribed(src, node, "final_time", FinalTimeBlock());
  RequireOrdered(src, node, "final_time", time.lower, time.upper);
  return time;
}

// Each output a file of its own in an existing directory, none of them an input (the problem,
// its base, a tracking reference): a failed or finished run must not replace what it read.
void CheckOutputs(const yaml::Source& src, const Document& root, const OptimizeOutputs& outputs,
                  const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  const auto same = [](const std::string& a, const std::string& b) {
    std::error_code error;
    return fs::weakly_canonical(a, error) == fs::weakly_canonical(b, error);
  };
  const std::pair<const char*, const std::string*> named[] = {{"scenario", &outputs.scenario},
                                                              {"summary", &outputs.summary},
                                                              {"trajectory", &outputs.trajectory}};
  for (std::size_t k = 0; k < 3; ++k) {
    // named, not a structured binding: a lambda below captures them
    const char* const key = named[k].first;
    const std::string* const target = named[k].second;
    const std::string at = std::string("output.") + key;
    const Document& node = root["output"] && root["output"][key] ? root["output"][key] : root;
    const auto fail = [&](const std::string& rule) {
      yaml::Fail(src, node, at, "'" + *target + "'", rule);
    };
    if (target->empty()) fail("must name a file");
    const fs::path parent = fs::path(*target).parent_path();
    std::error_code error;
    if (!parent.empty() && !fs::is_directory(parent, error)) {
      fail("its directory " + parent.string() + " does not exist");
    }
    if (fs::is_directory(*target, error)) fail("is a directory");
    if (const std::string outside = LinkOutsideItsDirectory(*target); !outside.empty()) {
      fail("is a symbolic link to " + outside +
           ", outside its directory: musclesim writes no output through it (remove the link, "
           "or name another file)");
    }
    for (const std::string& input : inputs) {
      if (same(*target, input))
        fail("is " + input + ", which the problem reads: it would be replaced");
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (same(*target, *named[j].second)) {
        fail(std::string("is also output.") + named[j].first + ": each output needs a file");
      }
    }
  }
}

// The node at `path` ("final_values[0].column", "effort.weight") below `root`, or its
// deepest ancestor present (a key given by default has no node of its own).
const Document& NodeAt(const Document& root, const std::string& path) {
  const Document* node = &root;
  std::size_t at = 0;
  while (at < path.size()) {
    const std::size_t end = path.find_first_of(".[", at);
    const std::string key = path.substr(at, end == std::string::npos ? end : end - at);
    if (!key.empty() && !(*node)[key]) return *node;
    if (!key.empty()) node = &(*node)[key];
    at = end == std::string::npos ? path.size() : end + 1;
    if (end != std::string::npos && path[end] == '[') {
      const std::size_t close = path.find(']', at);
      if (close == std::string::npos) return *node;
      const std::size_t i = std::stoul(path.substr(at, close - at));
      if (!node->IsSequence() || i >= node->size()) return *node;
      node = &(*node)[i];
      at = close + 1;
      if (at < path.size() && path[at] == '.') ++at;
    }
  }
  return *node;
}

}  // namespace

namespace {

// The optimizer block, its defaults where the file has none.
void ReadOptimizer(const yaml::Source& src, const Document& root, OptimizeOptions& options) {
  if (const Document& optimizer = root["optimizer"]) {
    options = ReadDescribed(src, optimizer, "optimizer", OptimizerBlock());
  } else {
    SetDefaults(OptimizerBlock().front(), options);
  }
}

// The lists and blocks of a problem (its own keys read by the caller), into `file`; `inputs`
// gains the files it reads (a tracking reference's CSV).
void ReadProblemBody(const yaml::Source& src, const Document& root, ProblemFile& file,
                     std::vector<std::string>& inputs) {
  OptimalControlProblem& problem = file.problem;
  const Document& controls = yaml::Required(src, root, "", "controls");
  if (!controls.IsSequence() || controls.size() == 0) {
    yaml::Fail(src, controls, "controls", yaml::Describe(controls),
               "must be a list of at least one control, {actuator: NAME, ...}");
  }
  for (std::size_t j = 0; j < controls.size(); ++j) {
    problem.controls.push_back(ReadControl(src, controls[j], Item("controls", j)));
  }
  if (const Document& finals = root["final_values"]) {
    if (!finals.IsSequence()) {
      yaml::Fail(src, finals, "final_values", yaml::Describe(finals),
                 "must be a list of {column: NODE.COLUMN, value: X} or {column, bounds}");
    }
    for (std::size_t k = 0; k < finals.size(); ++k) {
      problem.final_values.push_back(ReadFinal(src, finals[k], Item("final_values", k)));
    }
  }
  if (const Document& bounds = root["path_bounds"]) {
    ReadList(src, bounds, "path_bounds", "{column: NAME, bounds: [lower, upper]}",
             [&](const Document& n, const std::string& at) {
               problem.path_bounds.push_back(ReadPathBound(src, n, at));
             });
  }
  if (const Document& terms = root["tracking"]) {
    ReadList(src, terms, "tracking", "{column: NAME, reference: {...}, weight: W}",
             [&](const Document& n, const std::string& at) {
               problem.tracking.push_back(ReadTracking(src, n, at, inputs));
             });
  }
  if (const Document& terms = root["terminal"]) {
    ReadList(src, terms, "terminal", "{column: NAME, target: X, weight: W}",
             [&](const Document& n, const std::string& at) {
               problem.terminal.push_back(ReadDescribed(src, n, at, TerminalEntry()));
             });
  }
  if (const Document& free = root["parameters"]) {
    ReadList(src, free, "parameters", "{path: KEY.PATH, bounds: [lower, upper]}",
             [&](const Document& n, const std::string& at) {
               problem.parameters.push_back(ReadParameter(src, n, at));
             });
  }
  if (const Document& time = root["final_time"]) problem.final_time = ReadFinalTime(src, time);
  ReadOptimizer(src, root, file.options);
}

// The problem against its scenario (an actuator, a column, a parameter it lacks): the
// message's entry placed in the problem's own text.
void CheckAgainstScenario(const yaml::Source& src, const Document& root,
                          const OptimalControlProblem& problem) {
  try {
    CheckProblem(problem);
  } catch (const InputError& e) {
    InputFault fault = e.fault();
    fault.place = yaml::Place(src, NodeAt(root, fault.key));
    throw e.WithFault(fault);
  }
}

}  // namespace

ProblemFile LoadProblemFile(const std::string& path) {
  const yaml::Source src{path};
  const Document& root = yaml::LoadFile(path);
  yaml::RequireMap(src, root, "", VariantKeys(ProblemKeys(), "problem"));
  ProblemFile file;
  file.path = path;
  ReadFields(src, root, "", ProblemKeys().front(), file);
  file.base = (std::filesystem::path(path).parent_path() / file.base).lexically_normal().string();
  std::vector<std::string> inputs{path, file.base};  // what the outputs must not replace
  ReadProblemBody(src, root, file, inputs);
  const std::string stem = std::filesystem::path(path).stem().string();
  file.outputs = {stem + "_optimum.yaml", stem + "_optimum.json", stem + "_optimum.csv"};
  if (const Document& output = root["output"]) {
    std::vector<std::string> keys;
    AddVariantKeys(ProblemOutputBlock().front(), keys);
    yaml::RequireMap(src, output, "output", keys);
    ReadFields(src, output, "output", ProblemOutputBlock().front(), file.outputs);
  }
  CheckOutputs(src, root, file.outputs, inputs);
  file.problem.scenario = LoadScenario(file.base);
  CheckAgainstScenario(src, root, file.problem);
  return file;
}

ProblemFile ReadProblem(const Document& document, const std::string& name,
                        const Scenario& scenario) {
  const Document& root = document;
  const yaml::Source src{name, name};
  // a document in memory has a scenario given, and writes nothing: no base, no output
  PartVariant<ProblemFile> body = ProblemKeys().front();
  body.texts.clear();
  std::erase_if(body.other_keys, [](const char* key) { return std::string_view(key) == "output"; });
  std::vector<std::string> keys;
  AddVariantKeys(body, keys);
  yaml::RequireMap(src, root, "", keys);
  ProblemFile file;
  file.path = name;
  ReadFields(src, root, "", body, file);
  std::vector<std::string> inputs;
  ReadProblemBody(src, root, file, inputs);
  file.problem.scenario = scenario;
  CheckAgainstScenario(src, root, file.problem);
  return file;
}

}  // namespace musclesim
