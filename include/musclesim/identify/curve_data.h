// Measured curves given in memory (the Python module's arrays) checked by the rules a CSV of
// `musclesim identify` meets (ReadCurveCsv, identify.h), and the fewest points each fit takes.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "musclesim/identify/reference_fits.h"

namespace musclesim {

// The fewest points each identification takes: one more than its parameters, so that a
// residual variance, and with it a standard error, can be estimated [-].
inline constexpr std::size_t kMinPassivePoints = 4;  // k_p, alpha, slack_length
// 3 count + 1: an amplitude, a width and a center per Gaussian.
std::size_t MinActivePoints(int count);
// 2 with f_iso held fixed (v_max alone), else 3 (f_iso and v_max).
std::size_t MinVelocityPoints(bool f_iso_fixed);

// The points (x[i], y[i]) once they meet ReadCurveCsv's rules: as many y as x, at least
// `min_points` of them, every value finite, x strictly increasing (no duplicates), y not zero
// everywhere. x is a length [m] or a shortening velocity [m/s], y a tension [N]; `x_name` and
// `y_name` name them in messages as a CSV's columns would. Throws InputError naming `source`
// and the row (1-based) where ReadCurveCsv names file:line, e.g.
//   "active: row 4: length = 0.2 is not greater than the row before (0.3): rows must be
//    sorted by length, without duplicates".
std::vector<DataPoint> CheckedCurve(const std::string& source, const std::vector<double>& x,
                                    const std::vector<double>& y, const std::string& x_name,
                                    const std::string& y_name, std::size_t min_points);

}  // namespace musclesim
