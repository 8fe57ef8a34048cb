"""musclesim.Stepper: stepping from Python reproduces a one-shot run, closes a loop in
Python, and refuses bad calls."""
import os
import subprocess

import numpy as np
import pytest

import musclesim
from conftest import CLI, SOURCE

FORCE_REGULATION = os.path.join(SOURCE, "scenarios", "force_regulation.yaml")


def read_csv_columns(path, names):
    """The named numeric columns of a CSV with a header (other columns, text, skipped)."""
    with open(path) as file:
        header = file.readline().strip().split(",")
    indices = [header.index(name) for name in names]
    data = np.loadtxt(path, delimiter=",", skiprows=1, usecols=indices, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}


def test_stepping_in_1ms_pieces_reproduces_the_clis_one_shot_run(tmp_path):
    csv = tmp_path / "one_shot.csv"
    subprocess.run([CLI, "run", FORCE_REGULATION, "-o", str(csv)],
                   check=True, capture_output=True)
    reference = read_csv_columns(csv, ["t", "force.measured", "muscle.length", "tip.velocity"])

    stepper = musclesim.Stepper(FORCE_REGULATION)
    measured, length, velocity = [], [], []
    for t in reference["t"][1:]:
        assert stepper.advance(t) == "completed"
        sample = stepper.sample()
        measured.append(sample["force.measured"])
        length.append(sample["muscle.length"])
        velocity.append(sample["tip.velocity"])
    assert stepper.time == reference["t"][-1]
    # the scenario's rtol 1e-10, atol 1e-12 bound each run's local error; the two runs take
    # different steps (the pieces end at every ms), so their global errors differ by some
    # hundreds of local errors: 1e-7 N on a tension of 33 N (3e-9 relative) allows that, and
    # is far below the 0.1 N a wrongly held input or a lost restart would show
    np.testing.assert_allclose(measured, reference["force.measured"][1:], rtol=0, atol=1e-7)
    # the same for the length (0.1 m scale) and the tip's speed (up to ~0.1 m/s)
    np.testing.assert_allclose(length, reference["muscle.length"][1:], rtol=0, atol=1e-11)
    np.testing.assert_allclose(velocity, reference["tip.velocity"][1:], rtol=0, atol=1e-8)


def test_state_and_sample_agree_with_the_network_layout():
    stepper = musclesim.Stepper(FORCE_REGULATION, set=["nodes[1].position=0.101"])
    y = stepper.state
    assert y.dtype == np.float64 and y.ndim == 1
    # free node tip: position 0.101 m (the override), velocity 0, then the activation 0
    assert y[0] == 0.101 and y[1] == 0.0
    sample = stepper.sample()
    assert sample["t"] == 0.0
    assert sample["muscle.length"] == 0.101  # wall at 0, tip at 0.101 m
    assert sample["transducer.length"] == pytest.approx(0.2 - 0.101, abs=1e-15)
    # a copy: changing it changes nothing in the stepper
    y[0] = 5.0
    assert stepper.state[0] == 0.101


PI_NETWORK = """
name: python_pi
models:
  muscle:
    f_iso: 100.0
    passive: {k_p: 1.0, alpha: 100.0, slack_length: 0.105}
    active_length:
      optimal_range: [0.095, 0.105]
      gaussians:
        - {amplitude: 1.0, width: 2000.0, center: 0.1}
    velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}
nodes:
  - {name: wall, fixed: 0.0}
  - {name: tip, mass: 0.05, position: 0.1, velocity: 0.0}
  - {name: anchor, fixed: 0.2}
elements:
  - name: muscle
    type: actuator
    from: wall
    to: tip
    model: muscle
    excitation: {type: constant, value: 0.0}
    activation_dynamics: {tau_activation: 0.03, tau_deactivation: 0.03}
  - {name: transducer, type: spring, from: tip, to: anchor, stiffness: 1.0e5, rest_length: 0.1}
time: {start: 0.0, end: 1.0}
solver: {method: bdf, rtol: 1.0e-8, atol: 1.0e-10}
output: {file: unused.csv, interval: 0.001}
"""


def test_a_python_pi_loop_at_1khz_reaches_its_reference(tmp_path):
    scenario = tmp_path / "pi.yaml"
    scenario.write_text(PI_NETWORK)
    stepper = musclesim.Stepper(str(scenario))
    reference, kp, ki, dt = 33.0, 0.005, 0.15, 1e-3  # N, 1/N, 1/(N s), s (force_regulation's)
    integral, errors, excitations = 0.0, [], []
    for k in range(1, 1001):
        error = reference - stepper.sample()["muscle.tension"]
        integral += error * dt
        u = min(1.0, max(0.0, kp * error + ki * integral))
        stepper.set_activation("muscle", u)
        assert stepper.advance(k * dt) == "completed"
        errors.append(error)
        excitations.append(u)
    final = reference - stepper.sample()["muscle.tension"]
    # the loop's slowest pole is near -17 1/s (force_regulation.yaml's analysis): after 1 s
    # the step's error has decayed by e^-17; 0.1 N (0.3 %) leaves room for the 1 ms hold
    assert abs(final) < 0.1
    assert max(abs(e) for e in errors[-100:]) < 0.1
    # at rest the tension is the activation times f_iso times the length factors, so the
    # held excitation settles to a value inside (0, 1) rather than saturating
    assert 0.0 < excitations[-1] < 1.0
    # activation dynamics: the state's activation lags the excitation (first order, 30 ms)
    assert stepper.sample()["muscle.activation"] == pytest.approx(excitations[-1], abs=1e-3)


def test_advance_each_matches_advance():
    times = np.arange(1, 101) * 1e-3
    one = musclesim.Stepper(FORCE_REGULATION)
    for t in times:
        one.advance(t)
    each = musclesim.Stepper(FORCE_REGULATION)
    assert each.advance_each(times) == "completed"
    # the same calls in the same order: the same arithmetic, bit for bit
    np.testing.assert_array_equal(one.state, each.state)
    assert one.stats["steps"] == each.stats["steps"]


def test_bad_calls_raise_clear_errors(tmp_path):
    stepper = musclesim.Stepper(FORCE_REGULATION)
    stepper.advance(0.01)
    with pytest.raises(ValueError, match="t_next = 0.005.*after time"):
        stepper.advance(0.005)
    with pytest.raises(ValueError, match="t_next"):
        stepper.advance(float("nan"))
    with pytest.raises(ValueError, match="nope"):
        stepper.set_activation("nope", 0.5)
    with pytest.raises(ValueError, match="transducer"):
        stepper.set_activation("transducer", 0.5)  # a spring, not an actuator
    with pytest.raises(ValueError, match="muscle"):
        stepper.set_activation("muscle", 0.5)  # driven by the scenario's controller
    with pytest.raises(Exception, match="no_such_file.yaml"):
        musclesim.Stepper(str(tmp_path / "no_such_file.yaml"))
    with pytest.raises(Exception, match="solver.rtol"):
        musclesim.Stepper(FORCE_REGULATION, set={"solver.rtol": -1.0})
    with pytest.raises(TypeError, match="key=value"):
        musclesim.Stepper(FORCE_REGULATION, set="solver.rtol=1e-8")


def test_a_stepper_from_a_dict_scenario_runs_as_from_its_file():
    # a network given as a dict (no YAML file) steps as the file it was written from does
    path = os.path.join(SOURCE, "scenarios", "mass_spring_damper.yaml")
    d = {
        "name": "msd",
        "nodes": [{"name": "wall", "fixed": 0.0},
                  {"name": "load", "mass": 0.5, "position": 0.1, "velocity": 0.0}],
        "elements": [
            {"name": "spring", "type": "spring", "from": "wall", "to": "load",
             "stiffness": 50.0, "rest_length": 0.1},
            {"name": "damper", "type": "damper", "from": "wall", "to": "load", "damping": 0.5}],
        "loads": [{"node": "load", "type": "constant", "value": 1.0}],
        "time": {"start": 0.0, "end": 2.0},
        "solver": {"method": "bdf", "rtol": 1e-12, "atol": 1e-14},
    }
    from_dict = musclesim.Stepper(musclesim.scenario_from_dict(d).set("loads[0].value", 2.0))
    from_file = musclesim.Stepper(path, set={"loads[0].value": 2.0})
    for k in range(1, 51):
        assert from_dict.advance(k * 1e-2) == "completed"
        assert from_file.advance(k * 1e-2) == "completed"
    # the same system and settings: the same steps, to rounding
    assert abs(from_dict.sample()["load.position"] - from_file.sample()["load.position"]) < 1e-12


def test_a_single_actuator_steps_as_its_network_and_python_can_drive_it(tmp_path):
    # the CLI's one-shot run of the concentric scenario (its activation a step to 1 at
    # 0.05 s) against a stepper whose activation Python holds at 0, then sets to 1 at 0.05 s
    concentric = os.path.join(SOURCE, "scenarios", "concentric.yaml")
    tight = ["solver.rtol=1e-10", "solver.atol=1e-12", "time.end=0.2"]
    csv = tmp_path / "concentric.csv"
    command = [CLI, "run", concentric, "-o", str(csv)]
    for text in tight:
        command += ["--set", text]
    subprocess.run(command, check=True, capture_output=True)
    reference = read_csv_columns(csv, ["t", "length", "shortening_velocity", "tension_total"])

    stepper = musclesim.Stepper(musclesim.load_scenario(concentric, set=tight))
    assert stepper.sample()["tip.position"] == 0.1  # initial.length: the tip's position
    stepper.set_activation("actuator", 0.0)
    length, speed, tension = [], [], []
    assert 0.05 in reference["t"]  # the grid holds the step's time: hold 1 from there on
    for t in reference["t"][1:]:
        assert stepper.advance(t) == "completed"
        if t == 0.05:
            stepper.set_activation("actuator", 1.0)
        sample = stepper.sample()
        length.append(sample["actuator.length"])
        speed.append(sample["actuator.shortening_velocity"])
        tension.append(sample["actuator.tension"])
    # rtol 1e-10 on both sides, different step sequences: global differences of some
    # hundreds of local errors (1e-11 m each on 0.1 m): 1e-9 m, 1e-7 m/s on speeds up to
    # ~0.4 m/s and 1e-6 N on 40 N, far below what a wrong initial state or a lost hold gives
    np.testing.assert_allclose(length, reference["length"][1:], rtol=0, atol=1e-9)
    np.testing.assert_allclose(speed, reference["shortening_velocity"][1:], rtol=0, atol=1e-7)
    np.testing.assert_allclose(tension, reference["tension_total"][1:], rtol=0, atol=1e-6)


def test_threads_sharing_a_stepper_take_turns():
    # advance() lets the GIL go: without a lock of its own two threads would step one
    # integrator at once (a double free in CVODE's error path). Each call either advances or
    # is refused for a time not after `time`; the stepper ends consistent.
    import threading
    stepper = musclesim.Stepper(FORCE_REGULATION)
    refused, errors = [], []

    def work():
        for _ in range(200):
            try:
                stepper.advance(stepper.time + 1e-4)
                stepper.sample()
            except musclesim.ParameterError as error:
                refused.append(error)  # another thread got there first
            except Exception as error:  # noqa: BLE001 - any other is the failure
                errors.append(error)

    threads = [threading.Thread(target=work) for _ in range(8)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert errors == [] and all(e.path == "t_next" for e in refused)
    assert stepper.sample()["t"] == stepper.time > 0
