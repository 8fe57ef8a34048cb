// The blocks of `musclesim identify`'s data file described (identify_spec.h).
#include "musclesim/core/input_ranges.h"
#include "musclesim/io/readers/identify_spec.h"

namespace musclesim {

namespace {

// A block's `csv`: required, a path relative to the data file.
TextField<IdentifySpec> CsvField(std::optional<std::string> IdentifySpec::*member,
                                 const char* doc) {
  TextField<IdentifySpec> csv{
      "csv", doc, [member](const IdentifySpec& s) { return (s.*member).value_or(""); },
      [member](IdentifySpec& s, std::string path) { s.*member = std::move(path); }};
  csv.required = true;
  return csv;
}

std::vector<PartVariant<IdentifySpec>> MakeBlocks() {
  PartVariant<IdentifySpec> passive =
      OnlyVariant<IdentifySpec>("passive", "slack_length, k_p, alpha fitted", {});
  passive.texts = {CsvField(&IdentifySpec::passive_csv,
                            "the measured passive curve, columns length [m] and tension [N], "
                            "relative to the data file")};

  NumberField<IdentifySpec> count{
      "count",
      kGaussianCountRange,
      3.0,
      "the Gaussians f_L is fitted with",
      [](const IdentifySpec& s) { return static_cast<double>(s.active_count); },
      [](IdentifySpec& s, double n) { s.active_count = static_cast<int>(n); }};
  count.integer = true;
  PartVariant<IdentifySpec> active =
      OnlyVariant<IdentifySpec>("active", "the Gaussians and f_iso fitted", {std::move(count)});
  active.texts = {CsvField(&IdentifySpec::active_csv,
                           "the measured active curve, columns length [m] and tension [N], "
                           "relative to the data file")};
  active.flags = {MemberFlag("nonnegative", &IdentifySpec::active_nonnegative, false,
                             "keep every Gaussian's amplitude >= 0 (a non-negative least "
                             "squares fit)")};

  NumberField<IdentifySpec> f_iso{
      "f_iso",
      kPositiveForceRange,
      std::nullopt,
      "the isometric force, held fixed when given; else fitted with v_max and n",
      [](const IdentifySpec& s) { return s.velocity_f_iso.value_or(0.0); },
      [](IdentifySpec& s, double f) { s.velocity_f_iso = f; }};
  f_iso.given = [](const IdentifySpec& s) { return s.velocity_f_iso.has_value(); };
  PartVariant<IdentifySpec> velocity = OnlyVariant<IdentifySpec>(
      "velocity", "v_max, n and f_iso fitted (eccentric ones too)", {std::move(f_iso)});
  velocity.texts = {CsvField(&IdentifySpec::velocity_csv,
                             "the measured force-velocity curve, columns shortening_velocity "
                             "[m/s] and tension [N], relative to the data file")};
  return {std::move(passive), std::move(active), std::move(velocity)};
}

}  // namespace

const std::vector<PartVariant<IdentifySpec>>& IdentifyDataBlocks() {
  static const std::vector<PartVariant<IdentifySpec>> blocks = MakeBlocks();
  return blocks;
}

}  // namespace musclesim
