// OpenSim's .osim: DeGrooteFregly2016Muscle as family degroote2016 (docs/model.md 14.1), its
// absent properties at OpenSim 4.6's defaults (bench/peers/README.md); Millard's and Thelen's
// muscles converted to it (io/import/osim_millard.cc, io/import/osim_thelen.cc).
#include <string>
#include <utility>
#include <vector>

#include "io/import/muscle_import_readers.h"
#include "io/import/osim_muscle_parts.h"
#include "io/import/osim_property_reader.h"
#include "io/import/xml_reading.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/core/number_format.h"
#include "musclesim/core/printable_text.h"

namespace musclesim {

namespace {

using tinyxml2::XMLElement;

// OpenSim 4.6's DeGrooteFregly2016Muscle defaults for the properties a file leaves out
// (beside those of every muscle, StartMuscle's).
struct DeGrooteDefaults {
  double tendon_strain_at_one_norm_force = 0.049;
  double activation_time_constant = 0.015;    // s
  double deactivation_time_constant = 0.060;  // s
  double activation_dynamics_smoothing = 0.1;
};

ImportedMuscle ReadDeGroote(const XMLElement& element, const std::string& path) {
  const OsimPropertyReader read(element, path);
  const DeGrooteDefaults defaults;
  ImportedMuscle muscle = StartMuscle(read, "DeGrooteFregly2016Muscle");
  DeGrooteParams& d = muscle.params.degroote2016;
  d.active_force_width_scale = read.Number("active_force_width_scale", d.active_force_width_scale);
  d.passive_fiber_strain_at_one_norm_force = read.Number("passive_fiber_strain_at_one_norm_force",
                                                         d.passive_fiber_strain_at_one_norm_force);
  d.fiber_damping = read.Number("fiber_damping", d.fiber_damping);

  if (!read.Flag("ignore_tendon_compliance", false)) {
    const double strain =
        read.Number("tendon_strain_at_one_norm_force", defaults.tendon_strain_at_one_norm_force);
    SetCompliantTendon(muscle, strain, "tendon_strain_at_one_norm_force",
                       read.WhereOf("tendon_strain_at_one_norm_force"));
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
  ValidateImported(muscle, kOsimPropertyNames);
  AddCommonNotes(read, element, muscle);
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
      if (OsimPropertyReader(*force, path).Flag("ignore_passive_fiber_force", false)) {
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
    if (type == "Millard2012EquilibriumMuscle") {
      model.muscles.push_back(ReadMillard(*force, path));
      continue;
    }
    if (type == "Thelen2003Muscle") {
      model.muscles.push_back(ReadThelen(*force, path));
      continue;
    }
    const bool muscle = IsMuscleClass(type);
    model.unsupported.push_back(
        type + " '" + PrintableText(name == nullptr ? "" : name) + "' (" +
        xml::Where(path, *force) + "): " +
        (muscle ? "a muscle class musclesim does not import (it imports "
                  "DeGrooteFregly2016Muscle, and Millard2012EquilibriumMuscle converted to it)"
                : "not a muscle"));
  }
  return model;
}

}  // namespace musclesim
