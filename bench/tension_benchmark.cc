// Cost of one evaluation of the total tension with all its derivatives: the innermost
// call of every simulation's right-hand side and Jacobian.
#include <benchmark/benchmark.h>

#include "musclesim/model/tension.h"

namespace musclesim {
namespace {

ModelParams Example(int n, int gaussians) {
  ModelParams p;
  p.f_iso = 100.0;
  p.passive = {2.0, 30.0, 0.105};
  p.active_length = {0.095, 0.105, 1.0, {}};
  for (int k = 0; k < gaussians; ++k) {
    p.active_length.gaussians.push_back(
        {0.02, 2e5, 0.096 + 0.008 * k / std::max(1, gaussians - 1)});
  }
  p.velocity = {1.0, n, 1e-3};
  return p;
}

// args: n (the velocity exponent's denominator), number of Gaussians
void BM_TensionEvaluate(benchmark::State& state) {
  const TensionModel model(
      Example(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))));
  double x = 0.1, v = 0.01;
  for (auto _ : state) {
    const TensionSample s = model.Evaluate(x, v, 0.8);
    benchmark::DoNotOptimize(s);
    // move the state a little so that nothing is hoisted out of the loop
    x += 1e-9;
    v = -v;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TensionEvaluate)->ArgsProduct({{1, 3}, {2, 3}})->ArgNames({"n", "m"});

}  // namespace
}  // namespace musclesim
