// Each identified curve against the reference fitters, for `musclesim identify --report`.
#include "musclesim/identify/identify_comparisons.h"

#include <cstdio>
#include <functional>
#include <string>

namespace musclesim {

namespace {

// The reference fitters with the model's own fitter first: the report's first row.
template <typename Fit>
std::vector<std::pair<std::string, Fitter>> WithModel(const std::string& name, Fit fit) {
  auto models = ReferenceFitters();
  models.insert(models.begin(), {name, [fit](const std::vector<DataPoint>& d) {
                                   auto identified = fit(d);
                                   return std::function<double(double)>(
                                       [identified](double x) { return identified.Evaluate(x); });
                                 }});
  return models;
}

}  // namespace

CurveComparison ComparePassiveFit(const std::vector<DataPoint>& data,
                                  const PassiveIdentification& fit) {
  CurveComparison c = Compare("passive tension-length", "length units of the CSV", data,
                              WithModel("exponential (eq. 1)", [](const std::vector<DataPoint>& d) {
                                return IdentifyPassive(d);
                              }));
  // the report's tables print 4 significant digits; its notes alike
  const std::vector<std::string> notes = PassiveUncertaintyNotes(fit, [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return std::string(text);
  });
  c.notes.insert(c.notes.end(), notes.begin(), notes.end());
  return c;
}

CurveComparison CompareActiveFit(const std::vector<DataPoint>& data, int count, bool nonnegative) {
  return Compare("active tension-length", "length units of the CSV", data,
                 WithModel(std::to_string(count) + " Gaussians (eqs. 3-4)",
                           [count, nonnegative](const std::vector<DataPoint>& d) {
                             return IdentifyActive(d, count, nonnegative);
                           }));
}

CurveComparison CompareVelocityFit(const std::vector<DataPoint>& data, std::optional<double> f_iso,
                                   const VelocityIdentification& fit) {
  CurveComparison c = Compare(
      "tension-velocity", "shortening velocity units of the CSV", data,
      WithModel("power law (eq. 12)",
                [f_iso](const std::vector<DataPoint>& d) { return IdentifyVelocity(d, f_iso); }));
  if (fit.eccentric) {
    const std::vector<std::string> notes = DescribeEccentric(*fit.eccentric);
    c.notes.insert(c.notes.end(), notes.begin(), notes.end());
  }
  return c;
}

}  // namespace musclesim
