#include "io/import/osim_muscle_parts.h"

#include "io/import/xml_reading.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/core/number_format.h"

namespace musclesim {

using tinyxml2::XMLElement;

const std::vector<std::pair<std::string, std::string>> kOsimPropertyNames = {
    {"f_iso", "max_isometric_force"},
    {"pennation_angle", "pennation_angle_at_optimal"},
    {"tau_activation", "activation_time_constant"},
    {"tau_deactivation", "deactivation_time_constant"},
    {"smoothing", "activation_dynamics_smoothing"},
};

ImportedMuscle StartMuscle(const OsimPropertyReader& read, const char* class_name) {
  ImportedMuscle muscle;
  muscle.name = read.CheckedName();
  muscle.source = std::string(class_name) + " (" + read.Where() + ")";
  ModelParams& p = muscle.params;
  p.family = CurveFamily::kDeGroote2016;
  DeGrooteParams& d = p.degroote2016;
  p.f_iso = read.Number("max_isometric_force", 1000.0);                      // N
  d.optimal_fiber_length = read.Number("optimal_fiber_length", 0.1);         // m
  d.max_contraction_velocity = read.Number("max_contraction_velocity", 10);  // l_opt per s
  p.pennation_angle = read.Number("pennation_angle_at_optimal", 0.0);
  muscle.tendon_slack_length = read.Number("tendon_slack_length", 0.2);  // m
  if (!(muscle.tendon_slack_length >= 0.0 && kPositionRange.Contains(muscle.tendon_slack_length))) {
    throw InputError(read.What("tendon_slack_length") + " = " +
                     FormatNumber(muscle.tendon_slack_length) + " (" +
                     read.WhereOf("tendon_slack_length") +
                     "): must be >= 0 and at most 1e3 [m] (a length; 0: no tendon)");
  }
  return muscle;
}

void SetCompliantTendon(ImportedMuscle& muscle, double strain, const char* strain_property,
                        const std::string& where) {
  if (!kTendonStrainRange.Contains(strain)) {
    throw InputError(muscle.source + " '" + muscle.name + "': " + strain_property + " = " +
                     FormatNumber(strain) + " (" + where + "): " + kTendonStrainRange.Rule());
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

void SetFirstOrderActivation(const OsimPropertyReader& read, double tau_activation,
                             double tau_deactivation, ImportedMuscle& muscle) {
  const double floor = read.Number("minimum_activation", 0.01);
  if (!(floor >= 0.0 && floor <= 1.0)) {
    throw InputError(read.What("minimum_activation") + " = " + FormatNumber(floor) + " (" +
                     read.WhereOf("minimum_activation") + "): must be in [0, 1]");
  }
  if (read.Flag("ignore_activation_dynamics", false)) return;
  ActivationDynamics lag;
  lag.family = ActivationFamily::kThelen2003;
  lag.tau_activation = read.Number("activation_time_constant", tau_activation);
  lag.tau_deactivation = read.Number("deactivation_time_constant", tau_deactivation);
  muscle.activation_dynamics = lag;
  if (floor > 0.0) {
    muscle.notes.push_back("minimum_activation " + FormatNumber(floor) +
                           ": OpenSim holds the activation at or above it; musclesim's "
                           "activation falls to the excitation");
  }
}

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
  const auto counted = [](int n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  std::string note = "its path (" + counted(points, "point", "points");
  if (wraps > 0) note += ", " + counted(wraps, "wrap object", "wrap objects");
  return note +
         ") is not imported: the scenario puts the muscle-tendon unit on a line, its length the "
         "actuator's";
}

void AddCommonNotes(const OsimPropertyReader& read, const XMLElement& element,
                    ImportedMuscle& muscle) {
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
}

void AddPennationClampNote(const OsimPropertyReader& read, ImportedMuscle& muscle) {
  // OpenSim's default, acos(0.1)
  const double clamp = read.Number("maximum_pennation_angle", 1.4706289056333368);
  if (!(clamp >= 0.0 && clamp <= 1.5707963267948966)) {
    throw InputError(read.What("maximum_pennation_angle") + " = " + FormatNumber(clamp) + " (" +
                     read.WhereOf("maximum_pennation_angle") + "): must be in [0, pi/2] [rad]");
  }
  if (muscle.params.pennation_angle == 0.0) return;
  muscle.notes.push_back("maximum_pennation_angle " + FormatNumber(clamp) +
                         " rad: OpenSim clamps the pennation there; musclesim does not");
}

}  // namespace musclesim
