#include "musclesim/sweep/sweep.h"

#include <algorithm>
#include <cmath>

#include "musclesim/core/enum_names.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "sweep/sweep_names.h"

namespace musclesim {

std::string_view ToString(SweepMode mode) { return ToString(kSweepModeNames, mode); }

std::string_view ToString(TrajectoryPolicy policy) {
  return ToString(kTrajectoryPolicyNames, policy);
}

namespace {

// SplitMix64: a well-mixed 64-bit hash, here of (seed, index, axis).
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A uniform draw in [0, 1) from the top 53 bits, identical on every platform.
double Uniform(std::uint64_t seed, long index, std::size_t axis) {
  const std::uint64_t h = Mix(Mix(Mix(seed) ^ static_cast<std::uint64_t>(index)) ^ axis);
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

// Value i of `count` from `from` to `to`, both ends exact; geometric with `log_scale`.
double Spaced(double from, double to, long count, long i, bool log_scale) {
  double v;
  if (i == 0) {
    v = from;
  } else if (i == count - 1) {
    v = to;
  } else if (log_scale) {
    // in decades, so that decade steps land on round values (1e-5, not 1.0000000000000016e-05)
    v = std::pow(10.0, std::log10(from) + (std::log10(to) - std::log10(from)) * i / (count - 1));
  } else {
    v = from + (to - from) * static_cast<double>(i) / static_cast<double>(count - 1);
  }
  return v;
}

// Value i of a grid or zip axis: its text and its number (NaN for a list's word).
struct AxisValue {
  std::string text;
  double number;
};

AxisValue ValueOf(const SweepAxis& axis, long i) {
  if (axis.is_range()) {
    const double v = Spaced(axis.from, axis.to, axis.count, i, axis.log_scale);
    return {FormatNumber(v), v};
  }
  const auto k = static_cast<std::size_t>(i);
  return {axis.values[k], axis.is_numeric() ? axis.numbers[k] : std::nan("")};
}

// Every axis's value at point `index`.
std::vector<AxisValue> PointAxisValues(const SweepSpec& spec, long index) {
  std::vector<AxisValue> values(spec.axes.size());
  switch (spec.mode) {
    case SweepMode::kGrid: {
      long rest = index;
      for (std::size_t k = spec.axes.size(); k-- > 0;) {
        const long n = AxisLength(spec.axes[k]);
        values[k] = ValueOf(spec.axes[k], rest % n);
        rest /= n;
      }
      break;
    }
    case SweepMode::kZip:
      for (std::size_t k = 0; k < spec.axes.size(); ++k) values[k] = ValueOf(spec.axes[k], index);
      break;
    case SweepMode::kRandom:
      for (std::size_t k = 0; k < spec.axes.size(); ++k) {
        const SweepAxis& a = spec.axes[k];
        const double u = Uniform(spec.seed, index, k);
        if (!a.is_range()) {
          const auto pick =
              std::min(static_cast<std::size_t>(u * a.values.size()), a.values.size() - 1);
          values[k] = ValueOf(a, static_cast<long>(pick));
          continue;
        }
        const double v =
            a.log_scale
                ? std::pow(10.0, std::log10(a.from) + (std::log10(a.to) - std::log10(a.from)) * u)
                : a.from + (a.to - a.from) * u;
        values[k] = {FormatNumber(v), v};
      }
      break;
  }
  return values;
}

}  // namespace

long AxisLength(const SweepAxis& axis) {
  return axis.is_range() ? axis.count : static_cast<long>(axis.values.size());
}

long PointCount(const SweepSpec& spec) {
  if (spec.mode == SweepMode::kRandom) return spec.samples;
  if (spec.axes.empty()) return 0;
  if (spec.mode == SweepMode::kZip) return AxisLength(spec.axes.front());
  long count = 1;
  for (const SweepAxis& a : spec.axes) count *= AxisLength(a);
  return count;
}

std::vector<std::string> PointValues(const SweepSpec& spec, long index) {
  std::vector<std::string> values;
  for (AxisValue& value : PointAxisValues(spec, index)) values.push_back(std::move(value.text));
  return values;
}

std::vector<double> PointNumbers(const SweepSpec& spec, long index) {
  std::vector<double> numbers;
  for (const AxisValue& value : PointAxisValues(spec, index)) numbers.push_back(value.number);
  return numbers;
}

std::vector<std::string> PointOverrides(const SweepSpec& spec, long index) {
  std::vector<std::string> overrides = PointValues(spec, index);
  for (std::size_t k = 0; k < overrides.size(); ++k) {
    overrides[k] = spec.axes[k].path + "=" + overrides[k];
  }
  return overrides;
}

}  // namespace musclesim
