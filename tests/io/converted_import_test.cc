// `musclesim import` of OpenSim's Millard2012EquilibriumMuscle (tests/fixtures/import/
// opensim_millard.osim, written by OpenSim 4.6 through bench/peers/opensim_reference.py) and
// Thelen2003Muscle (data/opensim_hanging_mass.osim, likewise): converted to family
// degroote2016 with each curve's departure reported, their properties the file's, Millard's
// curves adjusted as OpenSim adjusts them, and every scenario runnable.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "musclesim/core/errors.h"
#include "musclesim/io/import/muscle_import.h"
#include "musclesim/model/degroote_conversion.h"
#include "support/cli_run.h"
#include "support/fresh_directory.h"
#include "support/scenario_files.h"

namespace musclesim {
namespace {

using ::testing::HasSubstr;

const std::string kMillard = testing::FixturePath("import/opensim_millard.osim");

const ImportedMuscle& Named(const ImportedModel& model, const std::string& name) {
  const auto at = std::find_if(model.muscles.begin(), model.muscles.end(),
                               [&](const ImportedMuscle& m) { return m.name == name; });
  EXPECT_NE(at, model.muscles.end()) << name;
  return *at;
}

// The file with `from` replaced by `to` once, inside the muscle named `muscle`.
std::string Edited(const std::string& muscle, const std::string& from, const std::string& to) {
  std::string text = testing::ReadFile(kMillard);
  const std::size_t start = text.find("<Millard2012EquilibriumMuscle name=\"" + muscle + "\"");
  const std::size_t at = text.find(from, start);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(ImportMillard, TakesTheFilesPropertiesIntoTheNearestDeGrooteMuscle) {
  const ImportedModel model = ImportMuscles(kMillard);
  ASSERT_EQ(model.muscles.size(), 4u);  // the DeGroote muscle of the case, and three Millard
  const ImportedMuscle& damped = Named(model, "damped");
  EXPECT_THAT(damped.source, HasSubstr("Millard2012EquilibriumMuscle (" + kMillard + ":"));
  EXPECT_EQ(damped.params.family, CurveFamily::kDeGroote2016);
  EXPECT_EQ(damped.params.f_iso, 800.0);
  EXPECT_EQ(damped.params.pennation_angle, 0.2);
  const DeGrooteParams& d = damped.params.degroote2016;
  EXPECT_EQ(d.optimal_fiber_length, 0.09);
  EXPECT_EQ(d.max_contraction_velocity, 10.0);
  EXPECT_EQ(d.fiber_damping, 0.1);                           // OpenSim's default
  EXPECT_EQ(d.passive_fiber_strain_at_one_norm_force, 0.7);  // Millard's default
  EXPECT_GT(d.active_force_width_scale, 1.0);
  EXPECT_EQ(damped.tendon_slack_length, 0.15);
  ASSERT_TRUE(damped.tendon_strain);
  EXPECT_EQ(*damped.tendon_strain, 0.049);
  ASSERT_TRUE(damped.activation_dynamics);  // Millard's first-order lag: thelen2003
  EXPECT_EQ(damped.activation_dynamics->family, ActivationFamily::kThelen2003);
  EXPECT_EQ(damped.activation_dynamics->tau_activation, 0.01);
  EXPECT_EQ(damped.activation_dynamics->tau_deactivation, 0.04);
  ASSERT_EQ(damped.conversion.size(), 4u);  // every curve, the tendon's too
  EXPECT_THAT(damped.conversion[0], HasSubstr("active force-length: De Groote's with width scale"));
  EXPECT_THAT(damped.conversion[2], HasSubstr("force-velocity: De Groote's with the file's v_max, "
                                              "shortening largest departure"));
  EXPECT_THAT(damped.conversion[2],
              HasSubstr("lengthening largest departure 0.394 f_iso at v~ = 1 "));
  EXPECT_THAT(damped.notes, ::testing::Contains(HasSubstr("minimum_activation 0.01")));
  EXPECT_THAT(damped.notes, ::testing::Contains(HasSubstr("maximum_pennation_angle")));

  const ImportedMuscle& classic = Named(model, "classic");
  EXPECT_EQ(classic.params.degroote2016.fiber_damping, 0.0);
  EXPECT_EQ(classic.params.degroote2016.passive_fiber_strain_at_one_norm_force, 0.5);
  EXPECT_EQ(*classic.tendon_strain, 0.06);
  EXPECT_EQ(classic.activation_dynamics->tau_activation, 0.02);
  EXPECT_THAT(classic.notes, ::testing::Contains(HasSubstr("minimum_activation 0.02")));
  EXPECT_THAT(classic.conversion[1], HasSubstr("strain at one norm force, 0.5, "));
  EXPECT_THAT(classic.conversion[1], HasSubstr("over l~ in [0.5, 1.5]"));

  const ImportedMuscle& rigid = Named(model, "rigid");
  EXPECT_FALSE(rigid.tendon_strain);
  EXPECT_FALSE(rigid.activation_dynamics);
  EXPECT_EQ(rigid.params.degroote2016.max_contraction_velocity, 8.0);
  EXPECT_EQ(rigid.params.degroote2016.fiber_damping, 0.02);
  EXPECT_EQ(rigid.conversion.size(), 3u);  // no tendon curve runs
}

TEST(ImportMillard, AdjustsTheCurvesAsOpenSimDidWhenItWroteTheFile) {
  // OpenSim raised the classic muscle's active floor to 0.1 and its end slopes to half the
  // near ones (0.15, 0.1) when it wrote the file; the values it was given convert the same
  std::string text = testing::ReadFile(kMillard);
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t start = text.find("<Millard2012EquilibriumMuscle name=\"classic\"");
    const std::size_t at = text.find(from, start);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("<minimum_value>0.10000000000000001</minimum_value>",
          "<minimum_value>0.05</minimum_value>");
  replace("<concentric_slope_at_vmax>0.14999999999999999<", "<concentric_slope_at_vmax>0.1<");
  replace("<eccentric_slope_at_vmax>0.10000000000000001<", "<eccentric_slope_at_vmax>0.05<");
  const ImportedModel given = ImportMuscles(testing::WriteTempFile("millard_given.osim", text));
  const ImportedModel written = ImportMuscles(kMillard);
  EXPECT_EQ(Named(given, "classic").conversion, Named(written, "classic").conversion);
  // and both are the departures of the curves OpenSim wrote (and runs)
  MillardCurves runs;
  runs.active = {0.5, 0.8, 1.7, 0.6, 0.1};
  runs.velocity = {0.15, 0.3, 4.0, 0.1, 0.2, 1.6, 0.3, 0.7};
  runs.passive = {0.1, 0.5, 0.5, 5.0, 0.4};
  runs.tendon = {0.06, 30.0, 0.5, 0.8};
  const DeGrooteConversion expected = NearestDeGroote(runs);
  const auto three_digits = [](double x) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.3g", x);
    return std::string(digits);
  };
  const std::vector<std::string>& lines = Named(given, "classic").conversion;
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_THAT(lines[0], HasSubstr("largest departure " + three_digits(expected.active.largest) +
                                  " f_iso at l~ = " + three_digits(expected.active.at) + " (RMS " +
                                  three_digits(expected.active.rms) + ")"));
  EXPECT_THAT(lines[2], HasSubstr("(RMS " + three_digits(expected.shortening.rms) + ")"));
  // the damped muscle drops the floor: a floor in its file changes nothing
  text = testing::ReadFile(kMillard);
  const std::string damped_floor = "<minimum_value>0</minimum_value>";
  const std::size_t at =
      text.find(damped_floor, text.find("<Millard2012EquilibriumMuscle name=\"damped\""));
  ASSERT_NE(at, std::string::npos);
  text.replace(at, damped_floor.size(), "<minimum_value>0.1</minimum_value>");
  const ImportedModel floored = ImportMuscles(testing::WriteTempFile("millard_floor.osim", text));
  EXPECT_EQ(Named(floored, "damped").conversion, Named(written, "damped").conversion);
  // nor its force-velocity slopes at v_max, which it sets to 0
  text = Edited("damped", "<concentric_slope_at_vmax>0</concentric_slope_at_vmax>",
                "<concentric_slope_at_vmax>0.1</concentric_slope_at_vmax>");
  const ImportedModel sloped = ImportMuscles(testing::WriteTempFile("millard_slope.osim", text));
  EXPECT_EQ(Named(sloped, "damped").conversion, Named(written, "damped").conversion);
}

TEST(ImportMillard, ARefusedCurvePropertyNamesItsCurveLineAndRule) {
  const std::string path = testing::WriteTempFile(
      "millard_bad.osim", Edited("classic", "<isometric_slope>4</isometric_slope>",
                                 "<isometric_slope>0.5</isometric_slope>"));
  try {
    ImportMuscles(path);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'classic': ForceVelocityCurve (" + path + ":"));
    EXPECT_THAT(e.what(), HasSubstr("<isometric_slope> = 0.5: must be above 1"));
  }
  const std::string partial = testing::WriteTempFile(
      "millard_partial.osim",
      Edited("classic", "<stiffness_at_low_force>0.5</stiffness_at_low_force>", ""));
  try {
    ImportMuscles(partial);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("FiberForceLengthCurve ("));
    EXPECT_THAT(e.what(), HasSubstr("<stiffness_at_one_norm_force> = 5: is one of the optional"));
  }
}

TEST(ImportMillard, RefusesWhatOpenSimRefusesEvenWhereItsAdjustmentWouldHideIt) {
  // each: muscle, the file's text, its replacement, what the refusal says (the probe's cases;
  // OpenSim 4.6 refuses each)
  const struct {
    const char *muscle, *from, *to, *says;
  } cases[] = {
      // the damped muscle sets these to 0, but OpenSim refuses them first
      {"damped", "<minimum_value>0</minimum_value>", "<minimum_value>-1</minimum_value>",
       "<minimum_value> = -1: must be in [0, 1)"},
      {"damped", "<concentric_slope_at_vmax>0</concentric_slope_at_vmax>",
       "<concentric_slope_at_vmax>-1</concentric_slope_at_vmax>",
       "<concentric_slope_at_vmax> = -1: must be in [0, 1)"},
      // the inverse curve OpenSim's muscle builds needs it below 1
      {"classic", "<concentric_slope_near_vmax>0.29999999999999999<",
       "<concentric_slope_near_vmax>1<", "<concentric_slope_near_vmax> = 1: must exceed"},
      // reported on the property that is wrong, not on the one the adjustment derives from it
      {"classic", "<concentric_slope_near_vmax>0.29999999999999999<",
       "<concentric_slope_near_vmax>1e300<", "<concentric_slope_near_vmax> = 1e+300"},
      {"classic", "<minimum_activation>0.02</minimum_activation>",
       "<minimum_activation>0</minimum_activation>", "minimum_activation = 0 ("},
      {"damped", "<max_isometric_force>",
       "<minimum_activation>-0.1</minimum_activation><max_isometric_force>",
       "<minimum_activation> = -0.1 ("},
      {"damped", "<max_isometric_force>",
       "<maximum_pennation_angle>2</maximum_pennation_angle><max_isometric_force>",
       "<maximum_pennation_angle> = 2 ("},
      // C's hexadecimal floats are no numbers to OpenSim
      {"classic", "<isometric_slope>4</isometric_slope>",
       "<isometric_slope>0x4p0</isometric_slope>", "<isometric_slope> = 0x4p0"},
  };
  for (const auto& c : cases) {
    const std::string path =
        testing::WriteTempFile("millard_refused.osim", Edited(c.muscle, c.from, c.to));
    try {
      ImportMuscles(path);
      ADD_FAILURE() << c.to << ": accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(c.says)) << c.to;
      EXPECT_THAT(e.what(), HasSubstr("millard_refused.osim:")) << c.to;
    }
  }
}

TEST(ImportMillardCli, WritesARunnableScenarioPerMuscleWithItsConversionReported) {
  const std::string dir = testing::FreshDirectory("import_millard");
  const testing::CliOutcome out =
      testing::RunMusclesim("import " + kMillard + " --to-gaussians 2 -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  EXPECT_THAT(out.err, HasSubstr("musclesim import: damped: Millard2012EquilibriumMuscle ("));
  EXPECT_THAT(out.err, HasSubstr("  converted: tendon force-length: De Groote's with the file's "
                                 "strain at one norm force, 0.049, largest departure"));
  EXPECT_THAT(out.err, HasSubstr("of its degroote2016 curves: RMSE passive"));
  // the classic muscle has no damping: its junction gets the least the balance needs
  EXPECT_THAT(out.err, HasSubstr("note: the fiber's damping is 0 (fiber_damping in the file)"));
  const std::string damped = testing::ReadFile(dir + "/damped.yaml");
  EXPECT_THAT(damped, HasSubstr("# Converted: active force-length: De Groote's with width scale"));
  EXPECT_THAT(damped, HasSubstr("activation_dynamics: {family: thelen2003, tau_activation: 0.01, "
                                "tau_deactivation: 0.04}"));
  for (const char* name :
       {"damped", "classic", "rigid", "damped_gaussians", "classic_gaussians", "rigid_gaussians"}) {
    const testing::CliOutcome run =
        testing::RunMusclesim("run " + dir + "/" + name + ".yaml -o " + dir + "/" + name + ".csv");
    EXPECT_EQ(run.exit_code, 0) << name << ": " << run.err;
  }
}

TEST(ImportMillardCli, AShortFibersJunctionBalanceIsSolvedAtEveryStep) {
  // a 3 mm fiber: the junction's balance bends steeply between flat stretches, where Newton's
  // steps crawled past their iteration limit (a NaN row, then a stalled run) until bisection
  // took over from steps that stopped halving
  const std::string dir = testing::FreshDirectory("import_millard_short");
  const std::string path = testing::WriteTempFile(
      "millard_short.osim",
      Edited("damped", "<optimal_fiber_length>0.089999999999999997</optimal_fiber_length>",
             "<optimal_fiber_length>0.003</optimal_fiber_length>"));
  ASSERT_EQ(testing::RunMusclesim("import " + path + " -o " + dir).exit_code, 0);
  const testing::CliOutcome run =
      testing::RunMusclesim("run " + dir + "/damped.yaml -o " + dir + "/damped.csv");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const std::string csv = testing::ReadFile(dir + "/damped.csv");
  EXPECT_GT(csv.size(), 1000u);
  EXPECT_EQ(csv.find("nan"), std::string::npos);
}

TEST(ImportMillardCli, ABadCurvePropertyExitsTwoAndWritesNothing) {
  const std::string dir = testing::FreshDirectory("import_millard_bad");
  const std::string path = testing::WriteTempFile(
      "millard_bad_cli.osim",
      Edited("damped", "<ForceVelocityCurve name=\"damped_ForceVelocityCurve\">",
             "<ForceVelocityCurve name=\"damped_ForceVelocityCurve\"><concentric_curviness>2"
             "</concentric_curviness>"));
  const testing::CliOutcome out = testing::RunMusclesim("import " + path + " -o " + dir);
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_THAT(out.err, HasSubstr("<concentric_curviness> = 2: must be in [0, 1]"));
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

const std::string kThelenFile =
    std::string(MUSCLESIM_SOURCE_DIR) + "/data/opensim_hanging_mass.osim";

TEST(ImportThelenCli, ItsScenariosRunAndABadPropertyIsRefusedByName) {
  const std::string dir = testing::FreshDirectory("import_thelen");
  const testing::CliOutcome out =
      testing::RunMusclesim("import " + kThelenFile + " --to-gaussians 3 -o " + dir);
  ASSERT_EQ(out.exit_code, 0) << out.err;
  EXPECT_THAT(out.err, HasSubstr("musclesim import: thelen: Thelen2003Muscle ("));
  // Thelen's fiber has no damping: the junction gets the least its balance needs
  EXPECT_THAT(out.err, HasSubstr("note: the fiber's damping is 0 (a Thelen2003Muscle has none)"));
  EXPECT_THAT(testing::ReadFile(dir + "/thelen.yaml"),
              HasSubstr("# Converted: force-velocity: De Groote's with the file's v_max"));
  for (const char* name : {"thelen", "thelen_gaussians"}) {
    const testing::CliOutcome run =
        testing::RunMusclesim("run " + dir + "/" + name + ".yaml -o " + dir + "/" + name + ".csv");
    EXPECT_EQ(run.exit_code, 0) << name << ": " << run.err;
  }
  std::string text = testing::ReadFile(kThelenFile);
  const std::string open = "<Thelen2003Muscle name=\"thelen\">";
  const std::size_t at = text.find(open);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + open.size(), "<Flen>0.9</Flen>");
  const std::string bad_dir = testing::FreshDirectory("import_thelen_bad");
  const testing::CliOutcome bad = testing::RunMusclesim(
      "import " + testing::WriteTempFile("thelen_bad.osim", text) + " -o " + bad_dir);
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  // the property's own line (the edit put it on the muscle's)
  EXPECT_THAT(bad.err, HasSubstr("Thelen2003Muscle ("));
  EXPECT_THAT(bad.err, HasSubstr("thelen_bad.osim:159) 'thelen'"));
  EXPECT_THAT(bad.err, HasSubstr("'thelen': Flen = 0.9: must be above 1"));
  EXPECT_TRUE(std::filesystem::is_empty(bad_dir));
}

}  // namespace
}  // namespace musclesim
