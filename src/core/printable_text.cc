#include "musclesim/core/printable_text.h"

#include <cstdio>

namespace musclesim {

namespace {

// The length of the control character starting at byte i (1, or 2 for a C1 control in
// UTF-8), or 0 when none starts there.
std::size_t ControlAt(std::string_view text, std::size_t i, bool line_breaks_too = false) {
  const auto byte = static_cast<unsigned char>(text[i]);
  const bool kept = !line_breaks_too && (byte == '\t' || byte == '\n');
  if ((byte < 0x20 && !kept) || byte == 0x7f) return 1;
  // U+0080..U+009F: 0xC2 then 0x80..0x9F (0x9B is CSI, the start of an escape sequence)
  if (byte == 0xc2 && i + 1 < text.size()) {
    const auto next = static_cast<unsigned char>(text[i + 1]);
    if (next >= 0x80 && next <= 0x9f) return 2;
  }
  return 0;
}

std::string Escaped(std::string_view text, bool line_breaks_too) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = ControlAt(text, i, line_breaks_too);
    if (length == 0) {
      out += text[i++];
      continue;
    }
    for (std::size_t k = 0; k < length; ++k, ++i) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned char>(text[i]));
      out += hex;
    }
  }
  return out;
}

}  // namespace

std::size_t FirstControlCharacter(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (ControlAt(text, i) > 0) return i;
  }
  return std::string_view::npos;
}

std::size_t FirstLineControlCharacter(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (ControlAt(text, i, true) > 0) return i;
  }
  return std::string_view::npos;
}

std::string PrintableText(std::string_view text) { return Escaped(text, false); }

std::string OneLineText(std::string_view text) { return Escaped(text, true); }

}  // namespace musclesim
