// The tension model alone, as a control engineer would drop it into their own loop: links
// musclesim::model only (Eigen and NLopt; no SUNDIALS, no yaml-cpp). Fits two Gaussians to
// the optimal range in closed form (the paper's case), then tabulates the total tension and
// its derivatives at full activation.
//   build/examples/model_curves/model_curves
#include <cstdio>

#include "musclesim/model/gaussian_fit.h"
#include "musclesim/model/tension.h"

int main() {
  using namespace musclesim;

  const double l1 = 0.095, l2 = 0.105;  // optimal range [m]
  FitSpec spec;                         // the indicator of [l1, l2] by default
  spec.count = 2;
  const FitResult fit = FitGaussians(spec, l1, l2, 1.0);
  std::printf("two Gaussians fitted to [%g, %g] m: relative residual %.4f\n", l1, l2,
              fit.relative_residual);

  ModelParams params;
  params.f_iso = 100.0;  // N
  params.passive = {.k_p = 1.0, .alpha = 100.0, .slack_length = 0.105};
  params.active_length = {
      .optimal_min = l1, .optimal_max = l2, .sigma = 1.0, .gaussians = fit.gaussians};
  params.velocity = {.v_max = 1.0, .n = 3, .epsilon = 1e-3};
  const TensionModel model(params);

  std::printf("%10s %10s %12s %12s %12s\n", "length_m", "v_m/s", "T_N", "dT/dx_N/m", "dT/dv_Ns/m");
  for (double x : {0.094, 0.1, 0.106}) {
    for (double v : {-0.2, 0.0, 0.2}) {
      const TensionSample s = model.Evaluate(x, v, 1.0);
      std::printf("%10.3f %10.3f %12.4f %12.2f %12.2f\n", x, v, s.total, s.d_length, s.d_velocity);
    }
  }
  return 0;
}
