#include "io/import/xml_reading.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "musclesim/core/errors.h"
#include "musclesim/core/printable_text.h"

namespace musclesim::xml {

namespace {

[[noreturn]] void Refuse(const std::string& what, const std::string& text, const std::string& where,
                         const std::string& rule) {
  throw InputError(what + " = " + PrintableText(text) + " (" + where + "): " + rule);
}

// One number from the front of `rest`, advancing it; false when none is there.
bool TakeNumber(const char*& rest, double& value) {
  while (*rest == ' ' || *rest == '\t' || *rest == '\n' || *rest == '\r') ++rest;
  if (*rest == '\0') return false;
  char* end = nullptr;
  value = std::strtod(rest, &end);
  if (end == rest) return false;
  // strtod reads C's hexadecimal floats; the tools read decimals only ("0x10": OpenSim's 0)
  for (const char* c = rest; c != end; ++c) {
    if (*c == 'x' || *c == 'X') return false;
  }
  rest = end;
  return std::isfinite(value);
}

}  // namespace

std::string Where(const std::string& path, const tinyxml2::XMLElement& element) {
  return path + ":" + std::to_string(element.GetLineNum());
}

std::vector<double> ParseNumbers(const std::string& text, std::size_t count,
                                 const std::string& what, const std::string& where) {
  const std::string rule =
      count == 1 ? "must be a number" : "must be " + std::to_string(count) + " numbers";
  std::vector<double> values;
  const char* rest = text.c_str();
  double value = 0.0;
  while (values.size() < count) {
    if (!TakeNumber(rest, value)) Refuse(what, text, where, rule);
    values.push_back(value);
  }
  while (*rest == ' ' || *rest == '\t' || *rest == '\n' || *rest == '\r') ++rest;
  if (*rest != '\0') Refuse(what, text, where, rule);
  return values;
}

std::vector<double> ParseNumberList(const std::string& text, std::size_t max_count,
                                    const std::string& what, const std::string& where) {
  std::vector<double> values;
  const char* rest = text.c_str();
  double value = 0.0;
  while (true) {
    while (*rest == ' ' || *rest == '\t' || *rest == '\n' || *rest == '\r') ++rest;
    if (*rest == '\0') break;
    if (values.size() == max_count || !TakeNumber(rest, value)) {
      Refuse(what, text, where, "must be at most " + std::to_string(max_count) + " numbers");
    }
    values.push_back(value);
  }
  return values;
}

double ParseNumber(const std::string& text, const std::string& what, const std::string& where) {
  return ParseNumbers(text, 1, what, where)[0];
}

bool ParseBool(const std::string& text, const std::string& what, const std::string& where) {
  std::istringstream in(text);
  std::string word, extra;
  in >> word >> extra;
  if (extra.empty() && word == "true") return true;
  if (extra.empty() && word == "false") return false;
  Refuse(what, text, where, "must be true or false");
}

const tinyxml2::XMLElement* Child(const tinyxml2::XMLElement& parent, const char* name) {
  return parent.FirstChildElement(name);
}

std::string TextOf(const tinyxml2::XMLElement& element) {
  const char* text = element.GetText();
  return text == nullptr ? std::string() : std::string(text);
}

std::string ImportedName(const std::string& raw, const std::string& label,
                         const std::string& where) {
  const std::size_t at = FirstLineControlCharacter(raw);
  if (at == std::string::npos) return raw;
  throw InputError(label + " name '" + OneLineText(raw) + "' (" + where +
                   "): holds the control character " + OneLineText(raw.substr(at, 1)) +
                   " at byte " + std::to_string(at + 1) +
                   "; a name is printable text on one line (it heads the written scenario and "
                   "names its file)");
}

}  // namespace musclesim::xml
