// Every kind of parameter identification takes reaches it with its sensitivity column: a
// node's initial coordinate, a fixed node's coordinate, a fixed via point's coordinate, an
// element's coefficient and a model block's key. For each, the series is a plain run of the
// truth, the fit starts away from it, and (the independent check) the sensitivity the fit
// uses at its estimate is compared with a central difference of two plain runs there. The
// kinds whose truth is 0 are the hard case: a difference quotient stepping by a fraction of
// the estimate's size (~1e-14) moves nothing, and the column would read as zero.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "musclesim/identify/identify_series.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/run.h"
#include "musclesim/scenario/scenario.h"
#include "musclesim/scenario/sensitivity_run.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

// A 1 kg bob on a spring (100 N/m, rest 1 m) over a fixed via point from a pivot, in the
// plane under gravity, released at rest: the via point at (0.5, 0.2), the bob at (1.2, 0).
constexpr const char* kPlanarBob = R"(name: planar_bob
dimensions: 2
gravity: [0.0, -9.81]
nodes:
  - {name: pivot, fixed: [0.0, 0.0]}
  - {name: bob, mass: 1.0, position: [1.2, 0.0]}
elements:
  - {name: link, type: spring, from: pivot, to: bob, stiffness: 100.0, rest_length: 1.0,
     via: [[0.5, 0.2]]}
time: {start: 0.0, end: 1.0}
solver: {method: bdf, rtol: 1.0e-11, atol: 1.0e-13, jacobian: analytic, linear_solver: auto}
output: {interval: 0.01}
)";

Scenario Parsed(const std::string& text) {
  return ReadScenario(ParseDocument("kinds.yaml", text), "kinds.yaml");
}

Scenario Shipped(const std::string& name) { return LoadScenario(testing::ScenarioPath(name)); }

Scenario At(const Scenario& scenario, const std::string& path, double value) {
  Scenario moved = scenario;
  moved.parameter(path).Set(moved, value);
  return moved;
}

// The truth's `columns` every `stride` rows of a plain run, noise `noise` stated (none added).
MeasuredSeries Series(const Scenario& truth, const std::vector<std::string>& columns, double noise,
                      std::size_t stride) {
  const RecordedRun run = RunScenario(truth);
  EXPECT_EQ(run.stats.status, RunStatus::kCompleted) << run.stats.message;
  const std::vector<double>& t = testing::ColumnOf(run, "t");
  MeasuredSeries s;
  s.columns = columns;
  s.noise.assign(columns.size(), noise);
  for (std::size_t r = stride; r < t.size(); r += stride) {
    s.times.push_back(t[r]);
    for (const std::string& c : columns) s.values.push_back(testing::ColumnOf(run, c)[r]);
    s.lines.push_back(s.lines.size() + 1);
  }
  return s;
}

struct Kind {
  Scenario scenario;  // holds the truth
  std::string path;
  double truth, start, lower, upper;
  std::vector<std::string> columns;
  double noise;  // [the columns' unit]
};

// Fits `kind` from the truth's series and checks the estimate, the verdict, and the
// sensitivity at the estimate against a central difference of plain runs.
void ExpectIdentified(const Kind& kind) {
  SCOPED_TRACE(kind.path);
  IdentifySeriesSpec spec;
  spec.source = "kinds in code";
  spec.scenario = kind.scenario.name;
  spec.parameters = {{kind.path, kind.start, kind.lower, kind.upper, InputPlace{"parameters[0]"}}};
  const MeasuredSeries series = Series(kind.scenario, kind.columns, kind.noise, 10);
  const SeriesIdentification fit =
      FitSeries(spec, {series}, ScenarioSensitivityRunner(kind.scenario));
  ASSERT_TRUE(fit.converged) << fit.stop_reason;
  const SeriesParameterResult& p = fit.parameters[0];
  EXPECT_EQ(p.verdict, Identifiability::kIdentifiable)
      << IdentifiabilityVerdict(fit) << " (column ratio " << p.column_ratio << ")";
  // noise-free data: the estimate is the truth to far within its standard error
  ASSERT_TRUE(std::isfinite(p.standard_error));
  EXPECT_LT(std::abs(p.estimate - kind.truth), 0.01 * p.standard_error + 1e-12);

  // the column the fit sees at its estimate, on the start's scale as the fit takes it,
  // against (y(p + h) - y(p - h)) / 2h of plain runs, h a thousandth of the start's size
  const double size = std::max(std::abs(kind.start), std::abs(kind.truth));
  const SensitivityTable table =
      RunWithSensitivities(At(kind.scenario, kind.path, p.estimate), {kind.path}, {}, {size});
  const double h = 1e-3 * size;
  const RecordedRun above = RunScenario(At(kind.scenario, kind.path, p.estimate + h));
  const RecordedRun below = RunScenario(At(kind.scenario, kind.path, p.estimate - h));
  for (const std::string& column : kind.columns) {
    const int c = table.FindColumn(column);
    ASSERT_GE(c, 0) << column;
    const std::vector<double>& up = testing::ColumnOf(above, column);
    const std::vector<double>& down = testing::ColumnOf(below, column);
    ASSERT_EQ(up.size(), table.rows());
    double largest = 0.0;
    for (std::size_t r = 0; r < table.rows(); ++r) {
      largest = std::max(largest, std::abs(table.derivative(r, 0, static_cast<std::size_t>(c))));
    }
    ASSERT_GT(largest, 0.0) << column << ": a column of zeros";
    for (std::size_t r = 0; r < table.rows(); ++r) {
      const double quotient = (up[r] - down[r]) / (2.0 * h);
      // the quotient's h^2 error and the runs' tolerances: 1e-4 of the column's largest
      EXPECT_NEAR(table.derivative(r, 0, static_cast<std::size_t>(c)), quotient, 1e-4 * largest)
          << column << " at t = " << table.times[r];
    }
  }
}

TEST(IdentifyParameterKinds, AFixedNodesCoordinateWhoseTruthIsZero) {
  // the wall of the mass-spring-damper at 0, started 1 mm off: the load's position depends on
  // it with a sensitivity of ~0.8 at the end (its column is not zero)
  ExpectIdentified({Shipped("mass_spring_damper.yaml"),
                    "nodes[0].fixed",
                    0.0,
                    0.001,
                    -0.05,
                    0.05,
                    {"load.position"},
                    1e-6});
}

TEST(IdentifyParameterKinds, AFreeNodesInitialCoordinateWhoseTruthIsZero) {
  ExpectIdentified(
      {Parsed(kPlanarBob), "nodes[1].position[1]", 0.0, 0.01, -0.1, 0.1, {"bob.x", "bob.y"}, 1e-6});
}

TEST(IdentifyParameterKinds, AFixedViaPointsCoordinate) {
  ExpectIdentified(
      {Parsed(kPlanarBob), "elements[0].via[0][1]", 0.2, 0.21, 0.1, 0.3, {"bob.x", "bob.y"}, 1e-6});
}

TEST(IdentifyParameterKinds, AFixedNodesCoordinateInThePlaneWhoseTruthIsZero) {
  ExpectIdentified(
      {Parsed(kPlanarBob), "nodes[0].fixed[0]", 0.0, 0.01, -0.1, 0.1, {"bob.x", "bob.y"}, 1e-6});
}

TEST(IdentifyParameterKinds, AnElementsCoefficient) {
  ExpectIdentified({Shipped("mass_spring_damper.yaml"),
                    "elements[0].stiffness",
                    50.0,
                    45.0,
                    1.0,
                    500.0,
                    {"load.position"},
                    1e-6});
}

TEST(IdentifyParameterKinds, AModelBlocksKey) {
  // the pair's first swings (its frequency moves with f_iso: over many the quotient's h^2
  // term grows), at tolerances tight enough for the difference check's 1e-4
  Scenario pair = Shipped("antagonist_pair.yaml");
  pair.t_end = 1.0;
  pair.solver.rtol = 1e-11;
  pair.solver.atol = 1e-14;
  ExpectIdentified(
      {pair, "models.muscle.f_iso", 100.0, 90.0, 10.0, 1000.0, {"load.position"}, 1e-9});
}

TEST(IdentifyParameterKinds, AViaPointsCoordinateIsAHandleCheckedAsTheFileIs) {
  const Scenario s = Parsed(kPlanarBob);
  EXPECT_NO_THROW(s.parameter("elements[0].via[0][0]"));
  EXPECT_THROW(s.parameter("elements[0].via[1][0]"), ParameterError);  // one via point
  EXPECT_THROW(s.parameter("elements[0].via[0][2]"), ParameterError);  // in the plane
  EXPECT_THROW(s.parameter("elements[0].via[0]"), ParameterError);     // a coordinate's index
  // the via point moved onto the pivot: its segment has no length, which the file refuses
  Scenario moved = At(s, "elements[0].via[0][0]", 0.0);
  EXPECT_THROW(moved.parameter("elements[0].via[0][1]").Set(moved, 0.0), ParameterError);
}

}  // namespace
}  // namespace musclesim
