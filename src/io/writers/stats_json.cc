#include "musclesim/io/writers/stats_json.h"

#include <sstream>

#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

std::string FormatStatsJson(const RunStats& s, const std::vector<SensitivityNote>& sensitivities) {
  std::ostringstream out;
  out << "{\n"
      << "  \"steps\": " << s.steps << ",\n"
      << "  \"rhs_evals\": " << s.rhs_evals << ",\n"
      << "  \"jac_evals\": " << s.jac_evals << ",\n"
      << "  \"linear_setups\": " << s.linear_setups << ",\n"
      << "  \"newton_iters\": " << s.newton_iters << ",\n"
      << "  \"newton_conv_fails\": " << s.newton_conv_fails << ",\n"
      << "  \"error_test_fails\": " << s.error_test_fails << ",\n"
      << "  \"wall_seconds\": " << FormatFull(s.wall_seconds) << ",\n"
      << "  \"final_time\": " << FormatFull(s.final_time) << ",\n"
      << "  \"linear_solver\": " << JsonString(std::string(ToString(s.linear_solver))) << ",\n"
      << "  \"status\": " << JsonString(std::string(ToString(s.status))) << ",\n"
      << "  \"message\": " << JsonString(s.message);
  if (!sensitivities.empty()) {
    out << ",\n"
        << "  \"sensitivity_rhs_evals\": " << s.sensitivity_rhs_evals << ",\n"
        << "  \"sensitivity_newton_iters\": " << s.sensitivity_newton_iters << ",\n"
        << "  \"sensitivity_newton_conv_fails\": " << s.sensitivity_newton_conv_fails << ",\n"
        << "  \"sensitivity_error_test_fails\": " << s.sensitivity_error_test_fails << ",\n"
        << "  \"sensitivities\": [";
    for (std::size_t i = 0; i < sensitivities.size(); ++i) {
      out << (i == 0 ? "\n" : ",\n") << "    {\"path\": " << JsonString(sensitivities[i].path)
          << ", \"derivative\": " << JsonString(sensitivities[i].derivative) << "}";
    }
    out << "\n  ]";
  }
  out << "\n}\n";
  return out.str();
}

}  // namespace musclesim
