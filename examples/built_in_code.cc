// A scenario built in code, with no file anywhere: the single actuator of the README's
// concentric scenario assembled from its parts, then run, differentiated (forward
// sensitivities), swept over its load (the summary kept in memory) and identified from a run
// of itself. Everything passes typed objects; the file system is never touched.
//   build/examples/built_in_code
#include <cmath>
#include <cstdio>
#include <exception>

#include "musclesim/identify/identify_series.h"
#include "musclesim/identify/identify_series_columns.h"
#include "musclesim/musclesim.h"
#include "musclesim/sweep/sweep_points.h"
#include "musclesim/sweep/sweep_runner.h"

namespace {

using namespace musclesim;

// The concentric scenario's actuator, one Gaussian for its three: a 100 N muscle switched on
// with a 40 N load at 0.01 s, which it lifts.
Scenario Concentric() {
  ActuatorScenarioSpec spec;
  spec.name = "built in code";
  ModelParams& p = spec.model.params;
  p.f_iso = 100.0;                                   // N
  p.passive = {1.0, 100.0, 0.105};                   // k_p [N], alpha [1/m], slack [m]
  p.active_length.optimal_min = 0.095;               // m
  p.active_length.optimal_max = 0.105;               // m
  p.active_length.gaussians = {{1.0, 3000.0, 0.1}};  // a [-], b [1/m^2], d [m]
  p.velocity.v_max = 1.0;                            // m/s
  p.velocity.n = 3;
  p.velocity.epsilon = 1e-3;  // m/s
  spec.actuator.mass = 0.1;   // kg
  spec.initial_length = 0.1;  // m
  spec.activation = Waveform::Step(0.01, 0.0, 1.0);
  spec.loads = {Load::Force(Waveform::Step(0.01, 0.0, 40.0))};  // N
  spec.t_end = 0.1;                                             // s
  spec.output.interval = 0.001;                                 // s
  return MakeActuatorScenario(spec);
}

}  // namespace

int main() {
  try {
    const Scenario scenario = Concentric();
    const RecordedRun run = RunScenario(scenario);
    const double final_length = run.values[1].back();  // the `length` column
    std::printf("run: %zu rows, final length %.6f m\n", run.values[0].size(), final_length);

    const SensitivityTable table = RunWithSensitivities(scenario, {"model.f_iso", "load[0].after"});
    const int length = table.FindColumn("length");
    std::printf("sensitivities at the end: dx/df_iso %.3e m/N, dx/dload %.3e m/N\n",
                table.derivative(table.rows() - 1, 0, static_cast<std::size_t>(length)),
                table.derivative(table.rows() - 1, 1, static_cast<std::size_t>(length)));

    SweepSpec spec;
    spec.source = spec.base = "built in code";
    spec.axes.push_back({"load[0].after", {}, {}, 10.0, 70.0, 4, false, {}});  // N
    spec.metrics = {Metric::kFinalLength, Metric::kPeakTension};
    const SweepPlan plan = PlanSweep(spec, ParameterPoints(scenario, spec), 2);
    const SweepOutcome outcome = RunSweep(plan, SweepRunOptions{"", 2, false, nullptr});
    for (const SweepRow& row : outcome.rows) {
      std::printf("sweep: load %5.1f N -> final length %.6f m\n", row.numbers[0], row.metrics[0]);
    }

    // f_iso from the run's lengths, starting 20% off
    IdentifySeriesSpec identify;
    identify.source = identify.scenario = "built in code";
    identify.series.push_back({});
    identify.parameters.push_back({"model.f_iso", 80.0, std::nullopt, std::nullopt, {}});
    const std::vector<MeasuredSeries> series = MeasuredSeriesFromColumns(
        identify, {{{"t", run.values[0]}, {"length", run.values[1]}}}, false);
    const SeriesIdentification fit =
        FitSeries(identify, series, ScenarioSensitivityRunner(scenario));
    std::printf("identified f_iso = %.4f N (true 100)\n", fit.parameters[0].estimate);
    return std::abs(fit.parameters[0].estimate - 100.0) < 1e-2 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
