#include "io/readers/model_yaml_node.h"

#include "io/readers/part_fields_yaml.h"
#include "io/readers/scenario_readers.h"
#include "musclesim/core/input_ranges.h"
#include "musclesim/model/family_fields.h"
#include "musclesim/model/fit_fields.h"

namespace musclesim {

namespace {

using yaml::Join;
using yaml::Required;

std::vector<TargetPoint> ReadPoints(const yaml::Source& src, const Document& node,
                                    const std::string& path) {
  if (!node.IsSequence()) {
    yaml::Fail(src, node, path, yaml::Describe(node), "must be a list of [x, y] pairs");
  }
  std::vector<TargetPoint> points;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string at = path + "[" + std::to_string(i) + "]";
    const std::vector<double> pair = yaml::ReadNumbers(src, node[i], at, 2);
    // x is a length, y a target value of about 1: bounded so the fit's integrals stay finite
    if (!kPositionRange.Contains(pair[0])) {
      yaml::Fail(src, node[i][0], at + "[0]", yaml::Describe(node[i][0]), kPositionRange.Rule());
    }
    if (!kFitValueRange.Contains(pair[1])) {
      yaml::Fail(src, node[i][1], at + "[1]", yaml::Describe(node[i][1]), kFitValueRange.Rule());
    }
    points.push_back({pair[0], pair[1]});
  }
  return points;
}

FitSpec ReadFitSpec(const yaml::Source& src, const Document& node, const std::string& path) {
  yaml::RequireMap(src, node, path, VariantKeys(FitBlock(), "fit"));
  FitSpec spec;
  ReadFields(src, node, path, FitBlock().front(), spec);
  if (node["points"]) spec.points = ReadPoints(src, node["points"], Join(path, "points"));
  if (node["widths"])
    spec.precisions = yaml::ReadNumbers(src, node["widths"], Join(path, "widths"));
  if (node["centers"]) {
    spec.centers = yaml::ReadNumbers(src, node["centers"], Join(path, "centers"));
    for (std::size_t k = 0; k < spec.centers.size(); ++k) {
      if (!kPositionRange.Contains(spec.centers[k])) {
        const Document& center = node["centers"][k];
        yaml::Fail(src, center, Join(path, "centers") + "[" + std::to_string(k) + "]",
                   yaml::Describe(center), kPositionRange.Rule());
      }
    }
  }
  const bool needs_points =
      spec.target == FitTargetKind::kPolygon || spec.target == FitTargetKind::kSamples;
  if (needs_points && spec.points.empty() && !node["points"]) {
    yaml::Fail(src, node, Join(path, "points"), "~",
               "target " + std::string(ToString(spec.target)) + " needs points");
  }
  yaml::ValidateAt(src, node, path, [&] { Validate(spec); });
  return spec;
}

// The paper's active_length block into `model`: its Gaussians listed, which ReadFields has
// read with its keys, sigma and L_opt, or fitted at load; whether they were fitted.
bool ReadActiveLength(const yaml::Source& src, const Document& active,
                      const std::string& active_path, ModelSpec& model) {
  ModelParams& p = model.params;
  const double range[2] = {p.active_length.optimal_min, p.active_length.optimal_max};
  const bool has_list = static_cast<bool>(active["gaussians"]);
  const bool has_fit = static_cast<bool>(active["fit"]);
  if (has_list == has_fit) {
    yaml::Fail(src, active, active_path, has_list ? "gaussians and fit" : "neither",
               "give exactly one of gaussians (explicit components) or fit (fitted at load)");
  }

  // the fit needs a valid range and sigma first: check the block without components
  ActiveLengthParams range_only = p.active_length;
  range_only.gaussians = {Gaussian{1.0, 1.0, 0.0}};
  yaml::ValidateAt(src, active, active_path, [&] { Validate(range_only); });

  if (!has_list) {
    const std::string fit_path = Join(active_path, "fit");
    model.fit = ReadFitSpec(src, active["fit"], fit_path);
    // a preset peaks at its optimal length: f_L, normalised over L_opt, follows it only if
    // that peak lies in L_opt
    if (const std::optional<double> l_opt = model.fit->optimal_length;
        model.fit->target == FitTargetKind::kPreset && l_opt &&
        !(*l_opt >= range[0] && *l_opt <= range[1])) {
      const Document& at = active["fit"]["optimal_length"];
      yaml::Fail(src, at, Join(fit_path, "optimal_length"), yaml::Describe(at),
                 "must lie within optimal_range [" + FormatNumber(range[0]) + ", " +
                     FormatNumber(range[1]) +
                     "]: the preset peaks there, and f_L is normalised by its maximum over "
                     "optimal_range");
    }
    yaml::ValidateAt(src, active["fit"], fit_path, [&] {
      model.fit_result = FitGaussians(*model.fit, p.active_length.optimal_min,
                                      p.active_length.optimal_max, p.active_length.sigma);
    });
    p.active_length.gaussians = model.fit_result->gaussians;
  }
  return has_fit;
}

}  // namespace

ModelSpec ReadModelSpec(const yaml::Source& src, const Document& node, const std::string& path) {
  if (node.IsMap() && node["family"]) {
    const Document& family = node["family"];
    const std::string text = yaml::ReadString(src, family, Join(path, "family"));
    const std::optional<CurveFamily> parsed = ParseCurveFamily(text);
    if (!parsed) {
      yaml::Fail(src, family, Join(path, "family"), yaml::Describe(family),
                 "must be paper, degroote2016 or mujoco (docs/model.md 14.1)");
    }
    if (*parsed != CurveFamily::kPaper) return ReadFamilyModelSpec(src, node, path, *parsed);
  }
  // the paper's block (model/family_fields.h): none of another family's keys
  const char* paper = ToString(CurveFamily::kPaper);
  std::vector<std::string> keys = VariantKeys(ModelFamilies(), paper);
  keys.emplace_back("family");
  yaml::RequireMap(src, node, path, keys);
  ModelSpec model;
  ModelParams& p = model.params;
  ReadFields(src, node, path, *SelectVariant(src, node, path, ModelFamilies(), paper), p);

  const std::string active_path = Join(path, "active_length");
  const Document& active = Required(src, node, path, "active_length");
  const bool has_fit = ReadActiveLength(src, active, active_path, model);

  // the model's constructor validates everything, including that f_L can be normalised
  try {
    TensionModel check(p);
  } catch (const ParameterError& error) {
    // components nobody wrote came from the fit: the message names the fit's target
    if (has_fit && error.path().rfind("active_length.gaussians", 0) == 0) {
      const Document& fit = active["fit"];
      const bool has_points = static_cast<bool>(fit["points"]);
      const std::string target_path = Join(active_path, has_points ? "fit.points" : "fit");
      yaml::Fail(
          src, has_points ? fit["points"] : fit, target_path,
          has_points ? std::to_string(fit["points"].size()) + " points" : yaml::Describe(fit),
          "the fit of this target gave " + error.path() + " = " + error.value() +
              " (rule: " + error.rule() + "); choose a target the Gaussians can follow");
    }
    yaml::Relocate(src, node, path, error);
  }
  return model;
}

namespace {

// A model file, or a scenario read whole: only `name` and `model` make a model file; any
// other key of the scenario vocabulary makes it a scenario, which must then be valid.
ModelSpec ReadModelFile(const yaml::Source& src, const Document& root) {
  yaml::RequireMap(src, root, "", kScenarioKeys);
  for (const std::string& key : root.keys()) {
    if (key != "model" && key != "name")
      return ReadActuatorScenario(src, root).models.at("model").spec;
  }
  return ReadModelSpec(src, Required(src, root, "", "model"), "model");
}

}  // namespace

ModelSpec LoadModelSpec(const std::string& path) {
  return ReadModelFile(yaml::Source{path}, yaml::LoadFile(path));
}

ModelSpec LoadModelFit(const std::string& path) {
  const Document& root = yaml::LoadFile(path);
  const yaml::Source src{path};
  ModelSpec model = ReadModelFile(src, root);
  if (model.params.family != CurveFamily::kPaper) {
    const Document& family = root["model"]["family"];
    yaml::Fail(src, family, "model.family", yaml::Describe(family),
               "has its own curves and no Gaussians to fit: `musclesim fit` fits the paper's "
               "model (family paper)");
  }
  if (!model.fit_result) {
    const Document& gaussians = root["model"]["active_length"]["gaussians"];
    yaml::Fail(src, gaussians, "model.active_length.gaussians",
               std::to_string(gaussians.size()) + " components",
               "explicit components leave nothing to fit: give model.active_length.fit instead "
               "(README \"The closed-form fit\")");
  }
  return model;
}

}  // namespace musclesim
