"""The peers' muscle curves as their own libraries compute them, on dense grids, written to
bench/peers/reference/ as CSV: the references for native curve families and for the curves
of the muscles `musclesim import` converts (docs/model.md 14). OpenSim's
DeGrooteFregly2016Muscle (its static curve functions and their derivatives), the four curves
of its Millard2012EquilibriumMuscle (quintic Bezier splines, each curve class's calcValue and
calcDerivative) and of its Thelen2003Muscle (read off realised states), and MuJoCo's muscle
(mju_muscleGain, mju_muscleBias, mju_muscleDynamics).
    "$(bash bench/peers/setup.sh)" bench/peers/reference_curves.py
"""
import pathlib

import mujoco
import numpy as np
import opensim

OUT = pathlib.Path(__file__).resolve().parent / "reference"


def write(name, header, rows, source):
    OUT.mkdir(parents=True, exist_ok=True)
    with open(OUT / name, "w") as f:
        f.write(f"# {source} (bench/peers/reference_curves.py)\n")
        f.write(",".join(header) + "\n")
        for row in rows:
            f.write(",".join(repr(float(v)) for v in row) + "\n")


def degroote():
    source = f"OpenSim {opensim.GetVersion()} DeGrooteFregly2016Muscle, default properties"
    muscle = opensim.DeGrooteFregly2016Muscle()
    curves = opensim.DeGrooteFregly2016Muscle
    rows = []
    for length in np.linspace(0.2, 1.8, 161):
        rows.append((length, muscle.calcActiveForceLengthMultiplier(length),
                     muscle.calcActiveForceLengthMultiplierDerivative(length),
                     muscle.calcPassiveForceMultiplier(length),
                     muscle.calcPassiveForceMultiplierDerivative(length)))
    write("degroote2016_fiber_length.csv",
          ["normalized_fiber_length", "active", "active_slope", "passive", "passive_slope"],
          rows, source)
    rows = [(v, curves.calcForceVelocityMultiplier(v)) for v in np.linspace(-1.0, 1.0, 201)]
    write("degroote2016_fiber_velocity.csv", ["normalized_fiber_velocity", "force_velocity"],
          rows, source + "; velocity positive lengthening")
    rows = [(t, muscle.calcTendonForceMultiplier(t), muscle.calcTendonForceMultiplierDerivative(t))
            for t in np.linspace(0.98, 1.08, 101)]
    write("degroote2016_tendon.csv", ["normalized_tendon_length", "force", "force_slope"], rows,
          source + " (tendon_strain_at_one_norm_force 0.049)")


# Millard 2012's curves, one parameter set per row: OpenSim's defaults; the active curve
# without its floor (what the damped muscle runs); every property set, the optional ones too
MILLARD_SETS = {
    "default": {},
    "damped": {"active": (0.4441, 0.73, 1.8123, 0.8616, 0.0)},
    "other": {"active": (0.5, 0.8, 1.7, 0.6, 0.05),
              "velocity": (0.1, 0.3, 4.0, 0.05, 0.2, 1.6, 0.3, 0.7),
              "passive": (0.1, 0.5, 0.5, 5.0, 0.4),
              "tendon": (0.06, 30.0, 0.5, 0.8)},
}


def millard():
    classes = {"active": opensim.ActiveForceLengthCurve, "velocity": opensim.ForceVelocityCurve,
               "passive": opensim.FiberForceLengthCurve, "tendon": opensim.TendonForceLengthCurve}
    grids = {"active": np.linspace(0.3, 2.0, 171), "velocity": np.linspace(-1.2, 1.2, 241),
             "passive": np.linspace(0.9, 2.0, 111), "tendon": np.linspace(0.99, 1.1, 111)}
    rows = []
    for index, properties in enumerate(MILLARD_SETS.values()):
        for number, (curve, make) in enumerate(classes.items()):
            function = make(*properties[curve]) if curve in properties else make()
            for x in grids[curve]:
                rows.append((index, number, x, function.calcValue(x),
                             function.calcDerivative(x, 1)))
    write("millard2012_curves.csv", ["set", "curve", "x", "value", "slope"], rows,
          f"OpenSim {opensim.GetVersion()} ActiveForceLengthCurve (curve 0), ForceVelocityCurve "
          "(1), FiberForceLengthCurve (2), TendonForceLengthCurve (3); sets " +
          "; ".join(f"{i} {name} {p}" for i, (name, p) in enumerate(MILLARD_SETS.items())))


# Thelen 2003's curves: OpenSim's defaults, and every property set
THELEN_SETS = {
    "default": {},
    "other": {"FmaxTendonStrain": 0.05, "FmaxMuscleStrain": 0.5, "KshapeActive": 0.3,
              "KshapePassive": 4.0, "Af": 0.3, "Flen": 1.6, "fv_linear_extrap_threshold": 0.9},
}


def thelen():
    """Thelen2003Muscle's curves are protected in OpenSim's API: they are read off a muscle
    (compliant, OpenSim 4.6 runs no other) whose fiber length, tendon strain and activation 1
    are set in a state, realised to dynamics: its active and passive force-length multipliers,
    its tendon force over F0 against the tendon's strain, and the force-velocity multiplier
    against the fiber velocity its equilibrium solves for (at activation 1)."""
    l_opt, l_s, v_max, f0 = 0.1, 0.2, 10.0, 1000.0
    rows = []
    for index, properties in enumerate(THELEN_SETS.values()):
        model = opensim.Model()
        body = opensim.Body("b", 1.0, opensim.Vec3(0), opensim.Inertia(0.01))
        model.addBody(body)
        joint = opensim.SliderJoint("s", model.getGround(), opensim.Vec3(0), opensim.Vec3(0),
                                    body, opensim.Vec3(0), opensim.Vec3(0))
        model.addJoint(joint)
        muscle = opensim.Thelen2003Muscle("thelen", f0, l_opt, l_s, 0.0)
        for name, value in properties.items():
            getattr(muscle, "set_" + name)(value)
        muscle.addNewPathPoint("o", model.getGround(), opensim.Vec3(0))
        muscle.addNewPathPoint("i", body, opensim.Vec3(0))
        model.addForce(muscle)
        state = model.initSystem()
        coordinate = joint.getCoordinate()

        def realised(length, strain):
            coordinate.setValue(state, length * l_opt + l_s * (1.0 + strain))
            coordinate.setSpeedValue(state, 0.0)
            muscle.setFiberLength(state, length * l_opt)
            muscle.setActivation(state, 1.0)
            model.realizeDynamics(state)

        for length in np.linspace(0.3, 1.9, 161):
            realised(length, 0.02)
            rows.append((index, 0, muscle.getFiberLength(state) / l_opt,
                         muscle.getActiveForceLengthMultiplier(state)))
            rows.append((index, 1, muscle.getFiberLength(state) / l_opt,
                         muscle.getPassiveForceMultiplier(state)))
        for strain in np.linspace(-0.005, 0.075, 161):
            realised(1.0, strain)  # the fiber at its optimal length: no passive force
            rows.append((index, 2, muscle.getFiberVelocity(state) / (v_max * l_opt),
                         muscle.getForceVelocityMultiplier(state)))
            rows.append((index, 3, muscle.getTendonStrain(state),
                         muscle.getTendonForce(state) / f0))
    write("thelen2003_curves.csv", ["set", "curve", "x", "value"], rows,
          f"OpenSim {opensim.GetVersion()} Thelen2003Muscle: active (curve 0) and passive (1) "
          "force-length against l~, force-velocity (2) against v~ (lengthening, activation 1), "
          "tendon force over F0 (3) against strain; sets " +
          "; ".join(f"{i} {name} {p}" for i, (name, p) in enumerate(THELEN_SETS.items())))


def mujoco_muscle():
    source = f"MuJoCo {mujoco.__version__} mju_muscleGain/mju_muscleBias"
    # parameter sets: [range0, range1, force, scale, lmin, lmax, vmax, fpmax, fvmax]
    sets = {"default": [0.75, 1.05, 100.0, 200.0, 0.5, 1.6, 1.5, 1.3, 1.2],
            "other": [0.6, 1.2, 250.0, 200.0, 0.4, 1.8, 2.0, 1.1, 1.5]}
    lengthrange = np.array([0.05, 0.25])  # m: the actuator length's range
    rows = []
    for index, prm in enumerate(sets.values()):
        prm = np.array(prm)
        for length in np.linspace(0.0, 0.35, 351):
            for velocity in (-0.6, -0.2, 0.0, 0.05, 0.3):  # m/s, positive lengthening
                gain = mujoco.mju_muscleGain(length, velocity, lengthrange, 1.0, prm)
                bias = mujoco.mju_muscleBias(length, lengthrange, 1.0, prm)
                rows.append((index, length, velocity, gain, bias))
    write("mujoco_muscle.csv", ["set", "length", "velocity", "gain", "bias"], rows,
          source + "; sets default " + str(sets["default"]) + " and other " + str(sets["other"])
          + " as gainprm, lengthrange [0.05, 0.25] m, acc0 1")
    rows = []
    for smooth in (0.0, 0.2, 5.0):  # 5: wider than every e - u, a blend at both ends
        for ctrl in np.linspace(0.0, 1.0, 11):
            for act in np.linspace(0.0, 1.0, 11):
                rows.append((smooth, ctrl, act,
                             mujoco.mju_muscleDynamics(ctrl, act, np.array([0.01, 0.04, smooth]))))
    write("mujoco_activation.csv", ["tausmooth", "ctrl", "act", "act_dot"], rows,
          f"MuJoCo {mujoco.__version__} mju_muscleDynamics, timeconst 0.01 0.04")


if __name__ == "__main__":
    degroote()
    millard()
    thelen()
    mujoco_muscle()
