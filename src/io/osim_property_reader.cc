#include "io/osim_property_reader.h"

#include "io/xml_reading.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/core/number_format.h"
#include "musclesim/core/printable_text.h"

namespace musclesim {

using tinyxml2::XMLElement;

const std::vector<std::pair<std::string, std::string>> kOsimPropertyNames = {
    {"f_iso", "max_isometric_force"},
    {"pennation_angle", "pennation_angle_at_optimal"},
    {"tau_activation", "activation_time_constant"},
    {"tau_deactivation", "deactivation_time_constant"},
    {"smoothing", "activation_dynamics_smoothing"},
};

double OsimPropertyReader::Number(const char* property, double fallback) const {
  const XMLElement* child = xml::Child(object_, property);
  if (child == nullptr) return fallback;
  return xml::ParseNumber(xml::TextOf(*child), What(property), xml::Where(path_, *child));
}

bool OsimPropertyReader::Flag(const char* property, bool fallback) const {
  const XMLElement* child = xml::Child(object_, property);
  if (child == nullptr) return fallback;
  return xml::ParseBool(xml::TextOf(*child), What(property), xml::Where(path_, *child));
}

std::optional<double> OsimPropertyReader::OptionalNumber(const char* property) const {
  const XMLElement* child = xml::Child(object_, property);
  if (child == nullptr) return std::nullopt;
  const std::string text = xml::TextOf(*child);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) return std::nullopt;
  return xml::ParseNumber(text, What(property), xml::Where(path_, *child));
}

std::string OsimPropertyReader::What(const char* property) const {
  return std::string(object_.Name()) + " '" + Name() + "' <" + property + ">";
}

std::string OsimPropertyReader::Name() const {
  const char* name = object_.Attribute("name");
  return name == nullptr ? std::string() : PrintableText(name);
}

std::string OsimPropertyReader::Where() const { return xml::Where(path_, object_); }

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

void SetCompliantTendon(ImportedMuscle& muscle, double strain, const char* strain_property) {
  if (!kTendonStrainRange.Contains(strain)) {
    throw InputError(muscle.source + " '" + muscle.name + "': " + strain_property + " = " +
                     FormatNumber(strain) + ": " + kTendonStrainRange.Rule());
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

}  // namespace musclesim
