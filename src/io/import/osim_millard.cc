// OpenSim's Millard2012EquilibriumMuscle as family degroote2016 (docs/model.md 14.5): its
// curves read with OpenSim 4.6's defaults, adjusted as the muscle adjusts them for its damped
// or classic formulation, and brought to the nearest De Groote muscle, each curve's departure
// reported.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "io/import/conversion_report.h"
#include "io/import/muscle_import_readers.h"
#include "io/import/osim_muscle_parts.h"
#include "io/import/osim_property_reader.h"
#include "io/import/xml_reading.h"
#include "musclesim/core/errors.h"
#include "musclesim/core/number_format.h"

namespace musclesim {

namespace {

using tinyxml2::XMLElement;

// Below this fiber damping OpenSim's muscle drops its damping (MIN_NONZERO_DAMPING_COEFFICIENT)
constexpr double kMillardLeastDamping = 0.001;

// The curve `name` of the muscle: its element, or the muscle's when the file leaves it out
// (every property then at its default).
const XMLElement& CurveElement(const XMLElement& muscle, const char* name) {
  const XMLElement* curve = muscle.FirstChildElement(name);
  return curve == nullptr ? muscle : *curve;
}

// Builds `curve` once to check it, a ParameterError becoming an InputError that names the
// curve, the property and its line (the curve's, for a refusal of the curve as a whole).
template <typename Curve>
void CheckCurve(const Curve& curve, const XMLElement& muscle, const char* name,
                const std::string& path, const std::string& source) {
  try {
    MillardCurve(curve);
  } catch (const ParameterError& e) {
    const std::string where =
        OsimPropertyReader(CurveElement(muscle, name), path).WhereOf(e.path());
    const std::string property = e.path() == name ? "" : " <" + e.path() + "> =";
    throw InputError(source + ": " + name + " (" + where + ")" + property + " " + e.value() + ": " +
                     e.rule());
  }
}

MillardCurves ReadCurves(const XMLElement& muscle, const std::string& path) {
  MillardCurves c;
  // a curve the file leaves out keeps every default
  if (const XMLElement* e = muscle.FirstChildElement("ActiveForceLengthCurve")) {
    const OsimPropertyReader r(*e, path);
    MillardActiveForceLength& a = c.active;
    r.Read("min_norm_active_fiber_length", a.min_norm_active_fiber_length);
    r.Read("transition_norm_fiber_length", a.transition_norm_fiber_length);
    r.Read("max_norm_active_fiber_length", a.max_norm_active_fiber_length);
    r.Read("shallow_ascending_slope", a.shallow_ascending_slope);
    r.Read("minimum_value", a.minimum_value);
  }
  if (const XMLElement* e = muscle.FirstChildElement("ForceVelocityCurve")) {
    const OsimPropertyReader r(*e, path);
    MillardForceVelocity& v = c.velocity;
    r.Read("concentric_slope_at_vmax", v.concentric_slope_at_vmax);
    r.Read("concentric_slope_near_vmax", v.concentric_slope_near_vmax);
    r.Read("isometric_slope", v.isometric_slope);
    r.Read("eccentric_slope_at_vmax", v.eccentric_slope_at_vmax);
    r.Read("eccentric_slope_near_vmax", v.eccentric_slope_near_vmax);
    r.Read("max_eccentric_velocity_force_multiplier", v.max_eccentric_velocity_force_multiplier);
    r.Read("concentric_curviness", v.concentric_curviness);
    r.Read("eccentric_curviness", v.eccentric_curviness);
  }
  if (const XMLElement* e = muscle.FirstChildElement("FiberForceLengthCurve")) {
    const OsimPropertyReader r(*e, path);
    MillardFiberForceLength& f = c.passive;
    r.Read("strain_at_zero_force", f.strain_at_zero_force);
    r.Read("strain_at_one_norm_force", f.strain_at_one_norm_force);
    f.stiffness_at_low_force = r.OptionalNumber("stiffness_at_low_force");
    f.stiffness_at_one_norm_force = r.OptionalNumber("stiffness_at_one_norm_force");
    f.curviness = r.OptionalNumber("curviness");
  }
  if (const XMLElement* e = muscle.FirstChildElement("TendonForceLengthCurve")) {
    const OsimPropertyReader r(*e, path);
    MillardTendonForceLength& t = c.tendon;
    r.Read("strain_at_one_norm_force", t.strain_at_one_norm_force);
    t.stiffness_at_one_norm_force = r.OptionalNumber("stiffness_at_one_norm_force");
    t.norm_force_at_toe_end = r.OptionalNumber("norm_force_at_toe_end");
    t.curviness = r.OptionalNumber("curviness");
  }
  return c;
}

// Millard2012EquilibriumMuscle's own changes to its curves: the classic formulation (an
// elastic tendon, no damping) needs an active floor and end slopes that keep its
// force-velocity curve invertible; the damped one (or a rigid tendon) drops both.
void AdjustAsOpenSim(MillardCurves& c, bool classic) {
  MillardForceVelocity& v = c.velocity;
  if (classic) {
    c.active.minimum_value = std::max(c.active.minimum_value, 0.1);
    v.concentric_slope_at_vmax =
        std::max(v.concentric_slope_at_vmax, 0.5 * v.concentric_slope_near_vmax);
    v.eccentric_slope_at_vmax =
        std::max(v.eccentric_slope_at_vmax, 0.5 * v.eccentric_slope_near_vmax);
  } else {
    c.active.minimum_value = 0.0;
    v.concentric_slope_at_vmax = 0.0;
    v.eccentric_slope_at_vmax = 0.0;
  }
}

}  // namespace

ImportedMuscle ReadMillard(const XMLElement& element, const std::string& path) {
  const OsimPropertyReader read(element, path);
  ImportedMuscle muscle = StartMuscle(read, "Millard2012EquilibriumMuscle");
  const std::string source = muscle.source + " '" + muscle.name + "'";
  DeGrooteParams& d = muscle.params.degroote2016;
  const double damping = read.Number("fiber_damping", 0.1);
  if (!(damping >= 0.0 && damping <= 1e3)) {
    throw InputError(source + ": fiber_damping = " + FormatNumber(damping) + " (" +
                     read.WhereOf("fiber_damping") +
                     "): must be >= 0 and at most 1e3 [-] (Millard's default 0.1)");
  }
  const bool rigid = read.Flag("ignore_tendon_compliance", false);
  const bool damped = damping >= kMillardLeastDamping;
  d.fiber_damping = damped ? damping : 0.0;
  if (damping > 0.0 && !damped) {
    muscle.notes.push_back("fiber_damping " + FormatNumber(damping) +
                           ": OpenSim drops a damping below 0.001 and so does this import");
  }

  // OpenSim builds the curves from the file's values (and refuses what cannot be built), then
  // the muscle adjusts them and builds them again: both checked, in that order
  MillardCurves curves = ReadCurves(element, path);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) AdjustAsOpenSim(curves, !rigid && !damped);
    CheckCurve(curves.active, element, "ActiveForceLengthCurve", path, source);
    CheckCurve(curves.velocity, element, "ForceVelocityCurve", path, source);
    CheckCurve(curves.passive, element, "FiberForceLengthCurve", path, source);
    CheckCurve(curves.tendon, element, "TendonForceLengthCurve", path, source);
  }
  // OpenSim's own rule: its classic formulation is singular at zero activation
  const double floor = read.Number("minimum_activation", 0.01);
  if (!rigid && !damped && floor < 0.01) {
    throw InputError(source + ": minimum_activation = " + FormatNumber(floor) + " (" +
                     read.WhereOf("minimum_activation") +
                     "): must be at least 0.01 with an elastic tendon and no fiber damping "
                     "(OpenSim's classic formulation is singular at zero activation)");
  }
  const DeGrooteConversion converted = NearestDeGroote(curves);
  ApplyConversion(converted, !rigid, muscle);
  if (!rigid) {
    const OsimPropertyReader tendon(CurveElement(element, "TendonForceLengthCurve"), path);
    SetCompliantTendon(muscle, converted.tendon_strain_at_one_norm_force,
                       "TendonForceLengthCurve <strain_at_one_norm_force>",
                       tendon.WhereOf("strain_at_one_norm_force"));
  }
  // Millard's first-order lag, its defaults
  SetFirstOrderActivation(read, 0.01, 0.04, muscle);
  std::vector<std::pair<std::string, std::string>> names = kOsimPropertyNames;
  names.emplace_back("passive_fiber_strain_at_one_norm_force",
                     "FiberForceLengthCurve <strain_at_one_norm_force> (De Groote's e0)");
  ValidateImported(muscle, names);
  muscle.notes.push_back(
      "OpenSim holds the fiber at or above min_norm_active_fiber_length times the optimal "
      "length (" +
      FormatNumber(curves.active.min_norm_active_fiber_length * d.optimal_fiber_length) +
      " m); musclesim's fiber is not clamped");
  AddPennationClampNote(read, muscle);
  AddCommonNotes(read, element, muscle);
  return muscle;
}

}  // namespace musclesim
