#include "musclesim/plot/plot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/model_yaml.h"
#include "support/scenario_files.h"
#include "support/fresh_directory.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;

const char* const kHeader =
    "t,length,shortening_velocity,activation,tension_passive,tension_active,tension_total,load,"
    "phase\n";

CsvTable Trajectory() {
  const std::string path =
      testing::WriteTempFile("trajectory.csv", std::string(kHeader) +
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
  EXPECT_THAT(script,
              HasSubstr("$trajectory << EOD\n0 0.1 0 0 0 0 0 0\n0.1 0.099 0.02 1 0 60 60 40\n"));
  EXPECT_THAT(script, HasSubstr("set multiplot layout 4,1"));
  for (const char* label :
       {"length [m]", "shortening velocity [m/s]", "activation [-]", "tension [N]", "time [s]"}) {
    EXPECT_THAT(script, HasSubstr(label));
  }
  for (const char* series :
       {"title 'length'", "title 'passive'", "title 'active'", "title 'total'", "title 'load'",
        "title 'concentric'", "title 'eccentric'", "title 'isometric'"}) {
    EXPECT_THAT(script, HasSubstr(series));
  }
  // three runs of phase: isometric [0, 0.1], concentric [0.1, 0.3], eccentric from 0.3 (empty)
  EXPECT_THAT(
      script,
      HasSubstr("set object 1 rect from first 0, graph 0 to first 0.1, graph 1 fc rgb '#e5e5e5'"));
  EXPECT_THAT(
      script,
      HasSubstr(
          "set object 2 rect from first 0.1, graph 0 to first 0.3, graph 1 fc rgb '#9ecae1'"));
}

CsvTable NetworkTrajectory() {
  const std::string path = testing::WriteTempFile(
      "network.csv",
      "t,wall.position,wall.velocity,it's.position,it's.velocity,flexor.length,flexor.tension,"
      "flexor.shortening_velocity,flexor.activation,flexor.tension_passive,flexor.tension_active,"
      "flexor.phase,spring.length,spring.tension,it's.load\n"
      "0,0,0,0.1,0,0.1,0,0,0,0,0,isometric,0.1,0,5\n"
      "0.5,0,0,0.09,-0.02,0.09,40,0.02,1,0,40,concentric,0.09,-1,5\n");
  return ReadCsv(path);
}

TEST(Plot, NetworkScriptHasAPanelPerKindAndALinePerPart) {
  PlotOptions options;
  options.output = "network.png";
  const CsvTable table = NetworkTrajectory();
  ASSERT_TRUE(IsNetworkTrajectory(table));
  EXPECT_FALSE(IsNetworkTrajectory(Trajectory()));
  const std::string script = NetworkPlotScript(table, options);
  // the inline data: t, the positions, the lengths, the tensions, the activations
  EXPECT_THAT(script,
              HasSubstr("$network << EOD\n0 0 0.1 0.1 0.1 0 0 0\n0.5 0 0.09 0.09 0.09 40 -1 1\n"));
  EXPECT_THAT(script, HasSubstr("set multiplot layout 4,1"));
  EXPECT_THAT(script, HasSubstr("$network using 1:2 with lines lw 2 title 'wall'"));
  // a quote in a node's name enters the script only through GnuplotString
  EXPECT_THAT(script,
              HasSubstr("$network using 1:3 with lines lw 2 title 'it'.sprintf(\"%c\",39).'s'"));
  EXPECT_THAT(script, HasSubstr("$network using 1:7 with lines lw 2 title 'spring'"));
  EXPECT_THAT(script, HasSubstr("$network using 1:8 with lines lw 2 title 'flexor'"));
  for (const char* label :
       {"position [m]", "length [m]", "tension [N]", "activation [-]", "time [s]"}) {
    EXPECT_THAT(script, HasSubstr(label));
  }
}

TEST(Plot, NetworkWithoutActuatorsHasThreePanels) {
  const std::string path = testing::WriteTempFile(
      "springs.csv",
      "t,m.position,m.velocity,s.length,s.tension,m.load\n0,0.1,0,0.1,0,0\n1,0.2,0,0.2,5,0\n");
  PlotOptions options;
  options.output = "springs.png";
  EXPECT_THAT(NetworkPlotScript(ReadCsv(path), options), HasSubstr("set multiplot layout 3,1"));
}

TEST(Plot, NetworkCellThatIsNotFiniteIsNamed) {
  const std::string path = testing::WriteTempFile(
      "nan.csv", "t,m.position,m.velocity,s.length,s.tension\n0,0.1,0,0.1,0\n1,nan,0,0.2,5\n");
  PlotOptions options;
  options.output = "nan.png";
  EXPECT_THAT([&] { NetworkPlotScript(ReadCsv(path), options); },
              ThrowsMessage<InputError>(HasSubstr("nan.csv:3: column m.position = 'nan'")));
}

TEST(Plot, MissingColumnsAreNamed) {
  const std::string path = testing::WriteTempFile("short.csv", "t,length,load\n0,0.1,0\n");
  PlotOptions options;
  options.output = "run.png";
  EXPECT_THAT([&] { TrajectoryPlotScript(ReadCsv(path), options); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr(": missing columns: shortening_velocity, activation, tension_passive, "
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
  return ReadCsv(testing::WriteTempFile(
      "summary.csv",
      "index,load[0].after,model.velocity.n,status,work,steps,rhs_evals,wall_seconds,message\n"
      "0,10,1,ok,0.5,100,150,0.001,\n"
      "1,10,3,ok,0.4,120,170,0.001,\n"
      "2,20,1,failed,,10,15,0.001,\"CVODE failed, badly\"\n"
      "3,20,3,ok,0.7,130,190,0.001,\n"));
}

TEST(Plot, SweepScriptDrawsALinePerColourGroupWithoutFailedRows) {
  PlotOptions options;
  options.output = "sweep.svg";
  const std::string script = SweepPlotScript(Summary(), "load[0].after", std::nullopt,
                                             std::string("model.velocity.n"), options);
  EXPECT_THAT(script, HasSubstr("$group0 << EOD\n10 0.5\nEOD\n"));
  EXPECT_THAT(script, HasSubstr("$group1 << EOD\n10 0.4\n20 0.7\nEOD\n"));
  EXPECT_THAT(script, HasSubstr("title 'model.velocity.n = 1'"));
  EXPECT_THAT(script, HasSubstr("title 'model.velocity.n = 3'"));
  EXPECT_THAT(script, HasSubstr("set ylabel 'work'"));
}

TEST(Plot, SweepOfTwoPathsWithoutColourIsAHeatMap) {
  PlotOptions options;
  options.output = "sweep.png";
  const std::string script =
      SweepPlotScript(Summary(), "load[0].after", std::string("steps"), std::nullopt, options);
  EXPECT_THAT(script, HasSubstr("with boxxyerror"));
  EXPECT_THAT(script, HasSubstr("set ylabel 'model.velocity.n'"));
  EXPECT_THAT(script, HasSubstr("$cells << EOD\n10 1 5 15 0 2 100\n"));
}

TEST(Plot, SweepRejectsUnknownPaths) {
  PlotOptions options;
  options.output = "sweep.png";
  EXPECT_THAT(
      [&] { SweepPlotScript(Summary(), "mass", std::nullopt, std::nullopt, options); },
      ::testing::ThrowsMessage<ParameterError>(HasSubstr("x = mass: not a swept path of ")));
  EXPECT_THAT(
      [&] {
        SweepPlotScript(Summary(), "load[0].after", std::string("speed"), std::nullopt, options);
      },
      ::testing::ThrowsMessage<ParameterError>(HasSubstr("y = speed: not a metric")));
}

TEST(Plot, OptionsNeedAKnownFormatAndSize) {
  PlotOptions options;
  options.output = "figure.jpg";
  EXPECT_THAT([&] { Validate(options); },
              ::testing::ThrowsMessage<ParameterError>(HasSubstr("must end in .png or .svg")));
  options.output = "figure.png";
  options.width = 20;
  EXPECT_THAT([&] { Validate(options); }, ::testing::ThrowsMessage<ParameterError>(
                                              HasSubstr("size = 20x750: width and height")));
}

// --- hostile text -----------------------------------------------------------------------

// What GnuplotString promises: single-quoted pieces, each quote of the text joined in as
// sprintf("%c",39).
std::string SingleQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'.sprintf(\"%c\",39).'") : std::string(1, c);
  return out + "'";
}

// Strings that would run `touch SENTINEL`, end a command or restyle text if pasted into a
// gnuplot script unquoted or double-quoted.
std::vector<std::string> HostileTexts(const std::string& sentinel) {
  return {"it's",
          "'",
          "''",
          "back\\slash\\",
          "\\",
          "system(\"touch " + sentinel + "\")",
          "'.system('touch " + sentinel + "').'",
          "`touch " + sentinel + "`",
          "$(touch " + sentinel + ")",
          "@GPVAL_PWD ; set output 'x' # not a comment",
          "a^{b}_c @d &{e} ~f",  // enhanced-text markup
          "<svg onload=x>&amp;",
          "\u00e9 \u20ac \U0001d11e",
          std::string(5000, 'x') + "'" + std::string(5000, 'y')};
}

std::size_t Lines(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

// A field of a CSV file as RFC 4180 quotes it.
std::string CsvField(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A summary whose swept paths are named `x_name` and `color_name`, the second taking the
// values 1 and `color_value`.
CsvTable SummaryNamed(const std::string& x_name, const std::string& color_name,
                      const std::string& color_value) {
  return ReadCsv(testing::WriteTempFile("named_summary.csv",
                                        "index," + CsvField(x_name) + "," + CsvField(color_name) +
                                            ",status,work,steps,rhs_evals,wall_seconds,message\n"
                                            "0,10,1,ok,0.5,100,150,0.001,\n"
                                            "1,20,1,ok,0.6,100,150,0.001,\n"
                                            "2,10," +
                                            CsvField(color_value) + ",ok,0.7,100,150,0.001,\n"));
}

TEST(GnuplotString, QuotesPiecesAndJoinsQuotesIn) {
  EXPECT_EQ(GnuplotString("it's", "--title"), "'it'.sprintf(\"%c\",39).'s'");
  EXPECT_EQ(GnuplotString("''", "--title"), "''.sprintf(\"%c\",39).''.sprintf(\"%c\",39).''");
  EXPECT_EQ(GnuplotString("a\\b\\", "--title"), "'a\\b\\'");
  EXPECT_EQ(GnuplotString("`x` $(y) @z \"w\"", "--title"), "'`x` $(y) @z \"w\"'");
  EXPECT_EQ(GnuplotString("", "--title"), "''");
}

bool HaveGnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

// What gnuplot prints (standard output and error) for `script`.
std::string GnuplotOutput(const std::string& script) {
  const std::string path = testing::WriteTempFile("script.gp", script);
  FILE* pipe = ::popen(("gnuplot '" + path + "' 2>&1").c_str(), "r");
  std::string out;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  ::pclose(pipe);
  return out;
}

TEST(GnuplotString, GnuplotReadsBackEveryString) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  // gnuplot's own '' escape fails on the first five; with a quote inside double quotes,
  // its macro expander would lose track of the quotes and replace @GPVAL_PWD
  const std::vector<std::string> texts = {"'",
                                          "''",
                                          "'a",
                                          "a''b",
                                          "'''",
                                          "it's",
                                          "'@GPVAL_PWD",
                                          "\"'@GPVAL_PWD",
                                          "'\"@GPVAL_PWD'",
                                          "@GPVAL_PWD",
                                          "\\",
                                          "a\\",
                                          "`echo x`",
                                          "# no comment",
                                          "a ; print 1",
                                          "\u00e9'\u20ac"};
  std::string script = "set print '-'\n", expected;
  for (const std::string& text : texts) {
    script += "print " + GnuplotString(text, "--title") + "\n";
    expected += text + "\n";
  }
  // all on one line too, where the quotes of one string could confuse the next
  script += "print ''";
  for (const std::string& text : texts) {
    script += ".'|'." + GnuplotString(text, "--title");
    expected += "|" + text;
  }
  EXPECT_EQ(GnuplotOutput(script + "\n"), expected + "\n");
}

TEST(GnuplotString, RejectsEveryControlByteNamingTheSourceAndTheRule) {
  for (int byte = 0; byte < 0x80; ++byte) {
    const std::string text = std::string("a") + static_cast<char>(byte) + "b";
    if (byte >= 0x20 && byte != 0x7f) {
      EXPECT_NO_THROW(GnuplotString(text, "--title")) << byte;
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "%02x", byte);
    EXPECT_THAT([&] { GnuplotString(text, "--title"); },
                ThrowsMessage<InputError>(HasSubstr(std::string("--title 'a\\x") + hex +
                                                    "b': must not contain control characters "
                                                    "(bytes below 0x20, and 0x7f); byte 0x" +
                                                    hex + " at offset 1")));
  }
}

TEST(GnuplotString, RejectsTextThatIsNotUtf8) {
  for (const char* bad : {"\xff", "\x80", "ab\xc3", "\xc0\xaf", "\xe0\x80\xaf", "\xed\xa0\x80",
                          "\xf4\x90\x80\x80", "\xf5\x80\x80\x80"}) {
    EXPECT_THAT([&] { GnuplotString(bad, "-o"); },
                ThrowsMessage<InputError>(HasSubstr("': must be valid UTF-8; byte 0x")))
        << bad;
  }
  // the last character before the surrogates, and the last of Unicode
  for (const char* good : {"\u00e9", "\u20ac", "\U0001d11e", "\xed\x9f\xbf", "\xf4\x8f\xbf\xbf"}) {
    EXPECT_EQ(GnuplotString(good, "-o"), "'" + std::string(good) + "'");
  }
}

TEST(Plot, HostileTitlesAreQuotedInEveryScript) {
  PlotOptions options;
  options.output = "figure.png";
  const TensionModel model(LoadModelSpec(testing::ScenarioPath("concentric.yaml")).params);
  const auto scripts = [&] {
    return std::vector<std::string>{TrajectoryPlotScript(Trajectory(), options),
                                    CurvesPlotScript(model, options),
                                    SweepPlotScript(Summary(), "load[0].after", std::nullopt,
                                                    std::string("model.velocity.n"), options)};
  };
  options.title = "plain";
  const std::vector<std::string> plain = scripts();
  for (const std::string& title : HostileTexts("F")) {
    options.title = title;
    const std::vector<std::string> hostile = scripts();
    for (std::size_t k = 0; k < hostile.size(); ++k) {
      EXPECT_THAT(hostile[k], HasSubstr(" title " + SingleQuoted(title) + "\n")) << k;
      EXPECT_EQ(Lines(hostile[k]), Lines(plain[k])) << k << ": " << title.substr(0, 40);
    }
  }
}

TEST(Plot, EveryScriptDrawsTextWithoutMarkup) {
  PlotOptions options;
  options.output = "figure.svg";
  const TensionModel model(LoadModelSpec(testing::ScenarioPath("concentric.yaml")).params);
  for (const std::string& script :
       {TrajectoryPlotScript(Trajectory(), options), CurvesPlotScript(model, options),
        SweepPlotScript(Summary(), "load[0].after", std::nullopt, std::nullopt, options)}) {
    EXPECT_THAT(script, HasSubstr("set termoption noenhanced\n"));
  }
}

TEST(Plot, HostileColumnNamesAndValuesAreQuoted) {
  PlotOptions options;
  options.output = "sweep.png";
  for (const std::string& text : HostileTexts("F")) {
    const std::string x = "x " + text, color = "c " + text;
    const std::string script =
        SweepPlotScript(SummaryNamed(x, color, text), x, std::nullopt, color, options);
    EXPECT_THAT(script, HasSubstr("set xlabel " + SingleQuoted(x) + "\n"));
    EXPECT_THAT(script, HasSubstr("set title " + SingleQuoted("work against " + x) + "\n"));
    EXPECT_THAT(script, HasSubstr(" title " + SingleQuoted(color + " = " + text)));
    // the same script as for plain names, but for the names: two groups, one line each
    const std::string plain =
        SweepPlotScript(SummaryNamed("x", "c", "2"), "x", std::nullopt, std::string("c"), options);
    EXPECT_EQ(Lines(script), Lines(plain)) << text.substr(0, 40);
  }
  // the heat map's axis and colour-box labels
  const std::string x = "x " + HostileTexts("F")[6], other = "o " + HostileTexts("F")[7];
  const std::string heat =
      SweepPlotScript(SummaryNamed(x, other, "3"), x, std::nullopt, std::nullopt, options);
  EXPECT_THAT(heat, HasSubstr("set ylabel " + SingleQuoted(other) + "\n"));
  EXPECT_THAT(heat, HasSubstr("set cblabel 'work'\n"));
}

TEST(Plot, ControlCharactersFromTheCsvAreRejectedNamingWhere) {
  PlotOptions options;
  options.output = "sweep.png";
  const CsvTable tabbed = SummaryNamed("x", "c", "a\tb");
  EXPECT_THAT([&] { SweepPlotScript(tabbed, "x", std::nullopt, std::string("c"), options); },
              ThrowsMessage<InputError>(
                  HasSubstr("named_summary.csv:4: the legend entry 'c = a\\x09b': must not contain "
                            "control characters")));
  const CsvTable escaped = SummaryNamed("x", "\x1b[31m", "2");
  EXPECT_THAT([&] { SweepPlotScript(escaped, "x", std::nullopt, std::nullopt, options); },
              ThrowsMessage<InputError>(
                  HasSubstr("named_summary.csv: the other swept path '\\x1b[31m': must not contain "
                            "control characters")));
  // the file's name is the trajectory's default title
  const CsvTable named = ReadCsv(testing::WriteTempFile(
      "tab\tname.csv", std::string(kHeader) + "0,0.1,0,0,0,0,0,0,isometric\n"));
  EXPECT_THAT([&] { TrajectoryPlotScript(named, options); },
              ThrowsMessage<InputError>(HasSubstr("the CSV file's name (the default title) '")));
  options.title = "a title";
  EXPECT_NO_THROW(TrajectoryPlotScript(named, options));
}

TEST(Plot, OptionsRejectControlCharactersInTheOutputAndTitle) {
  PlotOptions options;
  options.output = "a\nsystem(\"touch F\")\n#.png";
  EXPECT_THAT([&] { Validate(options); }, ThrowsMessage<ParameterError>(HasSubstr(
                                              "output = 'a\\x0asystem(\"touch F\")\\x0a#.png': "
                                              "must not contain control characters")));
  options.output = "a.png";
  options.title = "x\nsystem(\"touch F\")\n#";
  EXPECT_THAT([&] { Validate(options); },
              ThrowsMessage<ParameterError>(HasSubstr("title = 'x\\x0asystem(\"touch F\")\\x0a#': "
                                                      "must not contain control characters")));
}

// --- malformed CSV files ----------------------------------------------------------------

TEST(Plot, SweepSummaryOfAnotherLayoutNamesWhatIsMissing) {
  PlotOptions options;
  options.output = "sweep.png";
  const std::string layout =
      "(a summary CSV of musclesim sweep has the columns index, the swept paths, status, the "
      "metrics, steps, rhs_evals, wall_seconds, message)";
  const auto error = [&](const std::string& header) {
    const std::string path = testing::WriteTempFile("layout.csv", header + "\n");
    return testing::InputErrorOf(
        path, [&] { SweepPlotScript(ReadCsv(path), "x", std::nullopt, std::nullopt, options); });
  };
  EXPECT_EQ(error("index,steps,status,x"),
            "FILE: missing columns: rhs_evals, wall_seconds, message " + layout);
  EXPECT_EQ(error("index,status,work,steps,rhs_evals,wall_seconds,message"),
            "FILE: no swept path between index and status " + layout);
  EXPECT_EQ(error("x,index,status,work,steps,rhs_evals,wall_seconds,message"),
            "FILE: index is not the first column " + layout);
  EXPECT_EQ(error("index,x,status,work,steps,rhs_evals,message,wall_seconds"),
            "FILE: steps, rhs_evals, wall_seconds, message are not the last columns, after "
            "status " +
                layout);
  EXPECT_EQ(
      error(std::string(kHeader, std::strlen(kHeader) - 1)),
      "FILE: missing columns: index, status, steps, rhs_evals, wall_seconds, message " + layout);
}

TEST(Plot, SweepWithoutMetricsPlotsSteps) {
  PlotOptions options;
  options.output = "sweep.png";
  const CsvTable table = ReadCsv(testing::WriteTempFile(
      "no_metric.csv",
      "index,x,status,steps,rhs_evals,wall_seconds,message\n0,1,ok,100,150,0.001,\n"
      "1,2,ok,120,170,0.001,\n"));
  const std::string script = SweepPlotScript(table, "x", std::nullopt, std::nullopt, options);
  EXPECT_THAT(script, HasSubstr("$group0 << EOD\n1 100\n2 120\nEOD\n"));
  EXPECT_THAT([&] { SweepPlotScript(table, "x", std::string("message"), std::nullopt, options); },
              ThrowsMessage<ParameterError>(HasSubstr("y = message: not a metric of ")));
}

TEST(Plot, CellsThatAreNotFiniteNumbersAreNamedByLineAndColumn) {
  PlotOptions options;
  options.output = "run.png";
  for (const char* cell : {"nan", "inf", "-inf", "NaN", "infinity"}) {
    const std::string path = testing::WriteTempFile(
        "nonfinite.csv", std::string(kHeader) + "0,0.1,0,0,0,0,0,0,isometric\n0.1," + cell +
                             ",0,0,0,0,0,0,isometric\n");
    EXPECT_EQ(testing::InputErrorOf(path, [&] { TrajectoryPlotScript(ReadCsv(path), options); }),
              "FILE:3: column length = '" + std::string(cell) + "': must be a finite number");
  }
  for (const char* cell : {"abc", "", "1.5x", "\x1b[2J"}) {
    const std::string path = testing::WriteTempFile(
        "text.csv", std::string(kHeader) + "0,0.1,0,0," + cell + ",0,0,0,isometric\n");
    EXPECT_THAT(testing::InputErrorOf(path, [&] { TrajectoryPlotScript(ReadCsv(path), options); }),
                HasSubstr("FILE:2: column tension_passive = '"))
        << cell;
  }
  // a swept value or a metric
  const std::string summary = testing::WriteTempFile(
      "summary_nan.csv",
      "index,x,status,work,steps,rhs_evals,wall_seconds,message\n0,1,ok,0.5,100,150,0.001,\n"
      "1,2,ok,nan,100,150,0.001,\n2,abc,ok,0.5,100,150,0.001,\n");
  EXPECT_EQ(
      testing::InputErrorOf(
          summary,
          [&] { SweepPlotScript(ReadCsv(summary), "x", std::nullopt, std::nullopt, options); }),
      "FILE:3: column work = 'nan': must be a finite number");
}

TEST(Plot, TablesWithoutRowsAreRejected) {
  PlotOptions options;
  options.output = "run.png";
  const std::string run = testing::WriteTempFile("header_only.csv", kHeader);
  EXPECT_EQ(testing::InputErrorOf(run, [&] { TrajectoryPlotScript(ReadCsv(run), options); }),
            "FILE: no rows to plot");
  const std::string sweep = testing::WriteTempFile(
      "summary_header_only.csv", "index,x,status,work,steps,rhs_evals,wall_seconds,message\n");
  EXPECT_EQ(testing::InputErrorOf(
                sweep,
                [&] { SweepPlotScript(ReadCsv(sweep), "x", std::nullopt, std::nullopt, options); }),
            "FILE: no successful row with a value of work");
}

TEST(Plot, SingleRowTrajectoryIsOnePointWithoutShading) {
  PlotOptions options;
  options.output = "run.png";
  const CsvTable one = ReadCsv(testing::WriteTempFile(
      "one_row.csv", std::string(kHeader) + "0.5,0.1,0,1,0,60,60,40,concentric\n"));
  const std::string script = TrajectoryPlotScript(one, options);
  EXPECT_THAT(script, HasSubstr("$trajectory << EOD\n0.5 0.1 0 1 0 60 60 40\nEOD\n"));
  EXPECT_THAT(script, Not(HasSubstr("set object")));
}

// --- rendering ----------------------------------------------------------------------------

std::string FreshFolder() { return testing::FreshDirectory("render_") + "/"; }

std::set<std::string> Entries(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

// The text of every <text> element of an SVG, with XML's five entities read back.
std::vector<std::string> SvgTexts(const std::string& svg) {
  static const std::pair<std::string, char> kEntities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::vector<std::string> texts;
  for (std::size_t at = svg.find("<text"); at != std::string::npos; at = svg.find("<text", at)) {
    const std::size_t begin = svg.find('>', at) + 1, end = svg.find("</text>", begin);
    std::string text = svg.substr(begin, end - begin), plain;
    for (std::size_t i = 0; i < text.size(); ++i) {
      bool entity = false;
      for (const auto& [name, c] : kEntities) {
        if (text.compare(i, name.size(), name) == 0) {
          plain += c;
          i += name.size() - 1;
          entity = true;
          break;
        }
      }
      if (!entity) plain += text[i];
    }
    texts.push_back(plain);
    at = end;
  }
  return texts;
}

TEST(Render, HostileTextIsDrawnAsWrittenAndRunsNothing) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = FreshFolder();
  const std::string sentinel = dir + "F";
  PlotOptions options;
  options.output = dir + "figure.svg";
  const TensionModel model(LoadModelSpec(testing::ScenarioPath("concentric.yaml")).params);
  for (const std::string& text : HostileTexts(sentinel)) {
    SCOPED_TRACE(text.substr(0, 40));
    options.title = text;
    for (const std::string& script :
         {TrajectoryPlotScript(Trajectory(), options), CurvesPlotScript(model, options)}) {
      Render(script, options);
      EXPECT_THAT(SvgTexts(testing::ReadFile(options.output)), ::testing::Contains(text));
      EXPECT_EQ(Entries(dir), std::set<std::string>{"figure.svg"});
    }
    // column names and a legend entry from the CSV
    options.title.clear();
    const std::string x = "x " + text, color = "c " + text;
    Render(SweepPlotScript(SummaryNamed(x, color, text), x, std::nullopt, color, options), options);
    const std::vector<std::string> texts = SvgTexts(testing::ReadFile(options.output));
    EXPECT_THAT(texts, ::testing::Contains(x));
    EXPECT_THAT(texts, ::testing::Contains(color + " = " + text));
    EXPECT_EQ(Entries(dir), std::set<std::string>{"figure.svg"});
  }
  // and as a PNG, through pngcairo
  options.output = dir + "figure.png";
  options.title = HostileTexts(sentinel)[5];
  Render(TrajectoryPlotScript(Trajectory(), options), options);
  EXPECT_EQ(Entries(dir), (std::set<std::string>{"figure.png", "figure.svg"}));
}

TEST(Render, SingleRowsRender) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = FreshFolder();
  PlotOptions options;
  options.output = dir + "run.png";
  Render(TrajectoryPlotScript(
             ReadCsv(testing::WriteTempFile(
                 "one_row.csv", std::string(kHeader) + "0.5,0.1,0,1,0,60,60,40,concentric\n")),
             options),
         options);
  options.output = dir + "line.png";
  const CsvTable one = SummaryNamed("x", "c", "1");  // three rows; keep one
  CsvTable single = one;
  single.rows.resize(1);
  single.lines.resize(1);
  Render(SweepPlotScript(single, "x", std::nullopt, std::string("c"), options), options);
  options.output = dir + "heat.png";
  Render(SweepPlotScript(single, "x", std::nullopt, std::nullopt, options), options);
  EXPECT_EQ(Entries(dir), (std::set<std::string>{"heat.png", "line.png", "run.png"}));
  for (const std::string& name : Entries(dir)) {
    EXPECT_EQ(testing::ReadFile(dir + name).substr(1, 3), "PNG") << name;
  }
}

TEST(Render, FailedRenderKeepsTheEarlierFigureAndLeavesNoTemporary) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = FreshFolder();
  PlotOptions options;
  options.output = dir + "figure.png";
  std::ofstream(options.output) << "earlier figure";
  // gnuplot fails after it opened the temporary figure, and after it drew into it
  for (const char* script : {"plot no_such_function(x)\n", "plot sin(x)\nno_such_command\n"}) {
    EXPECT_THAT([&] { Render(script, options); },
                ThrowsMessage<std::runtime_error>(HasSubstr("gnuplot failed: ")));
    EXPECT_EQ(testing::ReadFile(options.output), "earlier figure");
    EXPECT_EQ(Entries(dir), std::set<std::string>{"figure.png"});
  }
  // a folder in the figure's place cannot be replaced
  options.output = dir + "folder.png";
  std::filesystem::create_directory(options.output);
  EXPECT_THAT([&] { Render("plot sin(x)\n", options); },
              ThrowsMessage<std::runtime_error>(HasSubstr("folder.png: cannot replace the file")));
  EXPECT_EQ(Entries(dir), (std::set<std::string>{"figure.png", "folder.png"}));
  EXPECT_TRUE(std::filesystem::is_empty(options.output));
  // a missing folder is named
  options.output = dir + "missing/figure.png";
  EXPECT_THAT([&] { Render("plot sin(x)\n", options); },
              ThrowsMessage<std::runtime_error>(HasSubstr("(no folder " + dir + "missing)")));
  // success replaces the earlier figure
  options.output = dir + "figure.png";
  Render("plot sin(x)\n", options);
  EXPECT_EQ(testing::ReadFile(options.output).substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_EQ(Entries(dir), (std::set<std::string>{"figure.png", "folder.png"}));
}

}  // namespace
}  // namespace musclesim
