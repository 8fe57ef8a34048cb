"""MuJoCo 4.0 against musclesim on MuJoCo's own muscle: a mass on a vertical slider hanging
from one muscle actuator (`<general>` with MuJoCo's muscle gain and bias, activation = control,
held constant: no activation dynamics), released at rest. mj_step at shrinking time steps,
with each of MuJoCo's integrators, must converge to musclesim's solution (family mujoco,
rtol 1e-12) at its integrator's order; the table gives the largest error over the trajectory
(length and velocity every 10 ms, relative to their largest values) and the time per
simulated second, then each tool's time to reach 1e-3, 1e-4 and 1e-5 relative error.
MuJoCo's time is one call of mj_step (nstep: the steps of the whole run, in C), its model
compiled once; musclesim's time is its own report of the integration.

    "$(bash bench/peers/setup.sh)" bench/peers/mujoco_convergence.py [MUSCLESIM]
"""
import math
import os
import platform
import sys
import tempfile
import time

import mujoco

import musclesim_cli  # the run and the reading shared with the OpenSim side

END = 0.5
SAMPLE = 0.01  # s, where the trajectories are compared; every time step divides it
MASS, F0, ACTIVATION, START = 10.0, 200.0, 0.6, 0.2  # kg, N, -, m
LENGTHRANGE = (0.05, 0.25)  # m; MuJoCo's default range, lmin, ..., fvmax
GAIN = "0.75 1.05 %g 200 0.5 1.6 1.5 1.3 1.2" % F0
REPEATS = 3

XML = """
<mujoco model="hanging_mass">
  <option timestep="%(dt)r" gravity="0 0 -9.81" integrator="%(integrator)s"/>
  <worldbody>
    <body name="mass">
      <joint name="drop" type="slide" axis="0 0 -1"/>
      <geom type="sphere" size="0.02" mass="%(mass)r" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <actuator>
    <general name="muscle" joint="drop" dyntype="none" gaintype="muscle" biastype="muscle"
             gainprm="%(gain)s" biasprm="%(gain)s" lengthrange="%(lr0)r %(lr1)r"/>
  </actuator>
</mujoco>
"""


def mujoco_run(integrator, dt):
    model = mujoco.MjModel.from_xml_string(XML % dict(
        dt=dt, integrator=integrator, mass=MASS, gain=GAIN, lr0=LENGTHRANGE[0],
        lr1=LENGTHRANGE[1]))
    assert tuple(model.actuator_lengthrange[0]) == LENGTHRANGE, model.actuator_lengthrange
    steps = int(round(SAMPLE / dt))

    def start():
        data = mujoco.MjData(model)
        data.qpos[0] = START
        data.ctrl[0] = ACTIVATION
        mujoco.mj_forward(model, data)
        return data

    # the actuator length is the joint's position; MuJoCo's velocity lengthens
    data = start()
    samples = [(float(data.qpos[0]), -float(data.qvel[0]))]
    for _ in range(int(round(END / SAMPLE))):
        mujoco.mj_step(model, data, nstep=steps)
        samples.append((float(data.qpos[0]), -float(data.qvel[0])))
    # timed apart, as one call of mj_step in C for the whole run: no Python between samples
    best = math.inf
    for _ in range(REPEATS):
        data = start()
        began = time.perf_counter()
        mujoco.mj_step(model, data, nstep=steps * int(round(END / SAMPLE)))
        best = min(best, time.perf_counter() - began)
    return samples, best


def musclesim_run(program, rtol, directory):
    rows, best = musclesim_cli.timed_run(
        program,
        "name: mujoco_drop\n"
        "model: {family: mujoco, f_iso: %r, lengthrange: [%r, %r]}\n"
        "actuator: {mass: %r}\ninitial: {length: %r}\n"
        "activation: {type: constant, value: %r}\n"
        "load: {type: constant, value: %r}\n"
        "time: {start: 0.0, end: %r}\n"
        "solver: {method: bdf, rtol: %r, atol: %r}\n"
        "output: {file: drop.csv, interval: %r}\n"
        % (F0, LENGTHRANGE[0], LENGTHRANGE[1], MASS, START, ACTIVATION, MASS * 9.81, END,
           rtol, rtol * 1e-3, SAMPLE),
        directory, REPEATS)
    return [(float(r["length"]), float(r["shortening_velocity"])) for r in rows], best


def main():
    program = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/musclesim")
    print("MuJoCo %s vs musclesim, %s, %s; best of %d\n"
          % (mujoco.__version__, platform.processor() or platform.machine(),
             platform.platform(), REPEATS))
    with tempfile.TemporaryDirectory() as directory:
        reference, _ = musclesim_run(program, 1e-12, directory)
        scales = [max(abs(sample[i]) for sample in reference) for i in (0, 1)]

        def error(samples):
            assert len(samples) == len(reference)
            return max(abs(a[i] - b[i]) / scales[i]
                       for a, b in zip(samples, reference) for i in (0, 1))

        print("| tool | setting | largest error | observed order | time per simulated s |")
        print("|---|---|---|---|---|")
        curves = {}
        for integrator in ["Euler", "implicitfast", "RK4"]:
            curves[integrator] = []
            previous = None
            for dt in [1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6, 2e-6]:
                samples, seconds = mujoco_run(integrator, dt)
                e = error(samples)
                order = "" if previous is None or e == 0 else "%.2f" % (
                    math.log(previous[1] / e) / math.log(previous[0] / dt))
                previous = (dt, e)
                curves[integrator].append((e, seconds / END))
                print("| MuJoCo mj_step, %s | dt %.0e | %.1e | %s | %.3g ms |"
                      % (integrator, dt, e, order, seconds / END * 1e3))
        curves["musclesim"] = []
        for rtol in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8]:
            samples, seconds = musclesim_run(program, rtol, directory)
            e = error(samples)
            curves["musclesim"].append((e, seconds / END))
            print("| musclesim, CVODE BDF | rtol %.0e | %.1e | | %.3g ms |"
                  % (rtol, e, seconds / END * 1e3))
    print("\n| error | " + " | ".join(curves) + " |")
    print("|---|" + "---|" * len(curves))
    for target in [1e-3, 1e-4, 1e-5]:
        cells = []
        for name in curves:
            s = musclesim_cli.at_error(curves[name], target)
            cells.append("not reached" if s is None else "%.3g ms" % (s * 1e3))
        print("| %.0e | %s |" % (target, " | ".join(cells)))


if __name__ == "__main__":
    main()
