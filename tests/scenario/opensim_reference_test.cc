// musclesim's degroote2016 family against OpenSim 4.6 itself: a mass hanging from one
// DeGrooteFregly2016Muscle with a rigid tendon, at constant activation or through OpenSim's
// activation dynamics (activation_dynamics family degroote2016), integrated by OpenSim
// at accuracy 1e-12 (bench/peers/opensim_reference.py wrote bench/peers/reference/
// opensim_drop_*.csv). musclesim at tight tolerance meets its length, velocity and tension
// to 1e-8 of their scales (the target is 1e-6; the two agree to about 1e-9), and its
// activation to 1e-8.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "musclesim/io/document.h"
#include "musclesim/io/scenario_yaml.h"
#include "musclesim/scenario/run.h"
#include "support/peer_reference.h"

namespace musclesim {
namespace {

using testing::PeerTable;
using testing::ReadPeerTable;

const std::vector<double>& Column(const RecordedRun& run, const std::string& name) {
  const std::vector<std::string>& names = run.columns.names();
  const auto at = std::find(names.begin(), names.end(), name);
  EXPECT_NE(at, names.end()) << name;
  return run.values[static_cast<std::size_t>(at - names.begin())];
}

// The case of bench/peers/opensim_reference.py in musclesim's terms: the actuator is the
// fiber along the line (muscle-tendon length less the rigid tendon), gravity a constant load.
// `drive`: the scenario's activation, or its excitation and activation dynamics, in YAML;
// ConstantActivation's by default.
std::string ConstantActivation(double activation) {
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "activation: {type: constant, value: " << activation << "}\n";
  return yaml.str();
}

RecordedRun RunMusclesim(double mass, double f_iso, double l_opt, double v_max, double pennation,
                         double damping, const std::string& drive, double length,
                         const std::string& initial_extra = "") {
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "name: opensim_drop\n"
       << "model: {family: degroote2016, f_iso: " << f_iso << ", optimal_fiber_length: " << l_opt
       << ", max_contraction_velocity: " << v_max << ", fiber_damping: " << damping
       << ", pennation_angle: " << pennation << "}\n"
       << "actuator: {mass: " << mass << "}\n"
       << "initial: {length: " << length << initial_extra << "}\n"
       << drive << "load: {type: constant, value: " << mass * 9.81 << "}\n"
       << "time: {start: 0.0, end: 0.5}\n"
       << "solver: {method: bdf, rtol: 1.0e-11, atol: 1.0e-14}\n"
       << "output: {file: opensim_drop.csv, interval: 0.005}\n";
  return RunScenario(ReadScenario(ParseDocument("opensim_drop", yaml.str()), "opensim_drop"));
}

void ExpectMatchesOpenSim(const RecordedRun& run, const PeerTable& opensim) {
  const std::vector<double>& t = opensim.at("t");
  ASSERT_EQ(Column(run, "t").size(), t.size());
  // scales: the drop's length change, its peak speed, its peak force
  const auto span = [](const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return std::max(std::abs(*lo), std::abs(*hi));
  };
  const double speed = span(opensim.at("shortening_velocity"));
  const double force = span(opensim.at("tendon_force"));
  const double length = span(opensim.at("length"));
  for (std::size_t k = 0; k < t.size(); ++k) {
    EXPECT_NEAR(Column(run, "t")[k], t[k], 1e-12);
    EXPECT_NEAR(Column(run, "length")[k], opensim.at("length")[k], 1e-8 * length) << "t = " << t[k];
    EXPECT_NEAR(Column(run, "shortening_velocity")[k], opensim.at("shortening_velocity")[k],
                1e-8 * speed)
        << "t = " << t[k];
    EXPECT_NEAR(Column(run, "tension_total")[k], opensim.at("tendon_force")[k], 1e-8 * force)
        << "t = " << t[k];
  }
}

TEST(OpenSimReference, HangingMassOnARigidTendonMuscleIsOpenSimsTrajectory) {
  // bench/peers/opensim_reference.py, case opensim_drop_rigid: height 0.16 m, l_s 0.05 m
  const RecordedRun run =
      RunMusclesim(5.0, 400.0, 0.10, 10.0, 0.0, 0.01, ConstantActivation(0.6), 0.11);
  ExpectMatchesOpenSim(run, ReadPeerTable("opensim_drop_rigid.csv"));
}

TEST(OpenSimReference, HangingMassOnAPennateMuscleIsOpenSimsTrajectory) {
  // case opensim_drop_pennate: height 0.13 m, l_s 0.05 m, 0.35 rad at the optimal length
  const RecordedRun run =
      RunMusclesim(5.0, 400.0, 0.10, 10.0, 0.35, 0.05, ConstantActivation(0.8), 0.08);
  ExpectMatchesOpenSim(run, ReadPeerTable("opensim_drop_pennate.csv"));
}

TEST(OpenSimReference, OpenSimsActivationDynamicsDrivenByAnExcitation) {
  // case opensim_drop_excited: the pennate case with OpenSim's defaults for the activation
  // dynamics (15 ms, 60 ms, smoothing 0.1), the excitation through points from activation 0.05
  const std::string drive =
      "excitation: {type: table, points: [[0, 0.9], [0.2, 0.9], [0.21, 0.1], [0.5, 0.1]]}\n"
      "activation_dynamics: {family: degroote2016, tau_activation: 0.015, "
      "tau_deactivation: 0.06, smoothing: 0.1}\n";
  const RecordedRun run =
      RunMusclesim(5.0, 400.0, 0.10, 10.0, 0.35, 0.05, drive, 0.08, ", activation: 0.05");
  const PeerTable opensim = ReadPeerTable("opensim_drop_excited.csv");
  ExpectMatchesOpenSim(run, opensim);
  const std::vector<double>& activation = Column(run, "activation");
  ASSERT_EQ(activation.size(), opensim.at("activation").size());
  for (std::size_t k = 0; k < activation.size(); ++k) {
    EXPECT_NEAR(activation[k], opensim.at("activation")[k], 1e-8) << "t = " << opensim.at("t")[k];
  }
}

}  // namespace
}  // namespace musclesim
