// An OpenSim object's properties read with its class's defaults (io/import/osim_muscles.cc,
// io/import/osim_millard.cc, io/import/osim_thelen.cc), every error naming the file and line, the
// object, the property and the rule.
#pragma once

#include <tinyxml2.h>

#include <optional>
#include <string>

namespace musclesim {

// The properties of one OpenSim object (a muscle, or one of its curves), each error naming
// the file and line, the object, the property and the rule.
class OsimPropertyReader {
 public:
  OsimPropertyReader(const tinyxml2::XMLElement& object, const std::string& path)
      : object_(object), path_(path) {}

  // The property's value, `fallback` when the file leaves it out.
  double Number(const char* property, double fallback) const;
  // `value` set to the property's, kept (a default) when the file leaves it out.
  void Read(const char* property, double& value) const { value = Number(property, value); }
  bool Flag(const char* property, bool fallback) const;
  // An optional property (OpenSim's empty `<curviness />`): none when absent or empty.
  std::optional<double> OptionalNumber(const char* property) const;

  // "Millard2012EquilibriumMuscle 'name' <property>", for messages
  std::string What(const char* property) const;
  // the object's name attribute, printable
  std::string Name() const;  // for messages: control characters escaped
  // The name as the file has it; InputError for a control character (xml::ImportedName).
  std::string CheckedName() const;
  // "path:line" of the object, and of its property (the object's when the file leaves it out)
  std::string Where() const;
  std::string WhereOf(const std::string& property) const;

 private:
  const tinyxml2::XMLElement& object_;
  const std::string& path_;
};

}  // namespace musclesim
