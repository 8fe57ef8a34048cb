"""musclesim.optimize takes its arguments through the problem file's own reader: what the
file refuses, the call refuses with the same rule, raising musclesim.InputError with the key
and value (never a bool or a fractional float for an integer, never NaN or infinity); and the
holes of a problem file are closed from Python too (an infeasible move ends, a reference too
long is refused, max_seconds bounds the solve)."""
import math

import pytest

import musclesim
from conftest import SCENARIOS

MOVE = SCENARIOS / "antagonist_move.yaml"
CONTROLS = [{"actuator": "flexor"}, {"actuator": "extensor"}]
FINALS = [{"column": "load.position", "value": 0.075}, {"column": "load.velocity", "value": 0.0}]


def call(**changes):
    arguments = dict(controls=CONTROLS, final_values=FINALS, intervals=10)
    arguments.update(changes)
    return musclesim.optimize(musclesim.load_scenario(MOVE), **arguments)


@pytest.mark.parametrize("changes, message", [
    ({"controls": [{"actuator": "flexor", "effort": {"power": 27}}]},
     r"controls\[0\]\.effort\.power = 27 \(optimize\(\.\.\.\)\): must be an integer from 2 to 3 \[-\]: 2: integral of u\^2"),
    ({"controls": [{"actuator": "flexor", "effort": {"kind": "l1"}}]},
     r"controls\[0\]\.effort\.kind .*unknown key"),
    ({"intervals": 20.5}, r"intervals = 20\.5 .*integer"),
    ({"intervals": True}, r"intervals = true"),
    ({"intervals": 0}, r"intervals = 0"),
    ({"max_iterations": 3.5}, r"optimizer\.max_iterations = 3\.5"),
    ({"max_iterations": False}, r"optimizer\.max_iterations = false"),
    ({"tolerance": math.nan}, r"optimizer\.tolerance = \.nan"),
    ({"tolerance": math.inf}, r"optimizer\.tolerance = \.inf"),
    ({"max_seconds": -1.0}, r"optimizer\.max_seconds = -1"),
    ({"final_values": [{"column": "load.position", "value": math.nan}]},
     r"final_values\[0\]\.value = \.nan"),
    ({"final_values": [{"column": "load.position", "bounds": [0.1, 0.05]}]},
     r"lower <= upper"),
    ({"controls": [{"actuator": "flexor", "bounds": [0, 1], "weight": 1}]},
     r"controls\[0\]\.weight .*unknown key"),
    ({"tracking": [{"column": "load.position", "reference": ([0.0, 1.0], [0.07])}]},
     r"tracking\[0\]\.reference \(optimize\(\.\.\.\)\): must be \(times, values\) of one"),
])
def test_what_the_problem_file_refuses_the_call_refuses(changes, message):
    with pytest.raises(musclesim.InputError, match=message) as refused:
        call(**changes)
    assert "optimize(...)" in str(refused.value)


def test_a_move_the_muscles_cannot_make_ends_infeasible_naming_it():
    result = call(final_values=[{"column": "load.position", "value": 0.3}], intervals=3)
    assert not result["solved"]
    assert result["status"] == "infeasibility_stalled" and result["infeasible"]
    assert result["largest_violation"].startswith("final_values[0] load.position: ")
    assert result["iterations"] < 150


def test_a_reference_of_too_many_points_is_refused_before_the_solve():
    n = 100_001
    times = [i / (n - 1) for i in range(n)]
    with pytest.raises(musclesim.InputError, match="more than the 100000 a reference may hold"):
        call(final_values=[], tracking=[{"column": "load.position",
                                         "reference": (times, [0.07] * n)}])


def test_max_seconds_ends_the_solve_with_the_point_reached():
    result = call(max_seconds=1e-6)
    assert result["status"] == "maximum_seconds_exceeded"
    assert result["scenario"].run()["t"][-1] == pytest.approx(1.0)


def test_a_valid_call_gives_the_problem_files_optimum(tmp_path):
    # the shipped problem, from Python: its controls as the file's optimum has them
    result = musclesim.optimize(musclesim.load_scenario(MOVE),
                                controls=[{"actuator": "flexor", "bounds": [0.0, 1.0],
                                           "effort": {"weight": 1.0, "power": 2}},
                                          {"actuator": "extensor", "bounds": [0.0, 1.0],
                                           "effort": {"weight": 1.0, "power": 2}}],
                                final_values=FINALS, intervals=20, tolerance=1e-8,
                                max_iterations=300)
    assert result["solved"], result["status"]
    assert result["infeasible"] is False
