#include "musclesim/model/tension.h"

#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

namespace {

// Re-throws a nested block's ParameterError with the block's name in front of its path.
template <typename Check>
void WithPrefix(const char* block, Check check) {
  try {
    check();
  } catch (const ParameterError& e) {
    throw ParameterError(std::string(block) + "." + e.path(), e.value(), e.rule());
  }
}

}  // namespace

void Validate(const ModelParams& params) {
  // as every force (input_ranges.h): the tension and its sums stay finite
  Require(
      std::isfinite(params.f_iso) && params.f_iso > 0.0 && params.f_iso <= kPositiveForceRange.max,
      "f_iso", params.f_iso,
      "must be > 0 and at most 1e9 [N]: " + std::string(kPositiveForceRange.why));
  WithPrefix("passive", [&] { Validate(params.passive); });
  WithPrefix("active_length", [&] { Validate(params.active_length); });
  WithPrefix("velocity", [&] { Validate(params.velocity); });
}

TensionModel::TensionModel(const ModelParams& params)
    : params_((Validate(params), params)),
      active_length_([&] {
        try {
          return ActiveLengthCurve(params.active_length);
        } catch (const ParameterError& e) {
          throw ParameterError("active_length." + e.path(), e.value(), e.rule());
        }
      }()),
      velocity_(params.velocity) {}

}  // namespace musclesim
