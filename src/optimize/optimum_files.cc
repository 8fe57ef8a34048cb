#include "musclesim/optimize/optimum_files.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "io/readers/yaml_fields.h"
#include "musclesim/io/writers/scenario_rewrite.h"
#include "musclesim/scenario/actuator_scenario.h"

namespace musclesim {

namespace {

// A JSON string of `text` (names are plain; quotes and backslashes escaped all the same).
std::string Quoted(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte < 0x20) {  // a control character, as \u00XX
      out.append("\\u00").append(1, kHex[byte >> 4]).append(1, kHex[byte & 15]);
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string Numbers(const std::vector<double>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ", ";
    out += FormatNumber(values[i]);
  }
  return out + "]";
}

// A JSON number, or null for one that is not finite (a re-simulation that failed).
std::string JsonNumber(double value) { return std::isfinite(value) ? FormatNumber(value) : "null"; }

}  // namespace

namespace {

Document Table(const std::vector<double>& times, const std::vector<double>& values) {
  std::vector<Document> points;
  for (std::size_t i = 0; i < times.size(); ++i) {
    points.push_back(Document::List(
        {Document::Number(times[i]), Document::Number(std::clamp(values[i], 0.0, 1.0))}));
  }
  return Document::Map(
      {{"type", Document::Text("table")}, {"points", Document::List(std::move(points))}});
}

}  // namespace

Document WithControlTables(Document base, const OptimalControlProblem& problem,
                           const OptimalControlResult& result) {
  // with activation dynamics the control is the excitation
  const auto key = [&](std::size_t j) {
    const std::vector<Element>& elements = problem.scenario.elements;
    for (const Element& e : elements) {
      if (e.name == problem.controls[j].actuator) return e.excitation ? "excitation" : "activation";
    }
    return "activation";
  };
  if (IsSingleActuator(problem.scenario)) {
    // the single actuator's own activation (or excitation), at the top: its one control
    if (!result.controls.empty()) base.Set(key(0), Table(result.times, result.controls[0]));
    return base;
  }
  const Document* listed = base.Find("elements");
  if (listed == nullptr || listed->kind() != Document::Kind::kList) {
    throw InputError("the scenario has no elements list to write the controls into");
  }
  std::vector<Document> elements = listed->items();
  const std::vector<Element>& built = problem.scenario.elements;
  for (std::size_t j = 0; j < result.controls.size(); ++j) {
    const std::string& name = problem.controls[j].actuator;
    const auto found =
        std::find_if(built.begin(), built.end(), [&](const Element& e) { return e.name == name; });
    const auto e = static_cast<std::size_t>(found - built.begin());
    if (e >= elements.size()) throw InputError(name + ": no such element in the document");
    elements[e].Set(key(j), Table(result.times, result.controls[j]));
  }
  base.Set("elements", Document::List(std::move(elements)));
  return base;
}

std::string OptimumScenarioText(const ProblemFile& file, const OptimalControlResult& result) {
  const Document base = ParseDocument(file.base, yaml::ReadText(file.base));
  // the free parameters and a free final time at their optimal values, exactly
  Overrides chosen({}, "optimum");
  for (std::size_t q = 0; q < result.parameter_values.size(); ++q) {
    chosen.texts.push_back(file.problem.parameters[q].path + "=" +
                           FormatNumber(result.parameter_values[q]));
  }
  if (file.problem.final_time && !result.times.empty()) {
    chosen.texts.push_back("time.end=" + FormatNumber(result.final_time));
  }
  return RewriteScenario(
      WithControlTables(base, file.problem, result), file.base, chosen,
      {"The optimum of " + file.path + " (musclesim optimize): " + file.base + " with the",
       "optimal activations as tables; `musclesim run` re-simulates it. IPOPT: " + result.status});
}

std::vector<FinalCheck> CheckFinalValues(const ProblemFile& file, const RecordedRun& run) {
  std::vector<FinalCheck> checks;
  const std::vector<std::string>& names = run.columns.names();
  for (const FinalValue& final : file.problem.final_values) {
    FinalCheck check{final.column, 0.0, final.lower, final.upper, 0.0};
    const auto found = std::find(names.begin(), names.end(), final.column);
    if (found == names.end() || run.values.empty()) {
      throw InputError(final.column + ": the re-simulation has no such column");
    }
    const std::vector<double>& column = run.values[static_cast<std::size_t>(found - names.begin())];
    if (column.empty()) throw InputError(final.column + ": the re-simulation recorded no row");
    if (run.stats.status != RunStatus::kCompleted) {
      // the last row is not the final time's: no value there (null in the summary)
      check.value = std::numeric_limits<double>::quiet_NaN();
      check.violation = std::numeric_limits<double>::infinity();
    } else {
      check.value = column.back();
      check.violation = std::max({0.0, final.lower - check.value, check.value - final.upper});
    }
    checks.push_back(check);
  }
  return checks;
}

std::string OptimumSummaryJson(const ProblemFile& file, const OptimalControlResult& result,
                               const RecordedRun& run, const std::vector<FinalCheck>& finals,
                               double wall_seconds) {
  std::string json = "{\n";
  json += "  \"problem\": " + Quoted(file.path) + ",\n";
  json += "  \"base\": " + Quoted(file.base) + ",\n";
  json += "  \"status\": " + Quoted(result.status) + ",\n";
  json += std::string("  \"solved\": ") + (result.solved ? "true" : "false") + ",\n";
  json += "  \"objective\": " + JsonNumber(result.objective) + ",\n";
  json += "  \"terms\": {\"effort\": " + JsonNumber(result.terms.effort) +
          ", \"tracking\": " + JsonNumber(result.terms.tracking) +
          ", \"terminal\": " + JsonNumber(result.terms.terminal) +
          ", \"final_time\": " + JsonNumber(result.terms.final_time) + "},\n";
  json += "  \"dual_infeasibility\": " + JsonNumber(result.dual_infeasibility) + ",\n";
  json += "  \"gradient_check\": " + JsonNumber(result.gradient_check) + ",\n";
  json += "  \"constraint_violation\": " + JsonNumber(result.constraint_violation) + ",\n";
  json += "  \"largest_violation\": " + Quoted(result.largest_violation) + ",\n";
  json += std::string("  \"infeasible\": ") + (result.infeasible ? "true" : "false") + ",\n";
  json += "  \"iterations\": " + std::to_string(result.iterations) + ",\n";
  json += "  \"intervals\": " + std::to_string(file.problem.intervals) + ",\n";
  json += "  \"wall_seconds\": " + JsonNumber(wall_seconds) + ",\n";
  json += "  \"solve_seconds\": " + JsonNumber(result.wall_seconds) + ",\n";
  json += "  \"integration_seconds\": " + JsonNumber(result.integration_seconds) + ",\n";
  json += "  \"final_time\": " + JsonNumber(result.final_time) + ",\n";
  json += "  \"times\": " + Numbers(result.times) + ",\n";
  json += "  \"parameters\": {";
  for (std::size_t q = 0; q < result.parameter_values.size(); ++q) {
    json += (q > 0 ? ", " : "") + Quoted(file.problem.parameters[q].path) + ": " +
            JsonNumber(result.parameter_values[q]);
  }
  json += "},\n";
  json += "  \"controls\": {";
  for (std::size_t j = 0; j < result.controls.size(); ++j) {
    json += (j > 0 ? ", " : "") + Quoted(file.problem.controls[j].actuator) + ": " +
            Numbers(result.controls[j]);
  }
  json += "},\n";
  json += "  \"resimulation\": {\"status\": " + Quoted(std::string(ToString(run.stats.status))) +
          ", \"end_time\": " + JsonNumber(run.stats.final_time) +
          ", \"message\": " + Quoted(run.stats.message) +
          ", \"state_deviation\": " + JsonNumber(result.resimulation_deviation) +
          ", \"final_values\": [";
  double worst = 0.0;
  for (std::size_t k = 0; k < finals.size(); ++k) {
    const FinalCheck& f = finals[k];
    json += (k > 0 ? ", " : "") + std::string("{\"column\": ") + Quoted(f.column) +
            ", \"value\": " + JsonNumber(f.value) + ", \"lower\": " + JsonNumber(f.lower) +
            ", \"upper\": " + JsonNumber(f.upper) + ", \"violation\": " + JsonNumber(f.violation) +
            "}";
    worst = std::max(worst, f.violation);
  }
  json += "], \"largest_violation\": " + JsonNumber(worst) + "}\n}\n";
  return json;
}

}  // namespace musclesim
