"""Networks in the plane and in space built as Python dicts (docs/model.md 12): a pendulum on
a stiff link against the rigid pendulum's elliptic-integral period and its energy balance, a
mass hung in space from a spring over a fixed via point against its static balance written
here, the dict's run against the CLI's run of the same text, and a Stepper stepping the
pendulum in 10 ms pieces against the same period."""
import json
import math
import subprocess

import numpy as np

import musclesim
from conftest import CLI

G = 9.81


def pendulum(amplitude):
    """A 1 kg bob on a 1 m link of 1e6 N/m, released at rest `amplitude` rad from the vertical."""
    return {
        "name": "dict_pendulum",
        "dimensions": 2,
        "gravity": [0.0, -G],
        "nodes": [
            {"name": "pivot", "fixed": [0.0, 0.0]},
            {"name": "bob", "mass": 1.0,
             "position": [math.sin(amplitude), -math.cos(amplitude)]},
        ],
        "elements": [{"name": "link", "type": "spring", "from": "pivot", "to": "bob",
                      "stiffness": 1.0e6, "rest_length": 1.0}],
        "time": {"start": 0.0, "end": 3.0},
        "solver": {"method": "bdf", "rtol": 1e-10, "atol": 1e-13, "jacobian": "analytic"},
        "output": {"file": "dict_pendulum.csv", "interval": 0.001},
    }


def elliptic_k(k):
    """K(k) by the arithmetic-geometric mean."""
    a, b = 1.0, math.sqrt(1.0 - k * k)
    for _ in range(40):
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return math.pi / (2.0 * a)


def test_dict_pendulum_swings_with_the_elliptic_period():
    amplitude = math.radians(40.0)
    result = musclesim.scenario_from_dict(pendulum(amplitude)).run()
    assert result.status == "completed"
    t, x = result["t"], result["bob.x"]
    # leftward crossings of x = 0, interpolated between rows
    i = np.nonzero((x[:-1] > 0.0) & (x[1:] <= 0.0))[0]
    crossings = t[i] + (t[i + 1] - t[i]) * x[i] / (x[i] - x[i + 1])
    assert len(crossings) >= 2
    exact = 4.0 * math.sqrt(1.0 / G) * elliptic_k(math.sin(amplitude / 2.0))
    np.testing.assert_allclose(np.diff(crossings), exact, rtol=5e-5)
    # the energy with gravity stays what it was: kinetic + the link's + m g y
    stretch = result["link.length"] - 1.0
    energy = (0.5 * (result["bob.vx"] ** 2 + result["bob.vy"] ** 2)
              + 0.5e6 * stretch ** 2 + G * result["bob.y"])
    assert np.max(np.abs(energy - energy[0])) < 1e-5 * G


def test_dict_in_space_hangs_at_its_static_balance():
    # a 2 kg mass hung from a spring that runs from a ceiling point over a fixed via point;
    # started at the balance computed here, it stays there
    k, rest, mass = 500.0, 0.3, 2.0
    anchor, via = np.array([0.2, 0.1, 1.0]), np.array([0.0, 0.0, 1.0])
    # below the via point the segment is vertical: stretch = m g / k
    first = np.linalg.norm(via - anchor)
    hang = rest - first + mass * G / k
    position = via - np.array([0.0, 0.0, hang])
    scenario = {
        "name": "dict_hanging",
        "dimensions": 3,
        "gravity": [0.0, 0.0, -G],
        "nodes": [{"name": "ceiling", "fixed": anchor.tolist()},
                  {"name": "load", "mass": mass, "position": position.tolist()}],
        "elements": [{"name": "cord", "type": "spring", "from": "ceiling", "to": "load",
                      "via": [via.tolist()], "stiffness": k, "rest_length": rest}],
        "time": {"start": 0.0, "end": 1.0},
        "solver": {"rtol": 1e-10, "atol": 1e-13},
        "output": {"file": "dict_hanging.csv", "interval": 0.01},
    }
    result = musclesim.scenario_from_dict(scenario).run()
    assert result.status == "completed"
    for c, expected in zip(("x", "y", "z"), position):
        np.testing.assert_allclose(result["load." + c], expected, atol=1e-9)
    np.testing.assert_allclose(result["cord.tension"], mass * G, rtol=1e-9)
    np.testing.assert_allclose(result["cord.length"], first + hang, rtol=1e-12)


def test_dict_gives_the_cli_result_of_its_text(tmp_path):
    scenario = pendulum(math.radians(20.0))
    scenario["time"]["end"] = 0.5
    text_file = tmp_path / "pendulum.yaml"
    text_file.write_text(json.dumps(scenario))  # JSON is YAML
    out = tmp_path / "cli.csv"
    subprocess.run([CLI, "run", str(text_file), "-o", str(out), "--quiet"], check=True)
    with open(out) as f:
        header = f.readline().strip().split(",")
    table = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    result = musclesim.scenario_from_dict(scenario).run()
    assert list(result.columns) == header
    assert {"bob.x", "bob.y", "bob.vx", "bob.vy", "link.length"} <= set(header)
    for i, name in enumerate(header):
        np.testing.assert_array_equal(result[name], table[:, i], err_msg=name)


def test_stepping_a_planar_pendulum_keeps_the_elliptic_period():
    amplitude = math.radians(40.0)
    stepper = musclesim.Stepper(musclesim.scenario_from_dict(pendulum(amplitude)))
    # the state: the bob's coordinates, then its velocities (the pivot is fixed)
    np.testing.assert_array_equal(stepper.state,
                                  [math.sin(amplitude), -math.cos(amplitude), 0.0, 0.0])
    times, x = [0.0], [math.sin(amplitude)]
    for k in range(1, 301):
        assert stepper.advance(k * 0.01) == "completed"
        times.append(k * 0.01)
        x.append(stepper.sample()["bob.x"])
    t, x = np.array(times), np.array(x)
    i = np.nonzero((x[:-1] > 0.0) & (x[1:] <= 0.0))[0]
    crossings = t[i] + (t[i + 1] - t[i]) * x[i] / (x[i] - x[i + 1])
    assert len(crossings) >= 2
    exact = 4.0 * math.sqrt(1.0 / G) * elliptic_k(math.sin(amplitude / 2.0))
    # rows 10 ms apart, the crossing interpolated where x is nearly linear in t
    np.testing.assert_allclose(np.diff(crossings), exact, rtol=1e-4)
