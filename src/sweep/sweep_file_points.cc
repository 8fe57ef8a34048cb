#include "sweep/sweep_file_points.h"

#include <optional>

#include "musclesim/core/errors.h"
#include "sweep/point_explanation.h"
#include "sweep/sweep_base.h"
#include "sweep/sweep_point_error.h"

namespace musclesim {

namespace {

class FilePointFactory final : public PointFactory {
 public:
  FilePointFactory(std::unique_ptr<ScenarioTemplate> base, const SweepSpec& spec)
      : template_(std::move(base)) {
    try {
      base_ = template_->Instantiate({});
    } catch (const InputError&) {
      return;  // every axis goes to the document, whose errors name the base's keys
    }
    for (std::size_t k = 0; k < spec.axes.size(); ++k) {
      const SweepAxis& axis = spec.axes[k];
      if (!axis.is_numeric()) continue;
      try {
        handles_.push_back(base_->parameter(axis.path));
        numeric_.push_back(k);
      } catch (const ParameterError&) {
        // no number of the base: the document's reader says what is wrong with it
      }
    }
  }

  FilePointFactory(const FilePointFactory& other)
      : template_(other.template_->Copy()),
        base_(other.base_),
        numeric_(other.numeric_),
        handles_(other.handles_) {}

  std::unique_ptr<PointFactory> Copy() const override {
    return std::make_unique<FilePointFactory>(*this);
  }

  LoadedScenario Make(const SweepSpec& spec, long index) const override {
    const std::vector<std::string> overrides = DocumentOverrides(spec, index);
    LoadedScenario made;
    if (base_ && overrides.empty()) {
      made.scenario = *base_;
    } else {
      try {
        made = template_->InstantiateLoaded(Overrides(overrides, kAxisLabel));
        // a text axis may rename the element the metrics read: told as that axis's doing
        MetricElementIndex(made.scenario, spec.metric_options.element);
      } catch (const InputError& e) {
        throw PointErrorExplainer(spec, *template_).Explain(index, e).error;
      }
    }
    if (numeric_.empty()) return made;
    made.system.reset();  // of the numbers before the handles set theirs
    Scenario& point = made.scenario;
    const std::vector<double> all = PointNumbers(spec, index);
    std::vector<double> numbers;
    for (std::size_t k : numeric_) numbers.push_back(all[k]);
    // the document's axes may have changed the parts a handle points into: find them again
    const std::vector<Parameter> handles = overrides.empty() ? handles_ : HandlesIn(point, spec);
    try {
      SetParameters(point, handles, numbers);
    } catch (const ParameterError& error) {
      throw ExplainInvalidPoint(spec, index, overrides.empty() ? *base_ : point, numeric_, handles,
                                all, error);
    }
    return made;
  }

 private:
  // The point's values for the axes that are not handles, as overrides of the document.
  std::vector<std::string> DocumentOverrides(const SweepSpec& spec, long index) const {
    if (!base_) return PointOverrides(spec, index);
    std::vector<std::string> all = PointOverrides(spec, index), text;
    std::size_t next = 0;
    for (std::size_t k = 0; k < all.size(); ++k) {
      if (next < numeric_.size() && numeric_[next] == k) {
        ++next;
      } else {
        text.push_back(std::move(all[k]));
      }
    }
    return text;
  }

  std::vector<Parameter> HandlesIn(const Scenario& point, const SweepSpec& spec) const {
    std::vector<Parameter> handles;
    try {
      for (std::size_t k : numeric_) handles.push_back(point.parameter(spec.axes[k].path));
    } catch (const ParameterError& error) {
      throw AxisError(spec.axes[numeric_[handles.size()]], std::nullopt, error.rule());
    }
    return handles;
  }

  std::unique_ptr<ScenarioTemplate> template_;
  std::optional<Scenario> base_;      // the base alone, when it is a valid scenario
  std::vector<std::size_t> numeric_;  // the axes set through handles, ascending
  std::vector<Parameter> handles_;    // theirs, found in base_
};

}  // namespace

std::unique_ptr<PointFactory> FilePoints(std::unique_ptr<ScenarioTemplate> base,
                                         const SweepSpec& spec) {
  return std::make_unique<FilePointFactory>(std::move(base), spec);
}

}  // namespace musclesim
