"""musclesim.optimize on a Scenario built in code: the rest-to-rest move of docs/model.md 13
whose optimum has a closed form (an actuator whose tension is f_iso u moves a mass against a
constant load with the least integral of u^2), the optimum's scenario re-run to its final
values, and bad problems refused."""
import numpy as np
import pytest

import musclesim

M, D, T, F0, F_ISO = 0.1, 0.02, 0.1, 20.0, 100.0


def flat_actuator():
    return musclesim.scenario_from_dict({
        "name": "flat_move",
        "models": {"flat": {
            "f_iso": F_ISO,
            "passive": {"k_p": 0.0, "alpha": 100.0, "slack_length": 0.105},
            "active_length": {"optimal_range": [0.095, 0.105],
                              "gaussians": [{"amplitude": 1.0, "width": 1e-4, "center": 0.09}]},
            "velocity": {"v_max": 1e7, "n": 1, "epsilon": 1e-3}}},
        "nodes": [{"name": "anchor", "fixed": 0.0},
                  {"name": "mass", "mass": M, "position": 0.1, "velocity": 0.0}],
        "elements": [{"name": "muscle", "type": "actuator", "from": "anchor", "to": "mass",
                      "model": "flat", "activation": {"type": "constant", "value": 0.2}}],
        "loads": [{"node": "mass", "type": "constant", "value": F0}],
        "time": {"start": 0.0, "end": T},
        "solver": {"rtol": 1e-11, "atol": 1e-14},
        "output": {"file": "flat_move.csv", "interval": 0.001},
    })


def test_the_optimum_is_the_closed_forms_linear_activation():
    result = musclesim.optimize(
        flat_actuator(), controls=[{"actuator": "muscle"}],
        final_values=[{"column": "mass.position", "value": 0.1 - D},
                      {"column": "mass.velocity", "value": 0.0}], intervals=4)
    assert result["solved"], result["status"]
    t = result["times"]
    exact = (F0 + 6.0 * M * D / T**2 * (1.0 - 2.0 * t / T)) / F_ISO
    np.testing.assert_allclose(result["controls"]["muscle"], exact, rtol=0, atol=1e-6)
    cost = (12.0 * M**2 * D**2 / T**3 + F0**2 * T) / F_ISO**2
    assert result["objective"] == pytest.approx(cost, rel=1e-7)
    # the optimum as a scenario, run again: it ends at rest where it was asked to
    run = result["scenario"].run()
    assert run["mass.position"][-1] == pytest.approx(0.1 - D, abs=1e-8)
    assert abs(run["mass.velocity"][-1]) < 1e-6


def test_bad_problems_are_refused():
    with pytest.raises(musclesim.InputError, match="biceps"):
        musclesim.optimize(flat_actuator(), controls=[{"actuator": "biceps"}])
    with pytest.raises(ValueError, match="unknown keys"):
        musclesim.optimize(flat_actuator(), controls=[{"actuator": "muscle", "weight": 2.0}])
    with pytest.raises(ValueError, match="either 'value' or 'bounds'"):
        musclesim.optimize(flat_actuator(), controls=[{"actuator": "muscle"}],
                           final_values=[{"column": "mass.position"}])
