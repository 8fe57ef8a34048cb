#include "musclesim/identify/identify_report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "musclesim/core/errors.h"

namespace musclesim {

std::vector<std::pair<std::string, Fitter>> ReferenceFitters() {
  return {
      {"natural cubic spline",
       [](const std::vector<DataPoint>& d) -> std::function<double(double)> {
         return NaturalCubicSpline(d);
       }},
      {"polynomial, degree 3",
       [](const std::vector<DataPoint>& d) -> std::function<double(double)> {
         return PolynomialFit(d, 3);
       }},
      {"polynomial, degree 4",
       [](const std::vector<DataPoint>& d) -> std::function<double(double)> {
         return PolynomialFit(d, 4);
       }},
  };
}

namespace {

ModelScore Score(const std::string& name, const Fitter& fit, const std::vector<DataPoint>& data) {
  ModelScore score;
  score.name = name;
  const std::function<double(double)> model = fit(data);
  double rss = 0.0, scale = 0.0;
  for (const DataPoint& p : data) {
    rss += std::pow(model(p.x) - p.y, 2);
    scale = std::max(scale, std::abs(p.y));
  }
  score.rmse = std::sqrt(rss / data.size());

  // leave one out: refit without point i, predict it
  double cv = 0.0;
  for (std::size_t i = 0; i < data.size() && std::isfinite(cv); ++i) {
    std::vector<DataPoint> rest = data;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
    try {
      cv += std::pow(fit(rest)(data[i].x) - data[i].y, 2);
    } catch (const std::exception&) {
      cv = std::numeric_limits<double>::quiet_NaN();
    }
  }
  score.loocv_rmse = std::sqrt(cv / data.size());

  // outside the data: a quarter of the span beyond each end
  const double lo = data.front().x, hi = data.back().x, reach = 0.25 * (hi - lo);
  score.outside_min = std::numeric_limits<double>::infinity();
  score.outside_max = -std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 200; ++i) {
    for (double x : {lo - reach * i / 200.0, hi + reach * i / 200.0}) {
      const double y = model(x);
      score.outside_min = std::min(score.outside_min, y);
      score.outside_max = std::max(score.outside_max, y);
    }
  }
  score.nonnegative = score.outside_min >= -1e-9 * scale;
  score.bounded = std::max(std::abs(score.outside_min), std::abs(score.outside_max)) <= 2.0 * scale;

  // cost of one evaluation over the data range
  const int repeats = 200, samples = 1000;
  volatile double sink = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) {
    for (int i = 0; i < samples; ++i) sink = sink + model(lo + (hi - lo) * i / samples);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  score.ns_per_eval = 1e9 * seconds / (repeats * samples);
  return score;
}

std::string Cell(double value) {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// a fraction as a percentage: "95%", "97.5%"
std::string Percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%g%%", 100.0 * fraction);
  return text;
}

}  // namespace

std::vector<std::string> PassiveUncertaintyNotes(const PassiveIdentification& fit,
                                                 const std::function<std::string(double)>& number) {
  const ProfileInterval& in = fit.slack_length_interval;
  // appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) on "literal" + temporary
  std::string interval = "slack_length: ";
  interval += Percent(in.level);
  interval += " profile-likelihood interval ";
  interval += in.low_bounded ? "[" : "(";
  interval += in.low_bounded ? number(in.low) : std::string("-inf");
  interval += ", ";
  interval += number(in.high);
  interval += in.high_bounded ? "] m (F test)" : ") m (F test)";
  if (!in.low_bounded) {
    interval +=
        "; not bounded below: the data reject no slack length however low (the curve "
        "then tends to a pure exponential)";
  }
  if (!in.high_bounded) {
    interval += "; not bounded above: it reaches ";
    interval += number(in.high);
    interval += " m, above which fewer than 2 positive tensions are left to fit";
  }
  if (in.wide) {
    interval += "; wide (";
    interval +=
        in.low_bounded && in.high_bounded
            ? "more than " + Percent(ProfileInterval::kWideFraction) + " of the data's length span"
            : std::string("one-sided");
    interval +=
        "): the data place it only coarsely, and its +-, a linearisation at the "
        "optimum, does not describe that";
  }
  std::string carried = "k_p and alpha at the slack lengths inside that interval: k_p from ";
  carried += number(fit.k_p_over_interval.low);
  carried += " to ";
  carried += number(fit.k_p_over_interval.high);
  carried += " N, alpha from ";
  carried += number(fit.alpha_over_interval.low);
  carried += " to ";
  carried += number(fit.alpha_over_interval.high);
  carried += " 1/m";
  if (in.wide) carried += "; their +-, a linearisation at the optimum, understate this";
  return {interval, carried};
}

std::vector<std::string> DescribeEccentric(const EccentricIdentification& e) {
  const auto plus_minus = [](const Estimate& x) {
    return FormatNumber(x.value) + " +- " +
           (std::isfinite(x.standard_error) ? FormatNumber(x.standard_error) : "n/a");
  };
  const std::string points = std::to_string(e.points) + " points with v < 0";
  if (!e.identified) {
    return {"eccentric branch not identifiable from the data (" + points + "): " + e.why_not +
            "; the model keeps the concentric v_max and n for it, and no limit"};
  }
  const std::string limit = e.limit_identified ? ", limit = " + plus_minus(e.best.limit) : "";
  std::vector<std::string> notes = {"eccentric branch (" + points +
                                    "): v_max = " + plus_minus(e.best.v_max) +
                                    " m/s, n = " + std::to_string(e.best.n) + limit + "; RMSE " +
                                    FormatNumber(e.best.rmse) + " N"};
  if (!e.limit_identified) {
    notes.push_back("eccentric limit not identifiable from the data: " + e.why_no_limit +
                    "; the model has none (the paper's unbounded form)");
  }
  return notes;
}

CurveComparison Compare(const std::string& curve, const std::string& x_unit,
                        const std::vector<DataPoint>& data,
                        const std::vector<std::pair<std::string, Fitter>>& models) {
  CurveComparison out;
  out.curve = curve;
  out.x_unit = x_unit;
  out.points = data.size();
  for (const auto& [name, fit] : models) {
    try {
      out.models.push_back(Score(name, fit, data));
    } catch (const std::invalid_argument& e) {
      // a reference model with more parameters than the data have points: said, not fitted
      out.notes.push_back(name + ": not fitted (" + e.what() + ")");
    }
  }
  return out;
}

std::string FormatReport(const std::vector<CurveComparison>& comparisons) {
  std::ostringstream s;
  s << "# musclesim identify: model against spline and polynomials\n\n"
    << "RMSE is on the fitted data; LOOCV RMSE predicts each point from a fit without it. "
       "\"Outside\" is the quarter-span beyond each end of the data: the extremes there, "
       "whether they stay non-negative, and whether they stay within twice the largest "
       "measured value. ns/eval is measured here, every model called the same way.\n";
  for (const CurveComparison& c : comparisons) {
    s << "\n## " << c.curve << " (" << c.points << " points; x in " << c.x_unit
      << ", tension and errors in the CSV's tension units)\n\n"
      << "| model | RMSE | LOOCV RMSE | outside min | outside max | non-negative | "
         "bounded | ns/eval |\n|---|---|---|---|---|---|---|---|\n";
    for (const ModelScore& m : c.models) {
      s << "| " << m.name << " | " << Cell(m.rmse) << " | " << Cell(m.loocv_rmse) << " | "
        << Cell(m.outside_min) << " | " << Cell(m.outside_max) << " | "
        << (m.nonnegative ? "yes" : "no") << " | " << (m.bounded ? "yes" : "no") << " | "
        << Cell(m.ns_per_eval) << " |\n";
    }
    if (!c.notes.empty()) s << "\n";
    for (const std::string& note : c.notes) s << "- " << note << "\n";
  }
  return s.str();
}

}  // namespace musclesim
