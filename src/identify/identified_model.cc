// The `model:` block of `musclesim identify` from the curves' identifications.
#include "musclesim/identify/identified_model.h"

#include <cmath>

#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"
#include "musclesim/identify/identify_report.h"

namespace musclesim {

namespace {

// "value +- standard error", or "+- n/a" when the error cannot be estimated.
std::string PlusMinus(const Estimate& e) {
  return FormatNumber(e.value) + " +- " +
         (std::isfinite(e.standard_error) ? FormatNumber(e.standard_error) : "n/a");
}

}  // namespace

ModelYamlDraft DraftIdentifiedModel(const std::string& source,
                                    const std::optional<PassiveIdentification>& passive,
                                    const std::optional<ActiveIdentification>& active,
                                    const std::optional<VelocityIdentification>& velocity) {
  ModelYamlDraft draft;
  draft.header = {"identified by musclesim identify from " + source,
                  "(+- standard errors from the Jacobian at the optimum)"};
  if (active) {
    draft.f_iso = {active->f_iso.value,
                   {"N, " + PlusMinus(active->f_iso) + ", the active curve's maximum"}};
  } else if (velocity) {
    draft.f_iso = {velocity->best.f_iso.value,
                   {"N, " + PlusMinus(velocity->best.f_iso) + ", from the tension-velocity curve"}};
  } else {
    draft.f_iso.comments = {"not identified (no active or velocity data)"};
  }

  if (passive) {
    draft.passive.params =
        PassiveParams{passive->k_p.value, passive->alpha.value, passive->slack_length.value};
    draft.passive.comments = {"k_p = " + PlusMinus(passive->k_p) + " N, alpha = " +
                              PlusMinus(passive->alpha) + " 1/m, slack_length = " +
                              PlusMinus(passive->slack_length) + " m; RMSE " +
                              FormatNumber(passive->rmse) + " N"};
    for (const std::string& note : PassiveUncertaintyNotes(*passive, FormatNumber)) {
      draft.passive.comments.push_back(note);
    }
  } else {
    draft.passive.comments = {"not identified: no passive tension"};
  }

  if (active) {
    draft.active_length.params = active->curve;
    draft.active_length.comments = {
        "optimal_range: where the fitted curve is within 2% of its maximum; RMSE " +
        FormatNumber(active->rmse) + " N"};
    for (std::size_t k = 0; k < active->curve.gaussians.size(); ++k) {
      draft.gaussian_comments.push_back(
          "amplitude " + PlusMinus(active->amplitudes[k]) + ", width " +
          PlusMinus(active->precisions[k]) + ", center " + PlusMinus(active->centers[k]));
    }
  } else {
    draft.active_length.comments = {"not identified: one Gaussian a kilometre wide, a flat f_L"};
  }

  if (velocity) {
    const VelocityCandidate& best = velocity->best;
    VelocityParams params{best.v_max.value, best.n, StandInEpsilon(best.v_max.value)};
    std::string others = "other n:";
    for (const VelocityCandidate& c : velocity->candidates) {
      if (c.n == best.n) continue;
      others += " n=" + std::to_string(c.n) + " " +
                (c.valid ? "RMSE " + FormatNumber(c.rmse) : "no fit") + ";";
    }
    std::vector<std::string> eccentric_comments;
    std::string epsilon_rule = "1e-3 v_max";
    if (velocity->eccentric) {
      const EccentricIdentification& e = *velocity->eccentric;
      eccentric_comments = DescribeEccentric(e);
      if (e.identified) {
        params.eccentric = {e.best.v_max.value, e.best.n, std::nullopt};
        if (e.limit_identified) params.eccentric.limit = e.best.limit.value;
        // eps must not exceed either v_max (the model's rule)
        if (e.best.v_max.value < best.v_max.value) {
          params.epsilon = StandInEpsilon(e.best.v_max.value);
          epsilon_rule = "1e-3 times the eccentric v_max, the smaller";
        }
        std::string other_exponents = "other eccentric n:";
        for (const EccentricCandidate& c : e.limit_identified ? e.bounded : e.unbounded) {
          if (c.n == e.best.n) continue;
          other_exponents += " n=" + std::to_string(c.n) + " " +
                             (c.valid ? "RMSE " + FormatNumber(c.rmse) : "no fit") + ";";
        }
        eccentric_comments.push_back(other_exponents);
      }
    }
    try {
      Validate(params);  // extreme eccentric estimates may break the model's rules: say so
    } catch (const ParameterError& error) {
      params.eccentric = {};
      params.epsilon = StandInEpsilon(best.v_max.value);
      epsilon_rule = "1e-3 v_max";
      eccentric_comments.push_back("eccentric branch left out: it gives velocity." + error.path() +
                                   " = " + error.value() + ", which " + error.rule());
    }
    draft.velocity.params = params;
    draft.velocity.comments = {"v_max = " + PlusMinus(best.v_max) + " m/s, RMSE " +
                                   FormatNumber(best.rmse) + " N; epsilon is not identified (" +
                                   epsilon_rule + ")",
                               others};
    draft.velocity.comments.insert(draft.velocity.comments.end(), eccentric_comments.begin(),
                                   eccentric_comments.end());
  } else {
    draft.velocity.comments = {"not identified: g close to 1"};
  }
  return draft;
}

}  // namespace musclesim
