// End-to-end tests of `musclesim plot` on hostile and malformed input: text that would run
// commands if pasted into the gnuplot script, file names gnuplot would read as pipes, CSV
// files that are not what plot expects, and a gnuplot that fails.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

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

}  // namespace
}  // namespace musclesim
