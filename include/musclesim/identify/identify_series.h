// Identification of a scenario's parameters from measured time series
// (docs/guide/identification.md): the scenario holds the experiment's known inputs, the measured
// series its outputs at some times, and a weighted least-squares fit (Levenberg-Marquardt inside
// box bounds) with the exact Jacobian of forward sensitivities (docs/model.md section 10) estimates
// the listed parameters. What the Jacobian says about them comes with the fit: standard errors and
// correlations from the Fisher information, the singular values of the scaled sensitivity matrix
// and a verdict on which parameters this experiment determines. The same analysis at the start
// values with the stated noise, without data, is the experiment's design check (`identify
// --design`).
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "musclesim/io/readers/identify_series_spec.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/scenario/sensitivity_run.h"

namespace musclesim {

// One series of the data file, read.
struct MeasuredSeries {
  std::string source;                // the CSV's path; "" without one (a --design series, or
                                     // values given in memory)
  InputPlace at;                     // where the data file names it (data.yaml:4:5) [-]
  std::vector<std::string> columns;  // outputs, named as the trajectory CSV names them [-]
  std::vector<double> noise;         // per column: standard deviation [the column's unit];
                                     // NaN where the data file gives none
  std::vector<double> times;         // [s], strictly increasing; empty (design only): the
                                     // scenario's output grid
  std::vector<double> values;        // times x columns, row-major [the columns' units]
  std::vector<std::size_t> lines;    // the CSV's line of each row, or its 1-based index [-]
};

// Reads the series of `spec`. Each CSV has a column `t` and one or more output columns;
// rows sorted by strictly increasing t, every value finite, at least one row. Noise keys must
// name columns of their CSV. Without `design`, every series needs a csv. With `design`, a
// series without one takes its columns from its noise keys and its times from the
// scenario's output grid, and every column needs a noise level. Throws InputError naming
// the file (and the line of a bad row), the column and the rule.
std::vector<MeasuredSeries> ReadMeasuredSeries(const IdentifySeriesSpec& spec, bool design);

// A run with sensitivities as identification uses it: the scenario with `values[i]` set at
// parameters[i] (key paths; `values` empty: the scenario as it is), its rows at `times`
// (empty: its output grid), the derivatives with respect to `parameters`, each taken on the
// scale of sizes[i] (empty: the values'; SensitivityRequest::size), so that an estimate
// nearing 0 is still differentiated on the scale of the start.
using SensitivityRunner = std::function<SensitivityTable(
    const std::vector<std::string>& parameters, const std::vector<double>& values,
    const std::vector<double>& times, const std::vector<double>& sizes)>;

// RunWithSensitivities on copies of `scenario`, the values set through the parameters'
// handles (SetParameters: a value a handle refuses throws its ParameterError).
SensitivityRunner ScenarioSensitivityRunner(Scenario scenario);

// The verdict on one parameter (thresholds below, and in the README).
enum class Identifiability {
  kIdentifiable,      // relative standard error <= kPoorRelativeError
  kPoorlyDetermined,  // determined in principle, but the noise hides it
  kNegligibleColumn,  // the outputs do not depend on it (to kNegligibleColumnRatio)
  kDependent,         // in a direction with a near-zero singular value (with others, or
                      // alone when its column is just above kNegligibleColumnRatio)
  kAtBound,           // the estimate sits on a bound: not estimated
};

// A column of the scaled sensitivity matrix below this fraction of the largest is
// negligible: the experiment does not see the parameter. 1e-6 is about the relative accuracy
// of the sensitivities at the solver's default tolerances (rtol 1e-6): a smaller column cannot
// be told from zero.
inline constexpr double kNegligibleColumnRatio = 1e-6;
// A singular value below this fraction of the largest: its direction (a combination of
// parameters) is not determined by the experiment; the same reason as above.
inline constexpr double kDependentSingularValueRatio = 1e-6;
// A parameter whose relative standard error exceeds this is poorly determined: its 95%
// interval (about +-2 standard errors) is wider than +-50% of its value.
inline constexpr double kPoorRelativeError = 0.25;
// An unresolved direction (unit length) involves the parameters whose component is at least
// this: they are named in its combination and have no standard error; the others' come from
// the resolved directions. 0.01 lies above the direction's numerical noise (about the
// sensitivities' error, 1e-6, over the gap to the next singular value).
inline constexpr double kComponentFloor = 0.01;

// A right singular vector of the scaled sensitivity matrix with a near-zero singular value:
// relative changes of the parameters (d p_j / |p_j|, in proportion to `components`) that
// leave the outputs unchanged to `ratio` of the best-determined direction.
struct WeakDirection {
  double ratio = 0.0;              // singular value / largest singular value [-]
  std::vector<double> components;  // one per parameter, unit length; 0 at a bound [-]
};

struct SeriesParameterResult {
  std::string path;                      // as the data file gives it [-]
  double scenario_value = 0.0;           // in the scenario (with --set) [the parameter's unit]
  double start = 0.0;                    // [the parameter's unit]
  double estimate = 0.0;                 // the fit's; the design's: the start
  double standard_error = 0.0;           // [the parameter's unit]; infinite: not determined
  double relative_standard_error = 0.0;  // standard error / max(|estimate|, |start|) [-]
  double column_ratio = 0.0;             // its sensitivity column / the largest [-]
  std::optional<double> lower, upper;    // the bounds [the parameter's unit]
  Identifiability verdict = Identifiability::kIdentifiable;
};

// One measured value beside the model's.
struct ResidualRow {
  std::size_t series = 0;     // index in the data file's list [-]
  std::string output;         // the column [-]
  double t = 0.0;             // [s]
  double measured = 0.0;      // [the column's unit]
  double model = 0.0;         // [the column's unit]
  double standardised = 0.0;  // (measured - model) / noise, or / s without noise levels [-]
};

struct SeriesIdentification {
  std::string scenario;  // the scenario's path [-]
  std::vector<SeriesParameterResult> parameters;
  Eigen::MatrixXd correlation;      // P x P [-]; NaN for a parameter not determined
  Eigen::VectorXd singular_values;  // of the scaled sensitivity matrix, descending [-]
  std::vector<WeakDirection> weak_directions;
  bool noise_given = false;      // covariance (J^T W J)^-1; else s^2 (J^T J)^-1
  double variance_factor = 1.0;  // 1, or s^2 = RSS / dof [the values' unit squared]
  std::size_t values = 0;        // measured values in the fit [-]
  int degrees_of_freedom = 0;    // values - parameters not at a bound [-]
  // the fit only (the design leaves them at their defaults)
  double weighted_rss = 0.0;  // sum of squared weighted residuals [-, or units^2]
  int iterations = 0;         // accepted Levenberg-Marquardt steps [-]
  int evaluations = 0;        // runs with sensitivities [-]
  bool converged = true;
  std::string stop_reason;
  std::vector<ResidualRow> residuals;
};

struct SeriesFitOptions {
  int max_evaluations = 200;  // runs with sensitivities the fit may take [-]
};

// Fits the parameters of `spec` to `series` (ReadMeasuredSeries without design) from their
// start values (the scenario's, where the data file gives none). Weighted by 1/noise when
// every column has a noise level; without noise levels, unweighted, which needs every series
// to measure one and the same column (values of different quantities cannot be weighed
// against each other without them). Throws InputError for a data file the scenario does not
// fit (a column the run does not differentiate, a time outside the run, noise given for
// some columns only, no more values than parameters, a start outside the bounds), and for
// a scenario or parameter that RunWithSensitivities refuses; std::runtime_error when the
// run fails at the start values.
SeriesIdentification FitSeries(const IdentifySeriesSpec& spec,
                               const std::vector<MeasuredSeries>& series,
                               const SensitivityRunner& run, const SeriesFitOptions& options = {});

// The design check: the Cramer-Rao standard errors and the identifiability analysis at the
// start values, with the stated noise (every column needs one), at the series' times (their
// CSV's, or the scenario's output grid). Measured values, if any, are not used. Throws as
// FitSeries does.
SeriesIdentification DesignSeries(const IdentifySeriesSpec& spec,
                                  const std::vector<MeasuredSeries>& series,
                                  const SensitivityRunner& run);

// `scenario` with every estimate of `fit` set at its parameter's path (ParameterError when
// one cannot be: the scenario is not the fit's).
Scenario EstimatedScenario(const Scenario& scenario, const SeriesIdentification& fit);

// "path=value" for every estimate, the shortest exact form: what applied to the scenario's
// file gives the estimated one (io/writers/scenario_rewrite.h writes it).
std::vector<std::string> EstimateOverrides(const SeriesIdentification& fit);

// The verdict in one or two plain sentences: "f_iso and v_max are identifiable from this
// experiment; slack_length is not: its column is 0 of the largest."
std::string IdentifiabilityVerdict(const SeriesIdentification& result);

// Markdown: the estimates with standard errors (and how they were computed), the
// correlation matrix, the singular values, the verdict, the fit's convergence.
std::string FormatSeriesReport(const SeriesIdentification& fit, const std::string& data_file);

// Markdown: the parameters ranked by their relative Cramer-Rao standard error, with the
// singular values and the verdict.
std::string FormatDesignReport(const SeriesIdentification& design, const std::string& data_file);

// The comment lines (without "# ") that head the estimated scenario.
std::vector<std::string> EstimatedScenarioHeader(const SeriesIdentification& fit,
                                                 const std::string& data_file);

// CSV with columns series, output, t, measured, model, residual, standardised: what
// `musclesim plot` draws as a residual figure.
std::string FormatResidualCsv(const SeriesIdentification& fit);

}  // namespace musclesim
