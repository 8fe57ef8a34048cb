// End-to-end tests of the `musclesim` command: exit codes, output format, messages.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include "musclesim/io/readers/model_yaml.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

struct Outcome {
  int exit_code;
  std::string out;  // standard output
  std::string err;  // standard error
};

Outcome RunCli(const std::string& arguments) {
  // one file per test: ctest runs the tests in parallel processes
  const std::string err_path = ::testing::TempDir() + "cli_test_stderr_" +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                               ".txt";
  const std::string command = std::string(MUSCLESIM_BINARY) + " " + arguments + " 2>" + err_path;
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer;
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  std::ifstream err_file(err_path);
  std::stringstream err;
  err << err_file.rdbuf();
  return {WEXITSTATUS(status), out, err.str()};
}

std::string Scenario(const std::string& name) {
  return std::string(MUSCLESIM_SOURCE_DIR) + "/scenarios/" + name;
}

std::vector<std::vector<double>> ParseCsv(const std::string& text, std::string* header) {
  std::istringstream in(text);
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST(Cli, CurvesOverLengthMatchTheLibrary) {
  const Outcome r = RunCli("curves " + Scenario("fit_indicator.yaml") + " --length 0.08:0.12:41");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  const auto rows = ParseCsv(r.out, &header);
  EXPECT_EQ(header, "length,f_L,tension_passive");
  ASSERT_EQ(rows.size(), 41u);
  const TensionModel model(LoadModelSpec(Scenario("fit_indicator.yaml")).params);
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 3u);
    EXPECT_DOUBLE_EQ(row[1], model.active_length().Evaluate(row[0]).value);
    EXPECT_DOUBLE_EQ(row[2], PassiveTension(model.params().passive, row[0]).value);
  }
  EXPECT_DOUBLE_EQ(rows.front()[0], 0.08);
  EXPECT_DOUBLE_EQ(rows.back()[0], 0.12);
}

TEST(Cli, CurvesOverVelocityWithSeventeenDigits) {
  const std::string path = ::testing::TempDir() + "cli_velocity.csv";
  const Outcome r =
      RunCli("curves " + Scenario("fit_indicator.yaml") + " --velocity -1:1:5 -o " + path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream file(path);
  std::string header, line;
  std::getline(file, header);
  EXPECT_EQ(header, "shortening_velocity,g");
  std::getline(file, line);  // v = -1: g = 1 + 1 (regularised: slightly less)
  EXPECT_THAT(line, StartsWith("-1,1.99999"));
  const std::string g = line.substr(line.find(',') + 1);
  EXPECT_EQ(g.size(), 18u) << g;  // 17 significant digits and the point
}

TEST(Cli, FitPrintsPasteableGaussians) {
  const Outcome r = RunCli("fit " + Scenario("fit_indicator.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, StartsWith("gaussians:\n  - {amplitude: "));
  EXPECT_THAT(r.out, HasSubstr("\ncost: "));
  EXPECT_THAT(r.out, HasSubstr("\nrelative_residual: "));
  // the printed block, pasted into a model, loads and reproduces the fit's cost
  std::string block = r.out.substr(0, r.out.find("cost:"));
  std::string indented;
  std::istringstream lines(block);
  for (std::string line; std::getline(lines, line);) indented += "    " + line + "\n";
  const std::string path = ::testing::TempDir() + "cli_pasted.yaml";
  std::ofstream(path)
      << "model:\n  f_iso: 100\n  passive: {k_p: 2, alpha: 30, slack_length: 0.105}\n"
         "  active_length:\n    optimal_range: [0.095, 0.105]\n"
      << indented << "  velocity: {v_max: 1, n: 3, epsilon: 0.001}\n";
  const ModelSpec pasted = LoadModelSpec(path);
  const ModelSpec fitted = LoadModelSpec(Scenario("fit_indicator.yaml"));
  ASSERT_EQ(pasted.params.active_length.gaussians.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(pasted.params.active_length.gaussians[k].precision,
              fitted.params.active_length.gaussians[k].precision);
  }
}

TEST(Cli, InvalidInputExitsTwoWithTheReason) {
  Outcome r = RunCli("curves " + Scenario("fit_indicator.yaml") + " --length 0.1:0.05:10");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--length 0.1:0.05:10: A must be less than B"));
  r = RunCli("curves " + Scenario("fit_indicator.yaml") + " --length 0:1:x");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("N must be an integer"));
  r = RunCli("curves " + Scenario("fit_indicator.yaml"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("give exactly one of --length"));
  r = RunCli("curves /nonexistent.yaml --length 0:1:3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("/nonexistent.yaml: cannot open the file"));
  r = RunCli("fit " + Scenario("fit_indicator.yaml") + " --frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("unknown option --frobnicate"));
  r = RunCli("dance");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("unknown verb 'dance'"));
}

TEST(Cli, BadModelValueExitsTwoNamingFileAndKey) {
  const std::string path = ::testing::TempDir() + "cli_bad.yaml";
  std::ofstream(path) << "model:\n  f_iso: 100\n  passive: {k_p: 2, alpha: 30, slack_length: 0.1}\n"
                         "  active_length: {optimal_range: [0.09, 0.1], fit: {count: 2}}\n"
                         "  velocity: {v_max: 1, n: 0, epsilon: 0.001}\n";
  const Outcome r = RunCli("fit " + path);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("model.velocity.n = 0 (" + path + ":5:27): must be an integer"));
}

TEST(Cli, FailedWriteKeepsThePreviousFile) {
  const std::string path = ::testing::TempDir() + "cli_keep.csv";
  std::ofstream(path) << "previous result\n";
  const Outcome r =
      RunCli("curves " + Scenario("fit_indicator.yaml") + " --length 1:0:3 -o " + path);
  EXPECT_EQ(r.exit_code, 2);
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  EXPECT_EQ(line, "previous result");
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Cli, RunWritesTheTrajectoryAndStats) {
  const std::string csv = ::testing::TempDir() + "cli_run.csv";
  const std::string json = ::testing::TempDir() + "cli_run.json";
  const Outcome r =
      RunCli("run " + Scenario("concentric.yaml") + " -o " + csv + " --stats " + json);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("concentric_isotonic: completed at t = 0.5 s: "));
  std::string header;
  const std::string text = ReadFile(csv);
  std::istringstream lines(text);
  std::getline(lines, header);
  EXPECT_EQ(header,
            "t,length,shortening_velocity,activation,tension_passive,tension_active,"
            "tension_total,load,phase");
  int rows = 0, concentric = 0;
  for (std::string line; std::getline(lines, line);) {
    ++rows;
    concentric += line.find(",concentric") != std::string::npos;
  }
  EXPECT_EQ(rows, 501);  // 0 to 0.5 s every millisecond
  EXPECT_GT(concentric, 400);
  const std::string stats = ReadFile(json);
  for (const char* key :
       {"\"steps\": ", "\"rhs_evals\": ", "\"jac_evals\": ", "\"linear_setups\": ",
        "\"newton_iters\": ", "\"newton_conv_fails\": ", "\"error_test_fails\": ",
        "\"wall_seconds\": ", "\"final_time\": 0.5", "\"status\": \"completed\""}) {
    EXPECT_THAT(stats, HasSubstr(key));
  }
}

TEST(Cli, RunToStandardOutputAndQuiet) {
  const Outcome r =
      RunCli("run " + Scenario("isometric.yaml") + " -o - --quiet --set output.interval=0.25");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_THAT(r.out, StartsWith("t,length,"));
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 4);  // header, t = 0, 0.25, 0.5
}

TEST(Cli, RunStoppedAtALimitSucceeds) {
  const std::string json = ::testing::TempDir() + "cli_limit.json";
  const Outcome r = RunCli("run " + Scenario("concentric.yaml") + " -o - --stats " + json +
                           " --set limits.min_length=0.09");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("min_length = 0.09 reached"));
  EXPECT_THAT(ReadFile(json), HasSubstr("\"status\": \"limit\""));
}

TEST(Cli, SolverFailureExitsThreeAndKeepsThePreviousResult) {
  const std::string csv = ::testing::TempDir() + "cli_fail.csv";
  std::ofstream(csv) << "previous result\n";
  std::remove((csv + ".partial").c_str());
  const Outcome r =
      RunCli("run " + Scenario("isometric.yaml") + " -o " + csv + " --set solver.max_steps=20");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_THAT(r.err, HasSubstr("solver failure: CVODE failed at t = "));
  EXPECT_THAT(r.err, HasSubstr("CV_TOO_MUCH_WORK"));
  EXPECT_THAT(r.err, HasSubstr(csv + ".partial"));
  EXPECT_EQ(ReadFile(csv), "previous result\n");
  EXPECT_THAT(ReadFile(csv + ".partial"), StartsWith("t,length,shortening_velocity"));
}

TEST(Cli, SmallLinearSolverRefusesANetworkOfMoreThanSixteenStates) {
  // the chain has 10 free nodes, 20 states; the stats name the solver each run used
  const Outcome refused =
      RunCli("run " + Scenario("chain.yaml") + " -o - --set solver.linear_solver=small");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("solver.linear_solver = small (--set): serves at most 16 "
                                     "states and this network has 20"));
  const std::string json = ::testing::TempDir() + "cli_small.json";
  const Outcome chain = RunCli("run " + Scenario("chain.yaml") + " -o - --quiet --stats " + json);
  EXPECT_EQ(chain.exit_code, 0) << chain.err;
  EXPECT_THAT(ReadFile(json), HasSubstr("\"linear_solver\": \"band\""));
  const Outcome single =
      RunCli("run " + Scenario("concentric.yaml") + " -o - --quiet --stats " + json);
  EXPECT_EQ(single.exit_code, 0) << single.err;
  EXPECT_THAT(ReadFile(json), HasSubstr("\"linear_solver\": \"small\""));
}

TEST(Cli, RunRejectsInvalidInputWithExitTwo) {
  Outcome r = RunCli("run " + Scenario("concentric.yaml") + " -o - --set model.velocity.n=0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("model.velocity.n = 0 (--set): must be an integer from 1 to 1000"));
  r = RunCli("run " + Scenario("concentric.yaml") + " -o - --set solver.rtol=-1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("solver.rtol = -1 (--set): must be >= 1e-14"));
  r = RunCli("run " + Scenario("fit_indicator.yaml"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("actuator (" + Scenario("fit_indicator.yaml") +
                               ":4:1): missing required key"));  // where the map begins
}

TEST(Cli, OutputToADeviceWritesIntoIt) {
  // an atomic rename over /dev/null would replace the device with a file
  const Outcome r =
      RunCli("run " + Scenario("concentric.yaml") + " --quiet -o /dev/null --stats /dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

TEST(Cli, UnwritableOutputExitsOne) {
  // a directory that exists but takes no new file, even from root: the system's refusal is
  // an I/O failure (a missing directory is bad input, exit 2: bad_input_test.cc)
  const Outcome r = RunCli("run " + Scenario("concentric.yaml") + " --quiet -o /proc/run.csv");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("/proc/run.csv: cannot write"));
}

TEST(Cli, EveryCanonicalScenarioRuns) {
  for (const char* name : {"isometric", "concentric", "eccentric", "twitches", "sine_load",
                           "activation_ramp", "hanging_mass"}) {
    const Outcome r = RunCli("run " + Scenario(std::string(name) + ".yaml") + " -o - --quiet");
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
  }
}

// Width and height from a PNG's IHDR chunk (big-endian, bytes 16 to 23), after checking
// the signature.
std::pair<int, int> PngSize(const std::string& path) {
  const std::string data = ReadFile(path);
  if (data.size() < 24 || data.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
      data.compare(12, 4, "IHDR") != 0) {
    return {0, 0};
  }
  const auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(data[at]) << 24) |
           (static_cast<unsigned char>(data[at + 1]) << 16) |
           (static_cast<unsigned char>(data[at + 2]) << 8) |
           static_cast<unsigned char>(data[at + 3]);
  };
  return {be32(16), be32(20)};
}

TEST(Cli, PlotsATrajectoryAsAPngOfTheRequestedSize) {
  const std::string dir = ::testing::TempDir();
  ASSERT_EQ(
      RunCli("run " + Scenario("twitches.yaml") + " --quiet -o " + dir + "plot_run.csv").exit_code,
      0);
  const Outcome r = RunCli("plot " + dir + "plot_run.csv -o " + dir +
                           "plot_run.png --size 800x600 --script " + dir + "plot_run.gp");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(PngSize(dir + "plot_run.png"), std::make_pair(800, 600));
  EXPECT_THAT(ReadFile(dir + "plot_run.gp"), HasSubstr("title 'concentric'"));
}

TEST(Cli, PlotsCurvesAndSweepsAsSvg) {
  const std::string dir = ::testing::TempDir();
  Outcome r = RunCli("plot --curves " + Scenario("concentric.yaml") + " -o " + dir +
                     "plot_curves.svg --size 640x480");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = ReadFile(dir + "plot_curves.svg");
  EXPECT_THAT(svg, HasSubstr("<svg"));
  EXPECT_THAT(svg, HasSubstr("width=\"640\""));
  EXPECT_THAT(svg, HasSubstr("height=\"480\""));
  EXPECT_THAT(svg, HasSubstr("</svg>"));
  ASSERT_EQ(
      RunCli("sweep " + Scenario("stiffness_sweep.yaml") + " --quiet -o " + dir + "plot_sweep.csv")
          .exit_code,
      0);
  r = RunCli("plot " + dir + "plot_sweep.csv --x model.velocity.epsilon --y steps -o " + dir +
             "plot_heat.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(PngSize(dir + "plot_heat.png"), std::make_pair(1000, 750));
}

TEST(Cli, PlotErrorsNameTheProblem) {
  const std::string dir = ::testing::TempDir();
  std::ofstream(dir + "plot_bad.csv") << "t,length\n0,0.1\n";
  Outcome r = RunCli("plot " + dir + "plot_bad.csv -o " + dir + "plot_bad.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("missing columns: shortening_velocity, activation"));
  // without gnuplot on PATH the message names the package to install
  const std::string command = "env PATH=/nonexistent " + std::string(MUSCLESIM_BINARY) +
                              " plot --curves " + Scenario("concentric.yaml") + " -o " + dir +
                              "plot_none.png 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
  EXPECT_EQ(WEXITSTATUS(pclose(pipe)), 1);
  EXPECT_THAT(
      out,
      HasSubstr(
          "gnuplot is not installed (or not on PATH): install the Debian package gnuplot-nox"));
}

TEST(Cli, IdentifyWritesALoadableModelAndTheReport) {
  const std::string dir = ::testing::TempDir();
  const Outcome r =
      RunCli("identify " + std::string(MUSCLESIM_SOURCE_DIR) + "/data/synthetic.yaml -o " + dir +
             "identified.yaml --report " + dir + "identified.md");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ModelSpec model = LoadModelSpec(dir + "identified.yaml");
  EXPECT_EQ(model.params.velocity.n, 3);  // the generating exponent
  // generated with v_max = 1 m/s and f_iso = 100 N plus noise of 2% of f_iso per point
  // (scripts/make_synthetic_data.py): the bounds are wide enough for that noise and narrow
  // enough that a wrong exponent or a misplaced curve falls outside them
  EXPECT_NEAR(model.params.velocity.v_max, 1.0, 0.05);
  EXPECT_NEAR(model.params.f_iso, 100.0, 3.0);
  EXPECT_EQ(model.params.active_length.gaussians.size(), 3u);
  const std::string report = ReadFile(dir + "identified.md");
  for (const char* heading :
       {"## passive tension-length", "## active tension-length", "## tension-velocity",
        "| natural cubic spline |", "| polynomial, degree 4 |"}) {
    EXPECT_THAT(report, HasSubstr(heading));
  }
}

TEST(Cli, IdentifyAnySubsetGivesACompleteModel) {
  const std::string dir = ::testing::TempDir();
  for (const char* data : {"hill", "ghj1966"}) {  // velocity alone, active alone
    const std::string out = dir + "identified_" + data + ".yaml";
    const Outcome r = RunCli("identify " + std::string(MUSCLESIM_SOURCE_DIR) + "/data/" + data +
                             ".yaml -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ModelSpec model = LoadModelSpec(out);  // every part present and valid
    EXPECT_THAT(ReadFile(out), HasSubstr("not identified")) << data;
    EXPECT_GT(model.params.f_iso, 0.0);
  }
}

TEST(Cli, IdentifyRejectsBadDataWithExitTwo) {
  const std::string dir = ::testing::TempDir();
  std::ofstream(dir + "bad_passive.csv") << "length,tension\n0.1,0\n0.2,0\n0.3,0\n0.4,0\n";
  std::ofstream(dir + "bad_data.yaml") << "passive: {csv: bad_passive.csv}\n";
  Outcome r = RunCli("identify " + dir + "bad_data.yaml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("bad_passive.csv: every tension is zero: nothing to fit"));
  std::ofstream(dir + "bad_key.yaml") << "pasive: {csv: x.csv}\n";
  r = RunCli("identify " + dir + "bad_key.yaml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("pasive (" + dir + "bad_key.yaml:1:1): unknown key"));
}

TEST(Cli, HelpForEveryVerb) {
  for (const char* verb : {"run", "sweep", "plot", "identify", "curves", "fit", "optimize"}) {
    const Outcome r = RunCli(std::string(verb) + " --help");
    EXPECT_EQ(r.exit_code, 0) << verb;
    EXPECT_THAT(r.out, HasSubstr("usage: musclesim " + std::string(verb)));
  }
  const Outcome top = RunCli("--help");
  EXPECT_EQ(top.exit_code, 0);
  EXPECT_THAT(top.out, HasSubstr("exit codes: 0 success, 1 other failure, 2 invalid input"));
  EXPECT_THAT(top.out, HasSubstr("musclesim --version"));
}

TEST(Cli, VersionIsTheProjectVersion) {
  // the version as the top-level CMakeLists.txt declares it: project(musclesim VERSION x.y.z
  const std::string cmake = ReadFile(std::string(MUSCLESIM_SOURCE_DIR) + "/CMakeLists.txt");
  const std::string marker = "project(musclesim VERSION ";
  const auto at = cmake.find(marker);
  ASSERT_NE(at, std::string::npos);
  const auto from = at + marker.size();
  const std::string version = cmake.substr(from, cmake.find_first_of(" )", from) - from);
  const Outcome r = RunCli("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "musclesim " + version + "\n");
  EXPECT_EQ(r.err, "");
}

}  // namespace
}  // namespace musclesim
