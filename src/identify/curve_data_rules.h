// The data rules of a measured curve, shared by the CSV reader (ReadCurveCsv) and the check of
// curves given in memory (CheckedCurve), so that both refuse the same data with the same words.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "musclesim/identify/reference_fits.h"

namespace musclesim::curve_rules {

// At least `min_points` rows; else InputError "SOURCE: too few points: N, need at least M".
void RequireEnoughPoints(const std::string& source, std::size_t rows, std::size_t min_points);

// Row `p`, after the rows accepted before it: finite, and x greater than the last x. `where`
// begins the message ("data.csv:7: " or "active: row 4: ").
void RequireRow(const std::string& where, const std::string& x_name, const std::string& y_name,
                const DataPoint& p, const std::vector<DataPoint>& before);

// Some y not zero; else InputError "SOURCE: every Y_NAME is zero: nothing to fit".
void RequireSomeTension(const std::string& source, const std::string& y_name,
                        const std::vector<DataPoint>& data);

}  // namespace musclesim::curve_rules
