// The comparison the paper left for later: musclesim's model of a measured curve against a
// natural cubic spline and third- and fourth-degree polynomials, on accuracy (RMSE on the
// data and in leave-one-out cross-validation), behaviour outside the data range, and the
// cost of an evaluation.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "musclesim/identify/identify.h"
#include "musclesim/identify/reference_fits.h"

namespace musclesim {

// Fits a model to data and returns it as a function of x.
using Fitter = std::function<std::function<double(double)>(const std::vector<DataPoint>&)>;

// Tensions and errors below are in the CSV's tension unit, written [N].
struct ModelScore {
  std::string name;          // the model, as the report's row names it
  double rmse = 0.0;         // on the data it was fitted to [N]
  double loocv_rmse = 0.0;   // each point predicted by a fit without it [N]; NaN: a fit failed
  double outside_min = 0.0;  // least value over the quarter-span beyond each end of the data [N]
  double outside_max = 0.0;  // greatest value there [N]
  bool nonnegative = false;  // outside_min >= 0 (to 1e-9 of the data's scale)
  bool bounded = false;      // |value| <= 2 max|data| outside the data
  double ns_per_eval = 0.0;  // [ns], measured through the same std::function call for every model
};

struct CurveComparison {
  std::string curve;               // which curve, as the report's heading names it
  std::string x_unit;              // the unit of x, as the report prints it
  std::size_t points = 0;          // data points compared on
  std::vector<ModelScore> models;  // one row each, in the order given
  std::vector<std::string> notes;  // sentences printed under the table, one bullet each
};

// Scores every model on `data`. A model whose fitter throws std::invalid_argument (more
// parameters than the data have points) gets no row; a note says so.
CurveComparison Compare(const std::string& curve, const std::string& x_unit,
                        const std::vector<DataPoint>& data,
                        const std::vector<std::pair<std::string, Fitter>>& models);

// The spline and the two polynomials, for Compare's list.
std::vector<std::pair<std::string, Fitter>> ReferenceFitters();

// What a passive fit leaves uncertain, one sentence each: the slack length's interval (and
// whether it is wide or one-sided), and the best k_p and alpha across it. Numbers are written
// by `number`. For the report's notes and the model block's comments.
std::vector<std::string> PassiveUncertaintyNotes(const PassiveIdentification& fit,
                                                 const std::function<std::string(double)>& number);

// What the eccentric identification found, in sentences for a reader: the branch's
// parameters with their standard errors, or plainly that the data do not determine them and
// why, and the same for the limit.
std::vector<std::string> DescribeEccentric(const EccentricIdentification& eccentric);

// A Markdown report: one table per curve, its notes below it.
std::string FormatReport(const std::vector<CurveComparison>& comparisons);

}  // namespace musclesim
