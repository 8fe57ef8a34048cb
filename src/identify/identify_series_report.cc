// What a time-series identification prints: the verdict in words, the Markdown reports of
// a fit and of a design, the estimated scenario's header and the residual CSV.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

#include "musclesim/core/number_format.h"
#include "musclesim/identify/identify_series.h"

namespace musclesim {

namespace {

// A number to `digits` significant digits, for tables and sentences.
std::string Short(double value, int digits = 4) { return FormatSignificant(value, digits); }

std::string Error(double standard_error) {
  return std::isfinite(standard_error) ? Short(standard_error, 2) : "not determined";
}

std::string Percent(double fraction) {
  if (!std::isfinite(fraction)) return "not determined";
  return Short(100.0 * fraction, 2) + "%";
}

// "a", "a and b", "a, b and c"
std::string List(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  }
  return text;
}

std::string VerdictWord(Identifiability verdict) {
  switch (verdict) {
    case Identifiability::kIdentifiable: return "identifiable";
    case Identifiability::kPoorlyDetermined: return "poorly determined";
    case Identifiability::kNegligibleColumn: return "not identifiable: no effect";
    case Identifiability::kDependent: return "not identifiable: a combination";
    case Identifiability::kAtBound: return "at a bound";
  }
  return "";
}

// The parameters taking part in a weak direction, as a sentence's subject and its
// combination of logarithms: "0.71 ln model.passive.k_p - 0.7 ln model.passive.alpha". A
// component is a relative change d p / |p|, d ln|p| times the sign of p; a parameter at 0 is
// scaled by 1, so its change is absolute.
std::pair<std::vector<std::string>, std::string> Combination(const SeriesIdentification& r,
                                                             const WeakDirection& w) {
  std::vector<std::string> names;
  std::string combination;
  for (std::size_t j = 0; j < r.parameters.size(); ++j) {
    const SeriesParameterResult& p = r.parameters[j];
    if (std::abs(w.components[j]) < kComponentFloor ||
        p.verdict == Identifiability::kNegligibleColumn) {
      continue;
    }
    names.push_back(p.path);
    const double c = p.estimate < 0.0 ? -w.components[j] : w.components[j];
    const std::string term = p.estimate > 0.0   ? "ln " + p.path
                             : p.estimate < 0.0 ? "ln|" + p.path + "|"
                                                : p.path;
    combination += std::string(combination.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ")) +
                   Short(std::abs(c), 2) + " " + term;
  }
  return {names, combination};
}

std::string Wrap(const std::string& text, std::size_t width, const std::string& indent) {
  std::istringstream words(text);
  std::string word, line, out;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line = indent;
    }
    line += (line.empty() || line == indent ? "" : " ") + word;
  }
  return out + line;
}

std::string StatisticsSentence(const SeriesIdentification& r, bool design) {
  if (design) {
    return "Cramer-Rao standard errors, (J^T W J)^-1 with W the inverse noise variances, at "
           "the start values and " +
           std::to_string(r.values) +
           " measured values: the "
           "smallest errors an unbiased estimate from this experiment can have.";
  }
  if (r.noise_given) {
    return "Weighted by the stated noise: standard errors from (J^T W J)^-1, the Fisher "
           "information's inverse at the estimate (" +
           std::to_string(r.values) + " values, " + std::to_string(r.degrees_of_freedom) +
           " degrees of freedom). The weighted residuals' "
           "mean square is " +
           Short(r.weighted_rss / r.degrees_of_freedom, 3) +
           " (near 1 when the noise levels describe the data).";
  }
  return "No noise levels: standard errors from s^2 (J^T J)^-1, s^2 = RSS / (N - P) = " +
         Short(r.variance_factor, 4) + " (s = " + Short(std::sqrt(r.variance_factor), 4) + ", " +
         std::to_string(r.values) + " values, " + std::to_string(r.degrees_of_freedom) +
         " degrees of freedom).";
}

void CorrelationTable(std::ostringstream& s, const SeriesIdentification& r) {
  s << "| |";
  for (const auto& p : r.parameters) s << " " << p.path << " |";
  s << "\n|---|";
  for (std::size_t j = 0; j < r.parameters.size(); ++j) s << "---|";
  s << "\n";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    s << "| " << r.parameters[i].path << " |";
    for (std::size_t k = 0; k < r.parameters.size(); ++k) {
      const auto row = static_cast<Eigen::Index>(i), column = static_cast<Eigen::Index>(k);
      s << " " << Short(r.correlation(row, column), 3) << " |";
    }
    s << "\n";
  }
}

void SingularValueTable(std::ostringstream& s, const SeriesIdentification& r) {
  s << "Each column of the scaled sensitivity matrix is the outputs' change, in noise standard "
       "deviations"
    << (r.noise_given ? "" : " (s)")
    << ", for a change of its parameter by its size (the larger of |estimate| and |start|; "
       "for a parameter at 0 in both, its larger bound, else 1). A singular value below "
    << Short(kDependentSingularValueRatio, 1) << " of the largest, or a column below "
    << Short(kNegligibleColumnRatio, 1) << " of the largest, is not resolved.\n\n"
    << "| | singular value | relative to the largest |\n|---|---|---|\n";
  for (Eigen::Index k = 0; k < r.singular_values.size(); ++k) {
    s << "| " << k + 1 << " | " << Short(r.singular_values[k], 4) << " | "
      << Short(r.singular_values[0] > 0 ? r.singular_values[k] / r.singular_values[0] : 0.0, 3)
      << " |\n";
  }
  for (const WeakDirection& w : r.weak_directions) {
    s << "\nNear-zero direction (" << Short(w.ratio, 2)
      << " of the largest): " << Combination(r, w).second << "\n";
  }
}

// A CSV field, quoted (RFC 4180) when it holds a comma, a quote or a line break.
std::string Quoted(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string out = "\"";
  for (char c : field) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string IdentifiabilityVerdict(const SeriesIdentification& r) {
  std::vector<std::string> good, reasons;
  for (const SeriesParameterResult& p : r.parameters) {
    switch (p.verdict) {
      case Identifiability::kIdentifiable: good.push_back(p.path); break;
      case Identifiability::kPoorlyDetermined:
        reasons.push_back(p.path + " is poorly determined: its relative standard error is " +
                          Percent(p.relative_standard_error) + " (above " +
                          Percent(kPoorRelativeError) + ")");
        break;
      case Identifiability::kNegligibleColumn:
        reasons.push_back(p.path + " is not: " +
                          (p.column_ratio == 0.0
                               ? std::string("its column is zero")
                               : "its column is " + Short(p.column_ratio, 1) + " of the largest") +
                          " (the outputs do not depend on it)");
        break;
      case Identifiability::kAtBound:
        reasons.push_back(p.path + " sits at its bound " + Short(p.estimate, 6) +
                          " and is not estimated");
        break;
      case Identifiability::kDependent: break;  // by direction, below
    }
  }
  for (const WeakDirection& w : r.weak_directions) {
    const auto [names, combination] = Combination(r, w);
    reasons.push_back(List(names) + (names.size() == 1 ? " is not: " : " are not, separately: ") +
                      "a step along " + combination + " changes the outputs " + Short(w.ratio, 1) +
                      " times as much as one along the best-determined "
                      "direction");
  }
  std::string text;
  if (good.empty()) {
    text = "no parameter is identifiable from this experiment";
  } else {
    text = List(good) + (good.size() == 1 ? " is" : " are") + " identifiable from this experiment";
  }
  for (const std::string& reason : reasons) text += "; " + reason;
  return text + ".";
}

std::string FormatSeriesReport(const SeriesIdentification& r, const std::string& data_file) {
  std::ostringstream s;
  s << "# Identification of " << r.scenario << " from " << data_file << "\n\n"
    << StatisticsSentence(r, false) << "\n\n"
    << "| parameter | scenario | start | estimate | standard error | relative | verdict |\n"
    << "|---|---|---|---|---|---|---|\n";
  for (const SeriesParameterResult& p : r.parameters) {
    s << "| " << p.path << " | " << Short(p.scenario_value, 6) << " | " << Short(p.start, 6)
      << " | " << Short(p.estimate, 6) << " | " << Error(p.standard_error) << " | "
      << Percent(p.relative_standard_error) << " | " << VerdictWord(p.verdict) << " |\n";
  }
  s << "\n" << IdentifiabilityVerdict(r) << "\n\n## Correlations\n\n";
  CorrelationTable(s, r);
  s << "\n## Singular values of the scaled sensitivity matrix\n\n";
  SingularValueTable(s, r);
  s << "\n## The fit\n\n"
    << (r.converged ? "Converged" : "Not converged") << " after " << r.iterations
    << " Levenberg-Marquardt steps (" << r.evaluations
    << " runs with sensitivities): " << r.stop_reason << ". Weighted residual sum of squares "
    << Short(r.weighted_rss, 6) << ".\n";
  return s.str();
}

std::string FormatDesignReport(const SeriesIdentification& r, const std::string& data_file) {
  std::vector<std::size_t> order(r.parameters.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return r.parameters[a].relative_standard_error < r.parameters[b].relative_standard_error;
  });
  std::ostringstream s;
  s << "# Experiment design: " << data_file << " on " << r.scenario << "\n\n"
    << StatisticsSentence(r, true) << " Ranked from the best determined.\n\n"
    << "| rank | parameter | value | standard error | relative | column | verdict |\n"
    << "|---|---|---|---|---|---|---|\n";
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    const SeriesParameterResult& p = r.parameters[order[rank]];
    s << "| " << rank + 1 << " | " << p.path << " | " << Short(p.estimate, 6) << " | "
      << Error(p.standard_error) << " | " << Percent(p.relative_standard_error) << " | "
      << Short(p.column_ratio, 2) << " | " << VerdictWord(p.verdict) << " |\n";
  }
  s << "\n" << IdentifiabilityVerdict(r) << "\n\n## Correlations\n\n";
  CorrelationTable(s, r);
  s << "\n## Singular values of the scaled sensitivity matrix\n\n";
  SingularValueTable(s, r);
  return s.str();
}

std::vector<std::string> EstimatedScenarioHeader(const SeriesIdentification& r,
                                                 const std::string& data_file) {
  std::vector<std::string> lines = {"estimated by musclesim identify from " + data_file +
                                    " (scenario " + r.scenario + ")"};
  for (const SeriesParameterResult& p : r.parameters) {
    lines.push_back("  " + p.path + " = " + FormatNumber(p.estimate) + " +- " +
                    Error(p.standard_error) + " (" + VerdictWord(p.verdict) + "; started at " +
                    Short(p.start, 6) + ")");
  }
  std::istringstream wrapped(Wrap(StatisticsSentence(r, false), 92, ""));
  for (std::string line; std::getline(wrapped, line);) lines.push_back(line);
  std::istringstream verdict(Wrap(IdentifiabilityVerdict(r), 92, ""));
  for (std::string line; std::getline(verdict, line);) lines.push_back(line);
  if (!r.converged) lines.push_back("NOT CONVERGED: " + r.stop_reason);
  return lines;
}

std::string FormatResidualCsv(const SeriesIdentification& r) {
  std::string csv = "series,output,t,measured,model,residual,standardised\n";
  for (const ResidualRow& row : r.residuals) {
    csv += std::to_string(row.series) + "," + Quoted(row.output) + "," + FormatFull(row.t) + "," +
           FormatFull(row.measured) + "," + FormatFull(row.model) + "," +
           FormatFull(row.measured - row.model) + "," + FormatFull(row.standardised) + "\n";
  }
  return csv;
}

}  // namespace musclesim
