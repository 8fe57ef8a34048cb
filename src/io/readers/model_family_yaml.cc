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
  try {
    TensionModel check(p);
  } catch (const ParameterError& error) {
    yaml::Relocate(src, node, path, error);
  }
  return model;
}

}  // namespace musclesim
