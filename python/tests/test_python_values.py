"""Python's own values where the module takes paths and numbers: pathlib paths, NumPy
scalars and arrays, relative paths across os.chdir, copies of scenarios and their YAML."""
import copy
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

import musclesim
from conftest import CLI, SOURCE

CONCENTRIC = SOURCE / "scenarios" / "concentric.yaml"


def test_pathlib_paths_are_taken_everywhere():
    scenario = musclesim.load_scenario(CONCENTRIC, set={"time.end": 0.05})
    assert musclesim.load_model(CONCENTRIC).params["f_iso"] == 100.0
    stepper = musclesim.Stepper(CONCENTRIC)
    assert stepper.advance(0.01) == "completed"
    [result] = musclesim.run_many([(CONCENTRIC, {"time.end": 0.05})])
    np.testing.assert_array_equal(result["length"], scenario.run()["length"])
    with pytest.raises(TypeError, match="path"):
        musclesim.load_scenario(42)


def test_a_relative_scenario_survives_chdir_and_serves_as_a_sweep_base(tmp_path, monkeypatch):
    monkeypatch.chdir(SOURCE)
    scenario = musclesim.load_scenario("scenarios/concentric.yaml").set("time.end", 0.06)
    reference = scenario.run()
    monkeypatch.chdir(tmp_path)  # elsewhere: the scenario still names its file
    np.testing.assert_array_equal(scenario.run()["length"], reference["length"])
    summary = musclesim.sweep({"base": scenario, "parameters": {"load[0].after": [40.0]},
                               "metrics": ["final_length"]})
    # the sweep's point is the scenario as set (time.end 0.06, the file's load of 40 N)
    assert summary["final_length"][0] == reference["length"][-1]
    # the file is named as the user gave it
    assert "from scenarios/concentric.yaml" in repr(scenario)


def test_run_many_keeps_dict_scenarios_of_a_generator_alive():
    d = {"model": {"f_iso": 100.0, "passive": {"k_p": 1.0, "alpha": 100.0, "slack_length": 0.105},
                   "active_length": {"optimal_range": [0.095, 0.105], "gaussians": [
                       {"amplitude": 1.0, "width": 1000.0, "center": 0.1}]},
                   "velocity": {"v_max": 1.0, "n": 3, "epsilon": 1.0e-3}},
         "actuator": {"mass": 0.1, "damping": 0.0, "stiffness": 0.0, "rest_length": 0.1},
         "initial": {"length": 0.1, "lengthening_rate": 0.0},
         "activation": {"type": "constant", "value": 1.0},
         "load": [{"type": "constant", "value": 20.0}],
         "time": {"start": 0.0, "end": 0.05}}
    results = musclesim.run_many(musclesim.scenario_from_dict(d).set("load[0].value", f)
                                 for f in (10.0, 20.0))
    assert [r.status for r in results] == ["completed", "completed"]
    # more load, less shortening: the two runs are the two loads, in order
    assert results[0]["length"][-1] < results[1]["length"][-1]


def test_numpy_numbers_and_arrays_are_python_numbers():
    scenario = musclesim.load_scenario(CONCENTRIC, set={"time.end": np.float64(0.05)})  # float32(0.05) is not 0.05
    scenario.set("model.f_iso", np.float32(80.0)).set("model.velocity.n", np.int64(2))
    as_python = musclesim.load_scenario(CONCENTRIC, set={"time.end": 0.05, "model.f_iso": 80.0,
                                                         "model.velocity.n": 2})
    np.testing.assert_array_equal(scenario.run()["length"], as_python.run()["length"])
    summary = musclesim.sweep({"base": CONCENTRIC, "metrics": ["final_length"],
                               "parameters": {"load[0].after": np.linspace(10.0, 30.0, 3)}})
    np.testing.assert_array_equal(summary["load[0].after"], [10.0, 20.0, 30.0])


def test_nan_in_a_dict_is_an_input_error_naming_the_key():
    with pytest.raises(musclesim.InputError) as error:
        musclesim.sweep({"base": CONCENTRIC, "metrics": ["final_length"],
                         "parameters": {"load[0].after": [10.0, math.nan]}})
    assert "load[0].after" in str(error.value) and "nan" in str(error.value)


def test_copies_are_independent_and_to_yaml_runs_as_the_scenario(tmp_path):
    scenario = musclesim.load_scenario(CONCENTRIC, set={"time.end": 0.1})
    for duplicate in (scenario.copy(), copy.copy(scenario), copy.deepcopy(scenario)):
        duplicate.set("load[0].after", 20.0)
        assert scenario.overrides == ["time.end=0.1"]
        assert duplicate.overrides == ["time.end=0.1", "load[0].after=20.0"]
    scenario.set("load[0].after", 20.0)
    written = tmp_path / "written.yaml"
    written.write_text(scenario.to_yaml())
    # the written file run by the CLI against the CLI's own --set of the original: the
    # rewrite and the overrides are two routes to the same scenario
    for name, command in (("a.csv", [CLI, "run", str(written)]),
                          ("b.csv", [CLI, "run", str(CONCENTRIC), "--set", "time.end=0.1",
                                     "--set", "load[0].after=20.0"])):
        subprocess.run(command + ["-o", str(tmp_path / name)], check=True, capture_output=True)
    assert (tmp_path / "a.csv").read_text() == (tmp_path / "b.csv").read_text()


def test_scenarios_and_results_pickle_for_other_processes():
    import pickle
    from concurrent.futures import ProcessPoolExecutor
    d_scenario = musclesim.scenario_from_dict(
        {"nodes": [{"name": "wall", "fixed": 0.0},
                   {"name": "mass", "position": 0.1, "mass": 1.0}],
         "elements": [{"name": "spring", "type": "spring", "from": "wall", "to": "mass",
                       "stiffness": 100.0, "rest_length": 0.1}],
         "loads": [{"node": "mass", "type": "constant", "value": 1.0}],
         "time": {"start": 0.0, "end": 0.1}}).set("loads[0].value", 2.0)
    f_scenario = musclesim.load_scenario(CONCENTRIC, set={"time.end": 0.05})
    for scenario in (d_scenario, f_scenario):
        here = scenario.run()
        copied = pickle.loads(pickle.dumps(scenario))
        assert copied.is_network == scenario.is_network
        # another process runs the unpickled scenario and sends its Result back pickled
        with ProcessPoolExecutor(max_workers=1) as pool:
            there = pool.submit(_run, scenario).result()
        assert list(there.columns) == list(here.columns) and there.stats["steps"] == here.stats["steps"]
        for column in here.columns:
            np.testing.assert_array_equal(there[column], here[column])


def _run(scenario):
    return scenario.run()
