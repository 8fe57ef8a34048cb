"""A skeleton built as a Python dict (docs/model.md 15, docs/guide/skeletons.md): one rigid
link on a revolute joint against the physical pendulum's elliptic-integral period, and an
elbow whose biceps spans it over points of the bodies, its moment arm against a central
difference of its length over the angle. A module built without the skeleton component (the
wheel, for now: docs/dependencies.md) refuses the same dict, saying so; the CMake build's
tests expect the component (MUSCLESIM_EXPECT_SKELETON=1)."""
import math
import os

import pytest

import musclesim

G = 9.81
LINK = {"name": "link", "mass": 1.0, "center_of_mass": [0.0, -0.5],
        "inertia": [0.08335, 0.00005, 0.08335, 0.0, 0.0, 0.0]}


def pendulum(amplitude):
    return {
        "name": "dict_link",
        "dimensions": 2,
        "gravity": [0.0, -G],
        "bodies": [LINK],
        "joints": [{"name": "hinge", "type": "revolute", "child": "link", "value": amplitude}],
        "time": {"start": 0.0, "end": 4.0},
        "solver": {"method": "bdf", "rtol": 1e-10, "atol": 1e-12},
        "output": {"file": "dict_link.csv", "interval": 0.001},
    }


def elliptic_k(k):
    a, b = 1.0, math.sqrt(1.0 - k * k)
    for _ in range(40):
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return math.pi / (2.0 * a)


EXPECTED = os.environ.get("MUSCLESIM_EXPECT_SKELETON", "") == "1"


def run(dict_scenario):
    try:
        return musclesim.scenario_from_dict(dict_scenario).run()
    except Exception as error:  # the build without the component says so
        if EXPECTED:
            raise
        assert "no skeleton component" in str(error)
        return None


def test_dict_link_swings_with_the_physical_pendulums_period():
    amplitude = math.radians(50.0)
    result = run(pendulum(amplitude))
    if result is None:
        return
    assert result.status == "completed"
    t, u = result["t"], result["hinge.u"]
    crossings = [t[i - 1] + (t[i] - t[i - 1]) * -u[i - 1] / (u[i] - u[i - 1])
                 for i in range(1, len(t)) if u[i - 1] < 0.0 <= u[i]]
    assert len(crossings) >= 2
    d, pivot = 0.5, LINK["inertia"][2] + LINK["mass"] * 0.25
    period = 4.0 * elliptic_k(math.sin(amplitude / 2.0)) / math.sqrt(LINK["mass"] * G * d / pivot)
    assert crossings[1] - crossings[0] == pytest.approx(period, rel=1e-6)


def elbow(angle):
    return {
        "name": "dict_elbow",
        "dimensions": 2,
        "bodies": [{"name": "forearm", "mass": 1.2, "center_of_mass": [0.0, -0.12],
                    "inertia": [0.006, 0.001, 0.006, 0.0, 0.0, 0.0]}],
        "joints": [{"name": "elbow", "type": "revolute", "child": "forearm", "value": angle}],
        "nodes": [{"name": "origin", "fixed": [0.02, 0.28]}],
        "elements": [{"name": "biceps", "type": "spring", "stiffness": 1000.0,
                      "rest_length": 0.3, "from": "origin",
                      "via": [[0.03, 0.03]],
                      "to": {"body": "forearm", "point": [0.01, -0.04]}}],
        "time": {"start": 0.0, "end": 1e-6},
        "output": {"file": "dict_elbow.csv", "interval": 1e-6},
    }


def test_dict_elbow_moment_arm_is_minus_the_lengths_derivative():
    q, h = 0.7, 1e-6
    runs = [run(elbow(a)) for a in (q, q - h, q + h)]
    if runs[0] is None:
        return
    arm = runs[0]["biceps.moment_arm.elbow"][0]
    slope = (runs[2]["biceps.length"][0] - runs[1]["biceps.length"][0]) / (2 * h)
    assert arm == pytest.approx(-slope, abs=1e-8)
    assert arm > 0.0  # in front of the elbow, it flexes
