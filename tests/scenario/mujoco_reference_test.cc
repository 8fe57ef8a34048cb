// musclesim's mujoco family against MuJoCo 4.0 itself: the three cases of
// bench/peers/mujoco_convergence.py (a 10 kg mass hanging from MuJoCo's muscle, a 50 g mass
// pulled past its isometric force into an eccentric stretch, and the mass hung through a
// linear tendon from a 1 g junction), as mj_step integrated them with RK4 at a step where it
// has converged (bench/peers/reference/mujoco_*.csv; the script measures RK4's fourth-order
// convergence to musclesim's solution). musclesim at tight tolerance meets every position,
// velocity and the actuator's force to 1e-8 of each column's largest value (measured: 1e-9
// and below).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/run.h"
#include "support/peer_reference.h"

namespace musclesim {
namespace {

using testing::PeerTable;
using testing::ReadPeerTable;

constexpr const char* kModel =
    "{family: mujoco, f_iso: 200.0, lengthrange: [0.05, 0.25]}";  // MuJoCo's defaults else
constexpr const char* kTail =
    "time: {start: 0.0, end: 0.5}\n"
    "solver: {method: bdf, rtol: 1.0e-12, atol: 1.0e-15}\n"
    "output: {file: mujoco.csv, interval: 0.01}\n";

RecordedRun RunYaml(const std::string& yaml) {
  return RunScenario(ReadScenario(ParseDocument("mujoco", yaml), "mujoco"));
}

// One mass on the muscle (activation 0.6, from 0.2 m at rest), pulled by `load` newtons.
RecordedRun SingleMass(double mass, double load) {
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "name: mujoco\nmodel: " << kModel << "\nactuator: {mass: " << mass << "}\n"
       << "initial: {length: 0.2}\nactivation: {type: constant, value: 0.6}\n"
       << "load: {type: constant, value: " << load << "}\n"
       << kTail;
  return RunYaml(yaml.str());
}

const std::vector<double>& Column(const RecordedRun& run, const std::string& name) {
  const std::vector<std::string>& names = run.columns.names();
  const auto at = std::find(names.begin(), names.end(), name);
  EXPECT_NE(at, names.end()) << name;
  return run.values[static_cast<std::size_t>(at - names.begin())];
}

// Each (musclesim's column, its sign, MuJoCo's column) pair row by row, to 1e-8 of MuJoCo's
// column's largest magnitude.
void ExpectMeets(const RecordedRun& run, const PeerTable& mujoco,
                 const std::vector<std::pair<std::pair<std::string, double>, std::string>>& pairs) {
  ASSERT_NE(run.stats.status, RunStatus::kFailed) << run.stats.message;
  const std::vector<double>& t = mujoco.at("t");
  ASSERT_EQ(Column(run, "t").size(), t.size());
  for (const auto& [mine, theirs] : pairs) {
    const std::vector<double>& reference = mujoco.at(theirs);
    double scale = 0.0;
    for (const double v : reference) scale = std::max(scale, std::abs(v));
    const std::vector<double>& values = Column(run, mine.first);
    for (std::size_t k = 0; k < t.size(); ++k) {
      EXPECT_NEAR(mine.second * values[k], reference[k], 1e-8 * scale)
          << mine.first << " against MuJoCo's " << theirs << " at t = " << t[k];
    }
  }
}

TEST(MujocoReference, HangingMassIsMujocosTrajectory) {
  ExpectMeets(SingleMass(10.0, 10.0 * 9.81), ReadPeerTable("mujoco_hanging.csv"),
              {{{"length", 1.0}, "length"},
               {{"shortening_velocity", -1.0}, "velocity"},
               {{"tension_total", -1.0}, "force"}});
}

TEST(MujocoReference, EccentricStretchIsMujocosTrajectory) {
  ExpectMeets(SingleMass(0.05, 135.0), ReadPeerTable("mujoco_eccentric.csv"),
              {{{"length", 1.0}, "length"},
               {{"shortening_velocity", -1.0}, "velocity"},
               {{"tension_total", -1.0}, "force"}});
}

TEST(MujocoReference, CompliantTendonThroughALightJunctionIsMujocosTrajectory) {
  // MuJoCo's fixed tendon with stiffness 2e4 N/m and springlength 0.1 m, starting stretched
  // to hold the mass, between a 1 g junction's slider and the mass's
  std::ostringstream yaml;
  yaml.precision(17);
  const double tendon = 0.1 + 10.0 * 9.81 / 2.0e4;
  yaml << "name: mujoco\nmodels:\n  muscle: " << kModel << "\n"
       << "nodes:\n  - {name: ceiling, fixed: 0.0}\n"
       << "  - {name: junction, mass: 0.001, position: 0.2}\n"
       << "  - {name: drop, mass: 10.0, position: " << 0.2 + tendon << "}\n"
       << "elements:\n"
       << "  - {name: muscle, type: actuator, from: ceiling, to: junction, model: muscle, "
       << "activation: {type: constant, value: 0.6}}\n"
       << "  - {name: tendon, type: spring, from: junction, to: drop, stiffness: 2.0e4, "
       << "rest_length: 0.1}\n"
       << "loads:\n  - {node: junction, type: constant, value: " << 0.001 * 9.81 << "}\n"
       << "  - {node: drop, type: constant, value: " << 10.0 * 9.81 << "}\n"
       << kTail;
  ExpectMeets(RunYaml(yaml.str()), ReadPeerTable("mujoco_compliant.csv"),
              {{{"junction.position", 1.0}, "junction_position"},
               {{"junction.velocity", 1.0}, "junction_velocity"},
               {{"drop.position", 1.0}, "drop_position"},
               {{"drop.velocity", 1.0}, "drop_velocity"},
               {{"muscle.tension", -1.0}, "force"}});
}

}  // namespace
}  // namespace musclesim
