// The comparison the paper left for later: musclesim's model of a measured curve against a
// natural cubic spline and third- and fourth-degree polynomials, on accuracy (RMSE on the
// data and in leave-one-out cross-validation), behaviour outside the data range, and the
// cost of an evaluation.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "musclesim/studies/reference_fits.h"

namespace musclesim {

// Fits a model to data and returns it as a function of x.
using Fitter = std::function<std::function<double(double)>(const std::vector<DataPoint>&)>;

struct ModelScore {
  std::string name;
  double rmse = 0.0;          // on the data it was fitted to
  double loocv_rmse = 0.0;    // each point predicted by a fit without it; NaN if a fit failed
  double outside_min = 0.0;   // extremes over the quarter-span beyond each end of the data
  double outside_max = 0.0;
  bool nonnegative = false;   // outside_min >= 0 (to 1e-9 of the data's scale)
  bool bounded = false;       // |value| <= 2 max|data| outside the data
  double ns_per_eval = 0.0;   // measured, through the same std::function call for every model
};

struct CurveComparison {
  std::string curve;          // "passive", "active", "velocity"
  std::string x_unit;
  std::size_t points = 0;
  std::vector<ModelScore> models;
};

CurveComparison Compare(const std::string& curve, const std::string& x_unit,
                        const std::vector<DataPoint>& data,
                        const std::vector<std::pair<std::string, Fitter>>& models);

// The spline and the two polynomials, for Compare's list.
std::vector<std::pair<std::string, Fitter>> ReferenceFitters();

// A Markdown report: one table per curve.
std::string FormatReport(const std::vector<CurveComparison>& comparisons);

}  // namespace musclesim
