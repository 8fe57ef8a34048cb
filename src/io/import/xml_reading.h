// Reading values out of another tool's XML file (io/import/muscle_import.h): each error names the
// file and line, the element, the property or attribute, the value and the rule broken.
#pragma once

#include <tinyxml2.h>

#include <string>
#include <vector>

namespace musclesim::xml {

// Where a value sits, for messages: "path:line".
std::string Where(const std::string& path, const tinyxml2::XMLElement& element);

// `text` as one finite number; InputError "what = text (where): must be a number" otherwise.
double ParseNumber(const std::string& text, const std::string& what, const std::string& where);
// `text` as exactly `count` finite numbers separated by blanks.
std::vector<double> ParseNumbers(const std::string& text, std::size_t count,
                                 const std::string& what, const std::string& where);
// `text` as at most `max_count` finite numbers separated by blanks (none for a blank text).
std::vector<double> ParseNumberList(const std::string& text, std::size_t max_count,
                                    const std::string& what, const std::string& where);
// "true" or "false" (OpenSim's booleans).
bool ParseBool(const std::string& text, const std::string& what, const std::string& where);

// An imported part's name, `raw` as the file holds it (`label` says whose, `where` its
// place): it heads the written scenario's comments and names its file, so a control
// character (a newline would start a line of YAML there) is an InputError.
std::string ImportedName(const std::string& raw, const std::string& label,
                         const std::string& where);

// The text of the child element `name` of `parent` (OpenSim's properties), or nullptr.
const tinyxml2::XMLElement* Child(const tinyxml2::XMLElement& parent, const char* name);
std::string TextOf(const tinyxml2::XMLElement& element);

}  // namespace musclesim::xml
