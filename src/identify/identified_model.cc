// The `model:` block of `musclesim identify` from the curves' identifications.
#include "musclesim/identify/identified_model.h"

#include <cmath>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/identify/identify_report.h"

namespace musclesim {

namespace {

// Runs `check` of a drafted block; its ParameterError re-thrown at the key path in the
// model file ("model.velocity.v_max"): the data gave a value the model cannot take.
template <typename Check>
void WithPath(const char* block, Check check) {
  try {
    check();
  } catch (const ParameterError& e) {
    throw ParameterError("model." + std::string(block) + "." + e.path(), e.value(),
                         e.rule() + " (the value the data give: no model file is written)");
  }
}

// "value +- standard error", or "+- n/a" when the error cannot be estimated.
std::string PlusMinus(const Estimate& e) {
  return FormatNumber(e.value) + " +- " +
         (std::isfinite(e.standard_error) ? FormatNumber(e.standard_error) : "n/a");
}

ModelYamlPart<double> DraftFIso(const std::optional<ActiveIdentification>& active,
                                const std::optional<VelocityIdentification>& velocity) {
  ModelYamlPart<double> f_iso;
  if (active) {
    f_iso = {active->f_iso.value,
             {"N, " + PlusMinus(active->f_iso) + ", the active curve's maximum"}};
  } else if (velocity) {
    f_iso = {velocity->best.f_iso.value,
             {"N, " + PlusMinus(velocity->best.f_iso) + ", from the tension-velocity curve"}};
  } else {
    f_iso.comments = {"not identified (no active or velocity data)"};
  }
  return f_iso;
}

ModelYamlPart<PassiveParams> DraftPassive(const std::optional<PassiveIdentification>& passive) {
  ModelYamlPart<PassiveParams> part;
  if (passive) {
    part.params =
        PassiveParams{passive->k_p.value, passive->alpha.value, passive->slack_length.value};
    WithPath("passive", [&] { Validate(*part.params); });  // a file the model can read back
    part.comments = {"k_p = " + PlusMinus(passive->k_p) +
                     " N, alpha = " + PlusMinus(passive->alpha) +
                     " 1/m, slack_length = " + PlusMinus(passive->slack_length) + " m; RMSE " +
                     FormatNumber(passive->rmse) + " N"};
    for (const std::string& note : PassiveUncertaintyNotes(*passive, FormatNumber)) {
      part.comments.push_back(note);
    }
  } else {
    part.comments = {"not identified: no passive tension"};
  }
  return part;
}

// The active_length part and its comment per Gaussian.
void DraftActiveLength(const std::optional<ActiveIdentification>& active, ModelYamlDraft& draft) {
  if (active) {
    draft.active_length.params = active->curve;
    draft.active_length.comments = {
        "optimal_range: where the fitted curve is within 2% of its maximum; RMSE " +
        FormatNumber(active->rmse) + " N"};
    for (std::size_t k = 0; k < active->curve.gaussians.size(); ++k) {
      draft.gaussian_comments.push_back("amplitude " + PlusMinus(active->amplitudes[k]) +
                                        ", width " + PlusMinus(active->precisions[k]) +
                                        ", center " + PlusMinus(active->centers[k]));
    }
  } else {
    draft.active_length.comments = {"not identified: one Gaussian a kilometre wide, a flat f_L"};
  }
}

// "`heading` n=1 RMSE ...; n=3 no fit;": the candidates other than the best exponent.
template <typename Candidate>
std::string OtherExponents(std::string heading, const std::vector<Candidate>& candidates,
                           int best_n) {
  for (const Candidate& c : candidates) {
    if (c.n == best_n) continue;
    heading += " n=" + std::to_string(c.n) + " " +
               (c.valid ? "RMSE " + FormatNumber(c.rmse) : "no fit") + ";";
  }
  return heading;
}

// The velocity part as it is being drafted: its parameters, and what its comments say of
// epsilon and of the eccentric branch.
struct VelocityDraft {
  VelocityParams params;
  std::string epsilon_rule = "1e-3 v_max";
  std::vector<std::string> eccentric_comments;
};

// The identified eccentric branch put in; epsilon kept below the smaller v_max.
void DraftEccentric(const EccentricIdentification& e, double concentric_v_max, VelocityDraft& v) {
  v.params.eccentric = {e.best.v_max.value, e.best.n, std::nullopt};
  if (e.limit_identified) v.params.eccentric.limit = e.best.limit.value;
  // eps must not exceed either v_max (the model's rule)
  if (e.best.v_max.value < concentric_v_max) {
    v.params.epsilon = StandInEpsilon(e.best.v_max.value);
    v.epsilon_rule = "1e-3 times the eccentric v_max, the smaller";
  }
  v.eccentric_comments.push_back(
      OtherExponents("other eccentric n:", e.limit_identified ? e.bounded : e.unbounded, e.best.n));
}

ModelYamlPart<VelocityParams> DraftVelocity(const VelocityIdentification& velocity) {
  const VelocityCandidate& best = velocity.best;
  VelocityDraft v;
  v.params = {best.v_max.value, best.n, StandInEpsilon(best.v_max.value)};
  // the concentric curve must be one the model takes (a curve flatter than any v_max within
  // range is refused here, not written as a file that cannot be read); only then may a
  // refusal below blame the eccentric branch
  WithPath("velocity", [&] {
    Validate(VelocityParams{v.params.v_max, v.params.n, v.params.epsilon});
  });
  const std::string others = OtherExponents("other n:", velocity.candidates, best.n);
  if (velocity.eccentric) {
    const EccentricIdentification& e = *velocity.eccentric;
    v.eccentric_comments = DescribeEccentric(e);
    if (e.identified) DraftEccentric(e, best.v_max.value, v);
  }
  try {
    Validate(v.params);  // extreme eccentric estimates may break the model's rules: say so
  } catch (const ParameterError& error) {
    v.params.eccentric = {};
    v.params.epsilon = StandInEpsilon(best.v_max.value);
    v.epsilon_rule = "1e-3 v_max";
    v.eccentric_comments.push_back("eccentric branch left out: it gives velocity." + error.path() +
                                   " = " + error.value() + ", which " + error.rule());
  }
  ModelYamlPart<VelocityParams> part;
  part.params = v.params;
  part.comments = {"v_max = " + PlusMinus(best.v_max) + " m/s, RMSE " + FormatNumber(best.rmse) +
                       " N; epsilon is not identified (" + v.epsilon_rule + ")",
                   others};
  part.comments.insert(part.comments.end(), v.eccentric_comments.begin(),
                       v.eccentric_comments.end());
  return part;
}

}  // namespace

ModelYamlDraft DraftIdentifiedModel(const std::string& source,
                                    const std::optional<PassiveIdentification>& passive,
                                    const std::optional<ActiveIdentification>& active,
                                    const std::optional<VelocityIdentification>& velocity) {
  ModelYamlDraft draft;
  draft.header = {"identified by musclesim identify from " + source,
                  "(+- standard errors from the Jacobian at the optimum)"};
  draft.f_iso = DraftFIso(active, velocity);
  draft.passive = DraftPassive(passive);
  DraftActiveLength(active, draft);
  if (velocity) {
    draft.velocity = DraftVelocity(*velocity);
  } else {
    draft.velocity.comments = {"not identified: g close to 1"};
  }
  return draft;
}

}  // namespace musclesim
