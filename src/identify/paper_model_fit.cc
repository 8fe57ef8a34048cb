#include "musclesim/identify/paper_model_fit.h"

#include <string>
#include <vector>

#include "musclesim/core/errors.h"

namespace musclesim {

namespace {

// `points` evenly spaced samples of f over [a, b].
template <typename F>
std::vector<DataPoint> Sample(double a, double b, int points, F f) {
  std::vector<DataPoint> data;
  for (int i = 0; i < points; ++i) {
    const double x = a + (b - a) * i / (points - 1);
    data.push_back({x, f(x)});
  }
  return data;
}

// Re-throws an identification's InputError with the curve it was fitting.
template <typename Fit>
auto Curve(const char* name, Fit fit) {
  try {
    return fit();
  } catch (const InputError& e) {
    throw InputError(std::string("--to-gaussians: the ") + name + " curve: " + e.what());
  }
}

}  // namespace

PaperModelFit FitPaperModel(const TensionModel& model, int count, double optimal_line_length,
                            double max_speed) {
  if (count < 1 || count > 20) {
    throw InputError("--to-gaussians = " + std::to_string(count) +
                     ": must be a whole number from 1 to 20 (Gaussians)");
  }
  const double f_iso = model.params().f_iso, x_opt = optimal_line_length;
  // the passive curve up to where it reaches f_iso: its exponential shape, not its far tail
  double passive_end = 3.0 * x_opt;
  for (int i = 0; i <= 300; ++i) {
    const double x = x_opt * (1.0 + 2.0 * i / 300.0);
    if (model.Passive(x, 0.0).total >= f_iso) {
      passive_end = x;
      break;
    }
  }
  PaperModelFit fit;
  fit.passive = Curve("passive", [&] {
    return IdentifyPassive(Sample(0.5 * x_opt, passive_end, 121,
                                  [&](double x) { return model.Passive(x, 0.0).total; }));
  });
  fit.active = Curve("active", [&] {
    return IdentifyActive(
        Sample(0.3 * x_opt, 2.0 * x_opt, 171,
               [&](double x) { return f_iso * model.ActiveLengthFactor(x).value; }),
        count, true);
  });
  fit.velocity = Curve("velocity", [&] {
    return IdentifyVelocity(Sample(-0.9 * max_speed, 0.9 * max_speed, 91,
                                   [&](double v) { return f_iso * model.VelocityFactor(v).value; }),
                            f_iso);
  });
  return fit;
}

}  // namespace musclesim
