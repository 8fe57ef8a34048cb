#include "musclesim/io/import/imported_scenario.h"

#include <cmath>
#include <sstream>

#include "musclesim/core/number_format.h"
#include "musclesim/core/printable_text.h"
#include "musclesim/dynamics/activation_families.h"
#include "musclesim/io/writers/flow_fields.h"
#include "musclesim/model/tension.h"

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
  out << "activation_dynamics: {family: " << ActivationFamilyName(d.family) << ", "
      << FlowFields(*VariantOf(ActivationFamilies(), d), d);
  out << "}   # s";
  return out.str();
}

// The model block under a network's `models:`, the muscle's model named `muscle`.
std::string NetworkModelBlock(const ModelParams& p) {
  const std::string block = FormatModelBlock(p);  // "model:\n  family: ...\n  ...\n"
  std::string out = "models:\n  muscle:\n";
  std::size_t line = block.find('\n') + 1;  // past "model:"
  while (line < block.size()) {
    const std::size_t end = block.find('\n', line);
    out += "  " + block.substr(line, end - line + 1);
    line = end + 1;
  }
  return out;
}

// How the muscle is driven: a step of its activation at 0.1 s, or of its excitation through
// its tool's activation dynamics from activation 0.
std::string Drive(const ImportedMuscle& muscle, const std::string& indent) {
  if (!muscle.activation_dynamics) {
    return indent + "activation: {type: step, time: 0.1, before: 0.0, after: 1.0}";
  }
  return indent + "excitation: {type: step, time: 0.1, before: 0.0, after: 1.0}\n" + indent +
         FormatActivationDynamics(*muscle.activation_dynamics);
}

const char* const kTail =
    "time: {start: 0.0, end: 1.0}\n"
    "solver: {method: bdf, rtol: 1.0e-8, atol: 1.0e-12}\n";

// The compliant tendon's template: a network of the fixed origin, the massless junction
// where fiber and tendon meet, and the hanging body.
std::string FormatCompliantScenario(const ImportedMuscle& muscle, const std::string& output,
                                    std::ostringstream& out) {
  ModelParams p = muscle.params;
  const double l_s = muscle.tendon_slack_length;
  out << "# Its tendon is compliant, De Groote's (strain " << FormatNumber(*muscle.tendon_strain)
      << " at the maximum isometric force): the fiber\n"
      << "# (`fiber`, along the line) and the tendon (`tendon`, slack length " << FormatNumber(l_s)
      << " m) meet at a\n# massless junction (docs/model.md 14.4).\n";
  if (p.degroote2016.fiber_damping < kJunctionFiberDamping) {
    out << "# " << JunctionDampingNote(muscle) << ".\n";
    p.degroote2016.fiber_damping = kJunctionFiberDamping;
  }
  for (const std::string& line : muscle.conversion) out << "# Converted: " << line << ".\n";
  for (const std::string& note : muscle.notes) out << "# Not carried over: " << note << ".\n";
  const double mass = 0.5 * p.f_iso / kGravity;
  const double fiber = OptimalLineLength(p);
  // the tendon stretched to carry what the fiber's passive element pulls at rest at its
  // optimal length: the junction starts in balance (De Groote's tendon inverted,
  // F = 0.2 F0 (exp(kT strain) - 1))
  const double pull = TensionModel(p).Passive(fiber, 0.0).total;
  const double k_t = std::log(6.0) / *muscle.tendon_strain;
  const double stretch = pull > 0.0 ? std::log1p(pull / (0.2 * p.f_iso)) / k_t : 0.0;
  out << "# The experiment is a template to edit: a " << FormatNumber(mass)
      << " kg mass (half the isometric force\n"
      << "# under gravity) hangs from the unit, released at rest, the fiber at its optimal "
         "length\n# and the tendon stretched to carry its passive force there, "
      << FormatNumber(pull) << " N (the junction in balance).\n";
  out << "name: " << Quoted(muscle.name) << "\n" << NetworkModelBlock(p);
  out << "nodes:\n"
      << "  - {name: origin, fixed: 0.0}   # m\n"
      << "  - {name: junction, mass: 0, position: " << FormatNumber(fiber)
      << "}   # kg, m: massless\n"
      << "  - {name: body, mass: " << FormatNumber(mass)
      << ", position: " << FormatNumber(fiber + l_s * (1.0 + stretch)) << "}   # kg, m\n";
  out << "elements:\n"
      << "  - name: fiber\n    type: actuator\n    from: origin\n    to: junction\n"
      << "    model: muscle\n"
      << Drive(muscle, "    ") << "\n";
  if (muscle.activation_dynamics) out << "    initial_activation: 0.0\n";
  out << "  - {name: tendon, type: tendon, from: junction, to: body, slack_length: "
      << FormatNumber(l_s) << ",   # m\n"
      << "     degroote2016: {max_isometric_force: " << FormatNumber(p.f_iso)
      << ", strain_at_one_norm_force: " << FormatNumber(*muscle.tendon_strain) << "}}   # N, -\n";
  out << "loads:\n  - {node: body, type: constant, value: " << FormatNumber(mass * kGravity)
      << "}   # N\n"
      << kTail << "output: {file: " << Quoted(output) << ", interval: 0.001}\n";
  return out.str();
}

}  // namespace

std::string JunctionDampingNote(const ImportedMuscle& muscle) {
  // a Thelen2003Muscle has no damping property; the others' is the file's, as OpenSim runs it
  const bool no_property = muscle.source.rfind("Thelen2003Muscle", 0) == 0;
  return "the fiber's damping is " + FormatNumber(muscle.params.degroote2016.fiber_damping) +
         (no_property ? " (a Thelen2003Muscle has none)" : " (fiber_damping in the file)") +
         "; the massless junction needs a tension that depends on its rate at zero "
         "activation, and below " +
         FormatNumber(kJunctionFiberDamping) +
         " its balance is ill-conditioned (docs/guide/networks.md), so the fiber's is " +
         FormatNumber(kJunctionFiberDamping) +
         ", which moves the trajectory by about 7 times that, relative to its scale";
}

std::string RigidTendonNote(const ImportedMuscle& muscle) {
  return "OpenSim's tendon is compliant (strain " + FormatNumber(*muscle.tendon_strain) +
         " at the maximum isometric force); this file takes it rigid, the actuator's length the "
         "muscle-tendon length less the tendon slack length, " +
         FormatNumber(muscle.tendon_slack_length) +
         " m: the paper's model has no tension that depends on its rate at zero activation, "
         "which a massless junction needs (docs/model.md 14.4)";
}

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
  // the file's path on one line: a newline in it would start a line of YAML
  out << "# " << muscle.name << ": " << OneLineText(muscle.source)
      << ", imported by `musclesim import " << OneLineText(source) << "`\n";
  if (muscle.tendon_strain && model_block.empty()) {
    return FormatCompliantScenario(muscle, output, out);
  }
  if (muscle.tendon_strain) {
    out << "# " << RigidTendonNote(muscle) << ".\n";
  } else if (muscle.tendon_slack_length > 0.0) {
    out << "# Its tendon is rigid: the actuator's length is the muscle-tendon length less the\n"
        << "# tendon slack length, " << FormatNumber(muscle.tendon_slack_length) << " m.\n";
  }
  for (const std::string& line : muscle.conversion) out << "# Converted: " << line << ".\n";
  for (const std::string& note : muscle.notes) out << "# Not carried over: " << note << ".\n";
  const double mass = 0.5 * p.f_iso / kGravity;
  out << "# The experiment is a template to edit: a " << FormatNumber(mass)
      << " kg mass (half the isometric force\n"
      << "# under gravity) hangs from the muscle, released at rest at its optimal length.\n";
  out << "name: " << Quoted(muscle.name) << "\n"
      << (model_block.empty() ? FormatModelBlock(p) : model_block);
  out << "actuator: {mass: " << FormatNumber(mass) << "}   # kg\n";
  out << "initial: {length: " << FormatNumber(OptimalLineLength(p));
  out << (muscle.activation_dynamics ? ", activation: 0.0}   # m, -\n" : "}   # m\n")
      << Drive(muscle, "") << "\n";
  out << "load: {type: constant, value: " << FormatNumber(mass * kGravity) << "}   # N\n"
      << kTail << "output: {file: " << Quoted(output) << ", interval: 0.001}\n";
  return out.str();
}

}  // namespace musclesim
