#!/usr/bin/env bash
# Mutation check: do the tests notice small, plausible mistakes in the model, dynamics and
# solver code? Each mutation below is a literal edit (a flipped sign, a dropped term, a
# changed constant, an off-by-one, < for <=) applied alone to a pristine copy of one file;
# the affected test targets are rebuilt in build-mutation/ (Release, tests on, benchmarks,
# examples and MPI off) and their tests run. A mutation is KILLED when a test fails, a test
# times out or the code no longer compiles (said so), SURVIVED when every test passes, and
# EQUIVALENT when it changes no observable behaviour (the reason is given; it is still run,
# as a check of that claim). Not part of CI: a full run takes over an hour on 2 cores, most of
# it recompiling the library after each mutation of a header the whole library includes.
# Before the first mutation, every target must exist and every mutation's tests must come
# from its own targets (see the t_* and r_* below); otherwise the run stops (status 2).
#
#   scripts/mutation_check.sh             every mutation; stdout is the report
#   scripts/mutation_check.sh --list      id, file and whether its pattern still applies
#   scripts/mutation_check.sh --only ID   one mutation (repeatable)
#
# Exit status 0 when every non-equivalent mutation is killed and every pattern applies.
# The mutated files must match HEAD before a run; they are restored on exit, Ctrl-C included,
# and checked with `git diff --quiet` at the end. Build and test logs: build-mutation/logs/.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh

build_dir=build-mutation
jobs=${JOBS:-2}
test_timeout=120  # [s] per test: the slowest test takes a few seconds; a hang is a kill

# ---------------------------------------------------------------------------------------
# The mutations. mutation ID FILE ORIGINAL REPLACEMENT TARGETS CTEST_REGEX [EQUIVALENT_REASON]
# ORIGINAL must occur exactly once in FILE; both are literal text (multi-line allowed).
ids=() files=() originals=() replacements=() targets=() regexes=() reasons=()
mutation() {
  ids+=("$1") files+=("$2") originals+=("$3") replacements+=("$4") targets+=("$5")
  regexes+=("$6") reasons+=("${7:-}")
}

# Test targets (t_*, names of tests/CMakeLists.txt's executables, <unit>_test) and ctest
# regexes (r_*, over the GoogleTest suite names those executables hold; a parameterised
# suite's tests carry a prefix, "Experiments/ActuatorScenario.Name/case") of each unit: its
# own tests, then the scenario and simulation tests that run it. Every test a regex selects
# must come from one of the targets, and every target must hold some of them (checked after
# the baseline build): a test of a target the mutant did not rebuild would run a stale binary.
suites() { local IFS='|'; echo "^([A-Za-z0-9_]+/)?($*)\\."; }
t_passive="passive_test tension_test closed_form_test simulation_test"
r_passive=$(suites Passive Tension ClosedForm Simulation)
t_velocity="velocity_test eccentric_velocity_test tension_test closed_form_test simulation_test
  eccentric_simulation_test"
r_velocity=$(suites Velocity EccentricVelocity Tension ClosedForm Simulation EccentricSimulation)
t_active="active_length_test tension_test model_ranges_test simulation_test"
r_active=$(suites ActiveLength Tension ModelRanges Simulation)
t_tension="tension_test tension_parameter_test actuator_test closed_form_test simulation_test"
r_tension=$(suites Tension TensionParameter TensionParameterParse TensionParameterPresence \
  Actuator ClosedForm Simulation)
t_fit="fit_target_test gaussian_fit_test model_file_test"
r_fit=$(suites FitTarget GaussianFit ModelFile)
t_waveform="waveform_test loads_test activation_dynamics_test actuator_scenario_test
  closed_form_test simulation_test"
r_waveform=$(suites Waveform Loads ActivationDynamics ActuatorScenario ActuatorKeyPaths \
  ActuatorSampleOf ActuatorScenarioFile ActuatorScenarioSpec ClosedForm Simulation)
t_loads="loads_test actuator_test actuator_scenario_test sensitivity_loads_test closed_form_test
  simulation_test"
r_loads=$(suites Loads Actuator ActuatorScenario ActuatorKeyPaths ActuatorSampleOf \
  ActuatorScenarioFile ActuatorScenarioSpec SensitivityLoads ClosedForm Simulation)
# the actuator's own right-hand side: runs integrate its network (ActuatorSystem::network()),
# which the actuator, network and actuator-scenario tests compare with it bit for bit
t_actuator="actuator_test network_test actuator_scenario_test closed_form_test simulation_test"
r_actuator=$(suites Actuator Network ActuatorScenario ActuatorKeyPaths ActuatorSampleOf \
  ActuatorScenarioFile ActuatorScenarioSpec ClosedForm Simulation)
# the integration: output rows and roots (src/solver, private headers)
t_solver="simulation_test closed_form_test integration_session_test stepper_test
  network_simulation_test"
r_solver=$(suites Simulation ClosedForm IntegrationSession OneAdvance Stepper NetworkSimulation)
# networks: every run is one (a single actuator too), so the actuator's runs use their
# Jacobian and pattern
t_network="network_test network_simulation_test control_scenarios_test sensitivity_elements_test
  closed_form_test simulation_test"
r_network=$(suites Network NetworkSimulation ControlScenarioFiles ForceRegulation \
  PositionTracking StiffnessModulation SensitivityElements ClosedForm Simulation)

# --- passive tension (eq. 1) ---
mutation passive-kink-strict include/musclesim/model/passive.h \
  'if (x <= params.slack_length)' \
  'if (x < params.slack_length)' "$t_passive" "$r_passive"
mutation passive-slope-drops-alpha include/musclesim/model/passive.h \
  'params.k_p * params.alpha * growth' \
  'params.k_p * growth' "$t_passive" "$r_passive"
# the curve's ranges, in its description (PassiveBlock)
mutation passive-kp-zero-refused src/model/passive.cc \
  'InputRange{0.0, kPositiveForceRange.max, "N", kPositiveForceRange.why}' \
  'InputRange{0.0, kPositiveForceRange.max, "N", kPositiveForceRange.why, true}' \
  "$t_passive" "$r_passive"
mutation passive-alpha-zero-accepted src/model/passive.cc \
  '"actuator'"'"'s",
                              true},' \
  '"actuator'"'"'s",
                              false},' "$t_passive" "$r_passive"

# --- tension-velocity g_eps and its slope (eq. 12, section 4) ---
# (alpha - 1) / 2 is now one helper, HalfExponent, of both the shortening and the
# lengthening branch: the mistake made there reaches both
mutation velocity-exponent-sign src/model/velocity.cc \
  'double HalfExponent(double alpha) { return 0.5 * (alpha - 1.0); }' \
  'double HalfExponent(double alpha) { return 0.5 * (1.0 - alpha); }' "$t_velocity" "$r_velocity"
mutation velocity-epsilon-not-squared src/model/velocity.cc \
  'epsilon_squared_(params.epsilon * params.epsilon)' \
  'epsilon_squared_(params.epsilon)' "$t_velocity" "$r_velocity"
mutation velocity-scale-exponent-sign src/model/velocity.cc \
  'std::pow(params.v_max, -alpha_)' \
  'std::pow(params.v_max, alpha_)' "$t_velocity" "$r_velocity"
mutation velocity-epsilon-max-refused src/model/velocity.cc \
  'params.epsilon <= params.v_max,' \
  'params.epsilon < params.v_max,' "$t_velocity" "$r_velocity"
mutation velocity-linear-shortcut-off src/model/velocity.cc \
  'linear_(params.n == 1)' \
  'linear_(false)' "$t_velocity" "$r_velocity" \
  'for n = 1 the general branch computes pow(w, 0), which IEEE 754 defines as exactly 1 for every w: the shortcut only saves a pow call'
mutation velocity-slope-drops-alpha include/musclesim/model/velocity.h \
  'p * (alpha_ * v * v + epsilon_squared_) / w' \
  'p * (v * v + epsilon_squared_) / w' "$t_velocity" "$r_velocity"
mutation velocity-g-slope-sign include/musclesim/model/velocity.h \
  '-phi.slope * inverse_scale_' \
  'phi.slope * inverse_scale_' "$t_velocity" "$r_velocity"

# --- active tension-length: Gaussians, their derivatives, the normalisation ---
mutation active-rate-drops-half include/musclesim/model/active_length.h \
  'g.precision / (2.0 * sigma)' \
  'g.precision / sigma' "$t_active" "$r_active"
mutation active-slope-factor src/model/active_length.cc \
  'out.slope -= 2.0 * t.rate * (x - t.center) * psi;' \
  'out.slope -= t.rate * (x - t.center) * psi;' "$t_active" "$r_active"
mutation active-curvature-sign src/model/active_length.cc \
  '4.0 * t.rate * t.rate * dx * dx - 2.0 * t.rate' \
  '4.0 * t.rate * t.rate * dx * dx + 2.0 * t.rate' "$t_active" "$r_active"
mutation active-narrowest-spread src/model/active_length.cc \
  'return 1.0 / std::sqrt(2.0 * largest_rate);' \
  'return 1.0 / std::sqrt(largest_rate);' "$t_active" "$r_active"
mutation active-bisection-direction src/model/active_length.cc \
  'if (sum.ValueAndSlope(mid).slope > 0.0) {' \
  'if (sum.ValueAndSlope(mid).slope < 0.0) {' "$t_active" "$r_active"
mutation active-max-ignores-right-end src/model/active_length.cc \
  '  consider(hi);' \
  '  // consider(hi);' "$t_active" "$r_active"
mutation active-max-misses-flat-grid-point src/model/active_length.cc \
  'left_slope > 0.0 && right_slope <= 0.0' \
  'left_slope > 0.0 && right_slope < 0.0' "$t_active" "$r_active"
mutation active-grid-min-cells src/model/active_length.cc \
  'std::clamp(std::ceil(width / step), 64.0,' \
  'std::clamp(std::ceil(width / step), 1.0,' "$t_active" "$r_active" \
  'step <= width / 64, exactly since dividing by a power of two is exact (for any width above the subnormals, 2e-308 m), so ceil(width / step) >= 64 and the lower bound of the clamp never binds'

# --- tension composition (eqs. 16-17) ---
mutation tension-total-sign include/musclesim/model/tension.h \
  'out.total = passive.value + out.active;' \
  'out.total = passive.value - out.active;' "$t_tension" "$r_tension"
mutation tension-d-length-drops-passive include/musclesim/model/tension.h \
  'out.d_length = passive.slope + u * params_.f_iso' \
  'out.d_length = u * params_.f_iso' "$t_tension" "$r_tension"
mutation tension-d-velocity-swaps-factor include/musclesim/model/tension.h \
  'length.value * velocity.slope' \
  'length.slope * velocity.slope' "$t_tension" "$r_tension"
mutation tension-error-loses-block src/model/tension.cc \
  'throw ParameterError(std::string(block) + "." + e.path(), e.value(), e.rule());' \
  'throw ParameterError(e.path(), e.value(), e.rule());' "$t_tension" "$r_tension"

# --- fit targets: closed-form normal equations and gradients (section 3.1) ---
mutation fit-normal-mass-tail-sign src/model/fit_target.cc \
  'if (z1 > 0.0) return 0.5 * (std::erfc(z1 * kInvSqrt2) - std::erfc(z2 * kInvSqrt2));' \
  'if (z1 > 0.0) return 0.5 * (std::erfc(z2 * kInvSqrt2) - std::erfc(z1 * kInvSqrt2));' \
  "$t_fit" "$r_fit"
mutation fit-polygon-norm-drops-cross-term src/model/fit_target.cc \
  '(p.y * p.y + p.y * q.y + q.y * q.y) / 3.0' \
  '(p.y * p.y + q.y * q.y) / 2.0' "$t_fit" "$r_fit"
mutation fit-gram-exponent-factor src/model/fit_target.cc \
  'std::exp(-bi * bj * gap * gap / (2.0 * sigma_ * sum))' \
  'std::exp(-bi * bj * gap * gap / (sigma_ * sum))' "$t_fit" "$r_fit"
mutation fit-gram-transposed src/model/fit_target.cc \
  'gram(i, j) = gram(j, i) = GramEntry(shapes, i, j);' \
  'gram(i, j) = gram(j, i) = GramEntry(shapes, j, i);' "$t_fit" "$r_fit" \
  'G_ij is symmetric bit for bit: b_i b_j and b_i + b_j commute exactly in IEEE arithmetic and the gap d_i - d_j enters only squared (negation is exact)'
mutation fit-piece-center-derivative-sign src/model/fit_target.cc \
  '- at_center * (n2 - n1) / spread' \
  '+ at_center * (n2 - n1) / spread' "$t_fit" "$r_fit"
mutation fit-projection-drops-last-piece src/model/fit_target.cc \
  '    for (std::size_t i = 0; i + 1 < vertices_.size(); ++i) {
      const TargetPoint& p = vertices_[i];
      const TargetPoint& q = vertices_[i + 1];
      const PieceIntegral piece =' \
  '    for (std::size_t i = 0; i + 2 < vertices_.size(); ++i) {
      const TargetPoint& p = vertices_[i];
      const TargetPoint& q = vertices_[i + 1];
      const PieceIntegral piece =' "$t_fit" "$r_fit"
mutation fit-gram-precision-gradient-sign src/model/fit_target.cc \
  '(-0.5 / sum - gap * gap * bj * bj' \
  '(0.5 / sum - gap * gap * bj * bj' "$t_fit" "$r_fit"
mutation fit-sample-center-gradient src/model/fit_target.cc \
  'gradient->centers(k) += weight * shapes.precisions(k) * dx / sigma_;' \
  'gradient->centers(k) += weight * shapes.precisions(k) * dx / (2.0 * sigma_);' \
  "$t_fit" "$r_fit"
mutation fit-cost-cross-term src/model/fit_target.cc \
  '- 2.0 * a.dot(projection) + NormSquared()' \
  '- a.dot(projection) + NormSquared()' "$t_fit" "$r_fit"

# --- the fit: reduced gradient, non-negative amplitudes, results (section 3.2) ---
mutation fit-reduced-gradient-chain-rule src/model/gaussian_fit.cc \
  'gradient[k] = g.precisions(k) * shapes.precisions(k) / norm_;' \
  'gradient[k] = g.precisions(k) / norm_;' "$t_fit" "$r_fit"
mutation fit-nnls-no-step-back src/model/gaussian_fit.cc \
  'a += step * (trial - a);' \
  'a = trial;' "$t_fit" "$r_fit"
mutation fit-relative-residual-unscaled src/model/gaussian_fit.cc \
  'result.relative_residual = result.cost / target.NormSquared();' \
  'result.relative_residual = result.cost;' "$t_fit" "$r_fit"
mutation fit-samples-needed src/model/gaussian_fit.cc \
  '(shapes_fixed ? 1 : 3)' \
  '(shapes_fixed ? 1 : 2)' "$t_fit" "$r_fit"

# --- waveforms: evaluation and breakpoints ---
mutation waveform-step-at-its-time src/dynamics/waveform.cc \
  'return t < time ? before : after;' \
  'return t <= time ? before : after;' "$t_waveform" "$r_waveform"
mutation waveform-ramp-reversed src/dynamics/waveform.cc \
  'return from + (to - from) * (t - start) / (end - start);' \
  'return from + (to - from) * (end - t) / (end - start);' "$t_waveform" "$r_waveform"
mutation waveform-sine-drops-two src/dynamics/waveform.cc \
  '2.0 * std::numbers::pi * frequency * t + phase' \
  'std::numbers::pi * frequency * t + phase' "$t_waveform" "$r_waveform"
mutation waveform-pulse-rises-late src/dynamics/waveform.cc \
  'if (t < start) return low;' \
  'if (t <= start) return low;' "$t_waveform" "$r_waveform"
mutation waveform-pulse-falls-late src/dynamics/waveform.cc \
  'return into_period < width ? high : low;' \
  'return into_period <= width ? high : low;' "$t_waveform" "$r_waveform"
mutation waveform-table-interpolates-from-right src/dynamics/waveform.cc \
  '(b.value - a.value) * (t - a.t) / (b.t - a.t)' \
  '(b.value - a.value) * (t - b.t) / (b.t - a.t)' "$t_waveform" "$r_waveform"
mutation waveform-table-first-point-strict src/dynamics/waveform.cc \
  'if (t <= points.front().t) return points.front().value;' \
  'if (t < points.front().t) return points.front().value;' "$t_waveform" "$r_waveform" \
  'at t = t_0 the first segment gives a.value + (b.value - a.value) * 0 / (b.t - a.t) = a.value exactly (a value of -0 comes out as +0, equal to it), and a one-point table returns at the next line'
mutation waveform-pulse-breakpoints-skip-current src/dynamics/waveform.cc \
  'std::max(0.0, std::floor((t0 - start) / period))' \
  'std::max(0.0, std::ceil((t0 - start) / period))' "$t_waveform" "$r_waveform"
mutation waveform-breakpoints-include-t0 src/dynamics/waveform.cc \
  'if (t > t0 && t < t1) times.push_back(t);' \
  'if (t >= t0 && t < t1) times.push_back(t);' "$t_waveform" "$r_waveform"

# --- loads ---
mutation loads-spring-sign src/dynamics/loads.cc \
  'weight_ + spring_pull_ - spring_stiffness_ * x' \
  'weight_ + spring_pull_ + spring_stiffness_ * x' "$t_loads" "$r_loads"
mutation loads-spring-drops-stiffness src/dynamics/loads.cc \
  'spring_pull_ += load.stiffness * load.anchor;' \
  'spring_pull_ += load.anchor;' "$t_loads" "$r_loads"
mutation loads-added-mass-last-only src/dynamics/loads.cc \
  'added_mass_ += load.mass;' \
  'added_mass_ = load.mass;' "$t_loads" "$r_loads"
mutation loads-breakpoints-unsorted src/dynamics/loads.cc \
  '  SortUnique(times);' \
  '  // SortUnique(times);' "$t_loads" "$r_loads"
# the spring's and the mass's ranges, in their kinds' descriptions (LoadVariants), which
# Validate(Load) checks
mutation loads-zero-mass-accepted src/dynamics/load_kinds.cc \
  'MemberField("mass", &Load::mass, kMassRange, std::nullopt,' \
  'MemberField("mass", &Load::mass, InputRange{0.0, kMassRange.max, "kg", kMassRange.why}, std::nullopt,' \
  "$t_loads" "$r_loads"
mutation loads-zero-stiffness-refused src/dynamics/load_kinds.cc \
  'MemberField("stiffness", &Load::stiffness, kStiffnessRange, std::nullopt,' \
  'MemberField("stiffness", &Load::stiffness, InputRange{0.0, kStiffnessRange.max, "N/m", kStiffnessRange.why, true}, std::nullopt,' \
  "$t_loads" "$r_loads"
mutation loads-error-index-off-by-one src/dynamics/loads.cc \
  '"load[" + std::to_string(i) + "]."' \
  '"load[" + std::to_string(i + 1) + "]."' "$t_loads" "$r_loads"

# --- actuator right-hand side and Jacobian (docs/model.md section 6) ---
mutation actuator-damping-sign include/musclesim/dynamics/actuator.h \
  '- actuator_.damping * xdot -' \
  '+ actuator_.damping * xdot -' "$t_actuator" "$r_actuator"
mutation actuator-jacobian-velocity-sign include/musclesim/dynamics/actuator.h \
  '(s.d_velocity - actuator_.damping) * inverse_mass_' \
  '(-s.d_velocity - actuator_.damping) * inverse_mass_' "$t_actuator" "$r_actuator"
# the constructor with an activation waveform (the one with an excitation sets the same
# inverse mass, but Acceleration and Jacobian are not defined with activation dynamics)
mutation actuator-ignores-load-mass src/dynamics/actuator.cc \
  'activation_((ValidateActivation(activation), std::move(activation))),
      loads_(std::move(loads)),
      inverse_mass_(1.0 / (actuator.mass + loads_.AddedMass())),' \
  'activation_((ValidateActivation(activation), std::move(activation))),
      loads_(std::move(loads)),
      inverse_mass_(1.0 / actuator.mass),' "$t_actuator" "$r_actuator"

# --- the integration: roots and output rows (src/solver) ---
mutation simulation-root-sign src/solver/run_roots.h \
  'default: return system.Length(root.element, t, y) - root.level;' \
  'default: return root.level - system.Length(root.element, t, y);' "$t_solver" "$r_solver" \
  'the root watch (src/solver/root_watch.h, crossing.h) reads only whether g is zero and whether two values share a sign, and its Illinois/secant iteration is invariant under g -> -g bit for bit (a - b = -(b - a) exactly in IEEE arithmetic, and the secant step is a ratio of differences); its search for dips between a step'"'"'s ends (FindDips), which reads signed slopes, watches only segment roots (kShortSegment, not this branch); the run reads only which root was found'
mutation simulation-last-output-past-end src/solver/output_rows.h \
  'return k >= count_ ? end_ : start_ + k * interval_;' \
  'return k > count_ ? end_ : start_ + k * interval_;' "$t_solver" "$r_solver"
mutation simulation-first-output-repeated src/solver/output_rows.h \
  '      while (count_ > 1 && start + (count_ - 1) * interval_ >= end - merge) --count_;
    }
    next_ = 1;' \
  '      while (count_ > 1 && start + (count_ - 1) * interval_ >= end - merge) --count_;
    }
    next_ = 0;' "$t_solver" "$r_solver"

# --- the network (docs/model.md section 7) ---
# the right-hand side of a network of several free nodes on a line (RightHandSide; a single
# free node has its own, SingleNodeRightHandSide, and a plane or space network its own)
mutation network-from-node-pushed src/dynamics/network.cc \
  'if (a.rate >= 0) ydot[a.rate] += tension;' \
  'if (a.rate >= 0) ydot[a.rate] -= tension;' "$t_network" "$r_network"
mutation network-mass-unscaled src/dynamics/network.cc \
  'if (!f.massless) ydot[m.ends[f.node].rate] *= f.inverse_mass;' \
  'if (!f.massless) ydot[m.ends[f.node].rate] *= 1.0;' "$t_network" "$r_network"
mutation network-jacobian-rate-sign src/dynamics/network.cc \
  'const double by_state[4] = {-tension.by_length, -tension.by_rate, tension.by_length,' \
  'const double by_state[4] = {-tension.by_length, tension.by_rate, tension.by_length,' "$t_network" "$r_network"
mutation network-tendon-pushes-when-slack src/dynamics/element_tension.h \
  'if (stretch <= 0.0 && !element.pushes_below_slack) return {0.0, 0.0, 0.0, 0.0};' \
  'if (stretch < -1.0 && !element.pushes_below_slack) return {0.0, 0.0, 0.0, 0.0};' \
  "$t_network" "$r_network"
mutation network-prescribed-still src/dynamics/network.cc \
  'return m.nodes[end.node].motion.Slope(t);' \
  'return 0.0;' "$t_network" "$r_network"
mutation network-exponential-slope-drops-alpha src/dynamics/element_tension.h \
  'return {element.k * (grow - 1.0), element.k * element.alpha * grow, 0.0, 0.0};' \
  'return {element.k * (grow - 1.0), element.k * grow, 0.0, 0.0};' "$t_network" "$r_network"
# the Jacobian's pattern, built with the network (network_build.cc)
mutation network-band-skips-lower src/dynamics/network_build.cc \
  'm.pattern.lower_bandwidth = std::max(m.pattern.lower_bandwidth, r - c);' \
  'm.pattern.lower_bandwidth = std::max(m.pattern.lower_bandwidth, r - c - 1);' "$t_network" "$r_network"


# --- the described parts (core/part_fields.h): what a file's reader and a handle apply ---
t_described="reference_table_test parameter_test junction_test"
r_described=$(suites ReferenceTable Parameter MasslessJunction)
mutation field-also-inverted include/musclesim/core/part_fields.h \
  '(field.also && value == *field.also)' \
  '(field.also && value != *field.also)' "$t_described" "$r_described"
mutation range-open-max-closed include/musclesim/core/input_ranges.h \
  '(max_exclusive ? value < max : value <= max)' \
  '(value <= max)' "$t_described" "$r_described"
mutation point-handle-sets-x src/scenario/parameter_resolver.h \
  '      x[c] = v;' \
  '      x[0] = v;' "$t_described" "$r_described"
# a part's signals (dynamics/signal_fields.h), the sweep's and the problem's files
t_signals="signal_fields_test spatial_network_yaml_test controller_yaml_test"
r_signals=$(suites SignalFields SpatialNetworkYaml ControllerYaml)
mutation signal-feedforward-bounded-as-position src/dynamics/controller_gains.cc \
  '&kFeedforwardRange, CheckWaveform' \
  '&kPositionRange, CheckWaveform' "$t_signals" "$r_signals"
mutation signal-motion-may-jump src/dynamics/node_kinds.cc \
  'motion.continuous = true;' \
  'motion.continuous = false;' "$t_signals" "$r_signals"
mutation signal-handle-matches-last-step-only src/scenario/parameter_resolver.h \
  'named = Key(next++) == signal.key.substr(begin, dot - begin);' \
  'named = dot != std::string::npos || Key(next) == signal.key.substr(begin); ++next;' \
  "$t_signals" "$r_signals"
mutation sweep-samples-always-required src/sweep/sweep_spec_fields.cc \
  'field.given = IsRandom;' \
  '(void)IsRandom;' "sweep_spec_test sweep_test" "$(suites SweepSpec Sweep)"
mutation problem-absent-optimizer-keeps-struct-defaults src/optimize/problem_file.cc \
  'SetDefaults(OptimizerBlock().front(), options);' \
  '(void)options;' "problem_file_test" "$(suites ProblemFile ProblemFileRefusal)"
# ---------------------------------------------------------------------------------------

# Literal single-occurrence replace: apply (default) or only check (--check).
replace() {  # FILE ORIGINAL REPLACEMENT [--check]
  "$python" - "$@" <<'PY'
import sys
path, old, new = sys.argv[1:4]
check = len(sys.argv) > 4
with open(path) as f:
    text = f.read()
count = text.count(old)
if count == 0:
    sys.exit(f"{path}: pattern not found: {old!r}")
if count > 1:
    sys.exit(f"{path}: pattern not unique ({count} occurrences): {old!r}")
if not check:
    with open(path, "w") as f:
        f.write(text.replace(old, new, 1))
PY
}

usage() { echo "usage: scripts/mutation_check.sh [--list] [--only ID]..." >&2; exit 2; }
list=false
only=()
while [ $# -gt 0 ]; do
  case "$1" in
    --list) list=true ;;
    --only) [ $# -ge 2 ] || usage; only+=("$2"); shift ;;
    *) usage ;;
  esac
  shift
done

if $list; then
  for i in "${!ids[@]}"; do
    state=$(replace "${files[i]}" "${originals[i]}" "${replacements[i]}" --check 2>&1 |
            sed 's/^[^:]*: \(pattern not [a-z]*\).*/\1/') || true
    [ -n "$state" ] || state="applies"
    [ -z "${reasons[i]}" ] || state="$state, equivalent"
    printf '%-42s %-40s %s\n' "${ids[i]}" "${files[i]}" "$state"
  done
  exit 0
fi

# which mutations to run
selected=()
if [ ${#only[@]} -eq 0 ]; then
  selected=("${!ids[@]}")
else
  for id in "${only[@]}"; do
    found=false
    for i in "${!ids[@]}"; do
      if [ "${ids[i]}" = "$id" ]; then selected+=("$i"); found=true; fi
    done
    $found || { echo "unknown mutation id: $id (see --list)" >&2; exit 2; }
  done
fi

# the files to mutate must match HEAD: they are restored from a copy and checked against it
mutated_files=()
for i in "${selected[@]}"; do mutated_files+=("${files[i]}"); done
mapfile -t mutated_files < <(printf '%s\n' "${mutated_files[@]}" | sort -u)
if ! git diff --quiet HEAD -- "${mutated_files[@]}"; then
  echo "mutation_check: these files differ from HEAD; commit or stash first:" >&2
  git diff --name-only HEAD -- "${mutated_files[@]}" >&2
  exit 2
fi

pristine=$(mktemp -d)
for f in "${mutated_files[@]}"; do
  mkdir -p "$pristine/$(dirname "$f")"
  cp "$f" "$pristine/$f"
done
current=""  # the file now mutated, if any
restore() {
  if [ -n "$current" ]; then
    # a fresh modification time, so that the next build recompiles what the mutant built
    cp "$pristine/$current" "$current"
    touch "$current"
    current=""
  fi
}
on_exit() {
  restore
  rm -rf "$pristine"
}
trap on_exit EXIT
trap 'echo "interrupted: tree restored" >&2; exit 130' INT TERM

logs="$build_dir/logs"
mkdir -p "$logs"
# warnings are not errors here: a mutant must break a test, or the compiler, to count as killed.
# ccache, where installed: restoring a mutated header otherwise recompiles everything that
# includes it a second time, for nothing (the restored text is the baseline's, in the cache).
launcher=$(command -v ccache || true)
"$cmake" -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DMUSCLESIM_BUILD_TESTS=ON \
  -DMUSCLESIM_BUILD_BENCHMARKS=OFF -DMUSCLESIM_BUILD_EXAMPLES=OFF -DMUSCLESIM_WITH_MPI=OFF \
  -DMUSCLESIM_WARNINGS_AS_ERRORS=OFF -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" \
  >"$logs/configure.log" 2>&1 ||
  { echo "configuring $build_dir failed: $logs/configure.log" >&2; exit 1; }

all_targets=$(for i in "${selected[@]}"; do echo ${targets[i]}; done | tr ' ' '\n' | sort -u | tr '\n' ' ')
mapfile -t all_regexes < <(for i in "${selected[@]}"; do echo "${regexes[i]}"; done | sort -u)
# Every target must exist: building an unknown one fails, which a mutant's build would count
# as a kill (compile error). `--target help` lists them ("... name" from Makefiles, "name: rule"
# from Ninja).
known_targets=$("$cmake" --build "$build_dir" --target help 2>/dev/null |
                sed -nE 's/^\.\.\. ([^ ]+).*/\1/p; s/^([A-Za-z0-9_.+-]+): .*/\1/p')
unknown=()
for t in $all_targets; do grep -qxF -- "$t" <<<"$known_targets" || unknown+=("$t"); done
if [ ${#unknown[@]} -gt 0 ]; then
  echo "mutation_check: no such target in $build_dir: ${unknown[*]} (see tests/CMakeLists.txt)" >&2
  exit 2
fi

build() {  # LOG TARGETS...
  local log=$1
  shift
  "$cmake" --build "$build_dir" -j"$jobs" --target "$@" >"$log" 2>&1
}
run_tests() {  # LOG REGEX
  "$ctest" --test-dir "$build_dir" -R "$2" -j"$jobs" --timeout "$test_timeout" \
    --no-tests=error --output-on-failure >"$1" 2>&1
}
# "Suite.Test" names of the failed tests in a ctest log, with how they failed unless plainly
# (a parameterised test's name is followed by "  # GetParam() = ...", left out)
failed_tests() {
  sed -nE 's/^[[:space:]]*[0-9]+ - ([^ ]+).* \(([^()]*)\)$/\1|\2/p' "$1" |
    awk -F'|' '{ print ($2 == "Failed") ? $1 : $1 " (" tolower($2) ")" }'
}
summarise() {  # NAMES... : at most three names, then a count
  if [ $# -le 3 ]; then
    local IFS=,
    echo "$*" | sed 's/,/, /g'
  else
    echo "$1, $2, $3 and $(($# - 3)) more"
  fi
}

# Which tests a mutation runs, checked once its targets are built (GoogleTest's tests are
# listed from the built executables): some; each from one of its targets, or it would run a
# binary this mutant did not rebuild (the baseline's, or a previous mutant's); some from each
# target; and some of each suite its regex names (a misspelt or renamed suite selects none).
check_selection() {  # TARGETS REGEX
  "$ctest" --test-dir "$build_dir" -N -R "$2" --show-only=json-v1 2>/dev/null |
    "$python" -c '
import json, os, re, sys
targets, regex = sys.argv[1].split(), sys.argv[2]
try:
    tests = json.load(sys.stdin).get("tests", [])
except ValueError:
    tests = []
problems = []
if not tests:
    problems.append("selects no test")
per_target = dict.fromkeys(targets, 0)
strays, suites = {}, set()
for test in tests:
    command = test.get("command") or ["?"]
    executable = os.path.basename(command[0])
    if executable in per_target:
        per_target[executable] += 1
    else:
        strays.setdefault(executable, test["name"])
    suites.add(re.sub(r"^[A-Za-z0-9_]+/", "", test["name"]).split(".")[0])
for executable, name in sorted(strays.items()):
    problems.append(f"selects tests of {executable} (such as {name}), not among its targets")
for target, count in per_target.items():
    if count == 0:
        problems.append(f"selects no test of its target {target}")
named = re.search(r"\(([A-Za-z0-9_|]+)\)\\\.$", regex)
for suite in named.group(1).split("|") if named else []:
    if suite not in suites:
        problems.append(f"names the suite {suite}, which has no test")
for problem in problems:
    print(f"  {regex}: {problem}")
sys.exit(1 if problems else 0)
' "$1" "$2"
}

# the pristine tree must build and pass every test the mutations use
echo "baseline: building $all_targets" >&2
build "$logs/baseline.build.log" $all_targets ||
  { echo "the unmutated tree does not build: $logs/baseline.build.log" >&2; exit 1; }
selection_ok=true
while IFS=$'\t' read -r t r; do
  check_selection "$t" "$r" >&2 || selection_ok=false
done < <(for i in "${selected[@]}"; do printf '%s\t%s\n' "$(echo ${targets[i]})" "${regexes[i]}"; done |
         sort -u)
$selection_ok ||
  { echo "mutation_check: fix the targets and regexes above (t_*, r_*)" >&2; exit 2; }
# one regex at a time: ctest's regular expressions hold at most 9 groups, too few for all at once
for k in "${!all_regexes[@]}"; do
  run_tests "$logs/baseline.test.$k.log" "${all_regexes[k]}" ||
    { echo "the unmutated tree fails its tests: $logs/baseline.test.$k.log" >&2; exit 1; }
done

echo "mutation check of $(git rev-parse --short HEAD): ${#selected[@]} mutations, $build_dir, -j$jobs"
printf '%-42s %-40s %-10s %s\n' ID FILE RESULT "BY / REASON"
killed=0 survived=0 equivalent=0 broken=0 equivalent_killed=0
survivors=()
for i in "${selected[@]}"; do
  id=${ids[i]} file=${files[i]}
  echo "[$id] $file" >&2
  current=$file  # before the edit, so that an interrupt at any point restores the file
  if ! message=$(replace "$file" "${originals[i]}" "${replacements[i]}" 2>&1); then
    restore
    printf '%-42s %-40s %-10s %s\n' "$id" "$file" ERROR "$message"
    broken=$((broken + 1))
    continue
  fi
  status="" detail=""
  if ! build "$logs/$id.build.log" ${targets[i]}; then
    status=KILLED detail="compile error (build failed: $logs/$id.build.log)"
  elif run_tests "$logs/$id.test.log" "${regexes[i]}"; then
    status=SURVIVED detail="every test of ${regexes[i]} passed"
  else
    mapfile -t names < <(failed_tests "$logs/$id.test.log")
    status=KILLED detail="$(summarise "${names[@]}")"
    [ ${#names[@]} -gt 0 ] || detail="ctest failed ($logs/$id.test.log)"
  fi
  restore
  if [ -n "${reasons[i]}" ]; then
    equivalent=$((equivalent + 1))
    if [ "$status" = SURVIVED ]; then
      detail=${reasons[i]}
    else
      # the claim of equivalence is wrong: say so loudly
      equivalent_killed=$((equivalent_killed + 1))
      detail="CLAIMED EQUIVALENT BUT KILLED by $detail; reason given: ${reasons[i]}"
    fi
    status=EQUIVALENT
  elif [ "$status" = KILLED ]; then
    killed=$((killed + 1))
  else
    survived=$((survived + 1))
    survivors+=("$id")
  fi
  printf '%-42s %-40s %-10s %s\n' "$id" "$file" "$status" "$detail"
done

restore
if ! git diff --quiet HEAD -- "${mutated_files[@]}"; then
  echo "mutation_check: the tree was not restored exactly:" >&2
  git diff --stat HEAD -- "${mutated_files[@]}" >&2
  exit 1
fi

non_equivalent=$((killed + survived))
echo
if [ "$non_equivalent" -gt 0 ]; then
  echo "kill rate: $killed / $non_equivalent non-equivalent mutations killed" \
       "($(awk -v k="$killed" -v n="$non_equivalent" 'BEGIN { printf "%.0f", 100 * k / n }')%)," \
       "$equivalent equivalent, $broken with a stale pattern"
fi
[ ${#survivors[@]} -eq 0 ] || echo "survivors: ${survivors[*]}"
[ "$equivalent_killed" -eq 0 ] || echo "equivalent mutations that were killed: $equivalent_killed (check their reasons)"
[ "$survived" -eq 0 ] && [ "$broken" -eq 0 ] && [ "$equivalent_killed" -eq 0 ]
