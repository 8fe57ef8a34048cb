#include "model_values.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace musclesim::python {

py::dict GaussianDict(const Gaussian& g) {
  return py::dict(py::arg("amplitude") = g.amplitude, py::arg("width") = g.precision,
                  py::arg("center") = g.center);
}

py::dict ParamsDict(const ModelParams& p) {
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
  return py::dict(py::arg("f_iso") = p.f_iso,
                  py::arg("passive") =
                      py::dict(py::arg("k_p") = p.passive.k_p, py::arg("alpha") = p.passive.alpha,
                               py::arg("slack_length") = p.passive.slack_length),
                  py::arg("active_length") = py::dict(
                      py::arg("optimal_range") =
                          py::make_tuple(p.active_length.optimal_min, p.active_length.optimal_max),
                      py::arg("sigma") = p.active_length.sigma, py::arg("gaussians") = gaussians),
                  py::arg("velocity") = velocity);
}

}  // namespace musclesim::python
