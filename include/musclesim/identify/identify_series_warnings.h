// What a time-series fit's user is warned of although its results stand: a model that does
// not describe the data at the optimum found. Shared by `musclesim identify` and the Python
// module, so that both warn alike.
#pragma once

#include <string>

#include "musclesim/identify/identify_series.h"

namespace musclesim {

// The weighted residuals' mean square (weighted RSS / degrees of freedom, 1 on average when
// the noise levels describe the data) above which a fit is poor: 4 noise variances,
// residuals of 2 standard deviations [-].
inline constexpr double kPoorFitMeanSquare = 4.0;

// For a fit weighted by noise levels whose mean square exceeds kPoorFitMeanSquare, the
// warning (one sentence: the value and what may cause it); "" otherwise.
std::string PoorFitWarning(const SeriesIdentification& fit);

}  // namespace musclesim
