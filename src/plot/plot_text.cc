#include "plot/plot_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"

namespace musclesim::plot_text {

bool EndsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

bool IsControl(unsigned char byte) { return byte < 0x20 || byte == 0x7f; }

// Offset of the first byte that does not start a well-formed UTF-8 sequence (RFC 3629: no
// overlong forms, no surrogates, nothing above U+10FFFF), or npos.
std::size_t FirstInvalidUtf8(const std::string& text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char lead = byte(i);
    std::size_t length = 1;
    unsigned char lo = 0x80, hi = 0xbf;  // the range allowed for the second byte
    if (lead < 0x80) {
      ++i;
      continue;
    } else if (lead >= 0xc2 && lead <= 0xdf) {
      length = 2;
    } else if (lead >= 0xe0 && lead <= 0xef) {
      length = 3;
      if (lead == 0xe0) lo = 0xa0;  // overlong
      if (lead == 0xed) hi = 0x9f;  // surrogates
    } else if (lead >= 0xf0 && lead <= 0xf4) {
      length = 4;
      if (lead == 0xf0) lo = 0x90;  // overlong
      if (lead == 0xf4) hi = 0x8f;  // above U+10FFFF
    } else {
      return i;
    }
    if (i + length > text.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      const unsigned char next = byte(i + k);
      if (next < (k == 1 ? lo : 0x80) || next > (k == 1 ? hi : 0xbf)) return i;
    }
    i += length;
  }
  return std::string::npos;
}

std::string Hex(unsigned char byte) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02x", byte);
  return text;
}

// Text echoed in a message: control bytes (and every non-ASCII byte of invalid UTF-8) as
// \xNN, so that an error never sends a terminal escape; cut after 80 bytes.
std::string Printable(const std::string& text) {
  const bool utf8 = FirstInvalidUtf8(text) == std::string::npos;
  std::string out;
  std::size_t i = 0;
  for (; i < text.size() && i < 80; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (IsControl(byte) || (!utf8 && byte >= 0x80)) {
      out += "\\x" + Hex(byte).substr(2);
    } else {
      out += text[i];
    }
  }
  // finish a multi-byte character the cut fell into
  while (utf8 && i < text.size() && (static_cast<unsigned char>(text[i]) & 0xc0) == 0x80) {
    out += text[i++];
  }
  return i < text.size() ? out + "..." : out;
}

// Plot data in the shortest exact form, as messages print numbers.
std::string Number(double value) { return FormatNumber(value); }

// The cell as a plotted number: gnuplot would draw NaN and infinity as gaps or clip them
// without a word, so they are errors here.
double FiniteValue(const CsvTable& table, std::size_t row, int column) {
  const std::string& text = table.rows[row][static_cast<std::size_t>(column)];
  const std::string where = table.source + ":" + std::to_string(table.lines[row]) + ": column " +
                            Printable(table.header[static_cast<std::size_t>(column)]) + " = '" +
                            Printable(text) + "'";
  const auto control = [](char c) { return IsControl(static_cast<unsigned char>(c)); };
  if (std::any_of(text.begin(), text.end(), control)) {
    throw InputError(where + ": must be a number");
  }
  const double value = table.Number(row, column);
  if (!std::isfinite(value)) throw InputError(where + ": must be a finite number");
  return value;
}

// What every figure shares. Text is drawn as written: enhanced-text markup (^ _ @ & { })
// is off here as well as in Render's terminal, so a script saved with --script and run
// under another terminal draws user text literally too.
const char* const kFrame =
    "set encoding utf8\nset termoption noenhanced\nset grid lc rgb '#dddddd'\n";

// A wide axis of positive values reads better on a log scale.
bool WantsLogScale(const std::vector<double>& values) {
  if (values.empty()) return false;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  return *lo > 0.0 && *hi / *lo >= 100.0;
}

std::string TitleOf(const PlotOptions& options, const std::string& fallback,
                    const std::string& fallback_source) {
  return options.title.empty() ? GnuplotString(fallback, fallback_source)
                               : OptionString(options.title, "title");
}

}  // namespace musclesim::plot_text
