// Control characters quoted from files are written as \xHH in messages: the escape sequences
// that would recolour or clear a terminal, the bell, and the C1 controls in UTF-8; tabs,
// newlines and other UTF-8 text (a name in Greek, a degree sign) are left as they are.
#include "musclesim/core/printable_text.h"

#include <gtest/gtest.h>

#include <string>

#include "musclesim/core/errors.h"

namespace musclesim {
namespace {

TEST(PrintableText, EscapesControlCharactersOnly) {
  EXPECT_EQ(PrintableText("red\x1b[31m!\x07"), "red\\x1B[31m!\\x07");
  EXPECT_EQ(PrintableText(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(PrintableText("del\x7f"), "del\\x7F");
  // U+009B (CSI) in UTF-8; U+00B0 (degree sign) shares its first byte and stays
  EXPECT_EQ(PrintableText("\xc2\x9b"
                          "2J 20\xc2\xb0"),
            "\\xC2\\x9B2J 20\xc2\xb0");
  EXPECT_EQ(PrintableText("tab\there\nline \xce\xb1"), "tab\there\nline \xce\xb1");
}

TEST(PrintableText, FindsTheFirstControlCharacter) {
  EXPECT_EQ(FirstControlCharacter("plain text\t\n"), std::string_view::npos);
  EXPECT_EQ(FirstControlCharacter("ab\x1b"), 2u);
  EXPECT_EQ(FirstControlCharacter("\xc2\xb0\xc2\x85"), 2u);
}

TEST(PrintableText, ErrorsQuoteTheirValuesEscaped) {
  const ParameterError parameter("name\x1b", "v\x07", "must be printable");
  EXPECT_STREQ(parameter.what(), "name\\x1B = v\\x07: must be printable");
  EXPECT_EQ(parameter.value(), "v\x07");  // the value itself is kept as given
  EXPECT_STREQ(InputError("file.yaml:1:1: bad \x1b[2J").what(), "file.yaml:1:1: bad \\x1B[2J");
}

}  // namespace
}  // namespace musclesim
