// Standard normalised active force-length curves from the literature (docs/guide/model.md): what a
// fit of Gaussians can take as its target (`fit: {target: preset, ...}`) and what `musclesim curves
// --preset` tabulates.
//
// Every preset is a function f(s) of the normalised length s = l / l_opt, scaled so that its
// peak is exactly 1 at s = 1, and exactly 0 outside its support [breaks.front(), breaks.back()].
// Each curve's source, constants and the choices made (where it is cut, how it is normalised)
// are in force_length_presets.cc.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "musclesim/core/enum_names.h"

namespace musclesim {

enum class ForceLengthPreset { kDeGroote2016, kThelen2003, kGordon1966, kMuJoCo };

// The presets' names, as a fit block's `name` gives them.
inline constexpr EnumName<ForceLengthPreset> kForceLengthPresetNames[] = {
    {ForceLengthPreset::kDeGroote2016, "degroote2016"},
    {ForceLengthPreset::kThelen2003, "thelen2003"},
    {ForceLengthPreset::kGordon1966, "gordon1966"},
    {ForceLengthPreset::kMuJoCo, "mujoco"},
};

std::string_view ToString(ForceLengthPreset preset);
// Throws ParameterError("name", text, "must be one of degroote2016, thelen2003, ...") for an
// unknown name.
ForceLengthPreset ParseForceLengthPreset(std::string_view text);
// Every preset, in the order their names are listed.
std::span<const ForceLengthPreset> AllForceLengthPresets();

// f(s) [-] at the normalised length s [-]: 1 at s = 1, at most 1 everywhere, 0 outside the
// support. Pure and thread-safe.
double EvaluatePreset(ForceLengthPreset preset, double normalized_length);

// Where a preset lives, for integrating it: the curve is smooth between consecutive breaks.
struct PresetPieces {
  std::vector<double> breaks;  // normalised lengths [-], increasing: the two ends of the
                               // support and every kink in between
  double panel = 0.0;          // widest interval [-] on which the curve is resolved by an
                               // 8-point Gauss-Legendre rule to roundoff
};
PresetPieces PiecesOf(ForceLengthPreset preset);

}  // namespace musclesim
