// The model block of a curve family other than the paper's (docs/model.md 14.1): its keys are
// the peer's own names, OpenSim's properties or MuJoCo's attributes.
#include <cmath>
#include <string>
#include <vector>

#include "io/readers/model_yaml_node.h"
#include "io/readers/part_fields_yaml.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/model/family_fields.h"

namespace musclesim {

namespace {

using yaml::Join;
using yaml::Required;

// MuJoCo's lists of two, `lengthrange` required and `range` optional.
void ReadMujocoLists(const yaml::Source& src, const Document& node, const std::string& path,
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
}

}  // namespace

ModelSpec ReadFamilyModelSpec(const yaml::Source& src, const Document& node,
                              const std::string& path, CurveFamily family) {
  ModelSpec model;
  ModelParams& p = model.params;
  // its keys and fields (model/family_fields.h)
  const ModelFamily& described = *SelectVariant(src, node, path, ModelFamilies(), ToString(family));
  std::vector<std::string> keys{"family"};
  for (std::string& key : VariantKeys(ModelFamilies(), described.type))
    keys.push_back(std::move(key));
  yaml::RequireMap(src, node, path, keys);
  described.make(p);
  ReadFields(src, node, path, described, p);
  if (family == CurveFamily::kMujoco) ReadMujocoLists(src, node, path, p.mujoco);
  try {
    TensionModel check(p);
  } catch (const ParameterError& error) {
    yaml::Relocate(src, node, path, error);
  }
  return model;
}

}  // namespace musclesim
