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
    with pytest.raises(musclesim.InputError, match="controls\\[0\\].weight .*unknown key"):
        musclesim.optimize(flat_actuator(), controls=[{"actuator": "muscle", "weight": 2.0}])
    with pytest.raises(musclesim.InputError, match="value \\(an equality\\) or bounds"):
        musclesim.optimize(flat_actuator(), controls=[{"actuator": "muscle"}],
                           final_values=[{"column": "mass.position"}])


def test_minimum_time_with_a_free_parameter_and_its_scenario_rerun():
    """Minimum time to the rest-to-rest move with f_iso free within [100, 150] N: the fastest
    move uses the strongest actuator, so f_iso ends at its upper bound; the optimum's
    scenario carries it and the final time, and re-runs to rest at the target."""
    result = musclesim.optimize(
        flat_actuator(), controls=[{"actuator": "muscle", "effort": {"weight": 0.0}}],
        final_values=[{"column": "mass.position", "value": 0.1 - D},
                      {"column": "mass.velocity", "value": 0.0}], intervals=10,
        parameters=[{"path": "models.flat.f_iso", "bounds": [100.0, 150.0]}],
        final_time={"bounds": [0.005, 0.1], "weight": 1.0})
    assert result["solved"], result["status"]
    assert result["parameters"]["models.flat.f_iso"] == pytest.approx(150.0, rel=1e-6)
    # no faster than bang-bang with f_iso = 150 N (docs/model.md 13.3's mass and load)
    a1, a2 = (150.0 - F0) / M, F0 / M
    fastest = (2.0 * D * a2 / (a1 * (a1 + a2))) ** 0.5 * (1.0 + a1 / a2)
    assert fastest <= result["final_time"] < 1.05 * fastest
    assert result["terms"]["final_time"] == pytest.approx(result["final_time"])
    assert result["states"].shape == (11, 2)
    assert result["resimulation_deviation"] < 1e-8
    optimum = result["scenario"]
    run = optimum.run()
    assert run["t"][-1] == pytest.approx(result["final_time"], rel=1e-12)
    assert run["mass.position"][-1] == pytest.approx(0.1 - D, abs=1e-8)
    assert abs(run["mass.velocity"][-1]) < 1e-6


def test_tracking_and_terminal_terms_from_python():
    """Tracking a reachable reference (the closed-form optimum's own motion, sampled every
    1 ms, linear between: within 2e-6 m of it) with a terminal term on the velocity: the
    optimum follows it with the closed form's activation, its tracking cost near zero."""
    exact = musclesim.optimize(
        flat_actuator(), controls=[{"actuator": "muscle"}],
        final_values=[{"column": "mass.position", "value": 0.1 - D},
                      {"column": "mass.velocity", "value": 0.0}], intervals=4)
    motion = exact["scenario"].run()
    result = musclesim.optimize(
        flat_actuator(), controls=[{"actuator": "muscle", "effort": {"weight": 0.0}}],
        tracking=[{"column": "mass.position",
                   "reference": (motion["t"], motion["mass.position"]),
                   "weight": 1e6}],
        terminal=[{"column": "mass.velocity", "target": 0.0, "weight": 1.0}], intervals=4)
    # the objective vanishes at this optimum, and IPOPT's optimality error stalls at the
    # integration's noise a little above its tolerance: "acceptable" is the expected status
    assert result["status"] in ("success", "solved_to_acceptable_level"), result["status"]
    assert result["terms"]["tracking"] < 1e-6
    np.testing.assert_allclose(result["controls"]["muscle"], exact["controls"]["muscle"],
                               atol=1e-4)
