// Measured curves read from CSV, with the rules identification needs of them.
#include "musclesim/studies/identify.h"

#include <cmath>

#include "musclesim/errors.h"
#include "musclesim/io/csv_table.h"
#include "musclesim/model/number_format.h"

namespace musclesim {

std::vector<DataPoint> ReadCurveCsv(const std::string& path, const std::string& x_name,
                                    const std::string& y_name, std::size_t min_points) {
  const CsvTable table = ReadCsv(path);
  table.Require({x_name, y_name}, "columns " + x_name + "," + y_name);
  if (table.rows.size() < min_points) {
    throw InputError(path + ": too few points: " + std::to_string(table.rows.size()) +
                     ", need at least " + std::to_string(min_points));
  }
  const int xc = table.Find(x_name), yc = table.Find(y_name);
  std::vector<DataPoint> data;
  bool any_tension = false;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const DataPoint p{table.Number(r, xc), table.Number(r, yc)};
    const std::string where = path + ":" + std::to_string(table.lines[r]) + ": ";
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw InputError(where + x_name + " = " + FormatNumber(p.x) + ", " + y_name + " = " +
                       FormatNumber(p.y) + ": values must be finite");
    }
    if (!data.empty() && !(p.x > data.back().x)) {
      throw InputError(where + x_name + " = " + FormatNumber(p.x) + " is not greater than the row "
                       "before (" + FormatNumber(data.back().x) + "): rows must be sorted by " +
                       x_name + ", without duplicates");
    }
    any_tension = any_tension || p.y != 0.0;
    data.push_back(p);
  }
  if (!any_tension) throw InputError(path + ": every " + y_name + " is zero: nothing to fit");
  return data;
}

}  // namespace musclesim
