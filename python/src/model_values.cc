#include "model_values.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace musclesim::python {

py::dict GaussianDict(const Gaussian& g) {
  return py::dict(py::arg("amplitude") = g.amplitude, py::arg("width") = g.precision,
                  py::arg("center") = g.center);
}

namespace {

// A family's block (docs/model.md 14.1): its own keys, as the `model:` block has them.
py::dict FamilyDict(const ModelParams& p) {
  py::dict out(py::arg("family") = ToString(p.family), py::arg("f_iso") = p.f_iso);
  if (p.family == CurveFamily::kDeGroote2016) {
    const DeGrooteParams& d = p.degroote2016;
    out["optimal_fiber_length"] = d.optimal_fiber_length;
    out["max_contraction_velocity"] = d.max_contraction_velocity;
    out["active_force_width_scale"] = d.active_force_width_scale;
    out["passive_fiber_strain_at_one_norm_force"] = d.passive_fiber_strain_at_one_norm_force;
    out["fiber_damping"] = d.fiber_damping;
  } else {
    const MujocoMuscleParams& m = p.mujoco;
    out["range"] = py::make_tuple(m.range[0], m.range[1]);
    out["lengthrange"] = py::make_tuple(m.lengthrange[0], m.lengthrange[1]);
    out["lmin"] = m.lmin;
    out["lmax"] = m.lmax;
    out["vmax"] = m.vmax;
    out["fpmax"] = m.fpmax;
    out["fvmax"] = m.fvmax;
  }
  if (p.pennation_angle != 0.0) out["pennation_angle"] = p.pennation_angle;
  return out;
}

}  // namespace

py::dict ParamsDict(const ModelParams& p) {
  if (p.family != CurveFamily::kPaper) return FamilyDict(p);
  py::list gaussians;
  for (const Gaussian& g : p.active_length.gaussians) gaussians.append(GaussianDict(g));
  py::dict velocity(py::arg("v_max") = p.velocity.v_max, py::arg("n") = p.velocity.n,
                    py::arg("epsilon") = p.velocity.epsilon);
  const EccentricParams& e = p.velocity.eccentric;
  if (e.v_max || e.n || e.limit) {
    py::dict eccentric;
    if (e.v_max) eccentric["v_max"] = *e.v_max;
    if (e.n) eccentric["n"] = *e.n;
    if (e.limit) eccentric["limit"] = *e.limit;
    velocity["eccentric"] = eccentric;
  }
  py::dict out(py::arg("f_iso") = p.f_iso,
               py::arg("passive") =
                   py::dict(py::arg("k_p") = p.passive.k_p, py::arg("alpha") = p.passive.alpha,
                            py::arg("slack_length") = p.passive.slack_length),
               py::arg("active_length") = py::dict(
                   py::arg("optimal_range") =
                       py::make_tuple(p.active_length.optimal_min, p.active_length.optimal_max),
                   py::arg("sigma") = p.active_length.sigma, py::arg("gaussians") = gaussians),
               py::arg("velocity") = velocity);
  if (p.pennation_angle != 0.0) out["pennation_angle"] = p.pennation_angle;
  return out;
}

}  // namespace musclesim::python
