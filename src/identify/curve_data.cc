// The data rules of a measured curve, and curves given in memory checked by them.
#include "musclesim/identify/curve_data.h"

#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "identify/curve_data_rules.h"

namespace musclesim {

namespace curve_rules {

void RequireEnoughPoints(const std::string& source, std::size_t rows, std::size_t min_points) {
  if (rows < min_points) {
    throw InputError(source + ": too few points: " + std::to_string(rows) + ", need at least " +
                     std::to_string(min_points));
  }
}

void RequireRow(const std::string& where, const std::string& x_name, const std::string& y_name,
                const DataPoint& p, const std::vector<DataPoint>& before) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
    throw InputError(where + x_name + " = " + FormatNumber(p.x) + ", " + y_name + " = " +
                     FormatNumber(p.y) + ": values must be finite");
  }
  if (!before.empty() && !(p.x > before.back().x)) {
    throw InputError(where + x_name + " = " + FormatNumber(p.x) +
                     " is not greater than the row "
                     "before (" +
                     FormatNumber(before.back().x) + "): rows must be sorted by " + x_name +
                     ", without duplicates");
  }
}

void RequireSomeTension(const std::string& source, const std::string& y_name,
                        const std::vector<DataPoint>& data) {
  for (const DataPoint& p : data) {
    if (p.y != 0.0) return;
  }
  throw InputError(source + ": every " + y_name + " is zero: nothing to fit");
}

}  // namespace curve_rules

std::size_t MinActivePoints(int count) { return 3 * static_cast<std::size_t>(count) + 1; }

std::size_t MinVelocityPoints(bool f_iso_fixed) { return f_iso_fixed ? 2 : 3; }

namespace {

std::vector<DataPoint> CurveOf(const std::string& source, const std::vector<double>& x,
                               const std::vector<double>& y, const std::string& x_name,
                               const std::string& y_name, std::size_t min_points) {
  if (x.size() != y.size()) {
    throw InputError(source + ": " + std::to_string(x.size()) + " " + x_name + " values and " +
                     std::to_string(y.size()) + " " + y_name + " values: give one " + y_name +
                     " per " + x_name);
  }
  curve_rules::RequireEnoughPoints(source, x.size(), min_points);
  std::vector<DataPoint> data;
  data.reserve(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const DataPoint p{x[i], y[i]};
    curve_rules::RequireRow(source + ": row " + std::to_string(i + 1) + ": ", x_name, y_name, p,
                            data);
    data.push_back(p);
  }
  curve_rules::RequireSomeTension(source, y_name, data);
  return data;
}

}  // namespace

std::vector<DataPoint> CheckedCurve(const std::string& source, const std::vector<double>& x,
                                    const std::vector<double>& y, const std::string& x_name,
                                    const std::string& y_name, std::size_t min_points) {
  try {
    return CurveOf(source, x, y, x_name, y_name, min_points);
  } catch (const InputError& e) {
    // values given in memory: the error's key is the argument that gave them
    InputFault fault = e.fault();
    fault.key = source;
    throw e.WithFault(fault);
  }
}

}  // namespace musclesim
