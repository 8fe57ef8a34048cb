"""Work-precision of musclesim against OpenSim 4.6 on OpenSim's own muscle: the hanging mass
of bench/peers/opensim_reference.py (DeGrooteFregly2016Muscle, rigid tendon, constant
activation, 0.5 s), each tool at a ladder of tolerances. The error is the length and the
velocity at t = 0.5 s against OpenSim's accuracy-1e-12 run (bench/peers/reference/), relative
to their scales; the time is the integration alone (OpenSim's Manager.integrate; musclesim's
own report of its run, which excludes reading the file), the best of REPEATS, per simulated
second. Prints a Markdown table, then the time ratio at equal error.

    "$(bash bench/peers/setup.sh)" bench/peers/opensim_work_precision.py [MUSCLESIM]

MUSCLESIM is the built program (default build/musclesim).
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
CASES = ["opensim_drop_rigid", "opensim_drop_pennate"]


def reference_end(name):
    with open(os.path.join(ref.HERE, "reference", name + ".csv")) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    length = [float(r["length"]) for r in rows]
    speed = [float(r["shortening_velocity"]) for r in rows]
    scales = (max(abs(v) for v in length), max(abs(v) for v in speed))
    return (length[-1], speed[-1]), scales


def error(end, reference, scales):
    return max(abs(a - b) / s for a, b, s in zip(end, reference, scales))


def opensim_run(case, accuracy):
    best = math.inf
    for _ in range(REPEATS):
        model, muscle, height = ref.hanging_mass(*case)
        state = model.initSystem()
        manager = osim.Manager(model)
        manager.setIntegratorAccuracy(accuracy)
        state.setTime(0.0)
        manager.initialize(state)
        start = time.perf_counter()
        state = manager.integrate(ref.END)
        best = min(best, time.perf_counter() - start)
    l_s = case[3]
    return (height.getValue(state) - l_s, -height.getSpeedValue(state)), best


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
    print("OpenSim %s vs musclesim, %s, %s; best of %d\n"
          % (osim.GetVersion(), platform.processor() or platform.machine(),
             platform.platform(), REPEATS))
    print("| case | tool | tolerance | error at 0.5 s | integration time per simulated s |")
    print("|---|---|---|---|---|")
    ratios = []
    with tempfile.TemporaryDirectory() as directory:
        for name in CASES:
            case = next(c[1:] for c in ref.CASES if c[0] == name)
            reference, scales = reference_end(name)
            curves = {"OpenSim": [], "musclesim": []}
            for accuracy in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]:
                end, seconds = opensim_run(case, accuracy)
                e = error(end, reference, scales)
                curves["OpenSim"].append((e, seconds / ref.END))
                print("| %s | OpenSim (RungeKuttaMerson) | accuracy %.0e | %.1e | %.3g ms |"
                      % (name, accuracy, e, seconds / ref.END * 1e3))
            for rtol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11]:
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
