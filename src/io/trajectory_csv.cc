#include "musclesim/io/trajectory_csv.h"

#include <sstream>

#include "musclesim/io/output_file.h"
#include "musclesim/model/enum_names.h"

namespace musclesim {

constexpr EnumName<Phase> kPhaseNames[] = {
    {Phase::kConcentric, "concentric"},
    {Phase::kEccentric, "eccentric"},
    {Phase::kIsometric, "isometric"},
};

std::string_view ToString(Phase phase) { return ToString(kPhaseNames, phase); }

void AppendTrajectoryRow(std::string& csv, const TrajectoryPoint& p, double phase_tolerance,
                         bool with_excitation) {
  const ActuatorSample& s = p.sample;
  const auto number = [&](double value) {
    csv += FormatFull(value);
    csv += ',';
  };
  for (double value : {p.t, s.length, s.shortening_velocity, s.activation}) number(value);
  if (with_excitation) number(s.excitation);
  for (double value : {s.tension.passive, s.tension.active, s.tension.total, s.load}) {
    number(value);
  }
  csv += ToString(ClassifyPhase(s.shortening_velocity, phase_tolerance));
  csv += '\n';
}

std::string FormatTrajectoryCsv(const std::vector<TrajectoryPoint>& trajectory,
                                double phase_tolerance, bool with_excitation) {
  std::string csv;
  csv.reserve(200 * (trajectory.size() + 1));
  csv += with_excitation ? kTrajectoryHeaderWithExcitation : kTrajectoryHeader;
  csv += '\n';
  for (const TrajectoryPoint& p : trajectory) {
    AppendTrajectoryRow(csv, p, phase_tolerance, with_excitation);
  }
  return csv;
}

namespace {

constexpr std::size_t kBlockBytes = 1 << 16;

}  // namespace

TrajectoryCsvWriter::TrajectoryCsvWriter(StreamedOutput& output, double phase_tolerance,
                                         bool with_excitation)
    : output_(output), phase_tolerance_(phase_tolerance), with_excitation_(with_excitation) {
  buffer_.reserve(kBlockBytes + 512);
  buffer_ += with_excitation ? kTrajectoryHeaderWithExcitation : kTrajectoryHeader;
  buffer_ += '\n';
}

void TrajectoryCsvWriter::Record(const TrajectoryPoint& point) {
  AppendTrajectoryRow(buffer_, point, phase_tolerance_, with_excitation_);
  ++rows_;
  last_ = point;
  if (buffer_.size() >= kBlockBytes) Flush();
}

void TrajectoryCsvWriter::Flush() {
  output_.Write(buffer_);
  buffer_.clear();
}

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
