// Time of a whole indicator fit (all starting points), as `fit:` in a model block does it.
#include <benchmark/benchmark.h>

#include "musclesim/model/gaussian_fit.h"

namespace musclesim {
namespace {

void BM_GaussianFitIndicator(benchmark::State& state) {
  FitSpec spec;
  spec.count = static_cast<int>(state.range(0));
  int evaluations = 0;
  for (auto _ : state) {
    const FitResult fit = FitGaussians(spec, 0.095, 0.105, 1.0);
    benchmark::DoNotOptimize(fit.cost);
    evaluations = fit.iterations;
  }
  state.counters["best_start_evaluations"] = evaluations;
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GaussianFitIndicator)->Arg(2)->Arg(3)->ArgName("m")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace musclesim
