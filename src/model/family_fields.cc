#include "musclesim/model/family_fields.h"

#include <utility>

#include "musclesim/model/tension_parameter.h"

namespace musclesim {

namespace {

using Field = NumberField<ModelParams>;

// A normalised quantity's range [-]: 1e3 is far beyond any muscle's curve.
constexpr InputRange Normalised(double min, bool min_exclusive, const char* why) {
  return {min, 1e3, "-", why, min_exclusive};
}

// f_iso and the pennation angle, every family's.
std::vector<Field> Common() {
  Field pennation =
      MemberField("pennation_angle", &ModelParams::pennation_angle, InputRange{0.0, 0.0, "rad", ""},
                  0.0, "at the optimal fiber length, >= 0 and below pi/2");
  pennation.values = FieldValues::kFinite;
  return {MemberField("f_iso", &ModelParams::f_iso, kPositiveForceRange, std::nullopt,
                      "the maximum isometric force"),
          std::move(pennation)};
}

// A field of a family's own block `block` (ModelParams::degroote2016, ::mujoco): its member
// `member`.
template <typename Block>
Field Own(const char* key, Block ModelParams::*block, double Block::*member,
          const InputRange& range, std::optional<double> fallback, const char* doc) {
  return {key,
          range,
          fallback,
          doc,
          [block, member](const ModelParams& p) { return p.*block.*member; },
          [block, member](ModelParams& p, double v) { p.*block.*member = v; }};
}

Field DeGroote(const char* key, double DeGrooteParams::*member, const InputRange& range,
               std::optional<double> fallback, const char* doc) {
  return Own(key, &ModelParams::degroote2016, member, range, fallback, doc);
}

Field Mujoco(const char* key, double MujocoMuscleParams::*member, const InputRange& range,
             double fallback, const char* doc) {
  return Own(key, &ModelParams::mujoco, member, range, fallback, doc);
}

ModelFamily Family(CurveFamily family, const char* law, std::vector<Field> own) {
  ModelFamily variant;
  variant.type = ToString(family);
  variant.name = variant.type;
  variant.law = law;
  variant.fields = Common();
  for (Field& field : own) variant.fields.push_back(std::move(field));
  variant.is = [family](const ModelParams& p) { return p.family == family; };
  variant.make = [family](ModelParams& p) { p.family = family; };
  return variant;
}

// A number of a Gaussian: finite, its rules (a width > 0) the model's own.
NumberField<Gaussian> GaussianNumber(const char* key, double Gaussian::*member, const char* unit,
                                     const char* doc, TensionParameterKind kind) {
  NumberField<Gaussian> field = MemberField(key, member, InputRange{0.0, 0.0, unit, ""},
                                            std::nullopt, doc, static_cast<int>(kind));
  field.values = FieldValues::kFinite;
  return field;
}

// An end of L_opt [m], finite: that it is a range of positive lengths is the model's rule.
Field OptimalEnd(std::size_t end, const char* doc, TensionParameterKind kind) {
  Field field{std::string("active_length.optimal_range[") + std::to_string(end) + "]",
              InputRange{0.0, 0.0, "m", ""},
              std::nullopt,
              doc,
              [end](const ModelParams& p) {
                return end == 0 ? p.active_length.optimal_min : p.active_length.optimal_max;
              },
              [end](ModelParams& p, double v) {
                (end == 0 ? p.active_length.optimal_min : p.active_length.optimal_max) = v;
              },
              static_cast<int>(kind),
              FieldValues::kFinite};
  return field;
}

// The paper's Gaussians (docs/model.md 3): listed, or fitted at load when `fit` is given
// instead (which its reader handles, with the rule that exactly one of them is).
ListField<ModelParams> Gaussians() {
  ListField<ModelParams> list = ItemList<ModelParams, Gaussian>(
      "active_length.gaussians", "a Gaussian",
      "the components a_k, b_k, d_k of f_L; or `fit` instead, fitted at load",
      [](auto& p) -> auto& { return p.active_length.gaussians; }, GaussianFields());
  list.required = false;
  return list;
}

// The paper's block (docs/model.md 2-5, 9): its passive and velocity curves described where
// they are defined (model/passive.h, model/velocity.h), active_length's sigma, L_opt and
// Gaussians; a fit in their place is its reader's own.
ModelFamily Paper() {
  // in the order of the block's keys in files: f_iso, passive, active_length, velocity
  std::vector<Field> common = Common();
  std::vector<Field> fields{common.front()};
  fields.front().partial = static_cast<int>(TensionParameterKind::kIsometricTension);
  for (Field& field : NestedFields("passive", &ModelParams::passive, PassiveBlock().fields)) {
    fields.push_back(std::move(field));
  }
  fields.push_back({"active_length.sigma", InputRange{0.0, 0.0, "-", ""},
                    ActiveLengthParams{}.sigma,
                    "the common scale of the widths, > 0: only width / sigma shapes the curve",
                    [](const ModelParams& p) { return p.active_length.sigma; },
                    [](ModelParams& p, double v) { p.active_length.sigma = v; },
                    static_cast<int>(TensionParameterKind::kSigma), FieldValues::kFinite});
  fields.push_back(OptimalEnd(0, "l1, where L_opt, the range f_L is normalised over, begins",
                              TensionParameterKind::kOptimalMin));
  fields.push_back(OptimalEnd(1, "l2, where it ends, > l1 > 0", TensionParameterKind::kOptimalMax));
  for (Field& field : NestedFields("velocity", &ModelParams::velocity, VelocityBlock().fields)) {
    fields.push_back(std::move(field));
  }
  fields.push_back(common.back());
  ModelFamily family =
      Family(CurveFamily::kPaper, "T = T_p(x) + u f_iso f_L(x) g_eps(v) (docs/model.md 1-5)", {});
  family.fields = std::move(fields);
  family.lists = {Gaussians()};
  family.other_keys = {"active_length.fit"};
  return family;
}

ModelFamily DeGroote2016() {
  const DeGrooteParams d;  // OpenSim's defaults
  return Family(CurveFamily::kDeGroote2016,
                "OpenSim's DeGrooteFregly2016Muscle: its active, passive and force-velocity curves",
                {DeGroote("optimal_fiber_length", &DeGrooteParams::optimal_fiber_length,
                          kLengthRange, std::nullopt, "l_opt, where the active force peaks"),
                 DeGroote("max_contraction_velocity", &DeGrooteParams::max_contraction_velocity,
                          InputRange{0.0, 1e6, "l_opt/s", "faster than any muscle by far", true},
                          d.max_contraction_velocity, "the shortening speed of zero active force"),
                 DeGroote("active_force_width_scale", &DeGrooteParams::active_force_width_scale,
                          Normalised(1.0, false, "OpenSim's rule: the curve only widens"),
                          d.active_force_width_scale, "w, the active curve's widening"),
                 DeGroote("passive_fiber_strain_at_one_norm_force",
                          &DeGrooteParams::passive_fiber_strain_at_one_norm_force,
                          Normalised(0.0, true, "a strain, far beyond any fiber's"),
                          d.passive_fiber_strain_at_one_norm_force, "e0, the fiber's strain at F0"),
                 DeGroote("fiber_damping", &DeGrooteParams::fiber_damping,
                          Normalised(0.0, false, "OpenSim's default 0, its suggestion 0.01"),
                          d.fiber_damping, "beta: F0 beta v~ beside the curves")});
}

ModelFamily MuJoCo() {
  const MujocoMuscleParams m;  // MuJoCo's defaults
  ModelFamily family = Family(
      CurveFamily::kMujoco, "MuJoCo's muscle: its piecewise-quadratic curves (mju_muscleGain)",
      {[&] {
         Field lmin = Mujoco("lmin", &MujocoMuscleParams::lmin, InputRange{0.0, 0.0, "-", ""},
                             m.lmin, "where the active curve vanishes below 1, in [0, 1)");
         lmin.values = FieldValues::kFinite;
         return lmin;
       }(),
       Mujoco("lmax", &MujocoMuscleParams::lmax,
              Normalised(1.0, true, "the active curve peaks at 1"), m.lmax,
              "where it vanishes above 1"),
       Mujoco("vmax", &MujocoMuscleParams::vmax,
              InputRange{0.0, 1e6, "L0/s", "faster than any muscle by far", true}, m.vmax,
              "the shortening speed of zero force"),
       Mujoco("fpmax", &MujocoMuscleParams::fpmax,
              Normalised(0.0, false, "far beyond any muscle's passive force"), m.fpmax,
              "the passive force at lmax, over F0"),
       Mujoco("fvmax", &MujocoMuscleParams::fvmax,
              Normalised(1.0, true, "the lengthening branch rises from 1 to fvmax"), m.fvmax,
              "the lengthening force, over F0")});
  // lists of two, each pair's order the model's rule
  const auto end = [](const char* list, std::size_t i, double(MujocoMuscleParams::*pair)[2],
                      const InputRange& range, std::optional<double> fallback, const char* doc) {
    return Field{std::string(list) + "[" + std::to_string(i) + "]",
                 range,
                 fallback,
                 doc,
                 [pair, i](const ModelParams& p) { return (p.mujoco.*pair)[i]; },
                 [pair, i](ModelParams& p, double v) { (p.mujoco.*pair)[i] = v; }};
  };
  const InputRange normalised{0.0, 1e3, "-", "a length over the optimal one", true};
  family.fields.push_back(end("range", 0, &MujocoMuscleParams::range, normalised, m.range[0],
                              "the normalised length at lengthrange[0]"));
  family.fields.push_back(end("range", 1, &MujocoMuscleParams::range, normalised, m.range[1],
                              "the normalised length at lengthrange[1], > range[0]"));
  family.fields.push_back(end("lengthrange", 0, &MujocoMuscleParams::lengthrange, kPositionRange,
                              std::nullopt, "the shortest actuator length MuJoCo scales by"));
  family.fields.push_back(end("lengthrange", 1, &MujocoMuscleParams::lengthrange, kPositionRange,
                              std::nullopt, "the longest, > lengthrange[0]"));
  return family;
}

}  // namespace

const std::vector<NumberField<Gaussian>>& GaussianFields() {
  using Kind = TensionParameterKind;
  static const std::vector<NumberField<Gaussian>> fields{
      GaussianNumber("amplitude", &Gaussian::amplitude, "-", "a_k, finite, may be negative",
                     Kind::kAmplitude),
      GaussianNumber(
          "width", &Gaussian::precision, "1/m^2",
          "b_k, > 0, the inverse-variance factor (its unit for sigma 1): larger is narrower",
          Kind::kWidth),
      GaussianNumber("center", &Gaussian::center, "m", "d_k, where the component peaks",
                     Kind::kCenter)};
  return fields;
}

const std::vector<ModelFamily>& ModelFamilies() {
  static const std::vector<ModelFamily> families{Paper(), DeGroote2016(), MuJoCo()};
  return families;
}

}  // namespace musclesim
