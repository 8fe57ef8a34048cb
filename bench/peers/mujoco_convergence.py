"""MuJoCo 4.0 against musclesim on MuJoCo's own muscle (`<general>` with MuJoCo's muscle gain
and bias, activation = control, held constant: no activation dynamics), in three cases:

- hanging: a 10 kg mass on a vertical slider hanging from the muscle, released at rest;
- eccentric: a 50 g mass pulled by a constant 135 N, more than the muscle's isometric force
  (120 N at activation 0.6): the muscle lengthens on its eccentric branch, and the mass's
  velocity relaxes to it at a rate of thousands per second (stiff);
- compliant: the hanging 10 kg mass, with a linear tendon (a MuJoCo fixed tendon with
  stiffness, 20 kN/m, slack 0.1 m) in series between the muscle and the mass, the junction a
  1 g body (MuJoCo's muscle has no compliant tendon: a careful user builds one this way, and
  musclesim runs the same equations, its junction a 1 g node; stiff: the junction relaxes at
  c/m ~ 1e5 per second).

mj_step at shrinking time steps, with each of MuJoCo's integrators, must converge to
musclesim's solution (family mujoco, rtol 1e-12) at its integrator's order; the tables give
the largest error over the trajectory (each compared position and velocity every 10 ms,
relative to its largest value) and the time per simulated second, then each tool's time to
reach 1e-3, 1e-4 and 1e-5 relative error. MuJoCo's time is one call of mj_step (nstep: the
steps of the whole run, in C), its model compiled once; musclesim's time is its own report of
the integration.

    "$(bash bench/peers/setup.sh)" bench/peers/mujoco_convergence.py [MUSCLESIM] [CASE...]

With --references instead, it writes MuJoCo's own trajectory of each case, RK4 at a step
where it has converged to 1e-9 or better (REFERENCE_STEPS), to bench/peers/reference/
mujoco_<case>.csv, which tests/scenario/mujoco_reference_test.cc meets without MuJoCo:

    "$(bash bench/peers/setup.sh)" bench/peers/mujoco_convergence.py --references
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
F0, ACTIVATION, START = 200.0, 0.6, 0.2  # N, -, m
LENGTHRANGE = (0.05, 0.25)  # m; MuJoCo's default range, lmin, ..., fvmax
GAIN = "0.75 1.05 %g 200 0.5 1.6 1.5 1.3 1.2" % F0
GRAVITY = 9.81
REPEATS = 3
STEPS = [1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6, 2e-6]

ACTUATOR = """
  <actuator>
    <general name="muscle" joint="%(joint)s" dyntype="none" gaintype="muscle" biastype="muscle"
             gainprm="%(gain)s" biasprm="%(gain)s" lengthrange="%(lr0)r %(lr1)r"/>
  </actuator>
"""
SLIDER = """
    <body name="%(name)s">
      <joint name="%(name)s" type="slide" axis="0 0 -1"/>
      <geom type="sphere" size="0.02" mass="%(mass)r" contype="0" conaffinity="0"/>
    </body>"""
MUSCLESIM_COMMON = (
    "time: {start: 0.0, end: %r}\n"
    "solver: {method: bdf, rtol: %%(rtol)r, atol: %%(atol)r}\n"
    "output: {file: drop.csv, interval: %r}\n" % (END, SAMPLE))
MUJOCO_MODEL = "model: {family: mujoco, f_iso: %r, lengthrange: [%r, %r]}\n" % (
    F0, LENGTHRANGE[0], LENGTHRANGE[1])


class SingleMass:
    """One mass on the muscle (its length the slider's position, lengthening downwards),
    pulled by gravity and a constant applied force."""

    def __init__(self, mass, gravity, applied):
        self.mass, self.gravity, self.applied = mass, gravity, applied

    def xml(self):
        return ("<worldbody>" + SLIDER % dict(name="drop", mass=self.mass) + "\n  </worldbody>"
                + ACTUATOR % dict(joint="drop", gain=GAIN, lr0=LENGTHRANGE[0],
                                  lr1=LENGTHRANGE[1]))

    def start(self, data):
        data.qpos[0] = START
        data.qfrc_applied[0] = self.applied

    def mujoco_sample(self, data):
        return (float(data.qpos[0]), float(data.qvel[0]))

    def scenario(self):
        return ("name: mujoco_drop\n" + MUJOCO_MODEL
                + "actuator: {mass: %r}\ninitial: {length: %r}\n"
                  "activation: {type: constant, value: %r}\n"
                  "load: {type: constant, value: %r}\n"
                % (self.mass, START, ACTIVATION, self.mass * self.gravity + self.applied)
                + MUSCLESIM_COMMON)

    @staticmethod
    def musclesim_sample(row):  # musclesim's velocity shortens, MuJoCo's lengthens
        return (float(row["length"]), -float(row["shortening_velocity"]))


class CompliantTendon:
    """The muscle from the ceiling to a light junction, a linear tendon from the junction to
    the hanging mass: the positions and velocities of both, the tendon starting stretched to
    hold the mass."""
    JUNCTION, MASS, STIFFNESS, SLACK = 0.001, 10.0, 2.0e4, 0.1  # kg, kg, N/m, m
    TENDON = SLACK + MASS * GRAVITY / STIFFNESS  # m

    def xml(self):
        return ("<worldbody>" + SLIDER % dict(name="junction", mass=self.JUNCTION)
                + SLIDER % dict(name="drop", mass=self.MASS) + "\n  </worldbody>\n"
                "  <tendon>\n"
                "    <fixed name=\"tendon\" stiffness=\"%r\" springlength=\"%r\">\n"
                "      <joint joint=\"drop\" coef=\"1\"/>\n"
                "      <joint joint=\"junction\" coef=\"-1\"/>\n"
                "    </fixed>\n"
                "  </tendon>" % (self.STIFFNESS, self.SLACK)
                + ACTUATOR % dict(joint="junction", gain=GAIN, lr0=LENGTHRANGE[0],
                                  lr1=LENGTHRANGE[1]))

    def start(self, data):
        data.qpos[0] = START
        data.qpos[1] = START + self.TENDON

    @staticmethod
    def mujoco_sample(data):
        return tuple(float(x) for x in (data.qpos[0], data.qvel[0], data.qpos[1], data.qvel[1]))

    def scenario(self):
        return ("name: mujoco_compliant\nmodels:\n  muscle: {family: mujoco, f_iso: %r, "
                "lengthrange: [%r, %r]}\n"
                "nodes:\n"
                "  - {name: ceiling, fixed: 0.0}\n"
                "  - {name: junction, mass: %r, position: %r}\n"
                "  - {name: drop, mass: %r, position: %r}\n"
                "elements:\n"
                "  - {name: muscle, type: actuator, from: ceiling, to: junction, model: muscle,"
                " activation: {type: constant, value: %r}}\n"
                "  - {name: tendon, type: spring, from: junction, to: drop, stiffness: %r,"
                " rest_length: %r}\n"
                "loads:\n"
                "  - {node: junction, type: constant, value: %r}\n"
                "  - {node: drop, type: constant, value: %r}\n"
                % (F0, LENGTHRANGE[0], LENGTHRANGE[1], self.JUNCTION, START, self.MASS,
                   START + self.TENDON, ACTIVATION, self.STIFFNESS, self.SLACK,
                   self.JUNCTION * GRAVITY, self.MASS * GRAVITY)
                + MUSCLESIM_COMMON)

    @staticmethod
    def musclesim_sample(row):
        return tuple(float(row[k]) for k in (
            "junction.position", "junction.velocity", "drop.position", "drop.velocity"))


# RK4's step for each case's stored trajectory: its largest error against musclesim's at
# rtol 1e-12 (the tables in docs/performance.md) is 1e-9 or below there
REFERENCE_STEPS = {"hanging": 1e-3, "eccentric": 5e-5, "compliant": 1e-6}

CASES = {
    "hanging": SingleMass(mass=10.0, gravity=GRAVITY, applied=0.0),
    "eccentric": SingleMass(mass=0.05, gravity=0.0, applied=135.0),
    "compliant": CompliantTendon(),
}


def mujoco_run(case, integrator, dt, repeats=REPEATS):
    """(the case's samples every SAMPLE, the least time of `repeats` runs timed apart); with
    repeats 0 the samples carry the actuator's force too, and nothing is timed."""
    gravity = getattr(case, "gravity", GRAVITY)
    model = mujoco.MjModel.from_xml_string(
        "<mujoco>\n  <option timestep=\"%r\" gravity=\"0 0 %r\" integrator=\"%s\"/>\n  %s\n"
        "</mujoco>" % (dt, -gravity, integrator, case.xml()))
    assert tuple(model.actuator_lengthrange[0]) == LENGTHRANGE, model.actuator_lengthrange
    steps = int(round(SAMPLE / dt))

    def start():
        data = mujoco.MjData(model)
        case.start(data)
        data.ctrl[0] = ACTIVATION
        mujoco.mj_forward(model, data)
        return data

    def sample(data):
        own = case.mujoco_sample(data)
        if repeats:
            return own
        mujoco.mj_forward(model, data)  # the force at this state: mj_step's is the step's start
        return own + (float(data.actuator_force[0]),)

    data = start()
    samples = [sample(data)]
    for _ in range(int(round(END / SAMPLE))):
        mujoco.mj_step(model, data, nstep=steps)
        samples.append(sample(data))
    # timed apart, as one call of mj_step in C for the whole run: no Python between samples
    best = math.inf
    for _ in range(repeats):
        data = start()
        began = time.perf_counter()
        mujoco.mj_step(model, data, nstep=steps * int(round(END / SAMPLE)))
        best = min(best, time.perf_counter() - began)
    return samples, best


def musclesim_run(case, program, rtol, directory):
    rows, best = musclesim_cli.timed_run(
        program, case.scenario() % dict(rtol=rtol, atol=rtol * 1e-3), directory, REPEATS)
    return [case.musclesim_sample(row) for row in rows], best


def compare(name, case, program, directory):
    reference, _ = musclesim_run(case, program, 1e-12, directory)
    width = len(reference[0])
    scales = [max(abs(sample[i]) for sample in reference) for i in range(width)]

    def error(samples):
        assert len(samples) == len(reference)
        return max(abs(a[i] - b[i]) / scales[i]
                   for a, b in zip(samples, reference) for i in range(width))

    print("### %s\n" % name)
    print("| tool | setting | largest error | observed order | time per simulated s |")
    print("|---|---|---|---|---|")
    curves = {}
    for integrator in ["Euler", "implicitfast", "RK4"]:
        curves[integrator] = []
        previous = None
        for dt in STEPS:
            samples, seconds = mujoco_run(case, integrator, dt)
            e = error(samples)
            if not math.isfinite(e) or e > 1e3:
                print("| MuJoCo mj_step, %s | dt %.0e | unstable | | %.3g ms |"
                      % (integrator, dt, seconds / END * 1e3))
                continue
            # an order only where both errors are small enough to be asymptotic
            order = "" if previous is None or e == 0 or previous[1] > 0.1 else "%.2f" % (
                math.log(previous[1] / e) / math.log(previous[0] / dt))
            previous = (dt, e)
            curves[integrator].append((e, seconds / END))
            print("| MuJoCo mj_step, %s | dt %.0e | %.1e | %s | %.3g ms |"
                  % (integrator, dt, e, order, seconds / END * 1e3))
    curves["musclesim"] = []
    for rtol in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8]:
        samples, seconds = musclesim_run(case, program, rtol, directory)
        e = error(samples)
        curves["musclesim"].append((e, seconds / END))
        print("| musclesim, CVODE BDF | rtol %.0e | %.1e | | %.3g ms |"
              % (rtol, e, seconds / END * 1e3))
    print("\n| error | " + " | ".join(curves) + " |")
    print("|---|" + "---|" * len(curves))
    for target in [1e-3, 1e-4, 1e-5]:
        cells = []
        for tool in curves:
            s = musclesim_cli.at_error(curves[tool], target)
            cells.append("not reached" if s is None else "%.3g ms" % (s * 1e3))
        print("| %.0e | %s |" % (target, " | ".join(cells)))
    print()


def write_references():
    here = os.path.dirname(os.path.abspath(__file__))
    for name, case in CASES.items():
        dt = REFERENCE_STEPS[name]
        samples, _ = mujoco_run(case, "RK4", dt, repeats=0)
        columns = (["length", "velocity", "force"] if isinstance(case, SingleMass) else
                   ["junction_position", "junction_velocity", "drop_position", "drop_velocity",
                    "force"])
        path = os.path.join(here, "reference", "mujoco_%s.csv" % name)
        with open(path, "w") as out:
            out.write("# MuJoCo %s mj_step, RK4 at dt %g, case %s of "
                      "bench/peers/mujoco_convergence.py; velocity positive lengthening, "
                      "force the actuator's (negative pulling)\n" % (mujoco.__version__, dt, name))
            out.write(",".join(["t"] + columns) + "\n")
            for k, sample in enumerate(samples):
                out.write(",".join("%.17g" % v for v in (k * SAMPLE,) + sample) + "\n")
        print(path, file=sys.stderr)


def main():
    if sys.argv[1:] == ["--references"]:
        write_references()
        return
    program = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/musclesim")
    names = sys.argv[2:] or list(CASES)
    for name in names:
        if name not in CASES:
            sys.exit("unknown case %r: the cases are %s" % (name, ", ".join(CASES)))
    print("MuJoCo %s vs musclesim, %s, %s; best of %d\n"
          % (mujoco.__version__, platform.processor() or platform.machine(),
             platform.platform(), REPEATS))
    with tempfile.TemporaryDirectory() as directory:
        for name in names:
            compare(name, CASES[name], program, directory)


if __name__ == "__main__":
    main()
