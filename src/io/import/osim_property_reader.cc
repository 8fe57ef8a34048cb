#include "io/import/osim_property_reader.h"

#include "io/import/xml_reading.h"
#include "musclesim/core/printable_text.h"

namespace musclesim {

using tinyxml2::XMLElement;

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
  return name == nullptr ? std::string() : OneLineText(name);
}

std::string OsimPropertyReader::CheckedName() const {
  const char* name = object_.Attribute("name");
  return xml::ImportedName(name == nullptr ? "" : name, object_.Name(), Where());
}

std::string OsimPropertyReader::Where() const { return xml::Where(path_, object_); }

std::string OsimPropertyReader::WhereOf(const std::string& property) const {
  const XMLElement* child = xml::Child(object_, property.c_str());
  return xml::Where(path_, child == nullptr ? object_ : *child);
}

}  // namespace musclesim
