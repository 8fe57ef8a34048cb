#include "musclesim/identify/identify_series_warnings.h"

#include "musclesim/core/number_format.h"

namespace musclesim {

std::string PoorFitWarning(const SeriesIdentification& fit) {
  if (!fit.noise_given || fit.degrees_of_freedom <= 0) return "";
  const double mean_square = fit.weighted_rss / fit.degrees_of_freedom;
  if (!(mean_square > kPoorFitMeanSquare)) return "";
  return "the weighted residuals' mean square is " + FormatNumber(mean_square) +
         ", far above the 1 the stated noise predicts: a local minimum (try another start), a "
         "parameter stuck on a bound, or noise levels too small";
}

}  // namespace musclesim
