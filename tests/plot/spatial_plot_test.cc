// The figures of a network in the plane or in space: the data each script plots against the
// CSV's numbers written here (the nodes' paths, each frame's nodes at the row nearest its
// time) and against the geometry written here (an element's polyline through its fixed and
// node via points), and the errors of a mismatched scenario, a time outside the run and a
// mixed CSV.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/plot/plot.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;
using Point = std::pair<double, double>;

// A planar run: pivot fixed at (0, 0), bob and hand moving; rows at t = 0, 0.5, 1.
const char* const kPlanarCsv =
    "t,pivot.x,pivot.y,pivot.vx,pivot.vy,bob.x,bob.y,bob.vx,bob.vy,hand.x,hand.y,hand.vx,"
    "hand.vy,link.length,link.tension,cord.length,cord.tension,bob.load_x,bob.load_y\n"
    "0,0,0,0,0,0.1,0,0,0,0.2,0.05,0,0,0.1,0,0.2,0,0,0\n"
    "0.5,0,0,0,0,0.06,-0.08,0,0,0.21,0.04,0,0,0.1,3,0.25,1,0,0\n"
    "1,0,0,0,0,-0.02,-0.098,0,0,0.22,0.03,0,0,0.1,2,0.3,2,0,0\n";

CsvTable PlanarRun() { return ReadCsv(testing::WriteTempFile("planar_run.csv", kPlanarCsv)); }

PlotOptions Options(const char* output) {
  PlotOptions options;
  options.output = output;
  return options;
}

// The scenario of that run: a link from the pivot to the bob, and a cord from the pivot over
// a fixed point and over the bob to the hand.
Scenario PlanarScenario() {
  Scenario s;
  s.source = "planar.yaml";
  s.space = Space{2, {0.0, -9.81, 0.0}};
  s.nodes = {Node::Fixed("pivot", Coordinates{0.0, 0.0, 0.0}),
             Node::Free("bob", 0.1, Coordinates{0.1, 0.0, 0.0}),
             Node::Fixed("hand", Coordinates{0.2, 0.05, 0.0})};
  Element link = Element::Spring("link", "pivot", "bob", 1e4, 0.1);
  Element cord = Element::LinearTendon("cord", "pivot", "hand", 0.1, 100.0);
  cord.via = {ViaPoint::Fixed({0.05, 0.07, 0.0}), ViaPoint::Node("bob")};
  s.elements = {link, cord};
  return s;
}

// The rows of inline block `name` of `script`, split at gnuplot's double blank lines into
// its data sets (index 0, 1, ...), each row its numbers.
std::vector<std::vector<std::vector<double>>> Block(const std::string& script,
                                                    const std::string& name) {
  const std::string start = name + " << EOD\n";
  const std::size_t begin = script.find(start);
  EXPECT_NE(begin, std::string::npos) << name;
  if (begin == std::string::npos) return {};
  std::istringstream in(script.substr(begin + start.size()));
  std::vector<std::vector<std::vector<double>>> sets(1);
  int blank = 0;
  for (std::string line; std::getline(in, line) && line != "EOD";) {
    if (line.empty()) {
      if (++blank == 2) sets.emplace_back();
      continue;
    }
    blank = 0;
    std::istringstream fields(line);
    std::vector<double> row;
    for (double v; fields >> v;) row.push_back(v);
    sets.back().push_back(row);
  }
  return sets;
}

std::vector<Point> Points(const std::vector<std::vector<double>>& rows) {
  std::vector<Point> points;
  for (const auto& row : rows) {
    EXPECT_EQ(row.size(), 2u);
    if (row.size() == 2) points.emplace_back(row[0], row[1]);
  }
  return points;
}

// The two ends of `set AXIS [lo:hi]`.
std::vector<double> Range(const std::string& script, const std::string& axis) {
  const std::string start = "set " + axis + " [";
  const std::size_t begin = script.find(start);
  if (begin == std::string::npos) return {};
  double lo = 0.0, hi = 0.0;
  char colon = 0;
  std::istringstream in(script.substr(begin + start.size()));
  if (!(in >> lo >> colon >> hi) || colon != ':') return {};
  return {lo, hi};
}

TEST(SpatialPlot, APlanarRunIsSpatialAndANetworkOnALineIsNot) {
  EXPECT_TRUE(IsSpatialTrajectory(PlanarRun()));
  EXPECT_FALSE(IsNetworkTrajectory(PlanarRun()));
  EXPECT_FALSE(IsSpatialTrajectory(
      ReadCsv(testing::WriteTempFile("line.csv", "t,m.position,m.velocity\n0,0.1,0\n"))));
  // x without y: a planar run's CSV with a column lost, refused rather than drawn without it
  EXPECT_THROW(IsSpatialTrajectory(ReadCsv(testing::WriteTempFile("x.csv", "t,a.x\n0,1\n"))),
               InputError);
}

TEST(SpatialPlot, ThePathFigurePlotsEveryNodesCoordinatesWithEqualScales) {
  const std::string script = SpatialPathPlotScript(PlanarRun(), Options("path.png"));
  // the plane's data: t, then x and y of pivot, bob, hand, as the CSV has them
  const auto plane = Block(script, "$plane");
  ASSERT_EQ(plane.size(), 1u);
  const std::vector<std::vector<double>> expected = {{0, 0, 0, 0.1, 0, 0.2, 0.05},
                                                     {0.5, 0, 0, 0.06, -0.08, 0.21, 0.04},
                                                     {1, 0, 0, -0.02, -0.098, 0.22, 0.03}};
  EXPECT_EQ(plane[0], expected);
  EXPECT_THAT(script, HasSubstr("set size ratio -1 0.5,0.94\n"));
  EXPECT_THAT(script, HasSubstr("set xlabel 'x [m]'\nset ylabel 'y [m]'\n"));
  EXPECT_THAT(script, HasSubstr("$plane using 2:3 with lines lw 2 title 'pivot'"));
  EXPECT_THAT(script, HasSubstr("$plane using 4:5 with lines lw 2 title 'bob'"));
  EXPECT_THAT(script, HasSubstr("$plane using 6:7 with lines lw 2 title 'hand'"));
  // beside it the elements' lengths and tensions against time
  const auto network = Block(script, "$network");
  ASSERT_EQ(network.size(), 1u);
  EXPECT_EQ(network[0][1], (std::vector<double>{0.5, 0.1, 0.25, 3, 1}));
  EXPECT_THAT(script, HasSubstr("set ylabel 'length [m]'"));
  EXPECT_THAT(script, HasSubstr("set ylabel 'tension [N]'"));
  EXPECT_THAT(script, Not(HasSubstr("activation")));
}

TEST(SpatialPlot, EachFrameHoldsTheNodesOfTheNearestRowAndTheElementsThroughTheirViaPoints) {
  const Scenario scenario = PlanarScenario();
  // 0.4 is nearest the row at 0.5; 0.75 is as near 0.5 as 1 and takes the earlier
  const std::string script =
      SpatialFramesPlotScript(PlanarRun(), {0.0, 0.4, 0.75, 1.0}, &scenario, Options("f.png"));
  const std::vector<std::vector<Point>> nodes_at_row = {{{0, 0}, {0.1, 0}, {0.2, 0.05}},
                                                        {{0, 0}, {0.06, -0.08}, {0.21, 0.04}},
                                                        {{0, 0}, {-0.02, -0.098}, {0.22, 0.03}}};
  const int row_of_frame[] = {0, 1, 1, 2};
  const char* titles[] = {"t = 0 s", "t = 0.5 s", "t = 0.5 s", "t = 1 s"};
  for (int f = 0; f < 4; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    const auto sets = Block(script, "$frame" + std::to_string(f));
    ASSERT_EQ(sets.size(), 3u);  // the nodes, link, cord
    const std::vector<Point>& nodes = nodes_at_row[static_cast<std::size_t>(row_of_frame[f])];
    EXPECT_EQ(Points(sets[0]), nodes);
    // link: pivot -> bob
    EXPECT_EQ(Points(sets[1]), (std::vector<Point>{nodes[0], nodes[1]}));
    // cord: pivot -> the fixed via point -> over the bob -> hand
    EXPECT_EQ(Points(sets[2]), (std::vector<Point>{nodes[0], {0.05, 0.07}, nodes[1], nodes[2]}));
    EXPECT_THAT(script, HasSubstr(std::string("set title '") + titles[f] + "'\n"));
  }
  EXPECT_THAT(script, HasSubstr("set multiplot layout 1,4 "));
  EXPECT_THAT(script, HasSubstr("set size ratio -1\n"));
  // the key names the elements once, in the first frame
  EXPECT_THAT(script, HasSubstr("$frame0 index 2 using 1:2 with lines lw 2 lc 2 title 'cord'"));
  EXPECT_THAT(script, HasSubstr("$frame1 index 2 using 1:2 with lines lw 2 lc 2 notitle"));
  // common axes around every point (x -0.02..0.22, y -0.098..0.07), 5% of 0.24 beyond
  const std::vector<double> x = Range(script, "xrange"), y = Range(script, "yrange");
  ASSERT_EQ(x.size(), 2u);
  ASSERT_EQ(y.size(), 2u);
  EXPECT_NEAR(x[0], -0.032, 1e-15);
  EXPECT_NEAR(x[1], 0.232, 1e-15);
  EXPECT_NEAR(y[0], -0.11, 1e-15);
  EXPECT_NEAR(y[1], 0.082, 1e-15);
}

TEST(SpatialPlot, WithoutTheScenarioAFrameHasTheNodesOnly) {
  const std::string script = SpatialFramesPlotScript(PlanarRun(), {1.0}, nullptr, Options("f.png"));
  const auto sets = Block(script, "$frame0");
  ASSERT_EQ(sets.size(), 1u);
  EXPECT_EQ(Points(sets[0]), (std::vector<Point>{{0, 0}, {-0.02, -0.098}, {0.22, 0.03}}));
  EXPECT_THAT(script, HasSubstr("set multiplot layout 1,1 "));
  EXPECT_THAT(script, Not(HasSubstr("index 1")));
}

TEST(SpatialPlot, EvenlySpacedTimesRunFromTheFirstRowToTheLast) {
  EXPECT_EQ(EvenlySpacedFrameTimes(PlanarRun(), 5),
            (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  EXPECT_EQ(EvenlySpacedFrameTimes(PlanarRun(), 1), (std::vector<double>{0.0}));
  EXPECT_THAT([] { EvenlySpacedFrameTimes(PlanarRun(), 0); },
              ThrowsMessage<ParameterError>(HasSubstr("frame-count = 0: must be 1 to 36")));
  // a strip of 6 is two rows of 4 places
  const std::string script = SpatialFramesPlotScript(
      PlanarRun(), EvenlySpacedFrameTimes(PlanarRun(), 6), nullptr, Options("f.png"));
  EXPECT_THAT(script, HasSubstr("set multiplot layout 2,4 "));
}

TEST(SpatialPlot, ATimeOutsideTheRunIsRefused) {
  EXPECT_THAT(
      [] {
        SpatialFramesPlotScript(PlanarRun(), {0.5, 1.5}, nullptr, Options("f.png"));
      },
      ThrowsMessage<ParameterError>(HasSubstr("frames = 1.5: outside the run's times: ")));
  EXPECT_THAT([] { SpatialFramesPlotScript(PlanarRun(), {-0.1}, nullptr, Options("f.png")); },
              ThrowsMessage<ParameterError>(HasSubstr("holds t = 0 to 1 s")));
  EXPECT_THAT([] { SpatialFramesPlotScript(PlanarRun(), {}, nullptr, Options("f.png")); },
              ThrowsMessage<ParameterError>(HasSubstr("give 1 to 36 times")));
}

TEST(SpatialPlot, AScenarioWhoseNodesDifferFromTheCsvsIsRefused) {
  Scenario missing = PlanarScenario();
  missing.nodes.push_back(Node::Fixed("elbow", Coordinates{0.3, 0.0, 0.0}));
  EXPECT_THAT([&] { SpatialFramesPlotScript(PlanarRun(), {0.0}, &missing, Options("f.png")); },
              ThrowsMessage<InputError>(HasSubstr("planar.yaml does not match ")));
  EXPECT_THAT([&] { SpatialFramesPlotScript(PlanarRun(), {0.0}, &missing, Options("f.png")); },
              ThrowsMessage<InputError>(
                  HasSubstr("nodes[3] 'elbow' has no columns elbow.x, elbow.y in the CSV")));
  Scenario fewer = PlanarScenario();
  fewer.nodes.erase(fewer.nodes.begin() + 2);
  fewer.elements.pop_back();
  EXPECT_THAT([&] { SpatialFramesPlotScript(PlanarRun(), {0.0}, &fewer, Options("f.png")); },
              ThrowsMessage<InputError>(HasSubstr(
                  "the CSV has columns hand.x, hand.y of a node the scenario does not have")));
  Scenario in_space = PlanarScenario();
  in_space.space.dimensions = 3;
  EXPECT_THAT([&] { SpatialFramesPlotScript(PlanarRun(), {0.0}, &in_space, Options("f.png")); },
              ThrowsMessage<InputError>(HasSubstr(
                  "the scenario has dimensions: 3, the CSV node columns of 2 (NODE.x, NODE.y)")));
}

TEST(SpatialPlot, ARunInSpaceIsDrawnInItsXYProjection) {
  const CsvTable run = ReadCsv(
      testing::WriteTempFile("space.csv",
                             "t,a.x,a.y,a.z,b.x,b.y,b.z,s.length,s.tension\n"
                             "0,0,0,0,0.1,0.2,0.3,0.374,0\n1,0,0,0,0.2,0.1,-0.3,0.374,0\n"));
  ASSERT_TRUE(IsSpatialTrajectory(run));
  const std::string path = SpatialPathPlotScript(run, Options("p.png"));
  EXPECT_EQ(Block(path, "$plane")[0][1], (std::vector<double>{1, 0, 0, 0.2, 0.1}));
  EXPECT_THAT(path, HasSubstr("set xlabel 'x [m] (x-y projection)'"));
  const std::string frames = SpatialFramesPlotScript(run, {1.0}, nullptr, Options("f.png"));
  EXPECT_EQ(Points(Block(frames, "$frame0")[0]), (std::vector<Point>{{0, 0}, {0.2, 0.1}}));
  // some nodes with z and some without is neither a plane nor space
  const CsvTable mixed =
      ReadCsv(testing::WriteTempFile("mixed.csv", "t,a.x,a.y,a.z,b.x,b.y\n0,0,0,0,1,1\n"));
  EXPECT_THAT([&] { IsSpatialTrajectory(mixed); },
              ThrowsMessage<InputError>(HasSubstr("1 of its 2 nodes have a NODE.z column")));
}

TEST(SpatialPlot, ANodeNameEntersTheScriptOnlyAsAString) {
  const CsvTable run =
      ReadCsv(testing::WriteTempFile("quote.csv", "t,it's.x,it's.y\n0,0,0\n1,0.1,0.1\n"));
  EXPECT_THAT(SpatialPathPlotScript(run, Options("p.png")),
              HasSubstr("title 'it'.sprintf(\"%c\",39).'s'"));
}

// A chain of `n` free nodes in the plane, each joined to the last by a spring and beside it
// a damper (2 n elements), two rows: node k at (k, 0) then (k, 0.1 k).
std::pair<CsvTable, Scenario> Chain(int n) {
  CsvTable table;
  table.source = "chain.csv";
  table.header = {"t"};
  Scenario s;
  s.source = "chain.yaml";
  s.space = Space{2, {}};
  for (int k = 0; k < n; ++k) {
    const std::string name = "n" + std::to_string(k);
    table.header.push_back(name + ".x");
    table.header.push_back(name + ".y");
    s.nodes.push_back(Node::Free(name, 1.0, Coordinates{1.0 * k, 0.0, 0.0}));
    if (k > 0) {
      const std::string before = "n" + std::to_string(k - 1);
      s.elements.push_back(Element::Spring("s" + name, before, name, 1.0, 1.0));
      s.elements.push_back(Element::Damper("d" + name, before, name, 1.0));
    }
  }
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    table.header.push_back(s.elements[e].name + ".length");
  }
  for (int r = 0; r < 2; ++r) {
    std::vector<std::string> row = {std::to_string(r)};
    for (int k = 0; k < n; ++k) {
      row.push_back(std::to_string(k));
      row.push_back(std::to_string(0.1 * k * r));
    }
    for (std::size_t e = 0; e < s.elements.size(); ++e) row.push_back("1");
    table.rows.push_back(row);
    table.lines.push_back(static_cast<std::size_t>(r) + 2);
  }
  return {table, s};
}

TEST(SpatialPlot, ManyNodesAndElementsAreDrawnAsOneCurveEachAndKeyedByTheirCount) {
  // 30 nodes, 58 elements: a titled curve per node or element made gnuplot pass over every
  // column of a wide block for each (minutes for a 32 x 32 lattice); one curve of many
  // pieces draws them, its data sets one per node (or line)
  const auto [table, scenario] = Chain(30);
  const std::string paths = SpatialPathPlotScript(table, Options("paths.png"));
  const auto plane = Block(paths, "$plane");
  ASSERT_EQ(plane.size(), 30u);
  EXPECT_EQ(plane[29], (std::vector<std::vector<double>>{{29, 0}, {29, 2.9}}));
  EXPECT_THAT(paths, HasSubstr("plot $plane using 1:2:(column(-2) + 1) with lines lw 1 lc "
                               "variable notitle"));
  EXPECT_THAT(paths, Not(HasSubstr("title 'n0'")));
  // the 58 lengths: one block of 58 data sets, one key entry
  EXPECT_EQ(Block(paths, "$network_0").size(), 58u);
  EXPECT_THAT(paths, HasSubstr("keyentry with lines lw 1 lc 1 title '58 lines'"));
  // the frames: elements by kind, each kind one data set of its elements' pieces
  const std::string frames =
      SpatialFramesPlotScript(table, {0.0, 1.0}, &scenario, Options("frames.png"));
  const auto frame = Block(frames, "$frame1");
  ASSERT_EQ(frame.size(), 3u);  // the nodes, the springs, the dampers
  EXPECT_EQ(frame[0].size(), 30u);
  EXPECT_EQ(frame[1].size(), 2u * 29u);  // 29 springs of 2 points each
  EXPECT_THAT(frames, HasSubstr("title 'springs (29)'"));
  EXPECT_THAT(frames, HasSubstr("title 'dampers (29)'"));
  EXPECT_THAT(frames, Not(HasSubstr("title 'sn1'")));
}

TEST(SpatialPlot, AFewElementsKeepAKeyEntryEach) {
  const auto [table, scenario] = Chain(5);
  const std::string frames =
      SpatialFramesPlotScript(table, {0.0}, &scenario, Options("frames.png"));
  EXPECT_THAT(frames, HasSubstr("title 'sn1'"));
  EXPECT_THAT(frames, HasSubstr("title 'dn4'"));
  const std::string paths = SpatialPathPlotScript(table, Options("paths.png"));
  EXPECT_THAT(paths, HasSubstr("title 'n4'"));
}

}  // namespace
}  // namespace musclesim
