// MuJoCo's MJCF: <muscle> actuators, and <general> ones with the muscle gain and bias, as
// family mujoco (docs/model.md 14.1); their absent attributes at MuJoCo 4.0's defaults, after
// those of their default class (<default> elements, nested classes inheriting).
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/import/muscle_import_readers.h"
#include "io/import/xml_reading.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/core/printable_text.h"

namespace musclesim {

namespace {

using tinyxml2::XMLElement;
using Attributes = std::map<std::string, std::string>;

// musclesim's key -> MuJoCo's attribute, for messages: of <muscle>, and of <general>
const std::vector<std::pair<std::string, std::string>> kShortcutNames = {
    {"f_iso", "force"},
    {"tau_activation", "timeconst[0]"},
    {"tau_deactivation", "timeconst[1]"},
    {"tausmooth", "tausmooth"},
};
const std::vector<std::pair<std::string, std::string>> kGeneralNames = {
    {"f_iso", "gainprm[2]"},
    {"tau_activation", "dynprm[0]"},
    {"tau_deactivation", "dynprm[1]"},
    {"tausmooth", "dynprm[2]"},
};

// What <default> classes set for each actuator element: class -> element name -> attributes.
using DefaultClasses = std::map<std::string, std::map<std::string, Attributes>>;

void CollectDefaults(const XMLElement& node, const std::string& name,
                     std::map<std::string, Attributes> inherited, DefaultClasses& classes) {
  for (const XMLElement* child = node.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    if (std::string(child->Name()) == "default") continue;
    Attributes& set = inherited[child->Name()];
    for (const tinyxml2::XMLAttribute* a = child->FirstAttribute(); a; a = a->Next()) {
      set[a->Name()] = a->Value();
    }
  }
  classes[name] = inherited;
  for (const XMLElement* nested = node.FirstChildElement("default"); nested;
       nested = nested->NextSiblingElement("default")) {
    const char* child_name = nested->Attribute("class");
    CollectDefaults(*nested, child_name == nullptr ? "" : child_name, inherited, classes);
  }
}

class ActuatorReader {
 public:
  ActuatorReader(const XMLElement& element, const std::string& path, Attributes defaults)
      : element_(element), path_(path), values_(std::move(defaults)) {
    for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
      values_[a->Name()] = a->Value();
    }
  }

  bool Has(const std::string& key) const { return values_.count(key) > 0; }
  std::string Text(const std::string& key, const std::string& fallback) const {
    const auto at = values_.find(key);
    return at == values_.end() ? fallback : at->second;
  }
  std::vector<double> Numbers(const std::string& key, std::size_t count,
                              const std::string& fallback) const {
    return xml::ParseNumbers(Text(key, fallback), count, What(key), Where());
  }
  // MuJoCo's parameter arrays (gainprm, biasprm, dynprm, gear): up to `count` numbers, the
  // rest at MuJoCo's defaults, which are `first` for the first number (1 for gainprm, dynprm
  // and gear, 0 for biasprm) and 0 for the others
  std::vector<double> Padded(const std::string& key, std::size_t count, double first) const {
    std::vector<double> values = xml::ParseNumberList(Text(key, ""), count, What(key), Where());
    if (values.empty()) values.push_back(first);
    values.resize(count, 0.0);
    return values;
  }
  std::string What(const std::string& key) const {
    return "<" + std::string(element_.Name()) + "> '" + Name() + "' " + key;
  }
  std::string Where() const { return xml::Where(path_, element_); }
  std::string Name() const { return OneLineText(Text("name", "")); }  // for messages
  std::string CheckedName() const {
    return xml::ImportedName(Text("name", ""), element_.Name(), Where());
  }
  std::string Label() const {
    return std::string(element_.Name()) + " '" + Name() + "' (" + Where() + ")";
  }

 private:
  const XMLElement& element_;
  const std::string& path_;
  Attributes values_;
};

// MuJoCo's <muscle> defaults, as gainprm and dynprm would hold them
const char* const kMuscleDefaults[][2] = {
    {"range", "0.75 1.05"}, {"force", "-1"},       {"scale", "200"},
    {"lmin", "0.5"},        {"lmax", "1.6"},       {"vmax", "1.5"},
    {"fpmax", "1.3"},       {"fvmax", "1.2"},      {"timeconst", "0.01 0.04"},
    {"tausmooth", "0"},     {"lengthrange", "0 0"}};

struct MuscleNumbers {
  std::vector<double> gain;  // range0, range1, force, scale, lmin, lmax, vmax, fpmax, fvmax
  std::optional<std::vector<double>> dynamics;  // tau_act, tau_deact, tausmooth; none: no lag
  std::vector<double> lengthrange;
};

MuscleNumbers ReadShortcut(const ActuatorReader& read) {
  std::map<std::string, std::string> d;
  for (const auto& [key, value] : kMuscleDefaults) d[key] = value;
  MuscleNumbers n;
  const std::vector<double> range = read.Numbers("range", 2, d["range"]);
  n.gain = {range[0], range[1]};
  for (const char* key : {"force", "scale", "lmin", "lmax", "vmax", "fpmax", "fvmax"}) {
    n.gain.push_back(read.Numbers(key, 1, d[key])[0]);
  }
  const std::vector<double> timeconst = read.Numbers("timeconst", 2, d["timeconst"]);
  n.dynamics = std::vector<double>{timeconst[0], timeconst[1],
                                   read.Numbers("tausmooth", 1, d["tausmooth"])[0]};
  n.lengthrange = read.Numbers("lengthrange", 2, d["lengthrange"]);
  return n;
}

// A <general> actuator: nullopt with `why` set when it is not a muscle musclesim takes.
std::optional<MuscleNumbers> ReadGeneral(const ActuatorReader& read, std::string& why) {
  if (read.Text("gaintype", "fixed") != "muscle") {
    why = "gaintype " + PrintableText(read.Text("gaintype", "fixed")) + ", not muscle";
    return std::nullopt;
  }
  if (read.Text("biastype", "none") != "muscle") {
    why = "gaintype muscle with biastype " + PrintableText(read.Text("biastype", "none")) +
          ", not muscle";
    return std::nullopt;
  }
  MuscleNumbers n;
  n.gain = read.Padded("gainprm", 10, 1.0);
  const std::vector<double> bias = read.Padded("biasprm", 10, 0.0);
  if (bias != n.gain) {
    why = "biasprm differs from gainprm: musclesim's muscle has one parameter set";
    return std::nullopt;
  }
  const std::string dyntype = read.Text("dyntype", "none");
  if (dyntype == "muscle") {
    const std::vector<double> dynamics = read.Padded("dynprm", 10, 1.0);
    n.dynamics = dynamics;
  } else if (dyntype != "none") {
    why = "dyntype " + PrintableText(dyntype) + ", not none or muscle";
    return std::nullopt;
  }
  n.lengthrange = read.Numbers("lengthrange", 2, "0 0");
  return n;
}

// The muscle from its numbers, or nullopt with `why` when MuJoCo would compute a value from
// the rest of the model (force < 0, lengthrange absent).
std::optional<ImportedMuscle> ToMuscle(
    const ActuatorReader& read, const MuscleNumbers& n,
    const std::vector<std::pair<std::string, std::string>>& names, std::string& why) {
  if (n.gain[2] < 0.0) {
    why = "force " + FormatNumber(n.gain[2]) +
          ": MuJoCo sets the peak force to scale / acc0 from the model's inertia when it "
          "compiles; give force >= 0";
    return std::nullopt;
  }
  if (n.lengthrange[0] == 0.0 && n.lengthrange[1] == 0.0) {
    why =
        "no lengthrange: MuJoCo computes it from the joint or tendon when it compiles; give "
        "lengthrange";
    return std::nullopt;
  }
  ImportedMuscle muscle;
  muscle.name = read.CheckedName();
  muscle.source = read.Label();
  ModelParams& p = muscle.params;
  p.family = CurveFamily::kMujoco;
  p.f_iso = n.gain[2];
  MujocoMuscleParams& m = p.mujoco;
  m.range[0] = n.gain[0];
  m.range[1] = n.gain[1];
  m.lengthrange[0] = n.lengthrange[0];
  m.lengthrange[1] = n.lengthrange[1];
  m.lmin = n.gain[4];
  m.lmax = n.gain[5];
  m.vmax = n.gain[6];
  m.fpmax = n.gain[7];
  m.fvmax = n.gain[8];
  if (n.dynamics) {
    const std::vector<double>& d = *n.dynamics;
    ActivationDynamics lag;
    lag.family = ActivationFamily::kMujoco;
    lag.tau_activation = d[0];
    lag.tau_deactivation = d[1];
    lag.tausmooth = d[2];
    muscle.activation_dynamics = lag;
  }
  ValidateImported(muscle, names);
  // MuJoCo's clamps and timing, which the scenario's muscle does not have
  const char* const clamps[][3] = {{"forcerange", "forcelimited", "force"},
                                   {"actrange", "actlimited", "activation"}};
  for (const auto& [range, limited, what] : clamps) {
    const std::string flag = read.Text(limited, "auto");
    if (flag == "true" || (flag == "auto" && read.Has(range))) {
      muscle.notes.push_back(std::string(range) + " " + PrintableText(read.Text(range, "")) +
                             ": musclesim does not clamp the " + what);
    }
  }
  if (read.Text("actearly", "false") == "true") {
    muscle.notes.push_back(
        "actearly: MuJoCo's force uses the next step's activation; the scenario's, the current "
        "one");
  }
  const std::vector<double> gear = read.Padded("gear", 6, 1.0);
  if (gear[0] != 1.0) {
    muscle.notes.push_back("gear " + FormatNumber(gear[0]) +
                           ": the scenario's length is the actuator's (gear times the joint's "
                           "or tendon's), and its force the actuator's");
  }
  muscle.notes.push_back(
      "its transmission is not imported: the scenario puts the actuator on a line, its length "
      "the actuator length of lengthrange");
  return muscle;
}

// Every <include> in the file, depth first: musclesim reads the one file it is given.
void ListIncludes(const XMLElement& element, const std::string& path,
                  std::vector<std::string>& unsupported) {
  for (const XMLElement* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    if (std::string(child->Name()) == "include") {
      const char* file = child->Attribute("file");
      unsupported.push_back("include '" + PrintableText(file == nullptr ? "" : file) + "' (" +
                            xml::Where(path, *child) +
                            "): not followed; import the included file on its own");
    }
    ListIncludes(*child, path, unsupported);
  }
}

}  // namespace

ImportedModel ReadMjcfMuscles(const tinyxml2::XMLDocument& document, const std::string& path) {
  ImportedModel model;
  model.tool = "MuJoCo";
  const XMLElement& root = *document.RootElement();
  DefaultClasses classes;
  for (const XMLElement* d = root.FirstChildElement("default"); d;
       d = d->NextSiblingElement("default")) {
    const char* name = d->Attribute("class");
    CollectDefaults(*d, name == nullptr ? "main" : name, {}, classes);
  }
  for (const XMLElement* section = root.FirstChildElement("actuator"); section;
       section = section->NextSiblingElement("actuator")) {
    for (const XMLElement* a = section->FirstChildElement(); a; a = a->NextSiblingElement()) {
      const std::string kind = a->Name();
      const char* class_name = a->Attribute("class");
      const std::string cls = class_name == nullptr ? "main" : class_name;
      Attributes defaults;
      if (const auto c = classes.find(cls); c != classes.end()) {
        if (const auto k = c->second.find(kind); k != c->second.end()) defaults = k->second;
      } else if (class_name != nullptr) {
        throw InputError("<" + kind + "> class = " + PrintableText(cls) + " (" +
                         xml::Where(path, *a) + "): no <default class=...> of that name");
      }
      const ActuatorReader read(*a, path, defaults);
      std::string why;
      std::optional<MuscleNumbers> numbers;
      if (kind == "muscle") {
        numbers = ReadShortcut(read);
      } else if (kind == "general") {
        numbers = ReadGeneral(read, why);
      } else {
        why = "not a muscle";
      }
      std::optional<ImportedMuscle> muscle;
      if (numbers) {
        muscle = ToMuscle(read, *numbers, kind == "muscle" ? kShortcutNames : kGeneralNames, why);
      }
      if (muscle) {
        model.muscles.push_back(std::move(*muscle));
      } else {
        model.unsupported.push_back(read.Label() + ": " + why);
      }
    }
  }
  ListIncludes(root, path, model.unsupported);
  return model;
}

}  // namespace musclesim
