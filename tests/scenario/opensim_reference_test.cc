// musclesim's degroote2016 family against OpenSim 4.6 itself: a mass hanging from one
// DeGrooteFregly2016Muscle with a rigid tendon, at constant activation or through OpenSim's
// activation dynamics (activation_dynamics family degroote2016), integrated by OpenSim
// at accuracy 1e-12 (bench/peers/opensim_reference.py wrote bench/peers/reference/
// opensim_drop_*.csv). musclesim at tight tolerance meets its length, velocity and tension
// to 1e-8 of their scales (the target is 1e-6; the two agree to about 1e-9), and its
// activation to 1e-8. With a compliant tendon (OpenSim's explicit tendon dynamics), the fiber
// and De Groote's tendon meet at a massless junction (docs/model.md 14.4): the mass's drop
// and speed, the tendon force and the fiber's length and velocity met to 1e-6 of their scales,
// hanging, and with the unit's length prescribed (an isokinetic stretch, a sinusoid); the
// rigid-tendon muscle with its length prescribed likewise, its activation then the only state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/number_format.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/readers/scenario_yaml.h"
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

// The compliant cases of bench/peers/opensim_reference.py: the ground, a massless junction
// where the fiber (along the line) meets the tendon, and the body, hanging by the tendon.
// The junction starts where OpenSim's equilibrateMuscles put the fiber (its first row).
// OpenSim's case has no fiber damping, and its explicit tendon dynamics find the fiber
// velocity by inverting the force-velocity curve; musclesim's junction needs a rate-dependent
// tension even at zero activation (docs/model.md 14.4), so its fiber has a damping `damping`,
// and OpenSim's trajectory is the limit of musclesim's as it goes to 0.
struct Compliant {
  double mass, f_iso, l_opt, v_max, pennation, activation, l_s, strain;
};

// The muscle-tendon unit's far end: the hanging body (`motion` empty), or a node whose position
// `motion` prescribes (a waveform in YAML), the body then playing no part.
RecordedRun RunCompliant(const Compliant& c, double damping, const PeerTable& opensim,
                         const std::string& motion = "") {
  const double fiber = opensim.at("fiber_length")[0];
  const double angle = opensim.at("pennation_angle")[0];
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "name: opensim_drop_compliant\n"
       << "models:\n  muscle: {family: degroote2016, f_iso: " << c.f_iso
       << ", optimal_fiber_length: " << c.l_opt << ", max_contraction_velocity: " << c.v_max
       << ", fiber_damping: " << damping << ", pennation_angle: " << c.pennation << "}\n"
       << "nodes:\n  - {name: ground, fixed: 0.0}\n"
       << "  - {name: junction, mass: 0, position: " << fiber * std::cos(angle) << "}\n"
       << "  - {name: body, "
       << (motion.empty() ? "mass: " + FormatNumber(c.mass) +
                                ", position: " + FormatNumber(opensim.at("length")[0])
                          : "prescribed: " + motion)
       << "}\n"
       << "elements:\n"
       << "  - {name: muscle, type: actuator, from: ground, to: junction, model: muscle, "
       << "activation: {type: constant, value: " << c.activation << "}}\n"
       << "  - {name: tendon, type: tendon, from: junction, to: body, slack_length: " << c.l_s
       << ", degroote2016: {max_isometric_force: " << c.f_iso
       << ", strain_at_one_norm_force: " << c.strain << "}}\n"
       << (motion.empty() ? "loads:\n  - {node: body, type: constant, value: " +
                                FormatNumber(c.mass * 9.81) + "}\n"
                          : "")
       << "time: {start: 0.0, end: 0.5}\n"
       << "solver: {method: bdf, rtol: 1.0e-12, atol: 1.0e-15}\n"
       << "output: {file: opensim_drop_compliant.csv, interval: 0.005}\n";
  return RunScenario(
      ReadScenario(ParseDocument("opensim_drop_compliant", yaml.str()), "opensim_drop_compliant"));
}

// The largest difference from OpenSim's trajectory, over its rows, of the mass's drop and
// speed, the tendon force and the fiber's length and velocity, each over its largest value.
double CompliantDeviation(const Compliant& c, double damping, const PeerTable& opensim,
                          const std::string& motion) {
  const RecordedRun run = RunCompliant(c, damping, opensim, motion);
  EXPECT_NE(run.stats.status, RunStatus::kFailed) << run.stats.message;
  const std::vector<double>& t = opensim.at("t");
  EXPECT_EQ(Column(run, "t").size(), t.size());
  if (Column(run, "t").size() != t.size()) return INFINITY;
  const auto span = [](const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return std::max(std::abs(*lo), std::abs(*hi));
  };
  const double width = c.l_opt * std::sin(c.pennation);  // the fiber's constant thickness
  double worst = 0.0;
  const auto compare = [&](double mine, const char* column, std::size_t k) {
    worst = std::max(worst, std::abs(mine - opensim.at(column)[k]) / span(opensim.at(column)));
  };
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double x = Column(run, "junction.position")[k];
    const double fiber = std::hypot(x, width);
    compare(Column(run, "body.position")[k], "length", k);
    compare(-Column(run, "body.velocity")[k], "shortening_velocity", k);
    compare(Column(run, "tendon.tension")[k], "tendon_force", k);
    compare(fiber, "fiber_length", k);
    // OpenSim's fiber velocity, positive lengthening: d/dt sqrt(x^2 + width^2)
    compare(x * Column(run, "junction.velocity")[k] / fiber, "fiber_velocity", k);
  }
  return worst;
}

// OpenSim's trajectory met to 1e-6 at a damping of 1e-8 (measured: 7e-8), the gap falling
// tenfold per tenfold of damping (the balance's first-order change; what remains at no
// damping, extrapolated, is about 1e-10)
void ExpectOpenSimsLimit(const Compliant& c, const std::string& reference,
                         const std::string& motion = "") {
  const PeerTable opensim = ReadPeerTable(reference);
  double previous = 0.0;
  for (const double damping : {1e-6, 1e-7, 1e-8}) {
    const double deviation = CompliantDeviation(c, damping, opensim, motion);
    if (previous > 0.0) {
      EXPECT_LT(deviation, 0.2 * previous) << "damping " << damping;
      EXPECT_GT(deviation, 0.05 * previous) << "damping " << damping;
    }
    previous = deviation;
  }
  EXPECT_LT(previous, 1e-6);
}

TEST(OpenSimReference, HangingMassOnACompliantTendonMeetsAtAMasslessJunction) {
  // case opensim_drop_compliant: the rigid case's muscle with a 0.2 m tendon, strain 0.049
  ExpectOpenSimsLimit({5.0, 400.0, 0.10, 10.0, 0.0, 0.6, 0.2, 0.049}, "opensim_drop_compliant.csv");
}

TEST(OpenSimReference, HangingMassOnAPennateMuscleWithACompliantTendon) {
  // case opensim_drop_compliant_pennate: the pennate case's muscle, a stiffer tendon (0.033)
  ExpectOpenSimsLimit({5.0, 400.0, 0.10, 10.0, 0.35, 0.8, 0.2, 0.033},
                      "opensim_drop_compliant_pennate.csv");
}

TEST(OpenSimReference, IsokineticStretchOfACompliantMuscleTendonUnit) {
  // case opensim_stretch_compliant: opensim_drop_compliant's unit lengthened at 0.05 m/s from
  // 0.3 m (OpenSim's LinearFunction on the prescribed coordinate, moving at t = 0 already: the
  // ramp runs through it, from t = -1 s to 1 s)
  ExpectOpenSimsLimit({5.0, 400.0, 0.10, 10.0, 0.0, 0.6, 0.2, 0.049},
                      "opensim_stretch_compliant.csv",
                      "{type: ramp, start: -1.0, end: 1.0, from: 0.25, to: 0.35}");
}

TEST(OpenSimReference, SinusoidalLengthChangeOfACompliantMuscleTendonUnit) {
  // case opensim_sine_compliant: 0.3 + 0.01 sin(2 pi 4 t) m (OpenSim's Sine)
  ExpectOpenSimsLimit({5.0, 400.0, 0.10, 10.0, 0.0, 0.6, 0.2, 0.049}, "opensim_sine_compliant.csv",
                      "{type: sine, offset: 0.3, amplitude: 0.01, frequency: 4.0}");
}

// The rigid-tendon cases with the length prescribed (bench/peers/opensim_reference.py's
// PRESCRIBED_RIGID): the excited pennate muscle from the ground to a node whose position
// `motion` prescribes (the fiber along the line: the muscle-tendon length less the tendon), no
// free node: its activation is the only state, as in OpenSim.
void ExpectPrescribedRigidIsOpenSims(const std::string& reference, const std::string& motion) {
  std::ostringstream yaml;
  yaml << "name: opensim_prescribed_rigid\n"
       << "models:\n  muscle: {family: degroote2016, f_iso: 400.0, optimal_fiber_length: 0.1, "
       << "max_contraction_velocity: 10.0, fiber_damping: 0.05, pennation_angle: 0.35}\n"
       << "nodes:\n  - {name: ground, fixed: 0.0}\n"
       << "  - {name: end, prescribed: " << motion << "}\n"
       << "elements:\n"
       << "  - {name: muscle, type: actuator, from: ground, to: end, model: muscle,\n"
       << "     excitation: {type: table, points: [[0, 0.9], [0.2, 0.9], [0.21, 0.1], "
       << "[0.5, 0.1]]},\n"
       << "     activation_dynamics: {family: degroote2016, tau_activation: 0.015, "
       << "tau_deactivation: 0.06, smoothing: 0.1}, initial_activation: 0.05}\n"
       << "time: {start: 0.0, end: 0.5}\n"
       << "solver: {method: bdf, rtol: 1.0e-11, atol: 1.0e-14}\n"
       << "output: {file: opensim_prescribed_rigid.csv, interval: 0.005}\n";
  const RecordedRun run = RunScenario(ReadScenario(
      ParseDocument("opensim_prescribed_rigid", yaml.str()), "opensim_prescribed_rigid"));
  ASSERT_NE(run.stats.status, RunStatus::kFailed) << run.stats.message;
  const PeerTable opensim = ReadPeerTable(reference);
  const std::vector<double>& t = opensim.at("t");
  ASSERT_EQ(Column(run, "t").size(), t.size());
  const auto span = [](const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return std::max(std::abs(*lo), std::abs(*hi));
  };
  const std::pair<const char*, const char*> compared[] = {
      {"muscle.length", "length"},
      {"muscle.shortening_velocity", "shortening_velocity"},
      {"muscle.tension", "tendon_force"},
      {"muscle.activation", "activation"}};
  for (const auto& [mine, theirs] : compared) {
    const double scale = span(opensim.at(theirs));
    for (std::size_t k = 0; k < t.size(); ++k) {
      EXPECT_NEAR(Column(run, mine)[k], opensim.at(theirs)[k], 1e-8 * scale)
          << mine << " at t = " << t[k];
    }
  }
}

TEST(OpenSimReference, IsokineticStretchOfAnExcitedMuscleWithARigidTendon) {
  // case opensim_stretch_rigid: from 0.16 m (0.11 m of fiber along the line) at 0.05 m/s, the
  // ramp running through t = 0 as OpenSim's LinearFunction does
  ExpectPrescribedRigidIsOpenSims("opensim_stretch_rigid.csv",
                                  "{type: ramp, start: -1.0, end: 1.0, from: 0.06, to: 0.16}");
}

TEST(OpenSimReference, SinusoidalLengthChangeOfAnExcitedMuscleWithARigidTendon) {
  // case opensim_sine_rigid: 0.16 + 0.01 sin(2 pi 4 t) m, less the 0.05 m tendon
  ExpectPrescribedRigidIsOpenSims("opensim_sine_rigid.csv",
                                  "{type: sine, offset: 0.11, amplitude: 0.01, frequency: 4.0}");
}

}  // namespace
}  // namespace musclesim
