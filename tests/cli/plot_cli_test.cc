// End-to-end tests of `musclesim plot` on hostile and malformed input: text that would run
// commands if pasted into the gnuplot script, file names gnuplot would read as pipes, CSV
// files that are not what plot expects, a gnuplot that fails; and a run in the plane, its
// path and frames, with the frames' data against the run's CSV.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

#include "musclesim/io/readers/csv_table.h"
#include "support/scenario_files.h"
#include "support/fresh_directory.h"

extern char** environ;

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

struct Outcome {
  int exit_code;
  std::string err;  // standard error
};

// Runs the command line with `args` in the folder `dir`, without a shell, so every byte of
// every argument arrives as written; `env` entries ("NAME=value") replace the inherited ones.
Outcome RunIn(const std::string& dir, const std::vector<std::string>& args,
              const std::vector<std::string>& env = {}) {
  const std::string err_path = ::testing::TempDir() + "plot_cli_" +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                               ".err";
  std::vector<std::string> all = {MUSCLESIM_BINARY, "plot"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::vector<std::string> variables = env;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('=') + 1);
    bool replaced = false;
    for (const std::string& v : env) replaced = replaced || v.rfind(name, 0) == 0;
    if (!replaced) variables.push_back(entry);
  }
  std::vector<char*> envp;
  for (std::string& v : variables) envp.push_back(v.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()), 0);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
          testing::ReadFile(err_path)};
}

// An empty folder of its own for the running test, and `name` beside it.
std::string FreshFolder(const std::string& name = "work") {
  return testing::FreshDirectory("plot_cli_", "_" + name) + "/";
}

std::set<std::string> Entries(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

const char* const kHeader =
    "t,length,shortening_velocity,activation,tension_passive,tension_active,tension_total,load,"
    "phase\n";

std::string Trajectory() {
  return testing::WriteTempFile("run.csv", std::string(kHeader) +
                                               "0,0.1,0,0,0,0,0,0,isometric\n"
                                               "0.1,0.099,0.02,1,0,60,60,40,concentric\n"
                                               "0.2,0.098,-0.01,1,0,70,70,80,eccentric\n");
}

bool HaveGnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

TEST(PlotCli, TitleOrOutputWithANewlineIsRejectedAndRunsNothing) {
  const std::string dir = FreshFolder(), run = Trajectory();
  Outcome r = RunIn(dir, {run, "--title", "x\nsystem(\"touch F\")\n#", "-o", "a.png"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("musclesim plot: --title 'x\\x0asystem(\"touch F\")\\x0a#': must "
                               "not contain control characters (bytes below 0x20, and 0x7f); "
                               "byte 0x0a at offset 1"));
  r = RunIn(dir, {run, "-o", "a\nsystem(\"touch F\")\n#.png"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("musclesim plot: -o 'a\\x0asystem(\"touch F\")\\x0a#.png': must "
                               "not contain control characters"));
  r = RunIn(dir, {run, "--title", "\x1b[2Jred", "-o", "a.png"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--title '\\x1b[2Jred': must not contain control characters"));
  EXPECT_EQ(Entries(dir), std::set<std::string>{});
}

TEST(PlotCli, HostileTitlesAreDrawnAndRunNothing) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = FreshFolder(), run = Trajectory();
  for (const char* title : {"`touch F`", "$(touch F)", "system(\"touch F\")",
                            "'.system('touch F').'", "' . system(\"touch F\") . '",
                            "\" . system(\"touch F\") . \"", "@GPVAL_PWD'", "it''s \\"}) {
    const Outcome r = RunIn(dir, {run, "--title", title, "-o", "a.png"});
    EXPECT_EQ(r.exit_code, 0) << title << ": " << r.err;
    EXPECT_EQ(Entries(dir), std::set<std::string>{"a.png"}) << title;
  }
}

TEST(PlotCli, OutputNamesGnuplotWouldReadAsAPipeOrHomeAreFiles) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = FreshFolder(), home = FreshFolder("home"), run = Trajectory();
  // gnuplot's `set output '|command'` would start the command
  Outcome r = RunIn(dir, {run, "-o", "|touch F;.png"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Entries(dir), std::set<std::string>{"|touch F;.png"});
  // and `set output '~/...'` would write into $HOME
  std::filesystem::create_directory(dir + "~");
  r = RunIn(dir, {run, "-o", "~/t.png"}, {"HOME=" + home});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Entries(dir + "~"), std::set<std::string>{"t.png"});
  EXPECT_EQ(Entries(home), std::set<std::string>{});
}

TEST(PlotCli, MalformedCsvIsInvalidInputAndKeepsTheEarlierFigure) {
  const std::string dir = FreshFolder(), inputs = FreshFolder("inputs");
  const std::string summary_header = "index,x,status,work,steps,rhs_evals,wall_seconds,message\n";
  const std::string layout =
      " (a summary CSV of musclesim sweep has the columns index, the swept paths, status, the "
      "metrics, steps, rhs_evals, wall_seconds, message)";
  struct Case {
    std::string name, content;
    std::vector<std::string> options;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"empty.csv", "", {}, "empty.csv: empty file, no header"},
      // a spatial run's CSV with a node's .y column removed: no path plot of half a node
      {"no_y.csv",
       "t,pivot.x,pivot.y,bob.x,bob.vx,link.length,link.tension\n0,0,0,1.2,0,1.2,20\n",
       {},
       "no_y.csv: column bob.x has no bob.y beside it"},
      {"header_only.csv", kHeader, {}, "header_only.csv: no rows to plot"},
      {"text.csv",
       std::string(kHeader) + "0,abc,0,0,0,0,0,0,isometric\n",
       {},
       "text.csv:2: column length = 'abc': must be a number"},
      {"nan.csv",
       std::string(kHeader) + "0,nan,0,0,0,0,0,0,isometric\n",
       {},
       "nan.csv:2: column length = 'nan': must be a finite number"},
      {"inf.csv",
       std::string(kHeader) + "0,0.1,0,0,0,0,0,-inf,isometric\n",
       {},
       "inf.csv:2: column load = '-inf': must be a finite number"},
      {"no_phase.csv",
       "t,length,shortening_velocity,activation,tension_passive,tension_active,"
       "tension_total,load\n0,0.1,0,0,0,0,0,0\n",
       {},
       "no_phase.csv: missing columns: phase (a trajectory CSV of musclesim run)"},
      {"unknown_phase.csv",
       std::string(kHeader) + "0,0.1,0,0,0,0,0,0,isometric\n0.1,0.1,0,0,0,0,0,0,sideways\n",
       {},
       "unknown_phase.csv:3: column phase = 'sideways': must be concentric, eccentric or "
       "isometric"},
      {"short_row.csv",
       std::string(kHeader) + "0,0.1,0\n",
       {},
       "short_row.csv:2: 3 fields where the header has 9"},
      {"bad_summary.csv",
       "index,steps,status,x\n0,10,ok,1\n",
       {"--x", "x"},
       "bad_summary.csv: missing columns: rhs_evals, wall_seconds, message" + layout},
      {"unswept.csv",
       "index,status,work,steps,rhs_evals,wall_seconds,message\n0,ok,1,2,3,0.1,\n",
       {"--x", "work"},
       "unswept.csv: no swept path between index and status" + layout},
      {"trajectory_as_summary.csv",
       std::string(kHeader) + "0,0.1,0,0,0,0,0,0,isometric\n",
       {"--x", "t"},
       "trajectory_as_summary.csv: missing columns: index, status, steps, rhs_evals, "
       "wall_seconds, message" +
           layout},
      {"all_failed.csv",
       summary_header + "0,1,failed,,10,15,0.001,diverged\n",
       {"--x", "x"},
       "all_failed.csv: no successful row with a value of work"},
      {"metric_nan.csv",
       summary_header + "0,1,ok,nan,10,15,0.001,\n",
       {"--x", "x"},
       "metric_nan.csv:2: column work = 'nan': must be a finite number"},
      {"swept_text.csv",
       summary_header + "0,fast,ok,1,10,15,0.001,\n",
       {"--x", "x"},
       "swept_text.csv:2: column x = 'fast': must be a number"},
  };
  std::ofstream(dir + "a.png") << "earlier figure";
  for (const Case& c : cases) {
    std::ofstream(inputs + c.name) << c.content;
    std::vector<std::string> args = {inputs + c.name, "-o", "a.png"};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const Outcome r = RunIn(dir, args);
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr(c.message)) << c.name;
    EXPECT_THAT(r.err, Not(HasSubstr("error:"))) << c.name;  // the form of exit 1's messages
    EXPECT_EQ(testing::ReadFile(dir + "a.png"), "earlier figure") << c.name;
    EXPECT_EQ(Entries(dir), std::set<std::string>{"a.png"}) << c.name;
  }
}

TEST(PlotCli, SingleRowsAndSummariesWithoutMetricsArePlotted) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const std::string dir = FreshFolder(), inputs = FreshFolder("inputs");
  std::ofstream(inputs + "one_row.csv") << kHeader << "0.5,0.1,0,1,0,60,60,40,concentric\n";
  std::ofstream(inputs + "one_point.csv")
      << "index,x,status,work,steps,rhs_evals,wall_seconds,message\n0,0,ok,1,10,15,0.001,\n";
  std::ofstream(inputs + "no_metric.csv")
      << "index,x,status,steps,rhs_evals,wall_seconds,message\n0,1,ok,10,15,0.001,\n"
         "1,2,ok,12,17,0.001,\n";
  EXPECT_EQ(RunIn(dir, {inputs + "one_row.csv", "-o", "run.png"}).exit_code, 0);
  EXPECT_EQ(RunIn(dir, {inputs + "one_point.csv", "--x", "x", "-o", "point.png"}).exit_code, 0);
  EXPECT_EQ(RunIn(dir, {inputs + "no_metric.csv", "--x", "x", "-o", "steps.svg"}).exit_code, 0);
  EXPECT_EQ(Entries(dir), (std::set<std::string>{"point.png", "run.png", "steps.svg"}));
}

// A stand-in for gnuplot that writes into the file the script's `set output` names, logs
// that name, and exits with `code`.
// A gnuplot that reads the script from its standard input, writes half a figure where the
// script says, logs that name and exits with `code`.
std::string FakeGnuplot(const std::string& bin, int code) {
  std::filesystem::create_directories(bin);
  std::ofstream(bin + "gnuplot") << "#!/bin/sh\n"
                                    "out=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\")\n"
                                    "printf 'half a figure' > \"$out\"\n"
                                    "printf '%s\\n' \"$out\" >> '"
                                 << bin
                                 << "written.log'\n"
                                    "echo 'fake gnuplot failed' >&2\n"
                                    "exit "
                                 << code << "\n";
  std::filesystem::permissions(bin + "gnuplot", std::filesystem::perms::owner_all);
  return bin;
}

TEST(PlotCli, FailingGnuplotKeepsTheEarlierFigureAndNoTemporary) {
  const std::string dir = FreshFolder(), run = Trajectory();
  const std::string bin = FakeGnuplot(FreshFolder("bin"), 1);
  std::ofstream(dir + "a.png") << "earlier figure";
  const Outcome r =
      RunIn(dir, {run, "-o", "a.png"}, {"PATH=" + bin + ":" + std::string(std::getenv("PATH"))});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("musclesim plot: error: gnuplot failed: fake gnuplot failed"));
  EXPECT_EQ(testing::ReadFile(dir + "a.png"), "earlier figure");
  // the fake did write its temporary file, which is gone
  const std::string written = testing::ReadFile(bin + "written.log");
  EXPECT_THAT(written, HasSubstr("a.png.tmp."));
  EXPECT_EQ(Entries(dir), std::set<std::string>{"a.png"});

  // no gnuplot at all
  const std::string empty = FreshFolder("empty_bin");
  const Outcome missing = RunIn(dir, {run, "-o", "a.png"}, {"PATH=" + empty});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, HasSubstr("gnuplot is not installed (or not on PATH): install the "
                                     "Debian package gnuplot-nox"));
  EXPECT_EQ(testing::ReadFile(dir + "a.png"), "earlier figure");
  EXPECT_EQ(Entries(dir), std::set<std::string>{"a.png"});
}

TEST(PlotCli, AGnuplotEndingBeforeReadingALongScriptIsAFailureNotASignal) {
  const std::string dir = FreshFolder(), bin = FreshFolder("bin");
  std::ofstream(bin + "gnuplot") << "#!/bin/sh\necho 'gave up at once' >&2\nexit 1\n";
  std::filesystem::permissions(bin + "gnuplot", std::filesystem::perms::owner_all);
  // 200,000 rows: a script of megabytes, far more than a pipe holds
  std::string csv = kHeader;
  for (int i = 0; i < 200000; ++i) {
    csv += std::to_string(i * 1e-4) + ",0.1,0.01,1,0,50,50,40,concentric\n";
  }
  const std::string run = testing::WriteTempFile("long_run.csv", csv);
  const Outcome r =
      RunIn(dir, {run, "-o", "a.png"}, {"PATH=" + bin + ":" + std::string(std::getenv("PATH"))});
  EXPECT_EQ(r.exit_code, 1) << r.err;  // 141 would be SIGPIPE
  EXPECT_THAT(r.err, HasSubstr("gnuplot failed: gave up at once"));
  EXPECT_EQ(Entries(dir), std::set<std::string>{});
}

TEST(PlotCli, TheScriptReachesGnuplotWithoutATemporaryFile) {
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  // no temporary folder to write into: the figure is still drawn
  const std::string dir = FreshFolder(), run = Trajectory();
  const Outcome r = RunIn(dir, {run, "-o", "a.png"}, {"TMPDIR=" + dir + "no_such_folder"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Entries(dir), std::set<std::string>{"a.png"});
}

TEST(PlotCli, WhatGnuplotPlotsToItsStandardOutputStaysOutOfTheMessage) {
  // gnuplot going on after a `set output` it could not open plots to its standard output
  const std::string dir = FreshFolder(), bin = FreshFolder("bin"), run = Trajectory();
  std::ofstream(bin + "gnuplot") << "#!/bin/sh\ncat > /dev/null\nprintf 'PNGDATA'\n"
                                    "echo 'cannot open file' >&2\nexit 1\n";
  std::filesystem::permissions(bin + "gnuplot", std::filesystem::perms::owner_all);
  const Outcome r =
      RunIn(dir, {run, "-o", "a.png"}, {"PATH=" + bin + ":" + std::string(std::getenv("PATH"))});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.err, HasSubstr("gnuplot failed: cannot open file"));
  EXPECT_THAT(r.err, Not(HasSubstr("PNGDATA")));
}

// --- networks in the plane ---------------------------------------------------------------

// A pendulum in the plane: a 0.1 kg bob on a stiff spring (1e4 N/m, 0.1 m) from a fixed
// pivot, released level, under gravity; rows every 5 ms for 0.3 s.
const char* const kPendulum =
    "dimensions: 2\n"
    "gravity: [0.0, -9.81]\n"
    "nodes:\n"
    "  - {name: pivot, fixed: [0.0, 0.0]}\n"
    "  - {name: bob, mass: 0.1, position: [0.1, 0.0]}\n"
    "elements:\n"
    "  - {name: link, type: spring, from: pivot, to: bob, stiffness: 1.0e4, rest_length: 0.1}\n"
    "time: {start: 0.0, end: 0.3}\n"
    "output: {interval: 0.005}\n";

// The pendulum's run: its scenario and its CSV, in `dir`.
void RunPendulum(const std::string& dir) {
  std::ofstream(dir + "pendulum.yaml") << kPendulum;
  const std::string command = std::string(MUSCLESIM_BINARY) + " run " + dir + "pendulum.yaml -o " +
                              dir + "pendulum.csv --quiet";
  ASSERT_EQ(std::system(command.c_str()), 0);
}

// The (x, y) rows of data set `index` of inline block `name` in `script`.
std::vector<std::pair<double, double>> FramePoints(const std::string& script,
                                                   const std::string& name, int index) {
  std::istringstream in(script.substr(script.find(name + " << EOD\n") + name.size() + 8));
  std::vector<std::pair<double, double>> points;
  int set = 0, blank = 0;
  for (std::string line; std::getline(in, line) && line != "EOD";) {
    if (line.empty()) {
      if (++blank == 2) ++set;
      continue;
    }
    blank = 0;
    double x = 0.0, y = 0.0;
    std::istringstream(line) >> x >> y;
    if (set == index) points.emplace_back(x, y);
  }
  return points;
}

TEST(PlotCli, APendulumInThePlaneIsPlottedWithItsPathAndFrames) {
  const std::string dir = FreshFolder(), inputs = FreshFolder("inputs");
  RunPendulum(inputs);
  const std::string csv = inputs + "pendulum.csv";
  // the frames' script: written even where gnuplot is missing (then the run fails after it)
  const Outcome frames =
      RunIn(dir, {csv, "--frames", "0,0.1,0.2,0.3", "--scenario", inputs + "pendulum.yaml",
                  "--script", "frames.gp", "-o", "frames.png"});
  const std::string script = testing::ReadFile(dir + "frames.gp");
  const CsvTable table = ReadCsv(csv);
  const int t = table.Find("t"), x = table.Find("bob.x"), y = table.Find("bob.y");
  for (int f = 0; f < 4; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    // the row of the time asked for (rows every 5 ms: the frame's own time)
    std::size_t row = 0;
    while (row < table.rows.size() && std::abs(table.Number(row, t) - 0.1 * f) > 1e-9) ++row;
    ASSERT_LT(row, table.rows.size());
    const std::pair<double, double> bob{table.Number(row, x), table.Number(row, y)};
    const auto nodes = FramePoints(script, "$frame" + std::to_string(f), 0);
    ASSERT_EQ(nodes.size(), 2u);
    EXPECT_EQ(nodes[0], (std::pair<double, double>{0.0, 0.0}));
    EXPECT_EQ(nodes[1], bob);
    // the link from the pivot to the bob, about its rest length (a stiff spring: its stretch
    // under at most 3 m g is 0.3 mm), and the bob swings down from level
    const auto link = FramePoints(script, "$frame" + std::to_string(f), 1);
    EXPECT_EQ(link, nodes);
    EXPECT_NEAR(std::hypot(bob.first, bob.second), 0.1, 1e-3);
    if (f > 0) {
      EXPECT_LT(bob.second, -0.01);
    }
  }
  if (!HaveGnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  EXPECT_EQ(frames.exit_code, 0) << frames.err;
  const Outcome path = RunIn(dir, {csv, "-o", "path.svg"});
  EXPECT_EQ(path.exit_code, 0) << path.err;
  const Outcome counted = RunIn(dir, {csv, "--frame-count", "6", "-o", "six.png"});
  EXPECT_EQ(counted.exit_code, 0) << counted.err;
  EXPECT_EQ(Entries(dir),
            (std::set<std::string>{"frames.gp", "frames.png", "path.svg", "six.png"}));
}

TEST(PlotCli, FramesOfTheWrongRunTimeOrScenarioAreInvalidInput) {
  const std::string dir = FreshFolder(), inputs = FreshFolder("inputs");
  RunPendulum(inputs);
  const std::string csv = inputs + "pendulum.csv";
  // the same pendulum whose bob is called weight
  std::string other = kPendulum;
  for (std::size_t at; (at = other.find("bob")) != std::string::npos;)
    other.replace(at, 3, "weight");
  std::ofstream(inputs + "other.yaml") << other;
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{Trajectory(), "--frames", "0"},
       "--frames: " + Trajectory() +
           " is not the run of a network in the plane or in space (frames need NODE.x and "
           "NODE.y columns, written by a run with dimensions: 2 or 3)"},
      {{csv, "--frames", "0,0.5"},
       "--frames 0.5: outside the run's times: " + csv + " holds t = 0 to 0.3 s"},
      {{csv, "--frames", "0,x"}, "--frames 0,x: expected times in seconds separated by commas"},
      {{csv, "--frame-count", "40"}, "--frame-count 40: must be 1 to 36"},
      {{csv, "--frame-count", "3", "--frames", "0"}, "give --frames (the times) or"},
      {{csv, "--scenario", inputs + "pendulum.yaml"}, "--scenario goes with --frames"},
      {{csv, "--frames", "0", "--scenario", inputs + "other.yaml"},
       inputs + "other.yaml does not match " + csv +
           ": nodes[1] 'weight' has no columns weight.x, weight.y in the CSV"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"-o", "a.png"});
    const Outcome r = RunIn(dir, args);
    EXPECT_EQ(r.exit_code, 2) << c.message << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr(c.message));
    EXPECT_EQ(Entries(dir), std::set<std::string>{}) << c.message;
  }
}

}  // namespace
}  // namespace musclesim
