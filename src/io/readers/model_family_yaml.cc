// The model block of a curve family other than the paper's (docs/model.md 14.1): its keys are
// the peer's own names, OpenSim's properties or MuJoCo's attributes.
#include <cmath>
#include <initializer_list>
#include <utility>

#include "io/readers/model_yaml_node.h"
#include "musclesim/core/input_ranges.h"

namespace musclesim {

namespace {

using yaml::Join;
using yaml::Required;

// Each of `fields` whose key `node` holds takes its value; an absent one keeps its default.
void ReadOptionalNumbers(const yaml::Source& src, const Document& node, const std::string& path,
                         std::initializer_list<std::pair<const char*, double*>> fields) {
  for (const auto& [key, value] : fields) {
    *value = yaml::ReadOptionalNumber(src, node, path, key, *value);
  }
}

void ReadDeGroote(const yaml::Source& src, const Document& node, const std::string& path,
                  DeGrooteParams& p) {
  p.optimal_fiber_length = yaml::ReadNumber(src, Required(src, node, path, "optimal_fiber_length"),
                                            Join(path, "optimal_fiber_length"));
  ReadOptionalNumbers(
      src, node, path,
      {{"max_contraction_velocity", &p.max_contraction_velocity},
       {"active_force_width_scale", &p.active_force_width_scale},
       {"passive_fiber_strain_at_one_norm_force", &p.passive_fiber_strain_at_one_norm_force},
       {"fiber_damping", &p.fiber_damping}});
}

void ReadMujoco(const yaml::Source& src, const Document& node, const std::string& path,
                MujocoMuscleParams& p) {
  const std::vector<double> lengthrange = yaml::ReadNumbers(
      src, Required(src, node, path, "lengthrange"), Join(path, "lengthrange"), 2);
  p.lengthrange[0] = lengthrange[0];
  p.lengthrange[1] = lengthrange[1];
  if (node["range"]) {
    const std::vector<double> range = yaml::ReadNumbers(src, node["range"], Join(path, "range"), 2);
    p.range[0] = range[0];
    p.range[1] = range[1];
  }
  ReadOptionalNumbers(src, node, path,
                      {{"lmin", &p.lmin},
                       {"lmax", &p.lmax},
                       {"vmax", &p.vmax},
                       {"fpmax", &p.fpmax},
                       {"fvmax", &p.fvmax}});
}

}  // namespace

ModelSpec ReadFamilyModelSpec(const yaml::Source& src, const Document& node,
                              const std::string& path, CurveFamily family) {
  ModelSpec model;
  ModelParams& p = model.params;
  p.family = family;
  if (family == CurveFamily::kDeGroote2016) {
    yaml::RequireMap(
        src, node, path,
        {"family", "f_iso", "pennation_angle", "optimal_fiber_length", "max_contraction_velocity",
         "active_force_width_scale", "passive_fiber_strain_at_one_norm_force", "fiber_damping"});
    ReadDeGroote(src, node, path, p.degroote2016);
  } else {
    yaml::RequireMap(src, node, path,
                     {"family", "f_iso", "pennation_angle", "range", "lengthrange", "lmin", "lmax",
                      "vmax", "fpmax", "fvmax"});
    ReadMujoco(src, node, path, p.mujoco);
  }
  p.f_iso = yaml::ReadNumber(src, Required(src, node, path, "f_iso"), Join(path, "f_iso"));
  p.pennation_angle = yaml::ReadOptionalNumber(src, node, path, "pennation_angle", 0.0);
  try {
    TensionModel check(p);
  } catch (const ParameterError& error) {
    yaml::Relocate(src, node, path, error);
  }
  return model;
}

}  // namespace musclesim
