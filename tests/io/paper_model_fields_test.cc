// The paper's model block as its description (model/family_fields.h) states it, through the
// reader of a model file: each ranged field, nested ones included, refused just past each
// bound with its rule at its key path and not refused at its bounds; an integer field refused
// at a fraction; an optional one left out, and a defaulted one taking its default.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/io/writers/flow_fields.h"
#include "musclesim/io/readers/model_text.h"
#include "musclesim/model/family_fields.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// A valid paper model, key path by key path.
using Keys = std::vector<std::pair<std::string, std::string>>;
Keys Base() {
  return {{"f_iso", "100"},
          {"passive.k_p", "2"},
          {"passive.alpha", "30"},
          {"passive.slack_length", "0.105"},
          {"active_length.optimal_range", "[0.095, 0.105]"},
          {"active_length.gaussians", "[{amplitude: 0.05, width: 90, center: 0.097}]"},
          {"velocity.v_max", "0.5"},
          {"velocity.n", "3"},
          {"velocity.epsilon", "0.001"}};
}

// `keys` as a YAML flow map, the keys below a common head in its own map, in order.
std::string Flow(const Keys& keys) {
  std::vector<std::string> heads;
  for (const auto& [key, value] : keys) {
    const std::string head = key.substr(0, key.find('.'));
    bool seen = false;
    for (const std::string& h : heads) seen = seen || h == head;
    if (!seen) heads.push_back(head);
  }
  std::string text = "{";
  for (const std::string& head : heads) {
    Keys below;
    std::string value;
    for (const auto& [key, v] : keys) {
      if (key == head) value = v;
      if (key.rfind(head + ".", 0) == 0) below.emplace_back(key.substr(head.size() + 1), v);
    }
    text += (text.size() > 1 ? ", " : "") + head + ": " + (below.empty() ? value : Flow(below));
  }
  return text + "}";
}

// The message of reading the base model with `key` at `value`, or "(read)".
std::string Error(const std::string& key, const std::string& value) {
  Keys keys = Base();
  bool replaced = false;
  for (auto& [k, v] : keys) {
    if (k == key) v = value, replaced = true;
  }
  if (!replaced) keys.emplace_back(key, value);
  try {
    ParseModelSpec("model.yaml", Flow(keys) + "\n");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read)";
}

const ModelFamily& Paper() { return ModelFamilies().front(); }

TEST(PaperModelFields, TheBaseModelIsRead) {
  ASSERT_EQ(std::string(Paper().type), "paper");
  EXPECT_EQ(Error("f_iso", "100"), "(read)");
}

TEST(PaperModelFields, EachBoundIsTheReadersAtItsKeyPath) {
  int checked = 0;
  for (const NumberField<ModelParams>& field : Paper().fields) {
    if (field.values != FieldValues::kRange) continue;
    SCOPED_TRACE(field.key);
    const std::string at = "model." + field.key + " = ";
    const double below = field.range.min_exclusive ? field.range.min : field.range.min - 1.0;
    for (const double bad : {field.range.max * 2.0, below}) {
      const std::string message = Error(field.key, FormatNumber(bad));
      EXPECT_THAT(message, HasSubstr(at + FormatNumber(bad) + " (model.yaml:"));
      EXPECT_THAT(message, HasSubstr(FieldRule(field)));
    }
    // the bounds themselves pass the range (a rule between fields may still refuse them)
    for (const double edge : {field.range.max, field.range.min}) {
      if (edge == field.range.min && field.range.min_exclusive) continue;
      EXPECT_THAT(Error(field.key, FormatNumber(edge)), Not(HasSubstr(FieldRule(field))));
    }
    if (field.integer) {
      const std::string message = Error(field.key, "2.5");
      EXPECT_THAT(message, HasSubstr(at + "2.5"));
      EXPECT_THAT(message, HasSubstr("must be an integer from 1 to 1000"));
    }
    ++checked;
  }
  // f_iso; k_p, alpha, slack_length; v_max, n, eccentric v_max, n, limit
  EXPECT_EQ(checked, 9);
}

TEST(PaperModelFields, OptionalAndDefaultedFieldsMayBeLeftOut) {
  const ModelSpec model = ParseModelSpec("model.yaml", Flow(Base()) + "\n");
  const VelocityParams& v = model.params.velocity;
  EXPECT_FALSE(v.eccentric.v_max || v.eccentric.n || v.eccentric.limit);
  EXPECT_EQ(model.params.active_length.sigma, 1.0);
  EXPECT_EQ(model.params.pennation_angle, 0.0);
  // a handle's value of a left-out eccentric key: the concentric one's, as the curve uses
  const NumberField<ModelParams>* n = FindField(Paper(), "velocity.eccentric.n");
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->get(model.params), 3.0);
  EXPECT_FALSE(n->given(model.params));
  // given, it is the part's own
  Keys keys = Base();
  keys.emplace_back("velocity.eccentric.n", "2");
  const ModelSpec eccentric = ParseModelSpec("model.yaml", Flow(keys) + "\n");
  EXPECT_EQ(eccentric.params.velocity.eccentric.n, 2);
}

TEST(PaperModelFields, ANestedMapHoldsOnlyItsKeys) {
  EXPECT_THAT(Error("velocity.eccentric.lim", "1.5"),
              HasSubstr("model.velocity.eccentric.lim (model.yaml:1:"));
  EXPECT_THAT(Error("velocity.eccentric.lim", "1.5"),
              HasSubstr("unknown key; allowed here: v_max, n, limit"));
  EXPECT_THAT(Error("active_length.sigmas", "1"),
              HasSubstr("allowed here: sigma, optimal_range, gaussians, fit"));
}

// The Gaussians, a list of sub-parts: each item's numbers read into its own component (the
// file's width is b_k, Gaussian::precision), the item map holding only their keys, the list
// not empty; L_opt a list of exactly two numbers.
TEST(PaperModelFields, EachGaussianIsReadIntoItsComponent) {
  Keys keys = Base();
  keys[5].second =
      "[{amplitude: 0.05, width: 90, center: 0.097}, {amplitude: -0.01, width: 40, center: 0.1}]";
  const ModelSpec model = ParseModelSpec("model.yaml", Flow(keys) + "\n");
  const std::vector<Gaussian>& g = model.params.active_length.gaussians;
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].amplitude, 0.05);
  EXPECT_EQ(g[0].precision, 90.0);
  EXPECT_EQ(g[0].center, 0.097);
  EXPECT_EQ(g[1].amplitude, -0.01);
  EXPECT_EQ(g[1].precision, 40.0);
  EXPECT_EQ(g[1].center, 0.1);
  EXPECT_EQ(model.params.active_length.optimal_min, 0.095);
  EXPECT_EQ(model.params.active_length.optimal_max, 0.105);

  const std::string misspelt = Error("active_length.gaussians",
                                     "[{amplitude: 0.05, width: 90, center: 0.097}, "
                                     "{amplitude: 0.05, widht: 90, center: 0.097}]");
  EXPECT_THAT(misspelt, HasSubstr("model.active_length.gaussians[1].widht (model.yaml:1:"));
  EXPECT_THAT(misspelt, HasSubstr("allowed here: amplitude, width, center"));
  EXPECT_THAT(Error("active_length.gaussians", "[{amplitude: 0.05, center: 0.097}]"),
              HasSubstr("model.active_length.gaussians[0].width"));
  EXPECT_THAT(Error("active_length.gaussians", "[]"),
              HasSubstr("must be a non-empty list of {amplitude, width, center}"));
  const std::string one_end = Error("active_length.optimal_range", "[0.095]");
  EXPECT_THAT(one_end, HasSubstr("model.active_length.optimal_range = "));
  EXPECT_THAT(one_end, HasSubstr("2"));
}

// A block written by its description reads back as the same numbers: MuJoCo's lists of two
// as lists, the nested maps as maps.
TEST(PaperModelFields, AFamilysFieldsWrittenReadBack) {
  const ModelFamily& mujoco =
      *std::find_if(ModelFamilies().begin(), ModelFamilies().end(),
                    [](const ModelFamily& f) { return std::string_view(f.type) == "mujoco"; });
  const ModelSpec given = ParseModelSpec(
      "model.yaml",
      "{family: mujoco, f_iso: 100, lmax: 1.5, range: [0.7, 1.1], lengthrange: [0.1, 0.3]}\n");
  const std::string text = FlowFields(mujoco, given.params);
  EXPECT_THAT(text, HasSubstr("range: [0.7, 1.1], lengthrange: [0.1, 0.3]"));
  const ModelSpec back = ParseModelSpec("model.yaml", "{family: mujoco, " + text + "}\n");
  for (const NumberField<ModelParams>& field : mujoco.fields) {
    EXPECT_EQ(field.get(back.params), field.get(given.params)) << field.key;
  }
  const std::string paper = FlowFields(Paper(), ParseModelSpec("m.yaml", Flow(Base())).params);
  EXPECT_THAT(paper, HasSubstr("active_length: {sigma: 1, optimal_range: [0.095, 0.105]}"));
}

}  // namespace
}  // namespace musclesim
