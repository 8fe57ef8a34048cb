"""Work-precision of musclesim against OpenSim 4.6 on OpenSim's own muscle: the hanging mass
of bench/peers/opensim_reference.py (DeGrooteFregly2016Muscle, constant activation, 0.5 s),
with a rigid tendon and with a compliant one, each tool at a ladder of tolerances. The error
is the length and the velocity at t = 0.5 s (with the length prescribed, an isokinetic stretch
and a sinusoidal length change: the fiber's length and the tendon's force, or with a rigid
tendon and OpenSim's activation dynamics the activation and the tendon's force) against OpenSim's
accuracy-1e-12 run
(bench/peers/reference/), relative to their scales; the time is the integration alone
(OpenSim's Manager.integrate; musclesim's own report of its run, which excludes reading the
file), the best of REPEATS, per simulated second. Prints a Markdown table, then the time
ratio at equal error.

With the compliant tendon OpenSim integrates its explicit tendon dynamics (the normalised
tendon force a state, the fiber velocity from the inverted force-velocity curve, no fiber
damping); musclesim joins fiber and tendon at a massless junction, whose balance needs a rate
term at zero activation: a fiber damping of COMPLIANT_DAMPING, which moves its trajectory by
about 7 times that, relative (tests/scenario/opensim_reference_test.cc), far below the errors
compared here.

    "$(bash bench/peers/setup.sh)" bench/peers/opensim_work_precision.py [MUSCLESIM] [CASE...]

MUSCLESIM is the built program (default build/musclesim); CASE, any of CASES (default all).
"""
import csv
import math
import os
import platform
import sys
import tempfile
import time

import opensim as osim

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import musclesim_cli  # noqa: E402  (the run and the reading shared with the MuJoCo side)
import opensim_reference as ref  # noqa: E402  (the same model and cases)

REPEATS = 5
CASES = ["opensim_drop_rigid", "opensim_drop_pennate", "opensim_drop_compliant",
         "opensim_drop_compliant_pennate", "opensim_stretch_compliant", "opensim_sine_compliant",
         "opensim_stretch_rigid", "opensim_sine_rigid"]
COMPLIANT_DAMPING = 1e-10


def compared(dynamics):
    """The two columns compared at the end: the length and its speed, or, where the length is
    prescribed (the same in both tools), the fiber's length and the tendon's force, or with a
    rigid tendon (the fiber's length then prescribed too) the activation and the force."""
    if "motion" in dynamics:
        return (("fiber_length", "tendon_force") if "tendon_strain" in dynamics
                else ("activation", "tendon_force"))
    return ("length", "shortening_velocity")


def reference_end(name, dynamics):
    with open(os.path.join(ref.HERE, "reference", name + ".csv")) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    columns = [[float(r[c]) for r in rows] for c in compared(dynamics)]
    scales = tuple(max(abs(v) for v in column) for column in columns)
    return tuple(column[-1] for column in columns), scales


def error(end, reference, scales):
    return max(abs(a - b) / s for a, b, s in zip(end, reference, scales))


def opensim_run(case, dynamics, accuracy):
    best = math.inf
    compliant = "tendon_strain" in dynamics
    for _ in range(REPEATS):
        model, muscle, height = ref.hanging_mass(*case, **dynamics)
        state = model.initSystem()
        if compliant:
            model.equilibrateMuscles(state)
        manager = osim.Manager(model)
        manager.setIntegratorAccuracy(accuracy)
        state.setTime(0.0)
        manager.initialize(state)
        start = time.perf_counter()
        state = manager.integrate(ref.END)
        best = min(best, time.perf_counter() - start)
    if "motion" in dynamics:
        model.realizeDynamics(state)
        first = muscle.getFiberLength(state) if compliant else muscle.getActivation(state)
        return (first, muscle.getTendonForce(state)), best
    l_s = 0.0 if compliant else case[3]
    return (height.getValue(state) - l_s, -height.getSpeedValue(state)), best


def first_row(name):
    with open(os.path.join(ref.HERE, "reference", name + ".csv")) as f:
        return next(csv.DictReader(line for line in f if not line.startswith("#")))


def waveform(motion, length):
    """OpenSim's prescribed function as musclesim's waveform: the ramp runs through t = 0."""
    if motion[0] == "ramp":
        return ("{type: ramp, start: -1.0, end: 1.0, from: %r, to: %r}"
                % (length - motion[1], length + motion[1]))
    return "{type: sine, offset: %r, amplitude: %r, frequency: %r}" % (length, motion[1],
                                                                       motion[2])


def musclesim_compliant_run(program, name, case, dynamics, rtol, directory):
    """The compliant case as a network: the fiber from the ground to a massless junction, where
    OpenSim's equilibrium put it, De Groote's tendon from there to the hanging body, or to the
    end whose motion OpenSim prescribed."""
    mass, f_iso, l_opt, l_s, v_max, pennation, _, activation, height = case
    strain, motion = dynamics["tendon_strain"], dynamics.get("motion")
    start = first_row(name)
    junction = float(start["fiber_length"]) * math.cos(float(start["pennation_angle"]))
    body = ("{name: body, prescribed: %s}" % waveform(motion, height) if motion
            else "{name: body, mass: %r, position: %r}" % (mass, height))
    loads = "" if motion else "loads:\n  - {node: body, type: constant, value: %r}\n" % (
        mass * ref.GRAVITY)
    rows, best = musclesim_cli.timed_run(
        program,
        "name: opensim_drop_compliant\n"
        "models:\n  muscle: {family: degroote2016, f_iso: %r, optimal_fiber_length: %r, "
        "max_contraction_velocity: %r, fiber_damping: %r, pennation_angle: %r}\n"
        "nodes:\n  - {name: ground, fixed: 0.0}\n"
        "  - {name: junction, mass: 0, position: %r}\n"
        "  - %s\n"
        "elements:\n"
        "  - {name: muscle, type: actuator, from: ground, to: junction, model: muscle, "
        "activation: {type: constant, value: %r}}\n"
        "  - {name: tendon, type: tendon, from: junction, to: body, slack_length: %r, "
        "degroote2016: {max_isometric_force: %r, strain_at_one_norm_force: %r}}\n"
        "%s"
        "time: {start: 0.0, end: %r}\n"
        "solver: {method: bdf, rtol: %r, atol: %r}\n"
        "output: {file: drop.csv, interval: %r}\n"
        % (f_iso, l_opt, v_max, COMPLIANT_DAMPING, pennation, junction, body, activation, l_s,
           f_iso, strain, loads, ref.END, rtol, rtol * 1e-3, ref.END),
        directory, REPEATS)
    last = rows[-1]
    if motion:
        width = l_opt * math.sin(pennation)
        return (math.hypot(float(last["junction.position"]), width),
                float(last["tendon.tension"])), best
    return (float(last["body.position"]), -float(last["body.velocity"])), best


def musclesim_prescribed_rigid_run(program, case, dynamics, rtol, directory):
    """The rigid-tendon muscle with its length prescribed: a network of the ground and the end
    OpenSim's motion drives (less the tendon), the activation its only state."""
    _, f_iso, l_opt, l_s, v_max, pennation, damping, _, height = case
    points = ", ".join("[%r, %r]" % point for point in dynamics["excitation"])
    rows, best = musclesim_cli.timed_run(
        program,
        "name: opensim_prescribed_rigid\n"
        "models:\n  muscle: {family: degroote2016, f_iso: %r, optimal_fiber_length: %r, "
        "max_contraction_velocity: %r, fiber_damping: %r, pennation_angle: %r}\n"
        "nodes:\n  - {name: ground, fixed: 0.0}\n  - {name: end, prescribed: %s}\n"
        "elements:\n"
        "  - {name: muscle, type: actuator, from: ground, to: end, model: muscle, "
        "excitation: {type: table, points: [%s]}, activation_dynamics: {family: degroote2016, "
        "tau_activation: 0.015, tau_deactivation: 0.06, smoothing: 0.1}, "
        "initial_activation: %r}\n"
        "time: {start: 0.0, end: %r}\n"
        "solver: {method: bdf, rtol: %r, atol: %r}\n"
        "output: {file: drop.csv, interval: %r}\n"
        % (f_iso, l_opt, v_max, damping, pennation, waveform(dynamics["motion"], height - l_s),
           points, dynamics["initial_activation"], ref.END, rtol, rtol * 1e-3, ref.END),
        directory, REPEATS)
    last = rows[-1]
    return (float(last["muscle.activation"]), float(last["muscle.tension"])), best


def musclesim_run(program, case, rtol, directory):
    mass, f_iso, l_opt, l_s, v_max, pennation, damping, activation, height = case
    rows, best = musclesim_cli.timed_run(
        program,
        "name: opensim_drop\n"
        "model: {family: degroote2016, f_iso: %r, optimal_fiber_length: %r, "
        "max_contraction_velocity: %r, fiber_damping: %r, pennation_angle: %r}\n"
        "actuator: {mass: %r}\ninitial: {length: %r}\n"
        "activation: {type: constant, value: %r}\n"
        "load: {type: constant, value: %r}\n"
        "time: {start: 0.0, end: %r}\n"
        "solver: {method: bdf, rtol: %r, atol: %r}\n"
        "output: {file: drop.csv, interval: %r}\n"
        % (f_iso, l_opt, v_max, damping, pennation, mass, height - l_s, activation,
           mass * ref.GRAVITY, ref.END, rtol, rtol * 1e-3, ref.END),
        directory, REPEATS)
    last = rows[-1]
    return (float(last["length"]), float(last["shortening_velocity"])), best


def main():
    program = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/musclesim")
    names = sys.argv[2:] or CASES
    for name in names:
        if name not in CASES:
            sys.exit("unknown case %r: the cases are %s" % (name, ", ".join(CASES)))
    print("OpenSim %s vs musclesim, %s, %s; best of %d\n"
          % (osim.GetVersion(), platform.processor() or platform.machine(),
             platform.platform(), REPEATS))
    print("| case | tool | tolerance | error at 0.5 s | integration time per simulated s |")
    print("|---|---|---|---|---|")
    ratios = []
    with tempfile.TemporaryDirectory() as directory:
        every = {name: (case, dynamics) for name, case, dynamics in ref.cases()}
        for name in names:
            case, dynamics = every[name]
            reference, scales = reference_end(name, dynamics)
            curves = {"OpenSim": [], "musclesim": []}
            for accuracy in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]:
                end, seconds = opensim_run(case, dynamics, accuracy)
                e = error(end, reference, scales)
                curves["OpenSim"].append((e, seconds / ref.END))
                print("| %s | OpenSim (RungeKuttaMerson) | accuracy %.0e | %.1e | %.3g ms |"
                      % (name, accuracy, e, seconds / ref.END * 1e3))
            for rtol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11]:
                if "motion" in dynamics and "tendon_strain" not in dynamics:
                    end, seconds = musclesim_prescribed_rigid_run(program, case, dynamics, rtol,
                                                                  directory)
                elif "tendon_strain" in dynamics:
                    end, seconds = musclesim_compliant_run(program, name, case, dynamics, rtol,
                                                           directory)
                else:
                    end, seconds = musclesim_run(program, case, rtol, directory)
                e = error(end, reference, scales)
                curves["musclesim"].append((e, seconds / ref.END))
                print("| %s | musclesim (CVODE BDF) | rtol %.0e | %.1e | %.3g ms |"
                      % (name, rtol, e, seconds / ref.END * 1e3))
            for target in [1e-4, 1e-6, 1e-8]:
                o = musclesim_cli.at_error(curves["OpenSim"], target)
                m = musclesim_cli.at_error(curves["musclesim"], target)
                ratios.append((name, target, o, m))
    print("\n| case | error | OpenSim per simulated s | musclesim per simulated s | ratio |")
    print("|---|---|---|---|---|")
    for name, target, o, m in ratios:
        cell = lambda s: "not reached on the ladder" if s is None else "%.3g ms" % (s * 1e3)
        ratio = "%.0fx" % (o / m) if o and m else "-"
        print("| %s | %.0e | %s | %s | %s |" % (name, target, cell(o), cell(m), ratio))


if __name__ == "__main__":
    main()
