// `musclesim import` and its reader: OpenSim's .osim (a file OpenSim 4.6 wrote itself,
// data/opensim_hanging_mass.osim) and MuJoCo's MJCF (tests/fixtures/import/
// muscles.xml, whose compiled parameters MuJoCo 4.0 prints with
// bench/peers/check_mjcf_import.py). The imported OpenSim muscle, run, meets OpenSim's own
// trajectory; every imported value is the tool's; every refusal names file, line and rule.
#include "musclesim/io/import/muscle_import.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "musclesim/core/errors.h"
#include "musclesim/io/readers/document.h"
#include "musclesim/io/import/imported_scenario.h"
#include "musclesim/io/readers/scenario_yaml.h"
#include "musclesim/scenario/parameter.h"
#include "musclesim/scenario/run.h"
#include "support/cli_run.h"
#include "support/fresh_directory.h"
#include "support/peer_reference.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::Contains;
using ::testing::ElementsAre;
using testing::FixturePath;
using ::testing::HasSubstr;
using ::testing::Not;

std::string Fixture(const std::string& name) { return FixturePath("import/" + name); }

// the model OpenSim 4.6 wrote for bench/peers/opensim_reference.py's pennate case, with a
// Thelen2003Muscle beside its DeGrooteFregly2016Muscle (converted on import)
const std::string kOpenSimModel =
    std::string(MUSCLESIM_SOURCE_DIR) + "/data/opensim_hanging_mass.osim";

const ImportedMuscle& Named(const ImportedModel& model, const std::string& name) {
  const auto at = std::find_if(model.muscles.begin(), model.muscles.end(),
                               [&](const ImportedMuscle& m) { return m.name == name; });
  EXPECT_NE(at, model.muscles.end()) << name;
  return *at;
}

TEST(ImportOpenSim, DeGrooteMuscleWithItsPropertiesAndTheThelenMuscleConverted) {
  const ImportedModel model = ImportMuscles(kOpenSimModel);
  EXPECT_EQ(model.tool, "OpenSim");
  ASSERT_EQ(model.muscles.size(), 2u);
  const ImportedMuscle& m = model.muscles[0];
  EXPECT_EQ(m.name, "muscle");
  EXPECT_THAT(m.source, HasSubstr("opensim_hanging_mass.osim:111"));
  // bench/peers/opensim_reference.py, case opensim_drop_pennate
  EXPECT_EQ(m.params.family, CurveFamily::kDeGroote2016);
  EXPECT_EQ(m.params.f_iso, 400.0);
  EXPECT_EQ(m.params.degroote2016.optimal_fiber_length, 0.1);
  EXPECT_EQ(m.params.degroote2016.max_contraction_velocity, 10.0);
  EXPECT_EQ(m.params.degroote2016.fiber_damping, 0.05);
  EXPECT_EQ(m.params.pennation_angle, 0.35);
  // left out of the file: OpenSim's defaults
  EXPECT_EQ(m.params.degroote2016.active_force_width_scale, 1.0);
  EXPECT_EQ(m.params.degroote2016.passive_fiber_strain_at_one_norm_force, 0.6);
  EXPECT_EQ(m.tendon_slack_length, 0.05);
  EXPECT_FALSE(m.activation_dynamics.has_value());
  EXPECT_TRUE(m.conversion.empty());  // a family of its own
  ASSERT_EQ(m.notes.size(), 1u);      // rigid tendon, no activation dynamics: only the path
  EXPECT_THAT(m.notes[0], HasSubstr("its path (2 points)"));
  EXPECT_TRUE(model.unsupported.empty());

  // opensim_reference.py's Thelen2003Muscle("thelen", 300, 0.08, 0.1, 0.1), OpenSim's
  // defaults otherwise: converted, compliant (OpenSim 4.6 runs no other), its lag thelen2003
  const ImportedMuscle& thelen = model.muscles[1];
  EXPECT_EQ(thelen.name, "thelen");
  EXPECT_THAT(thelen.source, HasSubstr("Thelen2003Muscle (" + kOpenSimModel + ":159)"));
  EXPECT_EQ(thelen.params.family, CurveFamily::kDeGroote2016);
  EXPECT_EQ(thelen.params.f_iso, 300.0);
  EXPECT_EQ(thelen.params.pennation_angle, 0.1);
  EXPECT_EQ(thelen.params.degroote2016.optimal_fiber_length, 0.08);
  EXPECT_EQ(thelen.params.degroote2016.fiber_damping, 0.0);
  EXPECT_EQ(thelen.params.degroote2016.passive_fiber_strain_at_one_norm_force, 0.6);
  EXPECT_EQ(thelen.tendon_slack_length, 0.1);
  ASSERT_TRUE(thelen.tendon_strain);
  EXPECT_EQ(*thelen.tendon_strain, 0.04);
  ASSERT_TRUE(thelen.activation_dynamics);
  EXPECT_EQ(thelen.activation_dynamics->family, ActivationFamily::kThelen2003);
  EXPECT_EQ(thelen.activation_dynamics->tau_activation, 0.015);
  EXPECT_EQ(thelen.activation_dynamics->tau_deactivation, 0.05);
  ASSERT_EQ(thelen.conversion.size(), 4u);
  EXPECT_THAT(thelen.conversion[3], HasSubstr("tendon force-length: De Groote's with the file's "
                                              "strain at one norm force, 0.04, largest departure"));
  EXPECT_THAT(thelen.notes, Contains(HasSubstr("scales its shortening velocity by 0.25 + 0.75")));
}

TEST(ImportOpenSim, AnotherMuscleClassIsListedNotImported) {
  std::string text = testing::ReadFile(kOpenSimModel);
  for (const std::string tag : {"<Thelen2003Muscle ", "</Thelen2003Muscle>"}) {
    const std::size_t at = text.find(tag);
    ASSERT_NE(at, std::string::npos) << tag;
    text.replace(at, tag.size(), tag[1] == '/' ? "</RigidTendonMuscle>" : "<RigidTendonMuscle ");
  }
  const std::string path = testing::WriteTempFile("rigid_tendon_muscle.osim", text);
  const ImportedModel model = ImportMuscles(path);
  ASSERT_EQ(model.muscles.size(), 1u);
  ASSERT_EQ(model.unsupported.size(), 1u);
  EXPECT_THAT(model.unsupported[0], HasSubstr("RigidTendonMuscle 'thelen' (" + path + ":159)"));
  EXPECT_THAT(model.unsupported[0], HasSubstr("a muscle class musclesim does not import"));
}

TEST(ImportOpenSim, TheImportedMuscleRunsOpenSimsTrajectory) {
  // the imported model block in the hanging-mass case OpenSim integrated at accuracy 1e-12
  const ImportedMuscle m = ImportMuscles(kOpenSimModel).muscles.at(0);
  const std::string yaml = "name: imported\n" + FormatModelBlock(m.params) +
                           "actuator: {mass: 5.0}\n"
                           "initial: {length: " +
                           std::to_string(0.13 - m.tendon_slack_length) +
                           "}\n"
                           "activation: {type: constant, value: 0.8}\n"
                           "load: {type: constant, value: 49.05}\n"
                           "time: {start: 0.0, end: 0.5}\n"
                           "solver: {method: bdf, rtol: 1.0e-11, atol: 1.0e-14}\n"
                           "output: {file: imported.csv, interval: 0.005}\n";
  const RecordedRun run = RunScenario(ReadScenario(ParseDocument("imported", yaml), "imported"));
  const testing::PeerTable opensim = testing::ReadPeerTable("opensim_drop_pennate.csv");
  const std::vector<std::string>& names = run.columns.names();
  const auto column = [&](const std::string& name) -> const std::vector<double>& {
    return run.values[static_cast<std::size_t>(std::find(names.begin(), names.end(), name) -
                                               names.begin())];
  };
  ASSERT_EQ(column("t").size(), opensim.at("t").size());
  for (std::size_t k = 0; k < opensim.at("t").size(); ++k) {
    EXPECT_NEAR(column("length")[k], opensim.at("length")[k], 1e-9) << k;
    EXPECT_NEAR(column("tension_total")[k], opensim.at("tendon_force")[k], 1e-6) << k;
  }
}

TEST(ImportOpenSim, ActivationDynamicsAreOpenSimsAndRunItsTrajectory) {
  // the excited case's model as OpenSim wrote it (bench/peers/opensim_reference.py): its
  // activation dynamics at OpenSim's defaults, which the file leaves out
  const ImportedMuscle m = ImportMuscles(Fixture("opensim_excited.osim")).muscles.at(0);
  ASSERT_TRUE(m.activation_dynamics.has_value());
  const ActivationDynamics& lag = *m.activation_dynamics;
  EXPECT_EQ(lag.family, ActivationFamily::kDeGroote2016);
  EXPECT_EQ(lag.tau_activation, 0.015);
  EXPECT_EQ(lag.tau_deactivation, 0.06);
  EXPECT_EQ(lag.smoothing, 0.1);
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "name: imported\n"
       << FormatModelBlock(m.params) << "actuator: {mass: 5.0}\n"
       << "initial: {length: " << 0.13 - m.tendon_slack_length << ", activation: 0.05}\n"
       << "excitation: {type: table, points: [[0, 0.9], [0.2, 0.9], [0.21, 0.1], [0.5, 0.1]]}\n"
       << "activation_dynamics: {family: degroote2016, tau_activation: " << lag.tau_activation
       << ", tau_deactivation: " << lag.tau_deactivation << ", smoothing: " << lag.smoothing
       << "}\n"
       << "load: {type: constant, value: 49.05}\n"
       << "time: {start: 0.0, end: 0.5}\n"
       << "solver: {method: bdf, rtol: 1.0e-11, atol: 1.0e-14}\n"
       << "output: {file: imported.csv, interval: 0.005}\n";
  const RecordedRun run =
      RunScenario(ReadScenario(ParseDocument("imported", yaml.str()), "imported"));
  const testing::PeerTable opensim = testing::ReadPeerTable("opensim_drop_excited.csv");
  const std::vector<std::string>& names = run.columns.names();
  const auto column = [&](const std::string& name) -> const std::vector<double>& {
    return run.values[static_cast<std::size_t>(std::find(names.begin(), names.end(), name) -
                                               names.begin())];
  };
  ASSERT_EQ(column("t").size(), opensim.at("t").size());
  for (std::size_t k = 0; k < opensim.at("t").size(); ++k) {
    EXPECT_NEAR(column("length")[k], opensim.at("length")[k], 1e-9) << k;
    EXPECT_NEAR(column("activation")[k], opensim.at("activation")[k], 1e-8) << k;
    EXPECT_NEAR(column("tension_total")[k], opensim.at("tendon_force")[k], 1e-6) << k;
  }
}

TEST(ImportMujoco, MusclesWithDefaultClassesAreWhatMujocoCompiles) {
  const ImportedModel model = ImportMuscles(Fixture("muscles.xml"));
  EXPECT_EQ(model.tool, "MuJoCo");
  ASSERT_EQ(model.muscles.size(), 3u);
  // bench/peers/check_mjcf_import.py: plain gainprm [0.75, 1.05, 150, 200, 0.45, 1.6, 1.5,
  // 1.3, 1.4], dynprm [0.01, 0.04, 0], lengthrange [0.05, 0.25]
  const ImportedMuscle& plain = Named(model, "plain");
  EXPECT_EQ(plain.params.family, CurveFamily::kMujoco);
  EXPECT_EQ(plain.params.f_iso, 150.0);
  const MujocoMuscleParams& p = plain.params.mujoco;
  EXPECT_THAT(p.range, ElementsAre(0.75, 1.05));
  EXPECT_THAT(p.lengthrange, ElementsAre(0.05, 0.25));
  EXPECT_EQ(p.lmin, 0.45);
  EXPECT_EQ(p.lmax, 1.6);
  EXPECT_EQ(p.vmax, 1.5);
  EXPECT_EQ(p.fpmax, 1.3);
  EXPECT_EQ(p.fvmax, 1.4);
  ASSERT_TRUE(plain.activation_dynamics.has_value());
  EXPECT_EQ(plain.activation_dynamics->tau_activation, 0.01);
  EXPECT_EQ(plain.activation_dynamics->tau_deactivation, 0.04);
  // quick: class fast over the main class: [0.6, 1.2, 80, 200, 0.45, 1.6, 3, 1.3, 1.4],
  // dynprm [0.02, 0.05, 0.2]
  const ImportedMuscle& quick = Named(model, "quick");
  EXPECT_EQ(quick.params.f_iso, 80.0);
  EXPECT_THAT(quick.params.mujoco.range, ElementsAre(0.6, 1.2));
  EXPECT_EQ(quick.params.mujoco.vmax, 3.0);
  EXPECT_EQ(quick.params.mujoco.lmin, 0.45);
  EXPECT_EQ(quick.params.mujoco.fvmax, 1.4);
  EXPECT_EQ(quick.activation_dynamics->tau_activation, 0.02);
  EXPECT_EQ(quick.activation_dynamics->tau_deactivation, 0.05);
  EXPECT_EQ(quick.activation_dynamics->family, ActivationFamily::kMujoco);
  EXPECT_EQ(quick.activation_dynamics->tausmooth, 0.2);
  // generic: <general> muscle without dynamics
  const ImportedMuscle& generic = Named(model, "generic");
  EXPECT_EQ(generic.params.f_iso, 300.0);
  EXPECT_THAT(generic.params.mujoco.range, ElementsAre(0.7, 1.1));
  EXPECT_THAT(generic.params.mujoco.lengthrange, ElementsAre(0.0, 0.2));
  EXPECT_EQ(generic.params.mujoco.lmax, 1.7);
  EXPECT_EQ(generic.params.mujoco.fvmax, 1.3);
  EXPECT_FALSE(generic.activation_dynamics.has_value());
  // what MuJoCo computes when compiling, and what is no muscle: listed with line and why
  ASSERT_EQ(model.unsupported.size(), 3u);
  EXPECT_THAT(model.unsupported[0], HasSubstr("muscle 'no_range'"));
  EXPECT_THAT(model.unsupported[0], HasSubstr("no lengthrange"));
  EXPECT_THAT(model.unsupported[1], HasSubstr("muscle 'inertial'"));
  EXPECT_THAT(model.unsupported[1], HasSubstr("scale / acc0"));
  EXPECT_THAT(model.unsupported[2], HasSubstr("motor 'drive' (" + Fixture("muscles.xml") + ":"));
  EXPECT_THAT(model.unsupported[2], HasSubstr("not a muscle"));
}

TEST(ImportOpenSim, AMuscleOutsideTheForceSetIsFoundAndWhatItIgnoresIsNoted) {
  const std::string path = testing::WriteTempFile(
      "components.osim",
      "<OpenSimDocument><Model><components>\n"
      "<DeGrooteFregly2016Muscle name='m'>\n<appliesForce>false</appliesForce>\n"
      "<default_activation>0.3</default_activation>\n"
      "<max_isometric_force>250</max_isometric_force>\n"
      "<ignore_tendon_compliance>true</ignore_tendon_compliance>\n"
      "<ignore_activation_dynamics>true</ignore_activation_dynamics>\n"
      "</DeGrooteFregly2016Muscle></components></Model></OpenSimDocument>\n");
  const ImportedModel model = ImportMuscles(path);
  ASSERT_EQ(model.muscles.size(), 1u);
  const ImportedMuscle& m = model.muscles[0];
  EXPECT_EQ(m.params.f_iso, 250.0);
  EXPECT_THAT(m.notes, Contains(HasSubstr("appliesForce is false")));
  EXPECT_THAT(m.notes, Contains(HasSubstr("default_activation 0.3: the scenario starts at "
                                          "activation 0")));
}

TEST(ImportMujoco, ClampsTimingAndIncludesAreListedNotDropped) {
  const std::string path = testing::WriteTempFile(
      "clamps.xml",
      "<mujoco>\n<include file='arm.xml'/>\n<actuator>\n"
      "<muscle name='m' joint='j' force='100' lengthrange='0.1 0.2' forcerange='0 50' "
      "actlimited='true' actrange='0 0.8' actearly='true'/>\n"
      "<muscle name='free' joint='j' force='100' lengthrange='0.1 0.2' forcerange='0 50' "
      "forcelimited='false'/>\n"
      "</actuator>\n</mujoco>\n");
  const ImportedModel model = ImportMuscles(path);
  ASSERT_EQ(model.muscles.size(), 2u);
  const std::vector<std::string>& notes = Named(model, "m").notes;
  EXPECT_THAT(notes, Contains(HasSubstr("forcerange 0 50: musclesim does not clamp the force")));
  EXPECT_THAT(notes,
              Contains(HasSubstr("actrange 0 0.8: musclesim does not clamp the activation")));
  EXPECT_THAT(notes, Contains(HasSubstr("actearly")));
  // forcelimited false: MuJoCo does not clamp either
  EXPECT_THAT(Named(model, "free").notes, Not(Contains(HasSubstr("forcerange"))));
  ASSERT_EQ(model.unsupported.size(), 1u);
  EXPECT_THAT(model.unsupported[0], HasSubstr("include 'arm.xml' (" + path + ":2): not followed"));
}

TEST(ImportMujoco, AGeneralMuscleTakesMujocosDefaultsAndItsNamesInMessages) {
  // dyntype muscle without dynprm: MuJoCo's default dynprm is [1, 0, ...], a deactivation
  // time constant of 0, which the message names as MuJoCo does
  const std::string path = testing::WriteTempFile(
      "general.xml",
      "<mujoco>\n<actuator>\n<general name='g' joint='j' gaintype='muscle' biastype='muscle' "
      "dyntype='muscle' gainprm='0.7 1.1 300 200 0.5 1.7 2 1.1 1.3' "
      "biasprm='0.7 1.1 300 200 0.5 1.7 2 1.1 1.3' lengthrange='0.0 0.2'/>\n"
      "</actuator>\n</mujoco>\n");
  try {
    ImportMuscles(path);
    ADD_FAILURE() << "imported a zero deactivation time constant";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'g': dynprm[1] = 0: "));
  }
}

std::string ImportError(const std::string& name, const std::string& text) {
  const std::string path = testing::WriteTempFile(name, text);
  try {
    ImportMuscles(path);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "imported " << name;
  return "";
}

TEST(ImportErrors, NameTheFileLineValueAndRule) {
  EXPECT_THAT(ImportError("broken.xml", "<mujoco>\n<actuator>\n<muscle name='a'\n"),
              HasSubstr("not well-formed XML"));
  EXPECT_THAT(ImportError("other.xml", "<robot/>\n"),
              HasSubstr("root element <robot> is neither OpenSim's"));
  EXPECT_THAT(ImportError("comment.xml", "<?xml version='1.0'?>\n<!-- only a comment -->\n"),
              HasSubstr("comment.xml: no root element"));
  EXPECT_THAT(ImportError("nothing.xml",
                          "<mujoco>\n<actuator>\n<motor name='m' joint='j'/>\n</actuator>\n"
                          "</mujoco>\n"),
              HasSubstr("no muscle musclesim imports"));
  const std::string bad_number = ImportError(
      "bad.osim",
      "<OpenSimDocument><Model><ForceSet><objects>\n"
      "<DeGrooteFregly2016Muscle name='m'>\n<optimal_fiber_length>abc</optimal_fiber_length>\n"
      "</DeGrooteFregly2016Muscle></objects></ForceSet></Model></OpenSimDocument>\n");
  EXPECT_THAT(bad_number, HasSubstr("<optimal_fiber_length> = abc"));
  EXPECT_THAT(bad_number, HasSubstr("bad.osim:3): must be a number"));
  const std::string bad_value = ImportError(
      "negative.osim",
      "<OpenSimDocument><Model><ForceSet><objects>\n"
      "<DeGrooteFregly2016Muscle name='m'>\n<max_isometric_force>-5</max_isometric_force>\n"
      "</DeGrooteFregly2016Muscle></objects></ForceSet></Model></OpenSimDocument>\n");
  EXPECT_THAT(bad_value, HasSubstr("'m': max_isometric_force = -5: must be > 0"));
  const std::string bad_range =
      ImportError("range.xml",
                  "<mujoco>\n<actuator>\n<muscle name='m' joint='j' force='1' "
                  "range='1.2 0.8' lengthrange='0.1 0.2'/>\n</actuator>\n</mujoco>\n");
  EXPECT_THAT(bad_range, HasSubstr("muscle 'm' ("));
  EXPECT_THAT(bad_range, HasSubstr("range"));
  EXPECT_THAT(ImportError("class.xml",
                          "<mujoco>\n<actuator>\n<muscle name='m' class='nope' joint='j'/>\n"
                          "</actuator>\n</mujoco>\n"),
              HasSubstr("class = nope ("));
}

TEST(ImportOpenSim, ACompliantMuscleIsANetworkThatRunsOpenSimsTrajectory) {
  // the compliant case of bench/peers/opensim_reference.py, as OpenSim wrote its model: the
  // scenario written for it, its experiment set to OpenSim's (5 kg at 0.32 m, activation 0.6,
  // the junction where equilibrateMuscles put the fiber), meets OpenSim's trajectory to 1e-6
  // of each column's scale with the fiber damping it gives (OpenSim's is 0: measured 7e-8)
  const ImportedMuscle m = ImportMuscles(Fixture("opensim_compliant.osim")).muscles.at(0);
  ASSERT_TRUE(m.tendon_strain.has_value());
  EXPECT_EQ(*m.tendon_strain, 0.049);
  EXPECT_EQ(m.tendon_slack_length, 0.2);
  EXPECT_EQ(m.params.degroote2016.fiber_damping, 0.0);
  const std::string text = FormatImportedScenario(m, "opensim_compliant.osim", "imported.csv");
  EXPECT_THAT(text, HasSubstr("the fiber's damping is 0 (fiber_damping in the file)"));
  Scenario scenario = ReadScenario(ParseDocument("imported", text), "imported");
  const testing::PeerTable opensim = testing::ReadPeerTable("opensim_drop_compliant.csv");
  const double junction =
      opensim.at("fiber_length")[0] * std::cos(opensim.at("pennation_angle")[0]);
  const std::vector<std::pair<std::string, double>> experiment = {
      {"nodes[1].position", junction},
      {"nodes[2].mass", 5.0},
      {"nodes[2].position", opensim.at("length")[0]},
      {"loads[0].value", 49.05},
      {"elements[0].activation.before", 0.6},
      {"elements[0].activation.after", 0.6},
      {"time.end", 0.5},
      {"output.interval", 0.005},
      {"solver.rtol", 1e-12},
      {"solver.atol", 1e-15}};
  std::vector<Parameter> parameters;
  std::vector<double> values;
  for (const auto& [path, value] : experiment) {
    parameters.push_back(FindParameter(scenario, path));
    values.push_back(value);
  }
  SetParameters(scenario, parameters, values);
  const RecordedRun run = RunScenario(scenario);
  const std::vector<std::string>& names = run.columns.names();
  const auto column = [&](const std::string& name) -> const std::vector<double>& {
    const auto at = std::find(names.begin(), names.end(), name);
    EXPECT_NE(at, names.end()) << name;
    return run.values[static_cast<std::size_t>(at - names.begin())];
  };
  const std::vector<double>& t = opensim.at("t");
  ASSERT_EQ(column("t").size(), t.size());
  const std::pair<const char*, const char*> compared[] = {{"body.position", "length"},
                                                          {"tendon.tension", "tendon_force"}};
  for (const auto& [mine, theirs] : compared) {
    const std::vector<double>& reference = opensim.at(theirs);
    const double scale =
        std::abs(*std::max_element(reference.begin(), reference.end(),
                                   [](double a, double b) { return std::abs(a) < std::abs(b); }));
    for (std::size_t k = 0; k < t.size(); ++k) {
      EXPECT_NEAR(column(mine)[k], reference[k], 1e-6 * scale) << mine << " at t = " << t[k];
    }
  }
}

TEST(ImportCli, ACompliantMusclesScenarioRunsAndSaysWhatItAdded) {
  const std::string dir = testing::FreshDirectory("import_compliant");
  const testing::CliOutcome out = testing::RunMusclesim(
      "import " + Fixture("opensim_compliant.osim") + " --to-gaussians 2 -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  EXPECT_THAT(out.err, HasSubstr("note: the fiber's damping is 0 (fiber_damping in the file)"));
  EXPECT_THAT(out.err, HasSubstr("note: OpenSim's tendon is compliant (strain 0.049"));
  const std::string native = testing::ReadFile(dir + "/muscle.yaml");
  EXPECT_THAT(native, HasSubstr("{name: junction, mass: 0,"));
  EXPECT_THAT(native, HasSubstr("degroote2016: {max_isometric_force: 400, "
                                "strain_at_one_norm_force: 0.049}"));
  EXPECT_THAT(testing::ReadFile(dir + "/muscle_gaussians.yaml"),
              HasSubstr("this file takes it rigid"));
  for (const char* name : {"muscle", "muscle_gaussians"}) {
    const testing::CliOutcome run =
        testing::RunMusclesim("run " + dir + "/" + name + ".yaml -o " + dir + "/" + name + ".csv");
    EXPECT_EQ(run.exit_code, 0) << name << ": " << run.err;
  }
  // the template starts with the junction in balance: the tendon carries the fiber's passive
  // force, and the junction is at rest (a tendon at its slack length would carry none, and the
  // fiber's 1e-8 damping alone would hold it: 1.8e6 m/s)
  const Scenario written = LoadScenario(dir + "/muscle.yaml");
  const RecordedRun run = RunScenario(written);
  const std::vector<std::string>& names = run.columns.names();
  const auto first = [&](const std::string& name) {
    const auto at = std::find(names.begin(), names.end(), name);
    EXPECT_NE(at, names.end()) << name;
    return run.values[static_cast<std::size_t>(at - names.begin())].front();
  };
  EXPECT_NEAR(first("tendon.tension"), first("fiber.tension"), 1e-9 * 400.0);
  EXPECT_GT(first("tendon.tension"), 1.0);  // De Groote's passive pull at the optimal length
  EXPECT_LT(std::abs(first("junction.velocity")), 1e-6);
}

TEST(ImportCli, ACompliantTendonWithoutASlackLengthIsRefused) {
  std::string text = testing::ReadFile(Fixture("opensim_compliant.osim"));
  const std::string slack = "<tendon_slack_length>0.20000000000000001</tendon_slack_length>";
  ASSERT_NE(text.find(slack), std::string::npos);
  text.replace(text.find(slack), slack.size(), "<tendon_slack_length>0</tendon_slack_length>");
  const std::string dir = testing::FreshDirectory("import_no_slack");
  const testing::CliOutcome out = testing::RunMusclesim(
      "import " + testing::WriteTempFile("no_slack.osim", text) + " -o " + dir);
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_THAT(out.err, HasSubstr("'muscle': tendon_slack_length = 0: must be > 0"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/muscle.yaml"));
}

TEST(ImportCli, WritesARunnableScenarioPerMuscleAndListsTheRest) {
  const std::string dir = testing::FreshDirectory("import");
  const testing::CliOutcome out =
      testing::RunMusclesim("import " + Fixture("muscles.xml") + " -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  EXPECT_THAT(out.err, HasSubstr("not imported: motor 'drive'"));
  const ImportedModel imported = ImportMuscles(Fixture("muscles.xml"));
  for (const char* name : {"plain", "quick", "generic"}) {
    const std::string scenario = dir + "/" + name + ".yaml";
    ASSERT_TRUE(std::filesystem::exists(scenario)) << scenario;
    // the written scenario reads back to the imported model, and runs
    const Scenario loaded = LoadScenario(scenario);  // held: the params are the model's
    const ModelParams& written = loaded.models.at("model").model->params();
    const ModelParams& own = Named(imported, name).params;
    EXPECT_EQ(written.family, own.family) << name;
    EXPECT_EQ(written.f_iso, own.f_iso) << name;
    EXPECT_THAT(written.mujoco.range, ElementsAre(own.mujoco.range[0], own.mujoco.range[1]));
    EXPECT_THAT(written.mujoco.lengthrange,
                ElementsAre(own.mujoco.lengthrange[0], own.mujoco.lengthrange[1]));
    EXPECT_EQ(written.mujoco.lmin, own.mujoco.lmin) << name;
    EXPECT_EQ(written.mujoco.lmax, own.mujoco.lmax) << name;
    EXPECT_EQ(written.mujoco.vmax, own.mujoco.vmax) << name;
    EXPECT_EQ(written.mujoco.fpmax, own.mujoco.fpmax) << name;
    EXPECT_EQ(written.mujoco.fvmax, own.mujoco.fvmax) << name;
    const testing::CliOutcome run =
        testing::RunMusclesim("run " + scenario + " -o " + dir + "/" + name + ".csv");
    EXPECT_EQ(run.exit_code, 0) << run.err;
  }
  EXPECT_THAT(testing::ReadFile(dir + "/quick.yaml"),
              HasSubstr("activation_dynamics: {family: mujoco, tau_activation: 0.02, "
                        "tau_deactivation: 0.05, tausmooth: 0.2}"));
}

TEST(ImportCli, ToGaussiansWritesThePapersModelFittedAndItsErrors) {
  const std::string dir = testing::FreshDirectory("import_gaussians");
  const testing::CliOutcome out =
      testing::RunMusclesim("import " + kOpenSimModel + " --to-gaussians 4 -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  EXPECT_THAT(out.err, HasSubstr("the paper's model, 4 Gaussians -> " + dir +
                                 "/muscle_gaussians.yaml: RMSE passive"));
  // both branches of the velocity curve are fitted, and each reports its error
  EXPECT_THAT(out.err, HasSubstr(" shortening, "));
  EXPECT_THAT(out.err, HasSubstr(" lengthening"));
  const Scenario fitted = LoadScenario(dir + "/muscle_gaussians.yaml");
  const ModelParams& params = fitted.models.at("model").model->params();
  EXPECT_EQ(params.family, CurveFamily::kPaper);
  EXPECT_EQ(params.active_length.gaussians.size(), 4u);
  // the same experiment as the muscle's own scenario, which is written beside it
  const Scenario own = LoadScenario(dir + "/muscle.yaml");
  EXPECT_EQ(fitted.t_end, own.t_end);
  const testing::CliOutcome run = testing::RunMusclesim(
      "run " + dir + "/muscle_gaussians.yaml -o " + dir + "/muscle_gaussians.csv");
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

TEST(ImportCli, ToGaussiansSaysWhatTheFitLeavesOut) {
  const std::string dir = testing::FreshDirectory("import_gaussians_damping");
  const testing::CliOutcome out = testing::RunMusclesim(
      "import " + Fixture("opensim_excited.osim") + " --to-gaussians 1 -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  // beta = 0.05 of F0 = 400 N per v_max l_opt = 10 x 0.1 m/s: 20 N s/m
  EXPECT_THAT(out.err,
              HasSubstr("not fitted: fiber_damping 0.05 (about actuator.damping 20 N s/m"));
}

TEST(ImportCli, ToGaussiansFileNamesStayUniqueWhenAMuscleIsNamedAfterAFit) {
  const std::string dir = testing::FreshDirectory("import_gaussians_names");
  const std::string file = testing::WriteTempFile(
      "names.xml",
      "<mujoco>\n<actuator>\n"
      "<muscle name='a_gaussians' joint='j' force='100' lengthrange='0.1 0.2'/>\n"
      "<muscle name='a' joint='j' force='200' lengthrange='0.1 0.2'/>\n"
      "</actuator>\n</mujoco>\n");
  const testing::CliOutcome out =
      testing::RunMusclesim("import " + file + " --to-gaussians 2 -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  // the first muscle keeps its own name; the second's fit takes the next free one
  EXPECT_EQ(LoadScenario(dir + "/a_gaussians.yaml").models.at("model").model->params().f_iso,
            100.0);
  EXPECT_EQ(LoadScenario(dir + "/a.yaml").models.at("model").model->params().f_iso, 200.0);
  const Scenario fit = LoadScenario(dir + "/a_gaussians_2.yaml");
  EXPECT_EQ(fit.models.at("model").model->params().family, CurveFamily::kPaper);
  // the fit of 'a' (f_iso 200 N, not 100 N): the identified f_iso is the fitted curve's
  EXPECT_NEAR(fit.models.at("model").model->params().f_iso, 200.0, 10.0);
  EXPECT_TRUE(std::filesystem::exists(dir + "/a_gaussians_gaussians.yaml"));
}

TEST(ImportCli, ToGaussiansOutOfRangeExitsTwoAndWritesNothing) {
  for (const char* count : {"0", "21", "3.5", "three"}) {
    const std::string dir = testing::FreshDirectory("import_bad_count");
    const testing::CliOutcome out = testing::RunMusclesim(
        "import " + kOpenSimModel + " --to-gaussians " + count + " -o " + dir);
    EXPECT_EQ(out.exit_code, 2) << count;
    EXPECT_THAT(out.err, HasSubstr("must be a whole number from 1 to 20")) << count;
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << count;
  }
}

TEST(ImportCli, NoMuscleExitsTwoAndWritesNothing) {
  const std::string dir = testing::FreshDirectory("import_none");
  const std::string file = testing::WriteTempFile(
      "motors.xml", "<mujoco>\n<actuator>\n<motor name='m' joint='j'/>\n</actuator>\n</mujoco>\n");
  const testing::CliOutcome out = testing::RunMusclesim("import " + file + " -o " + dir);
  EXPECT_EQ(out.exit_code, 2);
  EXPECT_THAT(out.err, HasSubstr("no muscle musclesim imports"));
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace musclesim
