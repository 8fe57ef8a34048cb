"""OpenSim's own trajectories of a hanging mass on one DeGrooteFregly2016Muscle, written to
bench/peers/reference/ for tests/scenario/opensim_reference_test.cc to meet at 1e-6.

The muscle runs from the ground to a body on a vertical slider, its tendon rigid
(ignore_tendon_compliance) and its activation the control (ignore_activation_dynamics), held
constant; the mass starts at rest away from equilibrium and falls or rises (Millard et al.
2013's hanging-mass benchmark without its tendon). musclesim's actuator length is the fiber's
length along the line, the muscle-tendon length less the tendon slack length.

The compliant cases keep the tendon elastic (OpenSim's explicit tendon dynamics, its state the
normalised tendon force), the muscle's equilibrium with it found by equilibrateMuscles at the
start; in musclesim the fiber and the tendon meet at a massless junction (docs/model.md 14.3).
Their fiber damping is 0: OpenSim's explicit mode finds the fiber velocity by inverting the
force-velocity curve alone, leaving the damping out of the balance it then reports a force
for, so with damping the two tools solve different equations (docs/guide/peers.md).

    "$(bash bench/peers/setup.sh)" bench/peers/opensim_reference.py
"""
import math
import os
import sys

import opensim as osim

osim.Logger.setLevelString("warn")  # not one report per output interval
osim.Logger.removeFileSink()  # no opensim.log in the working directory

HERE = os.path.dirname(os.path.abspath(__file__))
GRAVITY = 9.81

# one case per row: name, mass [kg], F0 [N], l_opt [m], l_s [m], v_max [l_opt/s],
# pennation at optimal [rad], fiber damping [-], activation [-], initial height [m]
CASES = [
    ("opensim_drop_rigid", 5.0, 400.0, 0.10, 0.05, 10.0, 0.0, 0.01, 0.6, 0.16),
    ("opensim_drop_pennate", 5.0, 400.0, 0.10, 0.05, 10.0, 0.35, 0.05, 0.8, 0.13),
]
# with a compliant tendon, no fiber damping: name, the rigid case it changes, tendon slack
# length [m], tendon strain at the maximum isometric force [-], initial height [m]
COMPLIANT = [
    ("opensim_drop_compliant", "opensim_drop_rigid", 0.2, 0.049, 0.32),
    ("opensim_drop_compliant_pennate", "opensim_drop_pennate", 0.2, 0.033, 0.3),
]
# the compliant muscle-tendon unit of opensim_drop_compliant with its length prescribed (the
# slider's coordinate, OpenSim's prescribed function): name, initial length [m], and either
# an isokinetic stretch ("ramp", speed [m/s]) or a sinusoidal length change ("sine",
# amplitude [m], frequency [Hz])
PRESCRIBED = [
    ("opensim_stretch_compliant", 0.30, ("ramp", 0.05)),
    ("opensim_sine_compliant", 0.30, ("sine", 0.01, 4.0)),
]
# with OpenSim's activation dynamics (tanh-blended, De Groote 2016): the pennate case driven
# by an excitation through piecewise-linear points (t [s], e [-]) from an initial activation
EXCITED = ("opensim_drop_excited", "opensim_drop_pennate",
           [(0.0, 0.9), (0.2, 0.9), (0.21, 0.1), (0.5, 0.1)], 0.05)
# the excited pennate muscle with its rigid tendon and its length prescribed, as PRESCRIBED:
# with no mechanical state, its activation is what OpenSim integrates (name, initial height
# [m], motion)
PRESCRIBED_RIGID = [
    ("opensim_stretch_rigid", 0.16, ("ramp", 0.05)),
    ("opensim_sine_rigid", 0.16, ("sine", 0.01, 4.0)),
]
END, INTERVAL, ACCURACY = 0.5, 0.005, 1e-12


def hanging_mass(mass, f_iso, l_opt, l_s, v_max, pennation, damping, activation, height,
                 excitation=None, initial_activation=None, tendon_strain=None, motion=None):
    model = osim.Model()
    model.setName("hanging_mass")
    model.setGravity(osim.Vec3(0, -GRAVITY, 0))
    body = osim.Body("mass", mass, osim.Vec3(0), osim.Inertia(0.01))
    model.addBody(body)
    # the slider's axis (x) turned to point down, so the coordinate is the drop below ground
    down = osim.Vec3(0, 0, -1.5707963267948966)
    joint = osim.SliderJoint("slider", model.getGround(), osim.Vec3(0), down, body,
                             osim.Vec3(0), down)
    joint.updCoordinate().setName("height")
    joint.updCoordinate().setDefaultValue(height)
    if motion is not None:  # the length prescribed from `height` on: the mass then plays no part
        if motion[0] == "ramp":
            function = osim.LinearFunction(motion[1], height)
        else:
            function = osim.Sine(motion[1], 2.0 * math.pi * motion[2], 0.0, height)
        joint.updCoordinate().setPrescribedFunction(function)
        joint.updCoordinate().setDefaultIsPrescribed(True)
    model.addJoint(joint)
    muscle = osim.DeGrooteFregly2016Muscle()
    muscle.setName("muscle")
    muscle.set_max_isometric_force(f_iso)
    muscle.set_optimal_fiber_length(l_opt)
    muscle.set_tendon_slack_length(l_s)
    muscle.set_max_contraction_velocity(v_max)
    muscle.set_pennation_angle_at_optimal(pennation)
    muscle.set_fiber_damping(damping)
    muscle.set_ignore_tendon_compliance(tendon_strain is None)
    if tendon_strain is not None:
        muscle.set_tendon_strain_at_one_norm_force(tendon_strain)
    muscle.set_ignore_activation_dynamics(excitation is None)
    if excitation is not None:
        muscle.set_default_activation(initial_activation)
    muscle.addNewPathPoint("origin", model.getGround(), osim.Vec3(0))
    muscle.addNewPathPoint("insertion", body, osim.Vec3(0))
    model.addForce(muscle)
    controller = osim.PrescribedController()
    controller.addActuator(muscle)
    if excitation is None:
        controller.prescribeControlForActuator("muscle", osim.Constant(activation))
    else:
        control = osim.PiecewiseLinearFunction()
        for t, e in excitation:
            control.addPoint(t, e)
        controller.prescribeControlForActuator("muscle", control)
    model.addController(controller)
    return model, muscle, joint.getCoordinate()


def write_import_example():
    """data/opensim_hanging_mass.osim, the file `musclesim import` is shown on: the pennate
    case's model as OpenSim writes it, with a Thelen2003Muscle beside the DeGroote one (a
    class musclesim lists as not imported). Its dynamics are not the case's: the second
    muscle pulls too."""
    name, *case = next(c for c in CASES if c[0] == "opensim_drop_pennate")
    model, _, _ = hanging_mass(*case)
    thelen = osim.Thelen2003Muscle("thelen", 300, 0.08, 0.1, 0.1)
    thelen.addNewPathPoint("o", model.getGround(), osim.Vec3(0))
    thelen.addNewPathPoint("i", model.getBodySet().get(0), osim.Vec3(0.01, 0, 0))
    model.addForce(thelen)
    model.finalizeConnections()
    path = os.path.join(HERE, "..", "..", "data", "opensim_hanging_mass.osim")
    model.printToXML(path)
    print(os.path.normpath(path), file=sys.stderr)


def write_millard_fixture():
    """tests/fixtures/import/opensim_millard.osim: three Millard2012EquilibriumMuscles as
    OpenSim writes them, for `musclesim import`'s conversion (tests/io/converted_import_test.cc):
    'damped' at OpenSim's defaults but for its size and pennation; 'classic' without fiber
    damping (OpenSim's classic formulation, whose curves it adjusts) and with every curve
    property set, the optional ones too; 'rigid' with a rigid tendon and no activation
    dynamics."""
    model, _, _ = hanging_mass(*next(c for c in CASES if c[0] == "opensim_drop_rigid")[1:])
    body = model.getBodySet().get(0)
    damped = osim.Millard2012EquilibriumMuscle("damped", 800.0, 0.09, 0.15, 0.2)
    classic = osim.Millard2012EquilibriumMuscle("classic", 600.0, 0.12, 0.25, 0.0)
    classic.setFiberDamping(0.0)
    classic.setActivationTimeConstant(0.02)
    classic.setDeactivationTimeConstant(0.05)
    classic.setMinimumActivation(0.02)
    classic.setMinControl(0.02)
    classic.setActiveForceLengthCurve(osim.ActiveForceLengthCurve(0.5, 0.8, 1.7, 0.6, 0.05))
    classic.setForceVelocityCurve(
        osim.ForceVelocityCurve(0.1, 0.3, 4.0, 0.05, 0.2, 1.6, 0.3, 0.7))
    classic.setFiberForceLengthCurve(osim.FiberForceLengthCurve(0.1, 0.5, 0.5, 5.0, 0.4))
    classic.setTendonForceLengthCurve(osim.TendonForceLengthCurve(0.06, 30.0, 0.5, 0.8))
    rigid = osim.Millard2012EquilibriumMuscle("rigid", 300.0, 0.05, 0.02, 0.1)
    rigid.set_ignore_tendon_compliance(True)
    rigid.set_ignore_activation_dynamics(True)
    rigid.setMaxContractionVelocity(8.0)
    rigid.setFiberDamping(0.02)
    for muscle in (damped, classic, rigid):
        muscle.addNewPathPoint("origin", model.getGround(), osim.Vec3(0))
        muscle.addNewPathPoint("insertion", body, osim.Vec3(0))
        model.addForce(muscle)
    model.finalizeConnections()
    model.initSystem()  # OpenSim's own checks of every property
    path = os.path.join(HERE, "..", "..", "tests", "fixtures", "import", "opensim_millard.osim")
    model.printToXML(path)
    print(os.path.normpath(path), file=sys.stderr)


def cases():
    """(name, hanging_mass's arguments) of every case."""
    for name, *case in CASES:
        yield name, case, {}
    name, base, excitation, initial_activation = EXCITED
    case = next(c for c in CASES if c[0] == base)[1:]
    yield name, case, {"excitation": excitation, "initial_activation": initial_activation}
    for name, base, l_s, strain, height in COMPLIANT:
        case = list(next(c for c in CASES if c[0] == base)[1:])
        case[3], case[6], case[8] = l_s, 0.0, height
        yield name, case, {"tendon_strain": strain}
    base = next(c for c in COMPLIANT if c[0] == "opensim_drop_compliant")
    for name, length, motion in PRESCRIBED:
        case = list(next(c for c in CASES if c[0] == base[1])[1:])
        case[3], case[6], case[8] = base[2], 0.0, length
        yield name, case, {"tendon_strain": base[3], "motion": motion}
    name, base, excitation, initial_activation = EXCITED
    for name, height, motion in PRESCRIBED_RIGID:
        case = list(next(c for c in CASES if c[0] == base)[1:])
        case[8] = height
        yield name, case, {"excitation": excitation, "initial_activation": initial_activation,
                           "motion": motion}


def main():
    write_import_example()
    write_millard_fixture()
    for name, case, dynamics in cases():
        model, muscle, height = hanging_mass(*case, **dynamics)
        state = model.initSystem()
        compliant = "tendon_strain" in dynamics
        if compliant:  # the fiber in equilibrium with the tendon, at rest
            model.equilibrateMuscles(state)
        # tests/io/muscle_import_test.cc imports the muscles of these two from the files
        fixtures = {EXCITED[0]: "opensim_excited.osim",
                    "opensim_drop_compliant": "opensim_compliant.osim"}
        if name in fixtures:
            fixture = os.path.join(HERE, "..", "..", "tests", "fixtures", "import",
                                   fixtures[name])
            model.printToXML(fixture)
            print(os.path.normpath(fixture), file=sys.stderr)
        manager = osim.Manager(model)
        manager.setIntegratorAccuracy(ACCURACY)
        state.setTime(0.0)
        manager.initialize(state)
        l_s = case[3]
        path = os.path.join(HERE, "reference", name + ".csv")
        with open(path, "w") as out:
            excited = "excitation" in dynamics
            drive = ("activation dynamics, excitation %s from activation %s"
                     % (dynamics["excitation"], dynamics["initial_activation"])
                     if excited else "constant activation")
            tendon = ("compliant tendon (strain %g at F0, explicit)" % dynamics["tendon_strain"]
                      if compliant else "rigid tendon")
            if "motion" in dynamics:
                tendon += ", length prescribed: %s %s" % (dynamics["motion"][0],
                                                         repr(dynamics["motion"][1:]))
            out.write("# OpenSim %s DeGrooteFregly2016Muscle, %s, %s; case %s, "
                      "accuracy %g (bench/peers/opensim_reference.py)\n"
                      % (osim.GetVersion(), tendon, drive, repr(tuple(case)), ACCURACY))
            out.write("t,length,shortening_velocity,fiber_length,pennation_angle,"
                      "tendon_force%s\n" % (",activation" if excited else
                                             ",fiber_velocity" if compliant else ""))
            steps = int(round(END / INTERVAL))
            for k in range(steps + 1):
                t = k * INTERVAL
                if k > 0:
                    state = manager.integrate(t)
                model.realizeDynamics(state)
                # length: the fiber along the line (rigid tendon) or the whole
                # muscle-tendon unit, the mass's drop (compliant)
                row = [state.getTime(), height.getValue(state) - (0.0 if compliant else l_s),
                       -height.getSpeedValue(state), muscle.getFiberLength(state),
                       muscle.getPennationAngle(state), muscle.getTendonForce(state)]
                if excited:
                    row.append(muscle.getActivation(state))
                elif compliant:
                    row.append(muscle.getFiberVelocity(state))
                out.write(",".join("%.17g" % v for v in row) + "\n")
        print(path, file=sys.stderr)


if __name__ == "__main__":
    main()
