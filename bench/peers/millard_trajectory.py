"""What `musclesim import` does to a trajectory when it converts OpenSim's
Millard2012EquilibriumMuscle to musclesim's nearest family, degroote2016 (docs/model.md 14.5).

OpenSim 4.6 runs the hanging mass of bench/peers/opensim_reference.py on one
Millard2012EquilibriumMuscle (5 kg under gravity on a vertical slider, F0 400 N, l_opt 0.1 m,
v_max 10, Millard's default fiber damping 0.1 (its damped formulation), activation the control
held at 0.6): (a) with a rigid tendon (slack length 0.05 m) from a drop of 0.16 m, (b) with
Millard's default compliant tendon (slack length 0.2 m) from a drop of 0.32 m, the fiber in
equilibrium with it at rest (equilibrateMuscles). The model is written to an .osim,
`musclesim import`ed, and the scenario it writes run with its experiment set to OpenSim's by
`musclesim run --set` (as tests/io/muscle_import_test.cc does): the same mass, its weight a
constant load, the same start at rest, activation 0.6, 0.5 s, output every 5 ms, rtol 1e-10.

The difference from OpenSim's Millard trajectory is the conversion's. As a control, OpenSim
also runs a DeGrooteFregly2016Muscle with the converted parameters read from the written
scenario, which musclesim's run should meet to about 1e-6 or better: then what remains against
Millard is the curves, not the integration. With the compliant tendon the control has no
fiber damping (0 in OpenSim, 1e-8 in musclesim, whose massless junction needs some):
OpenSim's explicit tendon dynamics leave the damping out of the fiber's balance
(docs/model.md 14.3), so with Millard's 0.1 the two tools would solve different equations;
that pair is shown too, marked as such.

Each model starts at its own equilibrium: with the compliant tendon, musclesim's junction is
placed where OpenSim's DeGroote muscle with the converted parameters puts the fiber (the
converted model's static equilibrium with the mass at rest, the same with or without
damping), while OpenSim's Millard muscle finds its own. Prints a Markdown table of the largest
differences over the run, the drop relative to its range over the run (how far the mass
moves) and the tendon force relative to F0, and the import's "converted:" lines.

    "$(bash bench/peers/setup.sh)" bench/peers/millard_trajectory.py [MUSCLESIM]

MUSCLESIM is the built program (default build/musclesim). Writes nothing outside a
temporary directory.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

import opensim as osim

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import opensim_reference as ref  # noqa: E402  (the hanging mass, its DeGroote muscle)

osim.Logger.setLevelString("warn")
osim.Logger.removeFileSink()  # no opensim.log in the working directory

MASS, F_ISO, L_OPT, V_MAX, DAMPING, ACTIVATION = 5.0, 400.0, 0.10, 10.0, 0.1, 0.6
END, INTERVAL, ACCURACY, RTOL = 0.5, 0.005, 1e-10, 1e-10
CONTROL_DAMPING = 1e-8  # musclesim's compliant control: its junction needs a rate term
# name, tendon slack length [m], rigid tendon, initial drop [m]
CASES = [("rigid", 0.05, True, 0.16), ("compliant", 0.2, False, 0.32)]


def millard_hanging_mass(l_s, rigid, height):
    """opensim_reference.hanging_mass with a Millard2012EquilibriumMuscle at OpenSim's defaults
    (damped, its default curves and tendon) but for its size, speed and tendon."""
    model = osim.Model()
    model.setName("hanging_mass_millard")
    model.setGravity(osim.Vec3(0, -ref.GRAVITY, 0))
    body = osim.Body("mass", MASS, osim.Vec3(0), osim.Inertia(0.01))
    model.addBody(body)
    # the slider's axis (x) turned to point down, so the coordinate is the drop below ground
    down = osim.Vec3(0, 0, -1.5707963267948966)
    joint = osim.SliderJoint("slider", model.getGround(), osim.Vec3(0), down, body,
                             osim.Vec3(0), down)
    joint.updCoordinate().setName("height")
    joint.updCoordinate().setDefaultValue(height)
    model.addJoint(joint)
    muscle = osim.Millard2012EquilibriumMuscle("muscle", F_ISO, L_OPT, l_s, 0.0)
    muscle.setMaxContractionVelocity(V_MAX)
    muscle.setFiberDamping(DAMPING)
    muscle.set_ignore_tendon_compliance(rigid)
    muscle.set_ignore_activation_dynamics(True)
    muscle.addNewPathPoint("origin", model.getGround(), osim.Vec3(0))
    muscle.addNewPathPoint("insertion", body, osim.Vec3(0))
    model.addForce(muscle)
    controller = osim.PrescribedController()
    controller.addActuator(muscle)
    controller.prescribeControlForActuator("muscle", osim.Constant(ACTIVATION))
    model.addController(controller)
    model.finalizeConnections()
    return model, muscle, joint.getCoordinate()


def degroote_hanging_mass(p, l_s, rigid, height, damping):
    """The same hanging mass on OpenSim's DeGrooteFregly2016Muscle with the converted
    parameters `p` (read from the imported scenario)."""
    model, muscle, height_coordinate = ref.hanging_mass(
        MASS, p["f_iso"], p["optimal_fiber_length"], l_s, p["max_contraction_velocity"], 0.0,
        damping, ACTIVATION, height,
        tendon_strain=None if rigid else p["strain_at_one_norm_force"])
    muscle.set_active_force_width_scale(p["active_force_width_scale"])
    muscle.set_passive_fiber_strain_at_one_norm_force(p["passive_fiber_strain_at_one_norm_force"])
    return model, muscle, height_coordinate


def opensim_run(built, compliant):
    """OpenSim's trajectory: rows of (t, drop, its speed, tendon force), and the fiber's
    length along the line at the start."""
    model, muscle, height = built
    state = model.initSystem()
    if compliant:  # the fiber in equilibrium with the tendon, the mass at rest
        model.equilibrateMuscles(state)
    manager = osim.Manager(model)
    manager.setIntegratorAccuracy(ACCURACY)
    state.setTime(0.0)
    manager.initialize(state)
    rows = []
    for k in range(int(round(END / INTERVAL)) + 1):
        if k > 0:
            state = manager.integrate(k * INTERVAL)
        model.realizeDynamics(state)
        rows.append((state.getTime(), height.getValue(state), height.getSpeedValue(state),
                     muscle.getTendonForce(state)))
        if k == 0:
            fiber = muscle.getFiberLength(state) * muscle.getCosPennationAngle(state)
    return rows, fiber


def import_muscle(program, osim_path, directory):
    """`musclesim import`: the scenario's path and text, and its report's "converted:" lines."""
    done = subprocess.run([program, "import", osim_path, "-o", directory], check=True,
                          capture_output=True, text=True)
    converted = [line.strip() for line in done.stderr.splitlines()
                 if line.strip().startswith("converted:")]
    path = os.path.join(directory, "muscle.yaml")
    with open(path) as f:
        return path, f.read(), converted


def converted_parameters(text):
    """The converted model's numbers, and the tendon's strain, from the written scenario."""
    p = {}
    for key in ("f_iso", "optimal_fiber_length", "max_contraction_velocity",
                "active_force_width_scale", "passive_fiber_strain_at_one_norm_force",
                "fiber_damping", "strain_at_one_norm_force"):
        found = re.search(r"(?<![\w.])%s: ([0-9.eE+-]+)" % key, text)
        if found:
            p[key] = float(found.group(1))
    return p


def musclesim_run(program, scenario, settings, csv_path):
    """`musclesim run SCENARIO --set ...`: its CSV as rows of dicts."""
    command = [program, "run", scenario, "-o", csv_path, "--quiet"]
    for key, value in settings.items():
        command += ["--set", "%s=%r" % (key, value)]
    subprocess.run(command, check=True, capture_output=True, text=True)
    with open(csv_path) as f:
        return list(csv.DictReader(f))


def experiment(rigid, l_s, height, junction=None):
    """The --set values making the written scenario OpenSim's experiment (the import's template
    hangs a mass of F0 / 2 g from the muscle, at rest at its optimal length, activated by a
    step at 0.1 s: here both sides of the step are 0.6)."""
    common = {"time.end": END, "output.interval": INTERVAL, "solver.rtol": RTOL,
              "solver.atol": RTOL * 1e-3}
    if rigid:  # the actuator is the fiber along the line: the drop less the tendon slack length
        return dict(common, **{"actuator.mass": MASS, "initial.length": height - l_s,
                               "load.value": MASS * ref.GRAVITY,
                               "activation.before": ACTIVATION,
                               "activation.after": ACTIVATION})
    return dict(common, **{"nodes[1].position": junction, "nodes[2].mass": MASS,
                           "nodes[2].position": height, "loads[0].value": MASS * ref.GRAVITY,
                           "elements[0].activation.before": ACTIVATION,
                           "elements[0].activation.after": ACTIVATION})


def musclesim_columns(rows, rigid, l_s):
    """musclesim's rows as OpenSim's: (t, drop, its speed, tendon force)."""
    if rigid:
        return [(float(r["t"]), float(r["length"]) + l_s, -float(r["shortening_velocity"]),
                 float(r["tension_total"])) for r in rows]
    return [(float(r["t"]), float(r["body.position"]), float(r["body.velocity"]),
             float(r["tendon.tension"])) for r in rows]


def differences(mine, theirs):
    """The largest |drop difference| over the range of OpenSim's drop, and the largest
    |tendon force difference| over F0."""
    assert len(mine) == len(theirs)
    assert all(abs(a[0] - b[0]) < 1e-12 for a, b in zip(mine, theirs))
    # the drop relative to how far the mass moves, not to its distance from the ground
    drops = [r[1] for r in theirs]
    scale = max(drops) - min(drops)
    return (max(abs(a[1] - b[1]) for a, b in zip(mine, theirs)) / scale,
            max(abs(a[3] - b[3]) for a, b in zip(mine, theirs)) / F_ISO)


def main():
    program = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                              os.path.join(ref.HERE, "..", "..", "build", "musclesim"))
    table, reports, notes = [], {}, []
    with tempfile.TemporaryDirectory() as directory:
        for name, l_s, rigid, height in CASES:
            case_dir = os.path.join(directory, name)
            os.mkdir(case_dir)
            millard = millard_hanging_mass(l_s, rigid, height)
            osim_path = os.path.join(case_dir, "millard.osim")
            millard[0].printToXML(osim_path)
            scenario, text, reports[name] = import_muscle(program, osim_path, case_dir)
            p = converted_parameters(text)
            assert p["fiber_damping"] == DAMPING, p
            opensim_millard, millard_fiber = opensim_run(millard, not rigid)
            # the control, with the converted damping (rigid) or none (compliant)
            control_damping = p["fiber_damping"] if rigid else 0.0
            opensim_degroote, junction = opensim_run(
                degroote_hanging_mass(p, l_s, rigid, height, control_damping), not rigid)
            settings = experiment(rigid, l_s, height, junction)
            rows = musclesim_run(program, scenario, settings,
                                 os.path.join(case_dir, "converted.csv"))
            converted = musclesim_columns(rows, rigid, l_s)
            table.append((name, "converted (damping %g)" % p["fiber_damping"],
                          "OpenSim Millard2012 (damping %g)" % DAMPING,
                          differences(converted, opensim_millard)))
            if rigid:
                table.append((name, "converted (damping %g)" % p["fiber_damping"],
                              "OpenSim DeGroote, converted parameters (control)",
                              differences(converted, opensim_degroote)))
            else:
                control = musclesim_columns(musclesim_run(
                    program, scenario,
                    dict(settings, **{"models.muscle.fiber_damping": CONTROL_DAMPING}),
                    os.path.join(case_dir, "control.csv")), rigid, l_s)
                table.append((name, "converted, damping %g" % CONTROL_DAMPING,
                              "OpenSim DeGroote, converted parameters, damping 0 (control)",
                              differences(control, opensim_degroote)))
                # the converted damping in OpenSim's explicit mode: not the same equations
                opensim_damped, _ = opensim_run(
                    degroote_hanging_mass(p, l_s, rigid, height, p["fiber_damping"]), True)
                table.append((name, "converted (damping %g)" % p["fiber_damping"],
                              "OpenSim DeGroote, damping %g, explicit (left out of its "
                              "balance: not comparable)" % p["fiber_damping"],
                              differences(converted, opensim_damped)))
                notes.append("%s: fiber along the line at the start, %.6g m (converted "
                             "model's equilibrium, musclesim's junction, its velocity there "
                             "%.1e m/s), %.6g m (Millard's)"
                             % (name, junction, float(rows[0]["junction.velocity"]),
                                millard_fiber))
            drops = [r[1] for r in opensim_millard]
            notes.append("%s: OpenSim Millard's drop from %.4g m to %.4g m (range %.4g m), "
                         "musclesim's to %.4g m" % (name, drops[0], drops[-1],
                                                   max(drops) - min(drops), converted[-1][1]))
    print("Millard2012EquilibriumMuscle converted by `musclesim import` (degroote2016) against "
          "OpenSim %s; hanging mass, activation %g, %g s, OpenSim accuracy %g, musclesim rtol "
          "%g\n" % (osim.GetVersion(), ACTIVATION, END, ACCURACY, RTOL))
    print("| case | musclesim | against | max abs drop diff / drop's range | "
          "max abs tendon force diff / F0 |")
    print("|---|---|---|---|---|")
    for name, mine, theirs, (drop, force) in table:
        print("| %s | %s | %s | %.2e | %.2e |" % (name, mine, theirs, drop, force))
    print()
    for note in notes:
        print(note)
    for name, lines in reports.items():
        print("\nthe import's report (%s):" % name)
        for line in lines:
            print("  " + line)


if __name__ == "__main__":
    main()
