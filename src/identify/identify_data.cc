// Measured curves read from CSV, with the rules identification needs of them.
#include "musclesim/identify/identify.h"

#include "musclesim/io/readers/csv_table.h"
#include "identify/curve_data_rules.h"

namespace musclesim {

std::vector<DataPoint> ReadCurveCsv(const std::string& path, const std::string& x_name,
                                    const std::string& y_name, std::size_t min_points) {
  const CsvTable table = ReadCsv(path);
  table.Require({x_name, y_name}, "columns " + x_name + "," + y_name);
  curve_rules::RequireEnoughPoints(path, table.rows.size(), min_points);
  const int xc = table.Find(x_name), yc = table.Find(y_name);
  std::vector<DataPoint> data;
  // row by row, so that of two faults the first in the file is the one reported
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const DataPoint p{table.Number(r, xc), table.Number(r, yc)};
    curve_rules::RequireRow(path + ":" + std::to_string(table.lines[r]) + ": ", x_name, y_name, p,
                            data);
    data.push_back(p);
  }
  curve_rules::RequireSomeTension(path, y_name, data);
  return data;
}

}  // namespace musclesim
