#include "musclesim/io/imported_scenario.h"

#include <cmath>
#include <sstream>

#include "musclesim/core/number_format.h"
#include "musclesim/core/printable_text.h"

namespace musclesim {

namespace {

constexpr double kGravity = 9.81;  // [m/s^2] of the template's hanging mass

// A double-quoted YAML scalar: the names come from another tool's file.
std::string Quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string Pair(const double (&values)[2]) {
  std::ostringstream out;  // not operator+: GCC 12 warns falsely (-Wrestrict) on such chains
  out << "[" << FormatNumber(values[0]) << ", " << FormatNumber(values[1]) << "]";
  return out.str();
}

// The `activation_dynamics:` line of the tool's lag, its family's smoothing included.
std::string FormatActivationDynamics(const ActivationDynamics& d) {
  std::ostringstream out;
  out << "activation_dynamics: {family: " << ActivationFamilyName(d.family)
      << ", tau_activation: " << FormatNumber(d.tau_activation)
      << ", tau_deactivation: " << FormatNumber(d.tau_deactivation);
  if (d.family == ActivationFamily::kDeGroote2016)
    out << ", smoothing: " << FormatNumber(d.smoothing);
  if (d.family == ActivationFamily::kMujoco) out << ", tausmooth: " << FormatNumber(d.tausmooth);
  out << "}   # s";
  return out.str();
}

}  // namespace

std::string FormatModelBlock(const ModelParams& p) {
  std::ostringstream out;
  out << "model:\n  family: " << ToString(p.family) << "\n";
  out << "  f_iso: " << FormatNumber(p.f_iso) << "                 # N\n";
  switch (p.family) {
    case CurveFamily::kDeGroote2016: {
      const DeGrooteParams& d = p.degroote2016;
      out << "  optimal_fiber_length: " << FormatNumber(d.optimal_fiber_length) << "   # m\n"
          << "  max_contraction_velocity: " << FormatNumber(d.max_contraction_velocity)
          << "   # optimal lengths per second\n"
          << "  active_force_width_scale: " << FormatNumber(d.active_force_width_scale) << "\n"
          << "  passive_fiber_strain_at_one_norm_force: "
          << FormatNumber(d.passive_fiber_strain_at_one_norm_force) << "\n"
          << "  fiber_damping: " << FormatNumber(d.fiber_damping) << "\n";
      break;
    }
    case CurveFamily::kMujoco: {
      const MujocoMuscleParams& m = p.mujoco;
      out << "  lengthrange: " << Pair(m.lengthrange) << "   # m\n"
          << "  range: " << Pair(m.range) << "\n"
          << "  lmin: " << FormatNumber(m.lmin) << "\n"
          << "  lmax: " << FormatNumber(m.lmax) << "\n"
          << "  vmax: " << FormatNumber(m.vmax) << "\n"
          << "  fpmax: " << FormatNumber(m.fpmax) << "\n"
          << "  fvmax: " << FormatNumber(m.fvmax) << "\n";
      break;
    }
    case CurveFamily::kPaper: break;  // the importers make no paper model
  }
  if (p.pennation_angle != 0.0) {
    out << "  pennation_angle: " << FormatNumber(p.pennation_angle) << "   # rad\n";
  }
  return out.str();
}

double OptimalLineLength(const ModelParams& p) {
  const double fiber = p.family == CurveFamily::kMujoco
                           ? p.mujoco.lengthrange[0] +
                                 (1.0 - p.mujoco.range[0]) * mujoco_muscle::LengthScale(p.mujoco)
                           : p.degroote2016.optimal_fiber_length;
  return fiber * std::cos(p.pennation_angle);
}

double MaxLineSpeed(const ModelParams& p) {
  const double fiber =
      p.family == CurveFamily::kMujoco
          ? p.mujoco.vmax * mujoco_muscle::LengthScale(p.mujoco)
          : p.degroote2016.max_contraction_velocity * p.degroote2016.optimal_fiber_length;
  return fiber * std::cos(p.pennation_angle);
}

std::string FormatImportedScenario(const ImportedMuscle& muscle, const std::string& source,
                                   const std::string& output, const std::string& model_block) {
  const ModelParams& p = muscle.params;
  std::ostringstream out;
  out << "# " << muscle.name << ": " << muscle.source << ", imported by `musclesim import "
      << PrintableText(source) << "`\n";
  if (muscle.tendon_slack_length > 0.0) {
    out << "# Its tendon is rigid: the actuator's length is the muscle-tendon length less the\n"
        << "# tendon slack length, " << FormatNumber(muscle.tendon_slack_length) << " m.\n";
  }
  for (const std::string& note : muscle.notes) out << "# Not carried over: " << note << ".\n";
  const double mass = 0.5 * p.f_iso / kGravity;
  out << "# The experiment is a template to edit: a " << FormatNumber(mass)
      << " kg mass (half the isometric force\n"
      << "# under gravity) hangs from the muscle, released at rest at its optimal length.\n";
  out << "name: " << Quoted(muscle.name) << "\n"
      << (model_block.empty() ? FormatModelBlock(p) : model_block);
  out << "actuator: {mass: " << FormatNumber(mass) << "}   # kg\n";
  out << "initial: {length: " << FormatNumber(OptimalLineLength(p));
  if (muscle.activation_dynamics) {
    out << ", activation: 0.0}   # m, -\n"
        << "excitation: {type: step, time: 0.1, before: 0.0, after: 1.0}\n"
        << FormatActivationDynamics(*muscle.activation_dynamics) << "\n";
  } else {
    out << "}   # m\n"
        << "activation: {type: step, time: 0.1, before: 0.0, after: 1.0}\n";
  }
  out << "load: {type: constant, value: " << FormatNumber(mass * kGravity) << "}   # N\n"
      << "time: {start: 0.0, end: 1.0}\n"
      << "solver: {method: bdf, rtol: 1.0e-8, atol: 1.0e-12}\n"
      << "output: {file: " << Quoted(output) << ", interval: 0.001}\n";
  return out.str();
}

}  // namespace musclesim
