// OpenSim's .osim: DeGrooteFregly2016Muscle as family degroote2016 (docs/model.md 14.1), its
// absent properties at OpenSim 4.6's defaults (bench/peers/README.md).
#include <string>
#include <utility>
#include <vector>

#include "io/muscle_import_readers.h"
#include "io/xml_reading.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/core/number_format.h"
#include "musclesim/core/printable_text.h"

namespace musclesim {

namespace {

using tinyxml2::XMLElement;

// OpenSim 4.6's DeGrooteFregly2016Muscle defaults for the properties a file leaves out.
struct DeGrooteDefaults {
  double max_isometric_force = 1000.0;  // N
  double optimal_fiber_length = 0.1;    // m
  double tendon_slack_length = 0.2;     // m
  double tendon_strain_at_one_norm_force = 0.049;
  double activation_time_constant = 0.015;    // s
  double deactivation_time_constant = 0.060;  // s
  double activation_dynamics_smoothing = 0.1;
};

// musclesim's key -> OpenSim's property, for messages
const std::vector<std::pair<std::string, std::string>> kPropertyNames = {
    {"f_iso", "max_isometric_force"},
    {"pennation_angle", "pennation_angle_at_optimal"},
    {"tau_activation", "activation_time_constant"},
    {"tau_deactivation", "deactivation_time_constant"},
    {"smoothing", "activation_dynamics_smoothing"},
};

class MuscleReader {
 public:
  MuscleReader(const XMLElement& muscle, const std::string& path) : muscle_(muscle), path_(path) {}

  double Number(const char* property, double fallback) const {
    const XMLElement* child = xml::Child(muscle_, property);
    if (child == nullptr) return fallback;
    return xml::ParseNumber(xml::TextOf(*child), What(property), xml::Where(path_, *child));
  }
  bool Flag(const char* property, bool fallback) const {
    const XMLElement* child = xml::Child(muscle_, property);
    if (child == nullptr) return fallback;
    return xml::ParseBool(xml::TextOf(*child), What(property), xml::Where(path_, *child));
  }
  std::string What(const char* property) const {
    return std::string(muscle_.Name()) + " '" + Name() + "' <" + property + ">";
  }
  std::string Name() const {
    const char* name = muscle_.Attribute("name");
    return name == nullptr ? std::string() : PrintableText(name);
  }

 private:
  const XMLElement& muscle_;
  const std::string& path_;
};

// The path's points and wrapping: not imported (the template puts the unit on a line).
std::string GeometryNote(const XMLElement& muscle) {
  int points = 0, wraps = 0;
  if (const XMLElement* path = muscle.FirstChildElement("GeometryPath")) {
    if (const XMLElement* set = path->FirstChildElement("PathPointSet")) {
      if (const XMLElement* objects = set->FirstChildElement("objects")) {
        for (const XMLElement* p = objects->FirstChildElement(); p; p = p->NextSiblingElement()) {
          ++points;
        }
      }
    }
    if (const XMLElement* set = path->FirstChildElement("PathWrapSet")) {
      if (const XMLElement* objects = set->FirstChildElement("objects")) {
        for (const XMLElement* w = objects->FirstChildElement(); w; w = w->NextSiblingElement()) {
          ++wraps;
        }
      }
    }
  }
  std::string note = "its path (" + std::to_string(points) + " points";
  if (wraps > 0) note += ", " + std::to_string(wraps) + " wrap objects";
  return note +
         ") is not imported: the scenario puts the muscle-tendon unit on a line, its length the "
         "actuator's";
}

ImportedMuscle ReadDeGroote(const XMLElement& element, const std::string& path) {
  const MuscleReader read(element, path);
  const DeGrooteDefaults defaults;
  ImportedMuscle muscle;
  muscle.name = read.Name();
  muscle.source = "DeGrooteFregly2016Muscle (" + xml::Where(path, element) + ")";
  ModelParams& p = muscle.params;
  p.family = CurveFamily::kDeGroote2016;
  DeGrooteParams& d = p.degroote2016;
  p.f_iso = read.Number("max_isometric_force", defaults.max_isometric_force);
  d.optimal_fiber_length = read.Number("optimal_fiber_length", defaults.optimal_fiber_length);
  d.max_contraction_velocity = read.Number("max_contraction_velocity", d.max_contraction_velocity);
  d.active_force_width_scale = read.Number("active_force_width_scale", d.active_force_width_scale);
  d.passive_fiber_strain_at_one_norm_force = read.Number("passive_fiber_strain_at_one_norm_force",
                                                         d.passive_fiber_strain_at_one_norm_force);
  d.fiber_damping = read.Number("fiber_damping", d.fiber_damping);
  p.pennation_angle = read.Number("pennation_angle_at_optimal", 0.0);
  muscle.tendon_slack_length = read.Number("tendon_slack_length", defaults.tendon_slack_length);

  if (!read.Flag("ignore_tendon_compliance", false)) {
    const double strain =
        read.Number("tendon_strain_at_one_norm_force", defaults.tendon_strain_at_one_norm_force);
    if (!kTendonStrainRange.Contains(strain)) {
      throw InputError(muscle.source + " '" + muscle.name +
                       "': tendon_strain_at_one_norm_force = " + FormatNumber(strain) + ": " +
                       kTendonStrainRange.Rule());
    }
    muscle.tendon_strain = strain;
    // De Groote's tendon is normalised by its slack length
    const double l_s = muscle.tendon_slack_length;
    if (!(l_s > 0.0) || !kPositionRange.Contains(l_s)) {
      throw InputError(muscle.source + " '" + muscle.name +
                       "': tendon_slack_length = " + FormatNumber(l_s) +
                       ": must be > 0 and at most 1e3 [m] for a compliant tendon (De Groote's "
                       "is normalised by it)");
    }
  }
  if (!read.Flag("ignore_activation_dynamics", false)) {
    ActivationDynamics lag;
    lag.family = ActivationFamily::kDeGroote2016;
    lag.tau_activation = read.Number("activation_time_constant", defaults.activation_time_constant);
    lag.tau_deactivation =
        read.Number("deactivation_time_constant", defaults.deactivation_time_constant);
    lag.smoothing =
        read.Number("activation_dynamics_smoothing", defaults.activation_dynamics_smoothing);
    muscle.activation_dynamics = lag;
  }
  ValidateImported(muscle, kPropertyNames);
  if (!read.Flag("appliesForce", true)) {
    muscle.notes.push_back(
        "appliesForce is false: OpenSim applies no force of this muscle; the scenario's muscle "
        "pulls");
  }
  if (xml::Child(element, "default_activation") != nullptr) {
    muscle.notes.push_back("default_activation " +
                           FormatNumber(read.Number("default_activation", 0.0)) +
                           ": the scenario starts at activation 0 (edit initial.activation)");
  }
  muscle.notes.push_back(GeometryNote(element));
  return muscle;
}

bool IsMuscleClass(const std::string& type) {
  return type.size() >= 6 && type.compare(type.size() - 6, 6, "Muscle") == 0;
}

// Every force under a ForceSet's <objects>, and every muscle elsewhere (a model's
// <components>), depth first (a model may nest sets).
void CollectForces(const XMLElement& element, std::vector<const XMLElement*>& forces) {
  for (const XMLElement* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    if (IsMuscleClass(child->Name())) {
      forces.push_back(child);
      continue;
    }
    if (std::string(child->Name()) == "ForceSet") {
      if (const XMLElement* objects = child->FirstChildElement("objects")) {
        for (const XMLElement* f = objects->FirstChildElement(); f; f = f->NextSiblingElement()) {
          forces.push_back(f);
        }
      }
      continue;
    }
    CollectForces(*child, forces);
  }
}

}  // namespace

ImportedModel ReadOpenSimMuscles(const tinyxml2::XMLDocument& document, const std::string& path) {
  ImportedModel model;
  model.tool = "OpenSim";
  std::vector<const XMLElement*> forces;
  CollectForces(*document.RootElement(), forces);
  for (const XMLElement* force : forces) {
    const std::string type = force->Name();
    const char* name = force->Attribute("name");
    if (type == "DeGrooteFregly2016Muscle") {
      if (MuscleReader(*force, path).Flag("ignore_passive_fiber_force", false)) {
        model.unsupported.push_back(
            type + " '" + PrintableText(name == nullptr ? "" : name) + "' (" +
            xml::Where(path, *force) +
            "): ignore_passive_fiber_force is true, and the degroote2016 family always has the "
            "passive fiber force");
        continue;
      }
      model.muscles.push_back(ReadDeGroote(*force, path));
      continue;
    }
    const bool muscle = IsMuscleClass(type);
    model.unsupported.push_back(
        type + " '" + PrintableText(name == nullptr ? "" : name) + "' (" +
        xml::Where(path, *force) + "): " +
        (muscle ? "a muscle class musclesim does not implement (DeGrooteFregly2016Muscle only)"
                : "not a muscle"));
  }
  return model;
}

}  // namespace musclesim
