#include "musclesim/studies/plot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>

#include "musclesim/errors.h"
#include "musclesim/io/model_yaml.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const char* const kHeader =
    "t,length,shortening_velocity,activation,tension_passive,tension_active,tension_total,load,phase\n";

CsvTable Trajectory() {
  const std::string path = testing::WriteTempFile("trajectory.csv",
      std::string(kHeader) +
      "0,0.1,0,0,0,0,0,0,isometric\n"
      "0.1,0.099,0.02,1,0,60,60,40,concentric\n"
      "0.2,0.097,0.02,1,0,58,58,40,concentric\n"
      "0.3,0.098,-0.01,1,0,70,70,80,eccentric\n");
  return ReadCsv(path);
}

TEST(Plot, TrajectoryScriptHasEveryPanelAndPhase) {
  PlotOptions options;
  options.output = "run.png";
  const std::string script = TrajectoryPlotScript(Trajectory(), options);
  EXPECT_THAT(script, HasSubstr("$trajectory << EOD\n0 0.1 0 0 0 0 0 0\n0.1 0.099 0.02 1 0 60 60 40\n"));
  EXPECT_THAT(script, HasSubstr("set multiplot layout 4,1"));
  for (const char* label : {"length [m]", "shortening velocity [m/s]", "activation [-]", "tension [N]",
                            "time [s]"}) {
    EXPECT_THAT(script, HasSubstr(label));
  }
  for (const char* series : {"title 'length'", "title 'passive'", "title 'active'", "title 'total'",
                             "title 'load'", "title 'concentric'", "title 'eccentric'",
                             "title 'isometric'"}) {
    EXPECT_THAT(script, HasSubstr(series));
  }
  // three runs of phase: isometric [0, 0.1], concentric [0.1, 0.3], eccentric from 0.3 (empty)
  EXPECT_THAT(script, HasSubstr("set object 1 rect from first 0, graph 0 to first 0.1, graph 1 fc rgb '#e5e5e5'"));
  EXPECT_THAT(script, HasSubstr("set object 2 rect from first 0.1, graph 0 to first 0.3, graph 1 fc rgb '#9ecae1'"));
}

TEST(Plot, MissingColumnsAreNamed) {
  const std::string path = testing::WriteTempFile("short.csv", "t,length,load\n0,0.1,0\n");
  PlotOptions options;
  options.output = "run.png";
  EXPECT_THAT([&] { TrajectoryPlotScript(ReadCsv(path), options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr(
                  ": missing columns: shortening_velocity, activation, tension_passive, "
                  "tension_active, tension_total, phase")));
}

TEST(Plot, CurvesScriptDrawsEveryComponentAndMarksOptimalRange) {
  PlotOptions options;
  options.output = "curves.png";
  const TensionModel model(LoadModelSpec(testing::ScenarioPath("concentric.yaml")).params);
  const std::string script = CurvesPlotScript(model, options);
  EXPECT_THAT(script, HasSubstr("set object 1 rect from first 0.095, graph 0 to first 0.105"));
  EXPECT_THAT(script, HasSubstr("title 'passive T_p'"));
  EXPECT_THAT(script, HasSubstr("title 'total'"));
  for (const char* column : {"using 1:5 ", "using 1:6 ", "using 1:7 "}) {  // three Gaussians
    EXPECT_THAT(script, HasSubstr(column));
  }
  EXPECT_THAT(script, Not(HasSubstr("using 1:8 ")));
  EXPECT_THAT(script, HasSubstr("title 'g(v), n = 3, eps = 0.001 m/s'"));
}

CsvTable Summary() {
  return ReadCsv(testing::WriteTempFile("summary.csv",
      "index,load[0].after,model.velocity.n,status,work,steps,rhs_evals,wall_seconds,message\n"
      "0,10,1,ok,0.5,100,150,0.001,\n"
      "1,10,3,ok,0.4,120,170,0.001,\n"
      "2,20,1,failed,,10,15,0.001,\"CVODE failed, badly\"\n"
      "3,20,3,ok,0.7,130,190,0.001,\n"));
}

TEST(Plot, SweepScriptDrawsALinePerColourGroupWithoutFailedRows) {
  PlotOptions options;
  options.output = "sweep.svg";
  const std::string script =
      SweepPlotScript(Summary(), "load[0].after", std::nullopt, std::string("model.velocity.n"), options);
  EXPECT_THAT(script, HasSubstr("$group0 << EOD\n10 0.5\nEOD\n"));
  EXPECT_THAT(script, HasSubstr("$group1 << EOD\n10 0.4\n20 0.7\nEOD\n"));
  EXPECT_THAT(script, HasSubstr("title 'model.velocity.n = 1'"));
  EXPECT_THAT(script, HasSubstr("title 'model.velocity.n = 3'"));
  EXPECT_THAT(script, HasSubstr("set ylabel 'work'"));
}

TEST(Plot, SweepOfTwoPathsWithoutColourIsAHeatMap) {
  PlotOptions options;
  options.output = "sweep.png";
  const std::string script = SweepPlotScript(Summary(), "load[0].after", std::string("steps"),
                                             std::nullopt, options);
  EXPECT_THAT(script, HasSubstr("with boxxyerror"));
  EXPECT_THAT(script, HasSubstr("set ylabel 'model.velocity.n'"));
  EXPECT_THAT(script, HasSubstr("$cells << EOD\n10 1 5 15 0 2 100\n"));
}

TEST(Plot, SweepRejectsUnknownPaths) {
  PlotOptions options;
  options.output = "sweep.png";
  EXPECT_THAT([&] { SweepPlotScript(Summary(), "mass", std::nullopt, std::nullopt, options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr(
                  "--x mass: not a swept path of " )));
  EXPECT_THAT([&] { SweepPlotScript(Summary(), "load[0].after", std::string("speed"), std::nullopt, options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("--y speed: not a metric")));
}

TEST(Plot, OptionsNeedAKnownFormatAndSize) {
  PlotOptions options;
  options.output = "figure.jpg";
  EXPECT_THAT([&] { Validate(options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("must end in .png or .svg")));
  options.output = "figure.png";
  options.width = 20;
  EXPECT_THAT([&] { Validate(options); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("--size 20x750: width and height")));
}

}  // namespace
}  // namespace musclesim
