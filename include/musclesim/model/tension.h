// Total tension T = T_p(x) + u f_iso f_L(x) g_eps(v) (paper eqs. 16-17, docs/model.md section 5)
// with its derivatives, which the simulator uses as its analytic Jacobian; or, for another
// curve family (section 14.1), that family's fiber tension, seen along the line of action
// through a pennation angle (section 14.2).
#pragma once

#include <optional>

#include "musclesim/model/active_length.h"
#include "musclesim/model/curve_family.h"
#include "musclesim/model/degroote2016.h"
#include "musclesim/model/mujoco_muscle.h"
#include "musclesim/model/passive.h"
#include "musclesim/model/tension_sample.h"
#include "musclesim/model/velocity.h"

namespace musclesim {

struct ModelParams {
  CurveFamily family = CurveFamily::kPaper;  // which curves; the blocks below say which apply
  double f_iso = 1.0;                        // isometric active tension at optimal length [N], > 0
  PassiveParams passive;                     // T_p(x) [N] (eq. 1); family paper
  ActiveLengthParams active_length;          // f_L(x) [-] (eqs. 3-4, 13); family paper
  VelocityParams velocity;                   // g_eps(v) [-] (eq. 12); family paper
  DeGrooteParams degroote2016;               // family degroote2016
  MujocoMuscleParams mujoco;                 // family mujoco
  double pennation_angle = 0.0;              // at the optimal fiber length [rad], in [0, pi/2)
};

// Throws ParameterError with paths such as "f_iso" or "velocity.n"; only the blocks of
// params.family are checked.
void Validate(const ModelParams& params);

// The whole tension model, built once from validated parameters and immutable after.
// Evaluate allocates nothing; one model may be shared by many threads.
class TensionModel {
 public:
  // Validates (ParameterError with paths relative to the model block).
  explicit TensionModel(const ModelParams& params);

  // x the length [m], v the shortening velocity [m/s] (v = -dx/dt), u the activation. With a
  // pennation angle, x is the fiber's length along the line of action and T its tension
  // along it.
  TensionSample Evaluate(double x, double v, double u) const {
    if (pennation_width_ > 0.0) return Pennate(x, v, u);
    if (params_.family == CurveFamily::kPaper) return PaperTension(x, v, u);
    return Fiber(x, v, u);
  }

  // The tension at zero activation, the passive part of every family (T is affine in u): its
  // d_length and d_velocity are the passive tension's (d_velocity nonzero with fiber damping).
  TensionSample Passive(double x, double v) const { return Evaluate(x, v, 0.0); }

  // The length where dT/dx jumps, for the integrator to stop at: the paper's slack length
  // when k_p > 0; none for the other families, whose curves are C1.
  std::optional<double> LengthKink() const;
  // Whether the tension at zero activation depends on v (De Groote's fiber damping): what lets
  // a massless junction's balance fix its velocity (docs/model.md 14.4).
  bool PassiveDependsOnRate() const;
  // Whether dT/dv jumps at v = 0 (the paper's asymmetric velocity curve).
  bool HasVelocityKink() const;
  // The curves `musclesim curves` tabulates, for every family: f_L(x), the active tension at
  // v = 0 over f_iso, along the line; g(v), the active tension at the optimal length over its
  // value at v = 0. For the paper's curves without pennation, f_L and g_eps exactly.
  // Each with its slope.
  CurvePoint ActiveLengthFactor(double x) const;
  CurvePoint VelocityFactor(double v) const;
  // The fiber length of peak isometric tension [m] (at zero pennation), the family's l_opt.
  double OptimalFiberLength() const;

  const ModelParams& params() const { return params_; }
  const ActiveLengthCurve& active_length() const { return active_length_; }
  const VelocityCurve& velocity() const { return velocity_; }

 private:
  // The family's tension along the fiber at fiber length l, shortening velocity v.
  TensionSample Fiber(double l, double v, double u) const {
    switch (params_.family) {
      case CurveFamily::kDeGroote2016:
        return DeGrooteFiber(params_.degroote2016, params_.f_iso, l, v, u);
      case CurveFamily::kMujoco: return MujocoFiber(params_.mujoco, params_.f_iso, l, v, u);
      case CurveFamily::kPaper: break;
    }
    return PaperTension(l, v, u);
  }
  TensionSample PaperTension(double x, double v, double u) const {
    const CurvePoint passive = PassiveTension(params_.passive, x);
    const CurvePoint length = active_length_.Evaluate(x);
    const CurvePoint velocity = velocity_.Evaluate(v);
    const double scale = params_.f_iso * length.value * velocity.value;  // T_a / u
    TensionSample out;
    out.passive = passive.value;
    out.active = u * scale;
    out.total = passive.value + out.active;
    out.d_length = passive.slope + u * params_.f_iso * length.slope * velocity.value;
    out.d_velocity = u * params_.f_iso * length.value * velocity.slope;
    out.d_activation = scale;
    return out;
  }
  // Constant thickness (section 14.2): l_f = sqrt(x^2 + w^2), cos(alpha) = x / l_f.
  TensionSample Pennate(double x, double v, double u) const;

  ModelParams params_;               // as validated (units as in ModelParams)
  ActiveLengthCurve active_length_;  // f_L [-], built from params_.active_length
  VelocityCurve velocity_;           // g_eps [-], built from params_.velocity
  double pennation_width_ = 0.0;     // w = l_opt sin(alpha_opt) [m], 0 without pennation
};

}  // namespace musclesim
