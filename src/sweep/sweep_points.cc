#include "musclesim/sweep/sweep_points.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/scenario/parameter.h"
#include "sweep/point_explanation.h"
#include "sweep/sweep_base.h"
#include "sweep/sweep_share.h"
#include "sweep/sweep_validation.h"

namespace musclesim {

namespace {

// "path=value, path=value" of a point, for messages.
std::string Describe(const SweepSpec& spec, const std::vector<std::string>& values) {
  std::string point;
  for (std::size_t k = 0; k < spec.axes.size(); ++k) {
    point += (k ? ", " : "") + spec.axes[k].path + "=" + values[k];
  }
  return point;
}

class ParameterPointFactory final : public PointFactory {
 public:
  ParameterPointFactory(Scenario base, std::vector<Parameter> handles)
      : base_(std::move(base)), handles_(std::move(handles)) {}

  std::unique_ptr<PointFactory> Copy() const override {
    return std::make_unique<ParameterPointFactory>(base_, handles_);
  }

  LoadedScenario Make(const SweepSpec& spec, long index) const override {
    Scenario point = base_;
    const std::vector<double> numbers = PointNumbers(spec, index);
    try {
      SetParameters(point, handles_, numbers);
    } catch (const ParameterError& error) {
      std::vector<std::size_t> axes(handles_.size());
      for (std::size_t k = 0; k < axes.size(); ++k) axes[k] = k;
      throw ExplainInvalidPoint(spec, index, base_, axes, handles_, numbers, error);
    }
    return {std::move(point), nullptr};
  }

 private:
  Scenario base_;
  std::vector<Parameter> handles_;  // one per axis
};

class FunctionPointFactory final : public PointFactory {
 public:
  explicit FunctionPointFactory(std::shared_ptr<const ScenarioMaker> make)
      : make_(std::move(make)) {}
  std::unique_ptr<PointFactory> Copy() const override {
    return std::make_unique<FunctionPointFactory>(make_);
  }
  LoadedScenario Make(const SweepSpec& spec, long index) const override {
    try {
      Scenario point = (*make_)(index, PointNumbers(spec, index));
      point.Validate();
      return {std::move(point), nullptr};
    } catch (const std::invalid_argument& error) {  // ParameterError among them
      throw InputError("point " + std::to_string(index) + " (" +
                       Describe(spec, PointValues(spec, index)) +
                       ") is not a valid scenario: " + error.what());
    }
  }

 private:
  std::shared_ptr<const ScenarioMaker> make_;
};

// The points checked before anything runs: all of a small sweep; of a large one, point 0
// and, for a grid, the lines through it (every value of every axis, the others at their
// first value), or the first points of a zip or random sweep; at most kUpFrontPoints.
std::vector<long> UpFrontPoints(const SweepSpec& spec) {
  const long points = PointCount(spec);
  std::vector<long> chosen;
  if (points <= kUpFrontPoints || spec.mode != SweepMode::kGrid) {
    for (long i = 0; i < std::min(points, kUpFrontPoints); ++i) chosen.push_back(i);
    return chosen;
  }
  chosen.push_back(0);
  long stride = 1;  // index step of one value along axis k: the product of the later axes
  for (std::size_t k = spec.axes.size(); k-- > 0;) {
    const long n = AxisLength(spec.axes[k]);
    for (long j = 1; j < n && static_cast<long>(chosen.size()) < kUpFrontPoints; ++j) {
      chosen.push_back(j * stride);
    }
    stride *= n;
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

// This rank's share of the chosen points after point 0.
std::vector<long> MyPoints(const SweepSpec& spec, const RankShare& share) {
  const std::vector<long> chosen = UpFrontPoints(spec);  // ascending, point 0 first
  std::vector<long> mine;
  for (std::size_t k = 1; k < chosen.size(); ++k) {
    // a kept point where it is kept; the sample of a large sweep in blocks of its positions
    const long owner = spec.kept ? PointOwner(spec, chosen[k])
                                 : static_cast<long>(k) / spec.share_block % share.ranks;
    if (owner == share.rank) mine.push_back(chosen[k]);
  }
  return mine;
}

}  // namespace

std::string AxisPlace(const SweepAxis& axis) {
  return axis.place.file.empty() ? "parameters." + axis.path : PlaceText(axis.place);
}

InputError AxisError(const SweepAxis& axis, const std::optional<std::string>& value,
                     const std::string& rule) {
  const std::string head =
      AxisPlace(axis) + ": axis " + axis.path + (value ? " = " + *value + " " : ": ");
  return InputError(head, InputFault{axis.place, "parameters." + axis.path, value, rule});
}

InputError ExplainInvalidPoint(const SweepSpec& spec, long index, const Scenario& base,
                               const std::vector<std::size_t>& axes,
                               const std::vector<Parameter>& handles,
                               const std::vector<double>& numbers, const ParameterError& error) {
  const std::vector<std::string> values = PointValues(spec, index);
  const std::string point = std::to_string(index) + " (" + Describe(spec, values) + ")";
  // the first axis whose value alone makes the base invalid is the culprit
  for (std::size_t j = 0; j < axes.size(); ++j) {
    const std::size_t k = axes[j];
    try {
      Scenario alone = base;
      handles[j].Set(alone, numbers[k]);
    } catch (const ParameterError& alone) {
      const SweepAxis& axis = spec.axes[k];
      return AxisError(axis, values[k],
                       "makes point " + point + " an invalid scenario: " + alone.what());
    }
  }
  const std::string where = spec.axes.empty() ? spec.source : AxisPlace(spec.axes.front());
  return InputError(
      where + ": point " + point +
          " is not a valid scenario, though each of its values is valid alone",
      InputError(InputFault{std::nullopt, error.path(), error.value(), error.rule()}));
}

std::unique_ptr<PointFactory> ParameterPoints(Scenario base, const SweepSpec& spec) {
  std::vector<Parameter> handles;
  for (const SweepAxis& axis : spec.axes) {
    if (!axis.is_numeric()) {
      throw AxisError(axis, std::nullopt,
                      "has values that are not numbers: a parameter handle sets numbers");
    }
    try {
      handles.push_back(base.parameter(axis.path));
    } catch (const ParameterError& error) {
      throw AxisError(axis, std::nullopt, error.rule() + " (" + base.source + ")");
    }
  }
  return std::make_unique<ParameterPointFactory>(std::move(base), std::move(handles));
}

std::unique_ptr<PointFactory> FunctionPoints(ScenarioMaker make) {
  return std::make_unique<FunctionPointFactory>(
      std::make_shared<const ScenarioMaker>(std::move(make)));
}

std::string ResolveElementInMemory(const SweepSpec& spec, const MetricElements& elements) {
  const std::string& given = spec.metric_options.element;
  if (!given.empty()) {
    if (std::find(elements.all.begin(), elements.all.end(), given) == elements.all.end()) {
      throw InputError("metric_options.element = " + given + ": must name an element of " +
                       spec.base + ": " + CommaSeparated(elements.all));
    }
    return given;
  }
  if (elements.actuators.size() == 1) return elements.actuators.front();
  throw InputError(
      "metric_options.element: missing: " + spec.base + " has " +
      std::to_string(elements.actuators.size()) +
      " actuators, so name the element the metrics read, one of: " + CommaSeparated(elements.all));
}

SweepPlan PlanSweep(SweepSpec spec, std::unique_ptr<PointFactory> points, int threads,
                    const ElementResolver& resolve) {
  const SweepBase base(points->Copy());
  const RankShare share = WorldShare();
  const long count = PointCount(spec);
  spec.kept = count <= kUpFrontPoints;
  spec.share_rank = share.rank;
  spec.share_ranks = share.ranks;
  spec.share_block = ShareBlock(count, share.ranks);
  spec.scenarios.clear();
  if (spec.kept) spec.scenarios.resize(static_cast<std::size_t>(KeptCount(spec)));
  // point 0 first, alone: the element the metrics read is resolved from it, and every later
  // point must have it too
  const long slot = KeptSlot(spec, 0);
  const MetricElements elements =
      base.Validate(spec, 0, spec.metric_options.element, slot >= 0 ? &spec : nullptr, slot);
  spec.metric_options.element = resolve(spec, elements);
  // the rest on every core, each rank its share; the first invalid point of them all is told
  const std::optional<InvalidPoint> found = ValidatePoints(
      spec, base, MyPoints(spec, share), threads > 0 ? threads : ValidationThreads(share));
  const long first = MinOverRanks(found ? found->index : std::numeric_limits<long>::max());
  if (first != std::numeric_limits<long>::max()) {
    if (found && found->index == first) throw InputError(found->message);
    // another rank found it: this one reads the same error from the point itself
    base.Validate(spec, first, spec.metric_options.element, nullptr, 0);
    throw std::logic_error("sweep point " + std::to_string(first) + " is invalid on one rank only");
  }
  return SweepPlan{std::move(spec), std::move(points)};
}

}  // namespace musclesim
