#include "musclesim/scenario/setting_fields.h"

#include <utility>

namespace musclesim {

namespace {

PartVariant<TimeSpan> DescribeTime() {
  return OnlyVariant<TimeSpan>(
      "time", "the run integrates from start to end",
      {MemberField("start", &TimeSpan::start, kTimeRange, std::nullopt,
                   "where the run begins, its initial state given there"),
       MemberField("end", &TimeSpan::end, kTimeRange, std::nullopt,
                   "where it ends: after start by at least 1e-9 of the time scale, the largest "
                   "of 1 s and the magnitudes of start and end")});
}

PartVariant<OutputRequest> DescribeOutput() {
  NumberField<OutputRequest> tolerance{
      "phase_tolerance", kPhaseToleranceRange, std::nullopt,
      "v_tol, the speed below which the phase column reads isometric; absent: each "
      "actuator's model's velocity epsilon",
      // absent: no value of its own (0 here; each model's epsilon stands in)
      [](const OutputRequest& o) { return o.phase_tolerance.value_or(0.0); },
      [](OutputRequest& o, double v) { o.phase_tolerance = v; }};
  tolerance.given = [](const OutputRequest& o) { return o.phase_tolerance.has_value(); };
  // its rule is against the span (the reader's): a time rather than a range of its own
  NumberField<OutputRequest> interval{
      "interval",
      InputRange{0.0, 0.0, "s", ""},
      std::nullopt,
      "the time between rows: at most 1e8 rows over the span, and at least 1e-12 of the "
      "time scale, the largest of 1 s and the magnitudes of start and end; absent: a "
      "thousandth of the span",
      [](const OutputRequest& o) { return o.interval; },
      [](OutputRequest& o, double v) {
        o.interval = v;
        o.every_step = false;
      }};
  interval.values = FieldValues::kFinite;
  interval.given = [](const OutputRequest& o) { return !o.every_step; };
  interval.word = "steps";
  interval.word_means = "a row per internal step";
  interval.set_word = [](OutputRequest& o) {
    o.every_step = true;
    o.interval = 0.0;
  };
  PartVariant<OutputRequest> block = OnlyVariant<OutputRequest>(
      "output", "the rows a run records", {std::move(interval), std::move(tolerance)});
  block.texts = {{"file",
                  "the CSV the rows go to, relative to the working directory; `-` standard "
                  "output; `-o PATH` overrides it, and must be given when it is absent",
                  [](const OutputRequest& o) { return o.file; },
                  [](OutputRequest& o, std::string file) { o.file = std::move(file); }}};
  return block;
}

}  // namespace

const std::vector<PartVariant<TimeSpan>>& TimeBlock() {
  static const std::vector<PartVariant<TimeSpan>> block{DescribeTime()};
  return block;
}

const std::vector<PartVariant<OutputRequest>>& OutputBlock() {
  static const std::vector<PartVariant<OutputRequest>> block{DescribeOutput()};
  return block;
}

}  // namespace musclesim
