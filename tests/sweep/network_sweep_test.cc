// Sweeps whose base is a network scenario (sweep/sweep_file.h): the metrics of the element
// metric_options.element names against static equilibria and energies worked by hand, the
// errors of a missing or unknown element, trajectories kept as network CSVs, resume and MPI
// giving the uninterrupted threaded summary, and the shipped millard_benchmark_sweep.yaml.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/csv_table.h"
#include "musclesim/sweep/sweep.h"
#include "musclesim/sweep/sweep_file.h"
#include "musclesim/sweep/sweep_runner.h"
#include "sweep/sweep_file_points.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorOf;
using testing::ReadFile;
using testing::SummaryWithoutWallTime;
using testing::WriteTempFile;

// A mass of 0.1 kg hanging from a wall by a spring (rest length 0.1 m) and a damper of 5 N s/m,
// pulled by 2 N. At rest the spring carries the load: l = 0.1 + 2 / k. The slowest mode decays
// as exp(-13.8 t) (k = 50 N/m, overdamped: 25 - sqrt(25^2 - k / m)), every other faster, so by
// t = 2 s what is left of the 2 / k = 0.04 m step is below 1e-13 m.
constexpr const char* kSpring = R"(nodes:
  - {name: wall, fixed: 0.0}
  - {name: mass, mass: 0.1, position: 0.1}
elements:
  - {name: spring, type: spring, from: wall, to: mass, stiffness: 100.0, rest_length: 0.1}
  - {name: damper, type: damper, from: wall, to: mass, damping: 5.0}
loads:
  - {node: mass, type: constant, value: 2.0}
time: {start: 0.0, end: 2.0}
solver: {rtol: 1.0e-10, atol: 1.0e-12}
output: {interval: 1.0e-4}
)";

// Two springs in series, wall - soft (100 N/m, rest 0.1 m) - middle - stiff (400 N/m, rest
// 0.2 m) - end, each with a damper of 5 N s/m, the load on `end`. At rest both carry it:
// soft at 0.1 + F / 100, stiff at 0.2 + F / 400. The modes decay as exp(-11.6 t) and
// exp(-63.4 t) (the roots of det(m s^2 + C s + K) = 0), so the transient is gone by 2 s.
constexpr const char* kSeries = R"(nodes:
  - {name: wall, fixed: 0.0}
  - {name: middle, mass: 0.1, position: 0.1}
  - {name: end, mass: 0.1, position: 0.3}
elements:
  - {name: soft, type: spring, from: wall, to: middle, stiffness: 100.0, rest_length: 0.1}
  - {name: stiff, type: spring, from: middle, to: end, stiffness: 400.0, rest_length: 0.2}
  - {name: soft_damper, type: damper, from: wall, to: middle, damping: 5.0}
  - {name: stiff_damper, type: damper, from: middle, to: end, damping: 5.0}
loads:
  - {node: end, type: constant, value: 2.0}
time: {start: 0.0, end: 2.0}
solver: {rtol: 1.0e-10, atol: 1.0e-12}
output: {interval: 0.01}
)";

// Two actuators pulling a mass between two walls, with the flexor's model of
// tests/fixtures/every_part.yaml.
constexpr const char* kAntagonists = R"(models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.095}
    active_length:
      optimal_range: [0.105, 0.115]
      gaussians: [{amplitude: 2.0, width: 4000.0, center: 0.1}]
    velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}
nodes:
  - {name: wall_a, fixed: 0.0}
  - {name: load, mass: 0.5, position: 0.1}
  - {name: wall_b, fixed: 0.2}
elements:
  - {name: flexor, type: actuator, from: wall_a, to: load, model: muscle,
     activation: {type: constant, value: 0.5}}
  - {name: extensor, type: actuator, from: load, to: wall_b, model: muscle,
     activation: {type: constant, value: 0.3}}
time: {start: 0.0, end: 0.05}
)";

// A sweep file `name`.yaml beside its base `name`_base.yaml (`base_text`).
std::string WriteSweep(const std::string& name, const std::string& base_text,
                       const std::string& body) {
  const std::string base = WriteTempFile(name + "_base.yaml", base_text);
  return WriteTempFile(name + ".yaml",
                       "base: " + std::filesystem::path(base).filename().string() + "\n" + body);
}

// Runs `plan` on `jobs` threads into a fresh summary named after `name`; returns its path.
std::string RunInto(const SweepPlan& plan, const std::string& name, int jobs = 1) {
  SweepRunOptions options;
  options.output = ::testing::TempDir() + "network_sweep_" + name + ".csv";
  std::filesystem::remove(options.output + ".partial");
  std::filesystem::remove_all(::testing::TempDir() + "network_sweep_" + name + "_trajectories");
  options.jobs = jobs;
  const SweepOutcome outcome = RunSweep(plan, options);
  EXPECT_FALSE(outcome.interrupted);
  return options.output;
}

TEST(NetworkSweep, SpringStiffnessGridSettlesAtTheStaticEquilibrium) {
  const SweepPlan plan = LoadSweep(WriteSweep("stiffness", kSpring, R"(parameters:
  elements[0].stiffness: {from: 50.0, to: 200.0, count: 4}
metrics: [final_length, work]
metric_options: {element: spring}
)"));
  EXPECT_EQ(plan.spec.form, ScenarioForm::kNetwork);
  const CsvTable summary = ReadCsv(RunInto(plan, "stiffness"));
  ASSERT_EQ(summary.rows.size(), 4u);
  const int k_column = summary.Find("elements[0].stiffness");
  for (std::size_t i = 0; i < summary.rows.size(); ++i) {
    EXPECT_EQ(summary.rows[i][static_cast<std::size_t>(summary.Find("status"))], "ok");
    const double k = summary.Number(i, k_column);
    EXPECT_EQ(k, 50.0 + 50.0 * static_cast<double>(i));
    // rtol 1e-10 on lengths of 0.1 m leaves errors of about 1e-11 m; the transient, 1e-13 m
    EXPECT_NEAR(summary.Number(i, summary.Find("final_length")), 0.1 + 2.0 / k, 1e-9) << k;
    // the work of the spring's tension is the energy it stored, F^2 / (2 k), with its sign
    // turned: it lengthened under tension. The trapezoidal rule over records 1e-4 s apart
    // errs by about (h w)^2 / 12 < 2e-6 of it (w = sqrt(k / m) <= 45 rad/s); 1e-5 leaves room
    const double stored = 2.0 * 2.0 / (2.0 * k);
    EXPECT_NEAR(summary.Number(i, summary.Find("work")), -stored, 1e-5 * stored) << k;
  }
}

TEST(NetworkSweep, MetricElementReadsTheElementItNames) {
  for (const auto& [element, rest, stiffness] :
       {std::tuple{"soft", 0.1, 100.0}, std::tuple{"stiff", 0.2, 400.0}}) {
    SCOPED_TRACE(element);
    const SweepPlan plan = LoadSweep(
        WriteSweep(std::string("series_") + element, kSeries,
                   "parameters:\n  loads[0].value: [1.0, 2.0, 4.0]\nmetrics: [final_length]\n"
                   "metric_options: {element: " +
                       std::string(element) + "}\n"));
    EXPECT_EQ(plan.spec.metric_options.element, element);
    const CsvTable summary = ReadCsv(RunInto(plan, std::string("series_") + element));
    ASSERT_EQ(summary.rows.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      const double load = summary.Number(i, summary.Find("loads[0].value"));
      // as above: solver errors about 1e-11 m, the transient below exp(-23) of 0.05 m
      EXPECT_NEAR(summary.Number(i, summary.Find("final_length")), rest + load / stiffness, 1e-9)
          << load << " N";
    }
  }
}

// A text axis makes each point by reading the base with the point's words; with a numeric axis
// beside it the handles change the point after it was read. Each point's final length is its
// own network's equilibrium: the load on `end` stretches `stiff` by F / 400, on `middle` not
// at all.
TEST(NetworkSweep, ATextAxisRunsEachPointsOwnNetwork) {
  for (const std::string& values :
       {std::string(""), std::string("  loads[0].value: [2.0, 4.0]\n")}) {
    SCOPED_TRACE(values);
    const std::string name = values.empty() ? "series_nodes" : "series_nodes_values";
    const SweepPlan plan =
        LoadSweep(WriteSweep(name, kSeries,
                             "parameters:\n  loads[0].node: [end, middle]\n" + values +
                                 "metrics: [final_length]\nmetric_options: {element: stiff}\n"));
    const CsvTable summary = ReadCsv(RunInto(plan, name));
    ASSERT_EQ(summary.rows.size(), values.empty() ? 2u : 4u);
    for (std::size_t i = 0; i < summary.rows.size(); ++i) {
      const std::string node =
          summary.rows[i][static_cast<std::size_t>(summary.Find("loads[0].node"))];
      const double load = values.empty() ? 2.0 : summary.Number(i, summary.Find("loads[0].value"));
      const double stretch = node == "end" ? load / 400.0 : 0.0;
      // as above: solver errors about 1e-11 m, the transient below exp(-23) of the step
      EXPECT_NEAR(summary.Number(i, summary.Find("final_length")), 0.2 + stretch, 1e-9)
          << node << ", " << load << " N";
    }
  }
}

// The right-hand side of `system` at its initial state.
std::vector<double> InitialRate(const NetworkSystem& system, double t) {
  std::vector<double> y(static_cast<std::size_t>(system.state_size())), f(y.size());
  system.InitialState(t, y.data());
  system.RightHandSide(t, y.data(), f.data());
  return f;
}

// A point a text axis makes hands the run the system its reading built (a point not kept from
// the up-front validation, as in a sweep of more points than that keeps, runs on it): that
// point's own, as building its scenario gives it. With a numeric axis beside it, whose handle
// changes the point after reading, it hands none, and the run builds one.
TEST(NetworkSweep, APointsSystemIsTheOneItsScenarioBuilds) {
  for (const std::string& values :
       {std::string(""), std::string("  loads[0].value: [2.0, 4.0]\n")}) {
    SCOPED_TRACE(values);
    const std::string sweep =
        WriteSweep("made", kSeries,
                   "parameters:\n  loads[0].node: [end, middle]\n" + values +
                       "metrics: [final_length]\nmetric_options: {element: stiff}\n");
    const SweepPlan plan = LoadSweep(sweep);
    const auto points = FilePoints(std::make_unique<ScenarioTemplate>(plan.spec.base), plan.spec);
    std::vector<std::vector<double>> rates;
    for (long i = 0; i < PointCount(plan.spec); ++i) {
      const LoadedScenario made = points->Make(plan.spec, i);
      const std::vector<double> built = InitialRate(made.scenario.Build(), made.scenario.t_start);
      if (!values.empty()) {
        EXPECT_EQ(made.system, nullptr);
        continue;
      }
      ASSERT_NE(made.system, nullptr);
      EXPECT_EQ(InitialRate(*made.system, made.scenario.t_start), built);
      rates.push_back(built);
    }
    // the load on `end` or on `middle`: two networks, each its point's
    if (values.empty()) {
      ASSERT_EQ(rates.size(), 2u);
      EXPECT_NE(rates[0], rates[1]);
    }
  }
}

TEST(NetworkSweep, TheOnlyActuatorIsTheDefaultElement) {
  const std::string points =
      "parameters:\n  elements[0].activation.value: [0.5, 1.0]\n"
      "  time.end: [0.2]\nmetrics: [peak_tension, work, final_length]\n";
  const std::string text = testing::ReadFile(testing::ScenarioPath("millard_benchmark.yaml"));
  const SweepPlan by_default = LoadSweep(WriteSweep("default", text, points));
  EXPECT_EQ(by_default.spec.metric_options.element, "muscle");
  const SweepPlan named =
      LoadSweep(WriteSweep("named", text, points + "metric_options: {element: muscle}\n"));
  const SweepPlan tendon =
      LoadSweep(WriteSweep("tendon", text, points + "metric_options: {element: tendon}\n"));
  const std::string first = SummaryWithoutWallTime(RunInto(by_default, "default"));
  EXPECT_EQ(first, SummaryWithoutWallTime(RunInto(named, "named")));
  EXPECT_NE(first, SummaryWithoutWallTime(RunInto(tendon, "tendon")));
}

TEST(NetworkSweep, AMissingOrUnknownElementIsAnInputErrorSayingWhere) {
  const std::string points = "parameters:\n  loads[0].value: [1.0, 2.0]\n";
  // no actuator and no metric_options: placed at metrics (line 4, column 10)
  const std::string none = WriteSweep("no_actuator", kSpring, points + "metrics: [final_length]\n");
  EXPECT_THAT(InputErrorOf(none, [&] { LoadSweep(none); }),
              HasSubstr("metric_options.element (FILE:4:10): missing: the network "));
  EXPECT_THAT(InputErrorOf(none, [&] { LoadSweep(none); }),
              HasSubstr("has no actuator, so name the element the metrics read, one of: spring, "
                        "damper"));

  // two actuators: placed at metric_options (line 5, column 17), naming them
  const std::string two =
      WriteSweep("two_actuators", kAntagonists,
                 "parameters:\n  elements[0].activation.value: [0.5]\nmetrics: [final_length]\n"
                 "metric_options: {window: [0.0, 0.01]}\n");
  EXPECT_THAT(InputErrorOf(two, [&] { LoadSweep(two); }),
              HasSubstr("metric_options.element (FILE:5:17): missing: the network "));
  EXPECT_THAT(InputErrorOf(two, [&] { LoadSweep(two); }),
              HasSubstr("has 2 actuators (flexor, extensor), so name the element"));

  const std::string unknown =
      WriteSweep("unknown_element", kSpring,
                 points + "metrics: [final_length]\nmetric_options: {element: sprung}\n");
  EXPECT_THAT(InputErrorOf(unknown, [&] { LoadSweep(unknown); }),
              HasSubstr("metric_options.element = sprung (FILE:5:27): must name an element of "
                        "the network "));
  EXPECT_THAT(InputErrorOf(unknown, [&] { LoadSweep(unknown); }), HasSubstr(": spring, damper"));

  // an axis that renames the element makes its points invalid, saying which axis did it
  const std::string renamed =
      WriteSweep("renamed_element", kSpring,
                 "parameters:\n  elements[0].name: [spring, coil]\nmetrics: [final_length]\n"
                 "metric_options: {element: spring}\n");
  EXPECT_THAT(InputErrorOf(renamed, [&] { LoadSweep(renamed); }),
              HasSubstr("FILE:3:3: axis elements[0].name = coil makes point 1 "
                        "(elements[0].name=coil) an invalid scenario: metric_options.element = "
                        "spring: the network "));
  EXPECT_THAT(InputErrorOf(renamed, [&] { LoadSweep(renamed); }),
              HasSubstr("has no such element (its elements: coil, damper)"));

  // from the command line: exit 2, the message with the place
  const std::string err = ::testing::TempDir() + "network_sweep_no_actuator.err";
  const std::string command = std::string(MUSCLESIM_BINARY) + " sweep '" + none + "' -o '" +
                              ::testing::TempDir() + "network_sweep_none.csv' 2>'" + err + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_THAT(ReadFile(err), HasSubstr("no_actuator.yaml:4:10): missing: the network "));
}

TEST(NetworkSweep, TheSingleActuatorFormTakesOnlyActuatorAsItsElement) {
  const std::string points = "parameters:\n  load[0].after: [20.0, 60.0]\nmetrics: [work]\n";
  const std::string concentric = ReadFile(testing::ScenarioPath("concentric.yaml"));
  const SweepPlan plain = LoadSweep(WriteSweep("single_plain", concentric, points));
  const SweepPlan named = LoadSweep(
      WriteSweep("single_named", concentric, points + "metric_options: {element: actuator}\n"));
  EXPECT_EQ(plain.spec.form, ScenarioForm::kActuator);
  EXPECT_EQ(SummaryWithoutWallTime(RunInto(plain, "single_plain")),
            SummaryWithoutWallTime(RunInto(named, "single_named")));
  const std::string other =
      WriteSweep("single_other", concentric, points + "metric_options: {element: spring}\n");
  EXPECT_THAT(InputErrorOf(other, [&] { LoadSweep(other); }),
              HasSubstr("metric_options.element = spring (FILE:5:27): the single-actuator "
                        "scenario "));
  EXPECT_THAT(InputErrorOf(other, [&] { LoadSweep(other); }),
              HasSubstr("has one element, `actuator`: give that or leave element out"));
}

TEST(NetworkSweep, KeptTrajectoriesAreNetworkCsvs) {
  // the columns scenario/run_columns.h lists for a network: t, each node's position and
  // velocity, each element's length and tension, each free node's load
  const std::string header =
      "t,wall.position,wall.velocity,mass.position,mass.velocity,spring.length,"
      "spring.tension,damper.length,damper.tension,mass.load";
  const std::string steps =
      "parameters:\n  solver.max_steps: [20, 10000000]\n"
      "metrics: [final_length]\nmetric_options: {element: spring}\n";
  const std::string folder = ::testing::TempDir() + "network_sweep_";

  // failed: only the point that ran out of steps
  const std::string failed = RunInto(
      LoadSweep(WriteSweep("kept_failed", kSpring, steps + "trajectories: failed\n")), "failed");
  EXPECT_THAT(ReadFile(failed), HasSubstr("\n0,20,failed,"));
  EXPECT_EQ(ReadFile(folder + "failed_trajectories/0.csv").substr(0, header.size() + 1),
            header + "\n");
  EXPECT_FALSE(std::filesystem::exists(folder + "failed_trajectories/1.csv"));

  // all: every point, its last row the state the summary's final_length comes from
  const CsvTable summary = ReadCsv(
      RunInto(LoadSweep(WriteSweep("kept_all", kSpring, steps + "trajectories: all\n")), "all"));
  const CsvTable run = ReadCsv(folder + "all_trajectories/1.csv");
  EXPECT_EQ(ReadFile(folder + "all_trajectories/1.csv").substr(0, header.size() + 1),
            header + "\n");
  EXPECT_EQ(run.rows.size(), 20001u);  // 2 s at 1e-4 s, both ends
  EXPECT_EQ(run.rows.back()[static_cast<std::size_t>(run.Find("spring.length"))],
            summary.rows[1][static_cast<std::size_t>(summary.Find("final_length"))]);
  EXPECT_TRUE(std::filesystem::exists(folder + "all_trajectories/0.csv"));
}

// Stops its sweep once `stop_after` rows are in.
class StopAfter : public SweepObserver {
 public:
  explicit StopAfter(long stop_after) : stop_after_(stop_after) {}
  void OnProgress(long done, long) override { done_ = done; }
  bool StopRequested() override { return done_ >= stop_after_; }

 private:
  long stop_after_;
  long done_ = 0;
};

TEST(NetworkSweep, AResumedSweepGivesTheUninterruptedSummary) {
  // 24 points: the pool is handed 16 at a time (16 per thread), so the stop requested after
  // 3 rows lands before the last 8 are handed out, however the threads are scheduled
  const std::string body =
      "parameters:\n  loads[0].value: {from: 1.0, to: 4.0, count: 8}\n"
      "  elements[1].stiffness: [300.0, 400.0, 500.0]\n"
      "metrics: [final_length, peak_tension, work]\n"
      "metric_options: {element: stiff}\n";
  const std::string path = WriteSweep("resume", kSeries, body);
  const SweepPlan plan = LoadSweep(path);
  const std::string whole = SummaryWithoutWallTime(RunInto(plan, "uninterrupted"));

  SweepRunOptions options;
  options.output = ::testing::TempDir() + "network_sweep_resumed.csv";
  std::filesystem::remove(options.output + ".partial");
  options.jobs = 1;
  StopAfter stop(3);
  options.observer = &stop;
  const SweepOutcome first = RunSweep(plan, options);
  ASSERT_TRUE(first.interrupted);
  ASSERT_LT(first.ran, 24);

  // the partial file belongs to this sweep: the same with another element is refused
  std::string other_text = ReadFile(path);
  other_text.replace(other_text.find("element: stiff"), 14, "element: soft");
  std::ofstream(path) << other_text;
  options.resume = true;
  options.observer = nullptr;
  EXPECT_THAT([&] { RunSweep(LoadSweep(path), options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("the metrics changed")));

  const SweepOutcome rest = RunSweep(plan, options);
  EXPECT_EQ(rest.resumed, first.ran);
  EXPECT_EQ(rest.resumed + rest.ran, 24);
  EXPECT_EQ(SummaryWithoutWallTime(options.output), whole);
}

#ifdef MUSCLESIM_MPIEXEC
// Eight ranks of one thread each, several times: a rank told that no points are left may still
// be running its last ones, and rank 0 must wait for their rows (this lost a row in about one
// run in three before rank 0 waited for every rank to say it was done).
TEST(NetworkSweep, MpiRanksGiveTheThreadedSummary) {
  const std::string sweep = WriteSweep(
      "mpi", kSeries,
      "parameters:\n  loads[0].value: {from: 1.0, to: 4.0, count: 10}\n"
      "  elements[0].stiffness: [100.0, 200.0]\nmetrics: [final_length, peak_tension, work]\n"
      "metric_options: {element: soft}\n");
  const std::string dir = ::testing::TempDir();
  const std::string threaded = SummaryWithoutWallTime(RunInto(LoadSweep(sweep), "mpi_threaded", 2));
  const std::string output = dir + "network_sweep_mpi.csv";
  for (int attempt = 0; attempt < 4; ++attempt) {
    std::filesystem::remove(output);
    std::filesystem::remove(output + ".partial");
    const std::string command = std::string(MUSCLESIM_MPIEXEC) +
                                " -n 8 --oversubscribe --allow-run-as-root " + MUSCLESIM_BINARY +
                                " sweep '" + sweep + "' -o '" + output + "' --jobs 1 --quiet 2>'" +
                                dir + "network_sweep_mpi.err' >/dev/null";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << "attempt " << attempt << ": " << ReadFile(dir + "network_sweep_mpi.err");
    EXPECT_EQ(ReadCsv(output).rows.size(), 20u);
    EXPECT_EQ(SummaryWithoutWallTime(output), threaded);
  }
}
#endif

// The passive tension of docs/model.md section 2, T_p = k_p (exp(alpha (x - x0)) - 1) above
// x0, with the muscle's k_p = 1 N, alpha = 100 1/m, x0 = 0.105 m (millard_benchmark.yaml).
double MillardPassiveTension(double x) {
  return x > 0.105 ? 1.0 * (std::exp(100.0 * (x - 0.105)) - 1.0) : 0.0;
}

TEST(NetworkSweep, MillardBenchmarkSweepRunsEveryActivation) {
  const SweepPlan plan = LoadSweep(testing::ScenarioPath("millard_benchmark_sweep.yaml"));
  EXPECT_EQ(plan.spec.metric_options.element, "muscle");
  const CsvTable summary = ReadCsv(RunInto(plan, "millard", 2));
  ASSERT_EQ(summary.rows.size(), 11u);
  summary.Require({"elements[0].activation.value", "status", "peak_tension", "work", "max_length",
                   "wall_seconds"},
                  "the summary");
  for (std::size_t i = 0; i < 11; ++i) {
    const double u = summary.Number(i, summary.Find("elements[0].activation.value"));
    EXPECT_EQ(u, static_cast<double>(i) / 10.0);
    EXPECT_EQ(summary.rows[i][static_cast<std::size_t>(summary.Find("status"))], "ok");
    EXPECT_GT(summary.Number(i, summary.Find("wall_seconds")), 0.0);
    if (i > 0) {
      EXPECT_LT(summary.Number(i, summary.Find("work")), 0.0) << "u = " << u;
    }
  }
  // inactive, the muscle pulls with its passive element alone, hardest where it is longest:
  // one recorded sample gives both numbers, so they agree to rounding (1e-12 relative)
  const double longest = summary.Number(0, summary.Find("max_length"));
  EXPECT_NEAR(summary.Number(0, summary.Find("peak_tension")), MillardPassiveTension(longest),
              1e-12 * MillardPassiveTension(longest));
}

}  // namespace
}  // namespace musclesim
