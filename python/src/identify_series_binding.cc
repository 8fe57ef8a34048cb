// Identification of a scenario's parameters from measured time series, as `musclesim
// identify DATA.yaml` does for a data file with a `scenario:` key, without the data file or
// the CSV files: the spec arrives as a dict read by the data file's own reader as a document
// (io/readers/document.h), the scenario as the Scenario in memory, the series as NumPy columns that
// pass the CSV's rules (MeasuredSeriesFromColumns). The fit and the design are the library's
// FitSeries and DesignSeries on copies of the scenario, run with the GIL released.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "document.h"
#include "musclesim/core/errors.h"
#include "musclesim/io/readers/identify_series_spec.h"
#include "musclesim/identify/identify_series.h"
#include "musclesim/identify/identify_series_columns.h"
#include "musclesim/identify/identify_series_warnings.h"
#include "py_scenario.h"
#include "typed_objects.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

using Column = py::array_t<double, py::array::c_style | py::array::forcecast>;

const char* VerdictName(Identifiability verdict) {
  switch (verdict) {
    case Identifiability::kIdentifiable: return "identifiable";
    case Identifiability::kPoorlyDetermined: return "poorly_determined";
    case Identifiability::kNegligibleColumn: return "negligible_column";
    case Identifiability::kDependent: return "dependent";
    case Identifiability::kAtBound: return "at_bound";
  }
  return "unknown";
}

py::array_t<double> ToArray(const std::vector<double>& values) {
  py::array_t<double> array(static_cast<py::ssize_t>(values.size()));
  if (!values.empty()) {
    std::memcpy(array.mutable_data(), values.data(), values.size() * sizeof(double));
  }
  return array;
}

py::array_t<double> ToArray(const Eigen::VectorXd& values) {
  return ToArray(std::vector<double>(values.data(), values.data() + values.size()));
}

py::array_t<double> ToArray(const Eigen::MatrixXd& matrix) {
  py::array_t<double> array(
      {static_cast<py::ssize_t>(matrix.rows()), static_cast<py::ssize_t>(matrix.cols())});
  auto out = array.mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) out(i, j) = matrix(i, j);
  }
  return array;
}

// The columns of every series as float64 vectors; a column that is not a 1-D array of
// numbers is an InputError at the series' entry.
std::vector<SeriesColumns> ColumnsOf(const AnyList& series, const IdentifySeriesSpec& spec) {
  std::vector<SeriesColumns> all;
  for (std::size_t i = 0; i < py::len(series); ++i) {
    const std::string label = "series[" + std::to_string(i) + "]";
    SeriesColumns columns;
    for (const py::handle item : series[i]) {
      const auto pair = item.cast<std::pair<std::string, py::object>>();
      const Column array = Column::ensure(pair.second);
      const auto fail = [&](const std::string& rule) {
        throw InputError(
            InputFault{spec.series[i].at, label + "." + pair.first, std::nullopt, rule});
      };
      if (!array) fail("must be a 1-D array of numbers");
      if (array.ndim() != 1) {
        std::string shape;
        for (py::ssize_t d = 0; d < array.ndim(); ++d) {
          shape += (d ? ", " : "") + std::to_string(array.shape(d));
        }
        fail("must be a 1-D array of numbers, not one of shape (" + shape + ")");
      }
      columns.emplace_back(pair.first,
                           std::vector<double>(array.data(), array.data() + array.size()));
    }
    all.push_back(std::move(columns));
  }
  return all;
}

// A fit's or a design's result, with what Python reads of it made once.
struct Identification {
  SeriesIdentification result;
  bool design = false;
  std::string report;
  std::vector<std::string> warnings;
  py::object scenario = py::none();  // the estimated scenario (a fit only)
};

Identification Identify(const py::object& scenario, const py::object& spec_dict,
                        const std::string& spec_name, const AnyList& series, bool design,
                        int max_evaluations) {
  if (max_evaluations < 1) {
    throw py::value_error(
        "max_evaluations must be at least 1 (runs with sensitivities the fit "
        "may take), not " +
        std::to_string(max_evaluations));
  }
  const PyScenario& given = ScenarioArgument(scenario, "scenario");
  const IdentifySeriesSpec spec =
      ReadIdentifySeriesSpec(DocumentFrom(spec_dict, ""), spec_name, "", SeriesValues::kInMemory);
  if (py::len(series) != spec.series.size()) {
    throw std::invalid_argument("_identify_series: the spec names " +
                                std::to_string(spec.series.size()) + " series, the values " +
                                std::to_string(py::len(series)));
  }
  const std::vector<SeriesColumns> columns = ColumnsOf(series, spec);
  Identification out;
  out.design = design;
  const PyScenario base = given;  // taken with the GIL
  {
    py::gil_scoped_release release;
    const std::vector<MeasuredSeries> measured = MeasuredSeriesFromColumns(spec, columns, design);
    const SensitivityRunner run = ScenarioSensitivityRunner(base.scenario);
    if (design) {
      out.result = DesignSeries(spec, measured, run);
      out.report = FormatDesignReport(out.result, spec_name);
    } else {
      SeriesFitOptions options;
      options.max_evaluations = max_evaluations;
      out.result = FitSeries(spec, measured, run, options);
      out.report = FormatSeriesReport(out.result, spec_name);
    }
  }
  if (!design) {
    if (const std::string poor = PoorFitWarning(out.result); !poor.empty()) {
      out.warnings.push_back(poor);
    }
    if (!out.result.converged) {
      out.warnings.push_back("the fit did not converge: " + out.result.stop_reason +
                             "; the result is its last point, not an optimum");
    }
    // the estimated scenario: the estimates set in place, and written as values set for
    // to_yaml()
    PyScenario estimated = base;
    // its system is built anew at its first run: the base's is of the values before the fit
    estimated.Assign({EstimatedScenario(base.scenario, out.result), nullptr});
    for (const std::string& o : EstimateOverrides(out.result)) estimated.overrides.push_back(o);
    out.scenario = py::cast(std::move(estimated));
  }
  return out;
}

ArrayDict Residuals(const SeriesIdentification& r) {
  const std::size_t n = r.residuals.size();
  py::array_t<std::int64_t> series(static_cast<py::ssize_t>(n));
  std::vector<std::string> outputs;
  std::vector<double> t, measured, model, residual, standardised;
  for (std::size_t i = 0; i < n; ++i) {
    const ResidualRow& row = r.residuals[i];
    series.mutable_data()[i] = static_cast<std::int64_t>(row.series);
    outputs.push_back(row.output);
    t.push_back(row.t);
    measured.push_back(row.measured);
    model.push_back(row.model);
    residual.push_back(row.measured - row.model);
    standardised.push_back(row.standardised);
  }
  ArrayDict columns;
  columns["series"] = series;
  columns["output"] = py::module_::import("numpy").attr("array")(outputs, py::arg("dtype") = "str");
  columns["t"] = ToArray(t);
  columns["measured"] = ToArray(measured);
  columns["model"] = ToArray(model);
  columns["residual"] = ToArray(residual);
  columns["standardised"] = ToArray(standardised);
  return columns;
}

py::object Optional(const std::optional<double>& value) {
  return value ? py::object(py::float_(*value)) : py::object(py::none());
}

void BindParameterEstimate(py::module_& m) {
  py::class_<SeriesParameterResult>(
      m, "SeriesParameterEstimate",
      "One parameter of identify_series: its values, its standard error and the verdict on "
      "whether the experiment determines it. Values are in the parameter's own unit (the "
      "scenario file's: N, m, m/s, s, ...).")
      .def_property_readonly(
          "path", [](const SeriesParameterResult& p) { return p.path; },
          "The dotted key path, as Scenario.set takes it ('model.f_iso').")
      .def_property_readonly(
          "scenario_value", [](const SeriesParameterResult& p) { return p.scenario_value; },
          "Its value in the scenario (with the scenario's set() overrides).")
      .def_property_readonly(
          "start", [](const SeriesParameterResult& p) { return p.start; },
          "Where the fit started: the entry's start, or the scenario's value.")
      .def_property_readonly(
          "estimate", [](const SeriesParameterResult& p) { return p.estimate; },
          "The fit's estimate; for the design, the start.")
      .def_property_readonly(
          "standard_error", [](const SeriesParameterResult& p) { return p.standard_error; },
          "Its standard error (the design's: the Cramer-Rao bound); inf when the experiment "
          "does not determine it (negligible column, dependent, at a bound).")
      .def_property_readonly(
          "relative_standard_error",
          [](const SeriesParameterResult& p) { return p.relative_standard_error; },
          "standard_error / |estimate| (/ 1 at an estimate of 0) [-].")
      .def_property_readonly(
          "column_ratio", [](const SeriesParameterResult& p) { return p.column_ratio; },
          "Its column of the scaled sensitivity matrix over the largest column [-]: near 0, "
          "the outputs do not depend on it.")
      .def_property_readonly(
          "lower", [](const SeriesParameterResult& p) { return Optional(p.lower); },
          "The lower bound, or None.")
      .def_property_readonly(
          "upper", [](const SeriesParameterResult& p) { return Optional(p.upper); },
          "The upper bound, or None.")
      .def_property_readonly(
          "verdict", [](const SeriesParameterResult& p) { return VerdictName(p.verdict); },
          "'identifiable' (relative standard error <= 0.25), 'poorly_determined' (above it), "
          "'negligible_column' (the outputs do not depend on it), 'dependent' (in a "
          "combination the outputs do not see: weak_directions), 'at_bound' (the estimate sits "
          "on a bound: not estimated).")
      .def("__repr__", [](const SeriesParameterResult& p) {
        return "<musclesim.SeriesParameterEstimate " + p.path + " = " +
               py::repr(py::float_(p.estimate)).cast<std::string>() + " +- " +
               py::repr(py::float_(p.standard_error)).cast<std::string>() + " (" +
               VerdictName(p.verdict) + ")>";
      });
}

// The estimates and what the experiment determines of them.
void DefineEstimates(py::class_<Identification>& identification) {
  identification
      .def_property_readonly(
          "design", [](const Identification& r) { return r.design; },
          "True for the design check (no fit: the start values, Cramer-Rao standard errors).")
      .def_property_readonly(
          "estimates",
          [](const Identification& r) {
            FloatDict estimates;
            for (const auto& p : r.result.parameters) estimates[py::str(p.path)] = p.estimate;
            return estimates;
          },
          "dict {path: estimate} in the parameters' order and units (the design: the starts).")
      .def_property_readonly(
          "parameters", [](const Identification& r) { return r.result.parameters; },
          "One SeriesParameterEstimate per parameter, in the order given.")
      .def_property_readonly(
          "correlation", [](const Identification& r) { return ToArray(r.result.correlation); },
          "P x P float64 array of the estimates' correlations [-]; NaN in the row and column "
          "of a parameter the experiment does not determine.")
      .def_property_readonly(
          "singular_values",
          [](const Identification& r) { return ToArray(r.result.singular_values); },
          "The singular values of the scaled sensitivity matrix (each column the outputs' "
          "change, in noise standard deviations, for a relative change of its parameter), "
          "descending, float64 [-].")
      .def_property_readonly(
          "weak_directions",
          [](const Identification& r) {
            DictList directions;
            for (const WeakDirection& w : r.result.weak_directions) {
              py::dict d;
              d["ratio"] = w.ratio;
              d["components"] = ToArray(w.components);
              directions.append(d);
            }
            return directions;
          },
          "The combinations the experiment does not determine: a list of dicts {ratio: its "
          "singular value over the largest [-], components: float64 array, one per parameter, "
          "unit length, relative changes d p_j / |p_j| that leave the outputs unchanged}.");
}

// The fit's counts and how it ended.
void DefineFitStatistics(py::class_<Identification>& identification) {
  identification
      .def_property_readonly(
          "noise_given", [](const Identification& r) { return r.result.noise_given; },
          "True: weighted by 1/noise, covariance (J^T W J)^-1; False: unweighted, s^2 "
          "(J^T J)^-1 with s^2 = RSS / degrees_of_freedom.")
      .def_property_readonly(
          "variance_factor", [](const Identification& r) { return r.result.variance_factor; },
          "1 with noise levels; else s^2 = RSS / degrees_of_freedom [the values' unit squared].")
      .def_property_readonly(
          "values", [](const Identification& r) { return r.result.values; },
          "The number of measured values in the fit.")
      .def_property_readonly(
          "degrees_of_freedom", [](const Identification& r) { return r.result.degrees_of_freedom; },
          "values - parameters not at a bound.")
      .def_property_readonly(
          "weighted_rss", [](const Identification& r) { return r.result.weighted_rss; },
          "The fit's sum of squared weighted residuals ((measured - model) / noise)^2 [-] (or "
          "of plain residuals without noise levels, in the values' unit squared); 0 for the "
          "design.")
      .def_property_readonly(
          "iterations", [](const Identification& r) { return r.result.iterations; },
          "Accepted Levenberg-Marquardt steps (0 for the design).")
      .def_property_readonly(
          "evaluations", [](const Identification& r) { return r.result.evaluations; },
          "Runs with sensitivities the fit took (0 for the design).")
      .def_property_readonly(
          "converged", [](const Identification& r) { return r.result.converged; },
          "Whether the fit converged (True for the design). A fit that did not is returned "
          "with its last point and a RuntimeWarning.")
      .def_property_readonly(
          "stop_reason", [](const Identification& r) { return r.result.stop_reason; },
          "Why the fit stopped ('' for the design).");
}

// The verdict, residuals, report, warnings and the estimated scenario.
void DefineOutcome(py::class_<Identification>& identification) {
  identification
      .def_property_readonly(
          "verdict", [](const Identification& r) { return IdentifiabilityVerdict(r.result); },
          "The verdict in plain sentences: which parameters this experiment determines.")
      .def_property_readonly(
          "residuals", [](const Identification& r) { return Residuals(r.result); },
          "dict of 1-D arrays, one entry per measured value (the columns of `musclesim "
          "identify --residuals`): series (int64, the index in `series`), output (str, the "
          "column), t [s], measured, model, residual (measured - model) [the column's unit], "
          "standardised (residual / noise, or / s without noise levels) [-]. Empty for the "
          "design.")
      .def_property_readonly(
          "report", [](const Identification& r) { return r.report; },
          "Markdown, as `musclesim identify --report` (a fit) or `--design` writes it.")
      .def_property_readonly(
          "warnings", [](const Identification& r) { return r.warnings; },
          "The warnings identify_series issued (a fit that did not converge, weighted "
          "residuals far above the stated noise), as texts; [] when none.")
      .def_property_readonly(
          "scenario", [](const Identification& r) { return r.scenario; },
          "The estimated Scenario (the given one with 'path=estimate' overrides after its "
          "own), ready to run(); None for the design.")
      .def("__repr__", [](const Identification& r) {
        std::string text =
            std::string("<musclesim.SeriesIdentification ") +
            (r.design ? "design" : (r.result.converged ? "fit" : "fit (not converged)"));
        for (const auto& p : r.result.parameters) {
          text += ", " + p.path + " = " + py::repr(py::float_(p.estimate)).cast<std::string>();
        }
        return text + ">";
      });
}

void BindSeriesIdentification(py::module_& m) {
  py::class_<Identification> identification(
      m, "SeriesIdentification",
      "The result of identify_series: a weighted least-squares fit of scenario parameters to "
      "measured time series (or, with design=True, the experiment's check at the start "
      "values), with what the Jacobian of forward sensitivities says about the parameters: "
      "standard errors, correlations, the singular values of the scaled sensitivity matrix "
      "and a verdict. As `musclesim identify DATA.yaml` (docs/guide/identification.md, \"From "
      "time series\"). Values in the units of the scenario's parameters and of the measured "
      "columns (SI: m, m/s, N, s).");
  DefineEstimates(identification);
  DefineFitStatistics(identification);
  DefineOutcome(identification);
}

}  // namespace

void BindIdentifySeries(py::module_& m) {
  BindParameterEstimate(m);
  BindSeriesIdentification(m);
  m.def("_identify_series", &Identify, py::arg("scenario"), py::arg("spec"), py::arg("spec_name"),
        py::arg("series"), py::arg("design"), py::arg("max_evaluations"),
        "identify_series's C++ half: `spec` a data file's keys as a dict without csv keys "
        "(messages name it `spec_name`), `series` one list of (column, array) pairs per entry "
        "of its series. identify_series is the public way.");
}

}  // namespace musclesim::python
