// Text from files and callers on its way to a terminal: control characters (escape, bell,
// backspace, the C1 controls) would move the cursor, recolour or clear the screen where a
// message quotes them, so they are shown as \xHH instead.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace musclesim {

// The byte offset of the first control character in `text` (a C0 control other than tab and
// newline, DEL, or a C1 control encoded in UTF-8), or std::string_view::npos.
std::size_t FirstControlCharacter(std::string_view text);

// `text` with every such control character written as \xHH (a C1 control: its two UTF-8
// bytes), the rest unchanged.
std::string PrintableText(std::string_view text);

// The same with tab, newline and carriage return counted as controls too: for text that must
// stay on one line (a comment in a written file, a name).
std::size_t FirstLineControlCharacter(std::string_view text);
std::string OneLineText(std::string_view text);

}  // namespace musclesim
