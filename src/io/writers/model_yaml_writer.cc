#include "musclesim/io/writers/model_yaml_writer.h"

#include <cassert>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "musclesim/io/writers/output_file.h"
#include "musclesim/model/family_fields.h"

namespace musclesim {

namespace {

using NumberFormat = std::string (*)(double);

// The shortest text that reads back as `value`, with a decimal point as YAML floats are
// usually written: 1.0, 0.0, -1.0, 1.0e-6, 1.0e6. Stand-ins are round numbers; 17 digits
// would only hide that.
std::string FormatShort(double value) {
  assert(std::isfinite(value));
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  const std::string text(buffer, result.ptr);
  const std::size_t e = text.find('e');
  std::string mantissa = text.substr(0, e);
  if (mantissa.find('.') == std::string::npos) mantissa += ".0";
  if (e == std::string::npos) return mantissa;
  // "e+06" -> "e6", "e-06" -> "e-6"
  const bool negative = text[e + 1] == '-';
  const std::size_t digits = text.find_first_not_of("+-0", e + 1);
  return mantissa + "e" + (negative ? "-" : "") + text.substr(digits);
}

std::string Comments(const std::vector<std::string>& comments, const char* indent) {
  std::string out;
  for (const std::string& c : comments) out += indent + ("# " + c) + "\n";
  return out;
}

// "   # a; b" after a value, or nothing.
std::string TrailingComment(const std::vector<std::string>& comments) {
  std::string joined;
  for (const std::string& c : comments) joined += (joined.empty() ? "" : "; ") + c;
  return joined.empty() ? "" : "   # " + joined;
}

// "{amplitude: a, width: b, center: d}": its fields (model/family_fields.h).
std::string GaussianMap(const Gaussian& g, NumberFormat number) {
  std::string map;
  for (const NumberField<Gaussian>& field : GaussianFields()) {
    map.append(map.empty() ? "{" : ", ")
        .append(field.key)
        .append(": ")
        .append(number(field.get(g)));
  }
  return map + "}";
}

std::string PassiveMap(const PassiveParams& p, NumberFormat number) {
  return "{k_p: " + number(p.k_p) + ", alpha: " + number(p.alpha) +
         ", slack_length: " + number(p.slack_length) + "}";
}

// `eccentric: {...}` with the keys given, or nothing when none is (the symmetric curve).
std::string EccentricEntry(const EccentricParams& e, NumberFormat number) {
  std::string keys;
  const auto add = [&](const std::string& key_value) {
    keys += (keys.empty() ? "" : ", ") + key_value;
  };
  if (e.v_max) add("v_max: " + number(*e.v_max));
  if (e.n) add("n: " + std::to_string(*e.n));
  if (e.limit) add("limit: " + number(*e.limit));
  return keys.empty() ? "" : ", eccentric: {" + keys + "}";
}

std::string VelocityMap(const VelocityParams& p, NumberFormat number) {
  return "{v_max: " + number(p.v_max) + ", n: " + std::to_string(p.n) +
         ", epsilon: " + number(p.epsilon) + EccentricEntry(p.eccentric, number) + "}";
}

std::string ActiveLengthBlock(const ModelYamlPart<ActiveLengthParams>& part,
                              const std::vector<std::string>& gaussian_comments) {
  const bool known = part.params.has_value();
  const ActiveLengthParams p = known ? *part.params : StandInModelParams().active_length;
  const NumberFormat number = known ? FormatFull : FormatShort;
  std::string out = "  active_length:\n" + Comments(part.comments, "    ");
  out += "    optimal_range: [" + number(p.optimal_min) + ", " + number(p.optimal_max) + "]\n";
  if (p.sigma != 1.0) out += "    sigma: " + number(p.sigma) + "\n";  // 1 is the default
  if (!known) {
    // a stand-in is short: the whole list on one line
    std::string items;
    for (const Gaussian& g : p.gaussians) {
      items += (items.empty() ? "" : ", ") + GaussianMap(g, number);
    }
    return out + "    gaussians: [" + items + "]\n";
  }
  if (!gaussian_comments.empty() && gaussian_comments.size() != p.gaussians.size()) {
    throw std::invalid_argument("FormatModelYaml: " + std::to_string(gaussian_comments.size()) +
                                " gaussian comments for " + std::to_string(p.gaussians.size()) +
                                " components");
  }
  out += "    gaussians:\n";
  for (std::size_t k = 0; k < p.gaussians.size(); ++k) {
    out += "      - " + GaussianMap(p.gaussians[k], number) + "\n";
    if (!gaussian_comments.empty()) out += "        # " + gaussian_comments[k] + "\n";
  }
  return out;
}

}  // namespace

std::string FormatModelYaml(const ModelYamlDraft& draft) {
  const ModelParams stand_in = StandInModelParams();
  std::string out = Comments(draft.header, "") + "model:\n";

  const auto& f_iso = draft.f_iso;
  out += "  f_iso: " + (f_iso.params ? FormatFull(*f_iso.params) : FormatShort(stand_in.f_iso)) +
         TrailingComment(f_iso.comments) + "\n";

  // known parts carry long comments (standard errors) on lines of their own
  const auto& passive = draft.passive;
  out += passive.params ? "  passive: " + PassiveMap(*passive.params, FormatFull) + "\n" +
                              Comments(passive.comments, "  ")
                        : "  passive: " + PassiveMap(stand_in.passive, FormatShort) +
                              TrailingComment(passive.comments) + "\n";

  out += ActiveLengthBlock(draft.active_length, draft.gaussian_comments);

  const auto& velocity = draft.velocity;
  out += velocity.params ? "  velocity: " + VelocityMap(*velocity.params, FormatFull) + "\n" +
                               Comments(velocity.comments, "  ")
                         : "  velocity: " + VelocityMap(stand_in.velocity, FormatShort) +
                               TrailingComment(velocity.comments) + "\n";
  return out;
}

std::string FormatGaussianYaml(const Gaussian& gaussian) {
  return GaussianMap(gaussian, FormatFull);
}

ModelParams StandInModelParams() {
  ModelParams p;
  p.f_iso = 1.0;
  p.passive = {0.0, 1.0, 0.0};
  p.active_length.optimal_min = -1.0;
  p.active_length.optimal_max = 1.0;
  p.active_length.sigma = 1.0;
  p.active_length.gaussians = {Gaussian{1.0, 1e-6, 0.0}};
  p.velocity = {1e6, 1, 1.0};
  return p;
}

double StandInEpsilon(double v_max) { return 1e-3 * v_max; }

}  // namespace musclesim
