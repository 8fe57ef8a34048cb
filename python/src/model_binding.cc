// musclesim.Model (the tension curves on NumPy arrays, with their derivatives), load_model
// and fit_gaussians (the closed-form least-squares fit of Gaussians to a force-length target).
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "document.h"
#include "model_values.h"
#include "overrides.h"
#include "typed_objects.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/io/readers/model_text.h"
#include "musclesim/io/readers/model_yaml.h"
#include "musclesim/model/force_length_presets.h"
#include "musclesim/model/gaussian_fit.h"
#include "musclesim/model/tension.h"

namespace py = pybind11;

namespace musclesim::python {

namespace {

using Array = py::array_t<double, py::array::forcecast>;

// Below this many points the GIL is kept: releasing it costs more than the loop.
constexpr py::ssize_t kReleaseGilFrom = 4096;

// The inputs broadcast against each other, as contiguous float64 arrays of one shape.
struct Broadcast {
  std::vector<py::array_t<double, py::array::c_style>> inputs;
  std::vector<py::ssize_t> shape;
  py::ssize_t size = 1;
};

Broadcast BroadcastInputs(const std::vector<py::object>& args) {
  const py::module_ np = py::module_::import("numpy");
  py::list arrays;
  for (const py::object& arg : args) {
    Array array = Array::ensure(arg);
    if (!array) throw py::type_error("expected numbers or arrays of numbers");
    arrays.append(array);
  }
  Broadcast out;
  const py::object common = np.attr("broadcast")(*arrays).attr("shape");
  for (const py::handle dim : common) out.shape.push_back(dim.cast<py::ssize_t>());
  for (const py::ssize_t dim : out.shape) out.size *= dim;
  for (const py::handle array : arrays) {
    out.inputs.push_back(py::array_t<double, py::array::c_style>::ensure(
        np.attr("ascontiguousarray")(np.attr("broadcast_to")(array, common))));
  }
  return out;
}

// A result of shape () becomes a numpy.float64 (a subclass of float), as NumPy's own
// functions return for scalar arguments; any other shape stays an array.
py::object Finish(py::array_t<double> result) {
  if (result.ndim() == 0) return result[py::tuple()];
  return result;
}

// Evaluates `fill(i, inputs, outputs)` for every point, writing `count` outputs of the
// broadcast shape; the GIL is released for large arrays.
template <typename Fill>
std::vector<py::array_t<double>> Evaluate(const std::vector<py::object>& args, int count,
                                          const Fill& fill) {
  const Broadcast b = BroadcastInputs(args);
  std::vector<py::array_t<double>> outputs;
  std::vector<double*> out_data;
  for (int k = 0; k < count; ++k) {
    outputs.emplace_back(b.shape);
    out_data.push_back(outputs.back().mutable_data());
  }
  std::vector<const double*> in_data;
  for (const auto& input : b.inputs) in_data.push_back(input.data());
  const auto loop = [&] {
    for (py::ssize_t i = 0; i < b.size; ++i) fill(i, in_data, out_data);
  };
  if (b.size >= kReleaseGilFrom) {
    py::gil_scoped_release release;
    loop();
  } else {
    loop();
  }
  return outputs;
}

// One curve of one argument: value or slope of a CurvePoint.
template <typename Curve>
py::object Curve1(const py::object& arg, const Curve& curve) {
  return Finish(Evaluate({arg}, 1,
                         [&](py::ssize_t i, const std::vector<const double*>& in,
                             const std::vector<double*>& out) { out[0][i] = curve(in[0][i]); })[0]);
}

// An activation as the model takes it: the tension is not defined outside [0, 1].
double Activation(double u) {
  Require(u >= 0.0 && u <= 1.0, "u", u, "must be in [0, 1] (an activation)");
  return u;
}

// The model and what built it.
struct Model {
  std::shared_ptr<const TensionModel> tension;
  std::optional<FitResult> fit_result;  // when the block asked for a fit
};

Model FromSpec(const ModelSpec& spec) {
  return {std::make_shared<const TensionModel>(spec.params), spec.fit_result};
}

Model FromDict(const AnyDict& params) {
  // the block goes through the file reader as a document, with its rules and messages
  const Document block = DocumentFrom(params, "model");
  ModelSpec spec;
  {
    py::gil_scoped_release release;  // a block asking for a fit runs it here
    spec = ReadModelSpec(block, "<model dict>");
  }
  return FromSpec(spec);
}

AnyDict FitDict(const FitResult& fit) {
  const auto column = [&](auto field) {
    py::array_t<double> out(static_cast<py::ssize_t>(fit.gaussians.size()));
    for (std::size_t k = 0; k < fit.gaussians.size(); ++k) {
      out.mutable_data()[k] = fit.gaussians[k].*field;
    }
    return out;
  };
  py::list gaussians;
  for (const Gaussian& g : fit.gaussians) gaussians.append(GaussianDict(g));
  return py::dict(py::arg("amplitudes") = column(&Gaussian::amplitude),
                  py::arg("widths") = column(&Gaussian::precision),
                  py::arg("centers") = column(&Gaussian::center), py::arg("gaussians") = gaussians,
                  py::arg("cost") = fit.cost, py::arg("relative_residual") = fit.relative_residual,
                  py::arg("iterations") = fit.iterations, py::arg("starts") = fit.starts);
}

std::vector<double> Vector(const py::object& values, const char* name) {
  const Array array = Array::ensure(values);
  if (!array || array.ndim() != 1) {
    throw py::value_error(std::string(name) + " must be a 1-d sequence of numbers");
  }
  return {array.data(), array.data() + array.size()};
}

AnyDict Fit(const py::object& x, const py::object& f, int n, std::optional<std::string> target,
            std::optional<std::string> preset, double optimal_length,
            std::optional<std::pair<double, double>> optimal_range, double sigma, bool nonnegative,
            const py::object& widths, const py::object& centers) {
  FitSpec spec;
  spec.count = n;
  spec.nonnegative = nonnegative;
  const bool has_points = !x.is_none() || !f.is_none();
  if (preset) {
    if (has_points) throw py::value_error("give either points (x, f) or a preset, not both");
    spec.target = FitTargetKind::kPreset;
    spec.preset = ParseForceLengthPreset(*preset);
    spec.optimal_length = optimal_length;
  } else if (has_points) {
    spec.target = ParseFitTargetKind(target.value_or("samples"));
    const std::vector<double> xs = Vector(x, "x");
    const std::vector<double> ys = Vector(f, "f");
    if (xs.size() != ys.size()) {
      throw py::value_error("x and f must have the same length (" + std::to_string(xs.size()) +
                            " and " + std::to_string(ys.size()) + ")");
    }
    for (std::size_t i = 0; i < xs.size(); ++i) {
      // the file reader's bounds on fit points, so that the fit's integrals stay finite
      const std::string at = "points[" + std::to_string(i) + "]";
      Require(kPositionRange.Contains(xs[i]), at + "[0]", xs[i], kPositionRange.Rule());
      Require(kFitValueRange.Contains(ys[i]), at + "[1]", ys[i], kFitValueRange.Rule());
      spec.points.push_back({xs[i], ys[i]});
    }
  } else {
    spec.target = ParseFitTargetKind(target.value_or("indicator"));
  }
  double l1 = 0.0;
  double l2 = 1.0;
  if (spec.target == FitTargetKind::kIndicator) {
    if (!optimal_range) throw py::value_error("target indicator needs optimal_range=(l1, l2)");
    l1 = optimal_range->first;
    l2 = optimal_range->second;
  }
  // range and sigma under the model's rules (a dummy component: the fit supplies them)
  Validate(ActiveLengthParams{l1, l2, sigma, {Gaussian{1.0, 1.0, 0.0}}});
  if (!widths.is_none()) spec.precisions = Vector(widths, "widths");
  if (!centers.is_none()) spec.centers = Vector(centers, "centers");
  FitResult result;
  {
    py::gil_scoped_release release;
    result = FitGaussians(spec, l1, l2, sigma);
  }
  return FitDict(result);
}

// The constructor and the tension with its parts.
void DefineTension(py::class_<Model>& model_class) {
  model_class
      .def(py::init(&FromDict), py::arg("params"),
           R"(A model from a dict with the keys of a scenario's `model:` block (docs/guide/model.md,
docs/model.md): f_iso [N]; passive {k_p [N], alpha [1/m], slack_length [m]}; active_length
{optimal_range [l1, l2] [m], sigma (optional), and gaussians [{amplitude, width, center}] or
fit {count, target, ...}}; velocity {v_max [m/s], n, epsilon [m/s], eccentric {v_max, n,
limit} (optional)}. The dict is read by the same reader as a file, as a document in memory
(no text in between; NumPy numbers and arrays as Python numbers and lists): the same rules,
and an InputError for a value that breaks one, naming the key path and "<model dict>" in
place of the file (a dict has no lines: location None), e.g. "model.passive.k_p = abc
(<model dict>): must be a number". A value of a type no file holds (not a number, bool, str,
None, list or dict) is a TypeError naming its key path.)")
      .def(
          "tension",
          [](const Model& self, const py::object& x, const py::object& v, const py::object& u) {
            const TensionModel& model = *self.tension;
            return Finish(
                Evaluate({x, v, u}, 1, [&](py::ssize_t i, const auto& in, const auto& out) {
                  out[0][i] = model.Evaluate(in[0][i], in[1][i], Activation(in[2][i])).total;
                })[0]);
          },
          py::arg("x"), py::arg("v"), py::arg("u"),
          "Total tension T [N] at length x [m], shortening velocity v [m/s] (> 0 shortening) "
          "and activation u [-] in [0, 1] (ParameterError outside, NaN included).")
      .def(
          "tension_parts",
          [](const Model& self, const py::object& x, const py::object& v, const py::object& u) {
            const TensionModel& model = *self.tension;
            auto parts =
                Evaluate({x, v, u}, 6, [&](py::ssize_t i, const auto& in, const auto& out) {
                  const TensionSample s = model.Evaluate(in[0][i], in[1][i], Activation(in[2][i]));
                  out[0][i] = s.total;
                  out[1][i] = s.passive;
                  out[2][i] = s.active;
                  out[3][i] = s.d_length;
                  out[4][i] = s.d_velocity;
                  out[5][i] = s.d_activation;
                });
            AnyDict result;
            const char* names[] = {"total",    "passive",    "active",
                                   "d_length", "d_velocity", "d_activation"};
            for (int k = 0; k < 6; ++k) result[names[k]] = Finish(parts[k]);
            return result;
          },
          py::arg("x"), py::arg("v"), py::arg("u"),
          R"(The tension and its parts at (x [m], v [m/s], u [-]), as a dict of arrays:
total T [N], passive T_p [N], active T_a = u f_iso f_L g [N], d_length dT/dx [N/m],
d_velocity dT/dv [N s/m] (v the shortening velocity), d_activation dT/du [N]. The
derivatives are the analytic ones the simulator's Jacobian uses; at x = slack_length the
passive slope is the left one (0).)");
}

// The curves of one argument: passive tension, f_L, g and their slopes.
void DefineCurves(py::class_<Model>& model_class) {
  model_class
      .def(
          "passive",
          [](const Model& self, const py::object& x) {
            const TensionModel& t = *self.tension;
            return Curve1(x, [&](double xi) { return t.Passive(xi, 0.0).passive; });
          },
          py::arg("x"),
          "Passive tension T_p [N] at length x [m]: k_p (exp(alpha (x - slack_length)) - 1) "
          "above the slack length, 0 at or below it.")
      .def(
          "f_L",
          [](const Model& self, const py::object& x) {
            const TensionModel& t = *self.tension;
            return Curve1(x, [&](double xi) { return t.ActiveLengthFactor(xi).value; });
          },
          py::arg("x"),
          "Active tension-length factor f_L [-] at length x [m]: the sum of Gaussians divided "
          "by its maximum over optimal_range, so its peak there is 1.")
      .def(
          "f_L_slope",
          [](const Model& self, const py::object& x) {
            const TensionModel& t = *self.tension;
            return Curve1(x, [&](double xi) { return t.ActiveLengthFactor(xi).slope; });
          },
          py::arg("x"), "df_L/dx [1/m] at length x [m].")
      .def(
          "g",
          [](const Model& self, const py::object& v) {
            const TensionModel& t = *self.tension;
            return Curve1(v, [&](double vi) { return t.VelocityFactor(vi).value; });
          },
          py::arg("v"),
          "Tension-velocity factor g [-] at shortening velocity v [m/s] (> 0 shortening): 1 at "
          "v = 0, 0 at v = v_max, epsilon-regularised so it is smooth at 0.")
      .def(
          "g_slope",
          [](const Model& self, const py::object& v) {
            const TensionModel& t = *self.tension;
            return Curve1(v, [&](double vi) { return t.VelocityFactor(vi).slope; });
          },
          py::arg("v"), "dg/dv [s/m] at shortening velocity v [m/s].");
}

void DefineModelProperties(py::class_<Model>& model_class) {
  model_class
      .def_property_readonly(
          "params", [](const Model& self) { return AnyDict(ParamsDict(self.tension->params())); },
          "The parameters as a dict with the `model:` block's keys (units as there), the "
          "Gaussians always explicit (a fit's result in its place): Model(model.params) is the "
          "same model.")
      .def_property_readonly(
          "optimal_length",
          [](const Model& self) {
            const TensionModel& t = *self.tension;
            return t.params().family == CurveFamily::kPaper ? t.active_length().optimal_length()
                                                            : t.OptimalFiberLength();
          },
          "Where f_L peaks on optimal_range [m] (f_L = 1 there); for another family "
          "(model.family), "
          "its optimal fiber length.")
      .def_property_readonly(
          "fit_result",
          [](const Model& self) -> std::optional<AnyDict> {
            if (!self.fit_result) return std::nullopt;
            return FitDict(*self.fit_result);
          },
          "The fit the block asked for (a dict as fit_gaussians returns), or None when the "
          "block gave its Gaussians.")
      .def("__repr__", [](const Model& self) {
        const ModelParams& p = self.tension->params();
        if (p.family != CurveFamily::kPaper) {
          return "<musclesim.Model family=" + std::string(ToString(p.family)) +
                 " f_iso=" + FormatNumber(p.f_iso) + " N>";
        }
        return "<musclesim.Model f_iso=" + FormatNumber(p.f_iso) + " N, " +
               std::to_string(p.active_length.gaussians.size()) +
               " Gaussians, v_max=" + FormatNumber(p.velocity.v_max) + " m/s>";
      });
}

void BindModelClass(py::module_& m) {
  py::class_<Model> model_class(m, "Model", R"(The tension model of one actuator (docs/model.md):
T(x, v, u) = T_p(x) + u f_iso f_L(x) g(v), x the length [m], v the shortening velocity [m/s]
(positive when the actuator shortens, v = -dx/dt), u the activation in [0, 1], T in [N].

Every curve method takes numbers or NumPy arrays (converted to float64) and broadcasts its
arguments against each other as NumPy does; it returns float64 arrays of the broadcast shape,
or a numpy.float64 (a subclass of float) when every argument is a scalar or 0-d. Immutable.)");
  DefineTension(model_class);
  DefineCurves(model_class);
  DefineModelProperties(model_class);
}

void BindLoadModel(py::module_& m) {
  m.def(
      "load_model",
      [](const py::object& given) {
        const std::string path = PathText(given, "load_model(path)");
        ModelSpec spec;
        {
          py::gil_scoped_release release;  // a block asking for a fit runs it here
          spec = LoadModelSpec(path);
        }
        return FromSpec(spec);
      },
      py::arg("path"),
      R"(The model of a YAML file: a model file (`name` and `model` only, as the CLI writes) or a
scenario, which is then checked whole (as `musclesim curves FILE` reads it). Raises the
reader's error (file:line:column, key, value, rule) for bad input.)");
}

void BindForceLengthPreset(py::module_& m) {
  m.def(
      "force_length_preset",
      [](const std::string& name, const py::object& x, double optimal_length) {
        ForceLengthPreset preset;
        try {
          preset = ParseForceLengthPreset(name);
        } catch (const ParameterError& e) {
          throw ParameterError("preset", e.value(), e.rule());  // the argument's name
        }
        Require(std::isfinite(optimal_length) && optimal_length > 0.0, "optimal_length",
                optimal_length, "must be finite and > 0 [m]");
        return Curve1(
            x, [&](double length) { return EvaluatePreset(preset, length / optimal_length); });
      },
      py::arg("preset"), py::arg("x"), py::arg("optimal_length") = 1.0,
      R"(A standard active force-length curve f_L [-] at lengths x [m], scaled so that its peak
is 1 at `optimal_length` [m] (default 1: x is then the normalised length l / L), as `musclesim
curves --preset NAME` tabulates it: preset degroote2016, thelen2003, gordon1966 or mujoco
(docs/guide/model.md, "Standard curves"). fit_gaussians(preset=...) fits Gaussians to it.)");
}

void BindFitGaussians(py::module_& m) {
  m.def("fit_gaussians", &Fit, py::arg("x") = py::none(), py::arg("f") = py::none(),
        py::arg("n") = 3, py::kw_only(), py::arg("target") = py::none(),
        py::arg("preset") = py::none(), py::arg("optimal_length") = 1.0,
        py::arg("optimal_range") = py::none(), py::arg("sigma") = 1.0,
        py::arg("nonnegative") = false, py::arg("widths") = py::none(),
        py::arg("centers") = py::none(),
        R"(Least-squares fit of n Gaussians (1..12) to a force-length target (docs/model.md
section 3.2; the `fit:` block of a model). Each component is
psi_k(x) = a_k / sqrt(2 pi sigma) exp(-b_k (x - d_k)^2 / (2 sigma)), the sum unnormalised.

Targets:
  fit_gaussians(x, f, n)                       samples (default with points): the cost is
      the sum over i of (sum_k psi_k(x_i) - f_i)^2 [-]; x in m, f on the f_L scale [-].
  fit_gaussians(x, f, n, target="polygon")     the piecewise-linear curve through (x, f),
      x strictly increasing, zero outside: the cost is the integral over the real line of
      the squared difference [m].
  fit_gaussians(n=..., target="indicator", optimal_range=(l1, l2))   1 on [l1, l2] [m],
      0 elsewhere; cost as for a polygon.
  fit_gaussians(n=..., preset=NAME, optimal_length=L)   a standard curve (degroote2016,
      thelen2003, gordon1966, mujoco) scaled to peak at L [m]; cost as for a polygon.
Amplitudes come from the linear solve (>= 0 with nonnegative=True); widths b_k (the YAML
key `width`, an inverse variance [1/m^2 when sigma = 1]) and centers d_k [m] from a
deterministic multi-start minimisation, unless both widths and centers are given (n values
each): then the shapes are fixed and only the amplitudes are solved.

Returns a dict: amplitudes, widths, centers (float64 arrays of n), gaussians (the list of
{amplitude, width, center} for a model block), cost (see above), relative_residual (cost
over the integral of target^2, or the sum of f_i^2 for samples), iterations (cost evaluations
of the best start; 0 with shapes fixed), starts (starting points tried). A bad argument
raises the library's ParameterError (a ValueError) naming it.)");
}

}  // namespace

void BindModel(py::module_& m) {
  BindModelClass(m);
  BindLoadModel(m);
  BindForceLengthPreset(m);
  BindFitGaussians(m);
}

}  // namespace musclesim::python
