// Total tension T = T_p(x) + u f_iso f_L(x) g_eps(v) (paper eqs. 16-17, docs/model.md section 5)
// with its derivatives, which the simulator uses as its analytic Jacobian.
#pragma once

#include "musclesim/model/active_length.h"
#include "musclesim/model/passive.h"
#include "musclesim/model/velocity.h"

namespace musclesim {

struct ModelParams {
  double f_iso = 1.0;                // isometric active tension at optimal length [N], > 0
  PassiveParams passive;             // T_p(x) [N] (eq. 1)
  ActiveLengthParams active_length;  // f_L(x) [-] (eqs. 3-4, 13)
  VelocityParams velocity;           // g_eps(v) [-] (eq. 12)
};

// Throws ParameterError with paths such as "f_iso" or "velocity.n".
void Validate(const ModelParams& params);

// Tension at one state, split into its parts, with derivatives.
struct TensionSample {
  double passive = 0.0;       // T_p [N]
  double active = 0.0;        // T_a [N]
  double total = 0.0;         // T [N]
  double d_length = 0.0;      // dT/dx [N/m]
  double d_velocity = 0.0;    // dT/dv, v the shortening velocity [N s/m]
  double d_activation = 0.0;  // dT/du [N]
};

// The whole tension model, built once from validated parameters and immutable after.
// Evaluate allocates nothing; one model may be shared by many threads.
class TensionModel {
 public:
  // Validates (ParameterError with paths relative to the model block).
  explicit TensionModel(const ModelParams& params);

  // x the length [m], v the shortening velocity [m/s] (v = -dx/dt), u the activation.
  TensionSample Evaluate(double x, double v, double u) const {
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

  const ModelParams& params() const { return params_; }
  const ActiveLengthCurve& active_length() const { return active_length_; }
  const VelocityCurve& velocity() const { return velocity_; }

 private:
  ModelParams params_;               // as validated (units as in ModelParams)
  ActiveLengthCurve active_length_;  // f_L [-], built from params_.active_length
  VelocityCurve velocity_;           // g_eps [-], built from params_.velocity
};

}  // namespace musclesim
