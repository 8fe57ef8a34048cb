// Private: reading a part's signals (dynamics/signal_fields.h) from its map: each a waveform
// map, or in 2 or 3 dimensions a list of one per coordinate, its values within the signal's
// bounds at the part, checked, its pulses resolved at the run's times. The messages name
// file:line:column, key path, value and rule, as every reader's do.
#pragma once

#include <string>
#include <vector>

#include "io/readers/coordinates_yaml.h"
#include "io/readers/scenario_fields.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/dynamics/signal_fields.h"

namespace musclesim {

// The first steps of `signals`' keys, each once, for a map's allowed keys: "co_contraction"
// of "co_contraction.level".
template <typename Part>
std::vector<std::string> SignalKeys(const std::vector<SignalField<Part>>& signals) {
  std::vector<std::string> keys;
  for (const SignalField<Part>& signal : signals) {
    std::string head = signal.key.substr(0, signal.key.find('.'));
    bool known = false;
    for (const std::string& key : keys) known = known || key == head;
    if (!known) keys.push_back(std::move(head));
  }
  return keys;
}

// Reads the signal `field` from the map `item` (the part's, at `path`) into `part`, if the
// part has a waveform for it (a controller's co_contraction made before its level; none: the
// signal is not the part's, and not read); a nested key's maps are the caller's to check. An
// optional one absent leaves the part's.
template <typename Part>
void ReadSignal(const yaml::Source& src, const Document& item, const std::string& path,
                const SignalField<Part>& field, Part& part, int dimensions, double t_start,
                double t_end) {
  if (field.get(part, 0) == nullptr) return;
  const Document* map = &item;
  std::string at = path;
  std::size_t begin = 0;
  for (std::size_t dot = field.key.find('.'); dot != std::string::npos;
       dot = field.key.find('.', begin)) {
    const std::string head = field.key.substr(begin, dot - begin);
    map = &yaml::Required(src, *map, at, head.c_str());
    at = yaml::Join(at, head);
    begin = dot + 1;
  }
  const std::string leaf = field.key.substr(begin);
  if (!(*map)[leaf] && !field.required) return;
  const Document& node = yaml::Required(src, *map, at, leaf.c_str());
  const std::string key_path = yaml::Join(at, leaf);
  const InputRange* values = field.values(part);
  const auto read = [&](const Document& given, const std::string& given_path, std::size_t c) {
    *field.at(part, c) = ReadSignalWaveform(src, given, given_path, values, field.check,
                                            field.continuous, t_start, t_end);
  };
  if (!field.per_coordinate) return read(node, key_path, 0);
  const std::string noun = field.coordinate_noun;
  if (dimensions == 1) {
    if (node.IsSequence()) {
      yaml::Fail(src, node, key_path, yaml::Describe(node),
                 "must be one " + noun + " (a waveform) in 1 dimension: a list of " + noun +
                     "s, one per coordinate, needs dimensions: 2 or 3 at the top level");
    }
    return read(node, key_path, 0);
  }
  const auto d = static_cast<std::size_t>(dimensions);
  if (!node.IsSequence() || node.size() != d) {
    yaml::Fail(src, node, key_path, yaml::Describe(node),
               "must be a list of " + std::to_string(d) + " " + noun + "s " +
                   (d == 2 ? "[x(t), y(t)]" : "[x(t), y(t), z(t)]") + ", each a waveform" +
                   (field.continuous ? " (constant, ramp, sine or table)" : "") + ": " +
                   HasDimensions(dimensions));
  }
  for (std::size_t c = 0; c < d; ++c) read(node[c], Indexed(key_path, c), c);
}

}  // namespace musclesim
