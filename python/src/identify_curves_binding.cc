// musclesim._identify_curves: `musclesim identify` on curves held in arrays. The checks, fits,
// model block and report are the library's, as the command runs them; this file converts the
// arrays in and the results out (musclesim/curves_identification.py wraps it).
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "model_values.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/io/readers/model_text.h"
#include "musclesim/io/writers/model_yaml_writer.h"
#include "musclesim/identify/curve_data.h"
#include "musclesim/identify/identified_model.h"
#include "musclesim/identify/identify.h"
#include "musclesim/identify/identify_comparisons.h"
#include "musclesim/identify/identify_report.h"
#include "typed_objects.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

// c_style: data() then walks the values in order, even for a column of a 2-d array
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// One curve's columns as given: x (a length [m] or a shortening velocity [m/s]) and tension [N].
struct Columns {
  std::vector<double> x, tension;
};

// `values`, a 1-d array of numbers, copied; else InputError naming `argument` and `column`.
std::vector<double> Column(const py::handle& values, const std::string& argument,
                           const std::string& column) {
  const Array array = Array::ensure(values);
  if (!array || array.ndim() != 1) {
    throw InputError(argument + ": ", InputFault{std::nullopt, argument, std::nullopt,
                                                 column + " must be a 1-d sequence of numbers"});
  }
  return {array.data(), array.data() + array.size()};
}

std::optional<Columns> ReadColumns(const py::object& curve, const std::string& argument,
                                   const std::string& x_name) {
  if (curve.is_none()) return std::nullopt;
  const py::tuple pair = curve.cast<py::tuple>();
  if (pair.size() != 2) {
    throw InputError(argument + ": ", InputFault{std::nullopt, argument, std::nullopt,
                                                 "give a pair (" + x_name + ", tension)"});
  }
  return Columns{Column(pair[0], argument, x_name), Column(pair[1], argument, "tension")};
}

py::tuple Pair(const Estimate& e) { return py::make_tuple(e.value, e.standard_error); }

py::list Pairs(const std::vector<Estimate>& estimates) {
  py::list out;
  for (const Estimate& e : estimates) out.append(Pair(e));
  return out;
}

py::dict PassiveDict(const PassiveIdentification& p, std::size_t points) {
  const ProfileInterval& i = p.slack_length_interval;
  return py::dict(
      py::arg("k_p") = Pair(p.k_p), py::arg("alpha") = Pair(p.alpha),
      py::arg("slack_length") = Pair(p.slack_length), py::arg("rmse") = p.rmse,
      py::arg("points") = points,
      py::arg("slack_length_interval") =
          py::dict(py::arg("low") = i.low, py::arg("high") = i.high,
                   py::arg("low_bounded") = i.low_bounded, py::arg("high_bounded") = i.high_bounded,
                   py::arg("level") = i.level, py::arg("wide") = i.wide),
      py::arg("k_p_over_interval") =
          py::make_tuple(p.k_p_over_interval.low, p.k_p_over_interval.high),
      py::arg("alpha_over_interval") =
          py::make_tuple(p.alpha_over_interval.low, p.alpha_over_interval.high));
}

py::dict ActiveDict(const ActiveIdentification& a, std::size_t points) {
  return py::dict(
      py::arg("f_iso") = Pair(a.f_iso),
      py::arg("optimal_range") = py::make_tuple(a.curve.optimal_min, a.curve.optimal_max),
      py::arg("amplitudes") = Pairs(a.amplitudes), py::arg("widths") = Pairs(a.precisions),
      py::arg("centers") = Pairs(a.centers), py::arg("rmse") = a.rmse, py::arg("points") = points);
}

py::dict EccentricDict(const EccentricIdentification& e, bool in_model) {
  const py::object none = py::none();
  return py::dict(py::arg("points") = e.points, py::arg("identified") = e.identified,
                  py::arg("limit_identified") = e.limit_identified, py::arg("in_model") = in_model,
                  py::arg("why_not") = e.identified ? none : py::str(e.why_not),
                  py::arg("why_no_limit") = e.limit_identified ? none : py::str(e.why_no_limit),
                  py::arg("v_max") = e.identified ? py::object(Pair(e.best.v_max)) : none,
                  py::arg("n") = e.identified ? py::object(py::int_(e.best.n)) : none,
                  py::arg("limit") = e.limit_identified ? py::object(Pair(e.best.limit)) : none,
                  py::arg("rmse") = e.identified ? py::object(py::float_(e.best.rmse)) : none);
}

py::dict VelocityDict(const VelocityIdentification& v, std::size_t points,
                      bool eccentric_in_model) {
  py::list candidates;
  for (const VelocityCandidate& c : v.candidates) {
    candidates.append(py::dict(py::arg("n") = c.n, py::arg("f_iso") = Pair(c.f_iso),
                               py::arg("v_max") = Pair(c.v_max), py::arg("rmse") = c.rmse,
                               py::arg("valid") = c.valid));
  }
  return py::dict(py::arg("f_iso") = Pair(v.best.f_iso), py::arg("v_max") = Pair(v.best.v_max),
                  py::arg("n") = v.best.n, py::arg("rmse") = v.best.rmse,
                  py::arg("points") = points, py::arg("candidates") = candidates,
                  py::arg("eccentric") =
                      v.eccentric ? py::object(EccentricDict(*v.eccentric, eccentric_in_model))
                                  : py::object(py::none()));
}

// What the fits give, before conversion to Python values (made with the GIL released).
struct Outcome {
  std::optional<PassiveIdentification> passive;
  std::optional<ActiveIdentification> active;
  std::optional<VelocityIdentification> velocity;
  std::size_t passive_points = 0, active_points = 0, velocity_points = 0;
  std::string model_yaml;
  ModelParams params;  // the block read back, as a scenario would read it
  std::optional<std::string> report;
};

AnyDict IdentifyCurves(const py::object& passive_curve, const py::object& active_curve,
                       const py::object& velocity_curve, int active_count, bool nonnegative,
                       std::optional<double> f_iso, bool report, const std::string& source) {
  if (source.find_first_of("\r\n") != std::string::npos) {
    throw py::value_error("source must be one line: it is written in a YAML comment");
  }
  const std::optional<Columns> passive = ReadColumns(passive_curve, "passive", "length");
  const std::optional<Columns> active = ReadColumns(active_curve, "active", "length");
  const std::optional<Columns> velocity =
      ReadColumns(velocity_curve, "velocity", "shortening_velocity");
  if (!passive && !active && !velocity) {
    throw InputError("give at least one of passive, active, velocity");
  }
  // the data file's active.count, the same rule
  if (!kGaussianCountRange.Contains(active_count)) {
    throw InputError(InputFault{
        std::nullopt, "active_count", std::to_string(active_count),
        "must be an integer " + kGaussianCountRange.Bounds() + " [-]: " + kGaussianCountRange.why});
  }
  if (f_iso && !kPositiveForceRange.Contains(*f_iso)) {
    throw InputError(
        InputFault{std::nullopt, "f_iso", FormatNumber(*f_iso), kPositiveForceRange.Rule()});
  }

  Outcome out;
  {
    py::gil_scoped_release release;  // the fits, and the refits of the report's comparisons
    std::vector<CurveComparison> comparisons;
    if (passive) {
      const auto data = CheckedCurve("passive", passive->x, passive->tension, "length", "tension",
                                     kMinPassivePoints);
      out.passive = IdentifyPassive(data);
      out.passive_points = data.size();
      if (report) comparisons.push_back(ComparePassiveFit(data, *out.passive));
    }
    if (active) {
      const auto data = CheckedCurve("active", active->x, active->tension, "length", "tension",
                                     MinActivePoints(active_count));
      out.active = IdentifyActive(data, active_count, nonnegative);
      out.active_points = data.size();
      if (report) comparisons.push_back(CompareActiveFit(data, active_count, nonnegative));
    }
    if (velocity) {
      const auto data =
          CheckedCurve("velocity", velocity->x, velocity->tension, "shortening_velocity", "tension",
                       MinVelocityPoints(f_iso.has_value()));
      out.velocity = IdentifyVelocity(data, f_iso);
      out.velocity_points = data.size();
      if (report) comparisons.push_back(CompareVelocityFit(data, f_iso, *out.velocity));
    }
    out.model_yaml =
        FormatModelYaml(DraftIdentifiedModel(source, out.passive, out.active, out.velocity));
    // the model is the block's text read back: the value of its `model:` key, whose lines
    // keep their two-space indent (YAML takes any consistent indent)
    const std::string key = "\nmodel:\n";
    const std::size_t block = out.model_yaml.find(key);
    out.params =
        ParseModelSpec("<identified model>", out.model_yaml.substr(block + key.size())).params;
    if (report) out.report = FormatReport(comparisons);
  }

  const py::object none = py::none();
  const bool eccentric_in_model = out.params.velocity.eccentric.v_max.has_value();
  return py::dict(
      py::arg("model_yaml") = out.model_yaml, py::arg("params") = ParamsDict(out.params),
      py::arg("passive") =
          out.passive ? py::object(PassiveDict(*out.passive, out.passive_points)) : none,
      py::arg("active") =
          out.active ? py::object(ActiveDict(*out.active, out.active_points)) : none,
      py::arg("velocity") =
          out.velocity
              ? py::object(VelocityDict(*out.velocity, out.velocity_points, eccentric_in_model))
              : none,
      py::arg("report") = out.report ? py::object(py::str(*out.report)) : none);
}

}  // namespace

void BindIdentifyCurves(py::module_& m) {
  m.def("_identify_curves", &IdentifyCurves, py::arg("passive"), py::arg("active"),
        py::arg("velocity"), py::arg("active_count"), py::arg("nonnegative"), py::arg("f_iso"),
        py::arg("report"), py::arg("source"),
        R"(The engine of musclesim.identify_curves (use that): each curve None or a pair of 1-d
arrays (x, tension), x a length [m] (passive, active) or a shortening velocity [m/s]
(velocity, > 0 shortening), tension [N]. Checks the data by the rules of the CLI's CSV
reader, fits them with the GIL released, and returns a dict: model_yaml (the `model:` block
of `musclesim identify`, its header naming `source`), params (that block read back, for
musclesim.Model), passive, active, velocity (the estimates, or None) and report (the
Markdown of --report, or None). Raises InputError naming the argument and row for bad data.)");
}

}  // namespace musclesim::python
