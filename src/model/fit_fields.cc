#include "musclesim/model/fit_fields.h"

#include <utility>

#include "musclesim/core/input_ranges.h"

namespace musclesim {

namespace {

PartVariant<FitSpec> Fit() {
  NumberField<FitSpec> count{"count",
                             kGaussianCountRange,
                             std::nullopt,
                             "the Gaussians the sum has, m",
                             [](const FitSpec& f) { return static_cast<double>(f.count); },
                             [](FitSpec& f, double n) { f.count = static_cast<int>(n); }};
  count.integer = true;
  NumberField<FitSpec> optimal_length{
      "optimal_length",
      kLengthRange,
      std::nullopt,
      "target preset: the length l_opt its curve peaks at, within optimal_range; required there",
      [](const FitSpec& f) { return f.optimal_length.value_or(0.0); },
      [](FitSpec& f, double l) { f.optimal_length = l; }};
  optimal_length.given = [](const FitSpec& f) { return f.optimal_length.has_value(); };
  PartVariant<FitSpec> fit = OnlyVariant<FitSpec>(
      "fit", "the Gaussians fitted at load to the target over optimal_range (docs/model.md 3.2)",
      {std::move(count), std::move(optimal_length)});
  WordField<FitSpec> name;
  name.key = "name";
  for (const EnumName<ForceLengthPreset>& preset : kForceLengthPresetNames) {
    name.names.push_back(preset.name);
  }
  name.doc = "target preset: the standard curve; required there";
  name.get = [](const FitSpec& f) { return f.preset ? ToString(*f.preset) : std::string_view{}; };
  name.set = [](FitSpec& f, std::string_view text) {
    f.preset = Parse(kForceLengthPresetNames, "name", text);
  };
  name.optional = true;
  fit.words = {EnumField("target", &FitSpec::target, kFitTargetNames,
                         "indicator: 1 on optimal_range; polygon or samples: its points; "
                         "preset: a standard curve"),
               std::move(name)};
  fit.flags = {MemberFlag("nonnegative", &FitSpec::nonnegative, false,
                          "keep every amplitude >= 0 (a non-negative least squares fit)")};
  fit.other_keys = {"points", "widths", "centers"};
  return fit;
}

}  // namespace

const std::vector<PartVariant<FitSpec>>& FitBlock() {
  static const std::vector<PartVariant<FitSpec>> block{Fit()};
  return block;
}

}  // namespace musclesim
