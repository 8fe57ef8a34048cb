"""A run, a run with sensitivities, run_many, a sweep and an identification from Python, of a
scenario built from a dict, touch no file: the temporary directory (TMPDIR, which both
Python's tempfile and C++'s std::filesystem::temp_directory_path take) and the working
directory stay as they were, and their results are the ones the in-file ways give."""
import os

import numpy as np
import pytest

import musclesim

# the concentric scenario, shorter, as a dict (so that no file is read either)
SCENARIO = {
    "name": "in_memory",
    "model": {
        "f_iso": 100.0,
        "passive": {"k_p": 1.0, "alpha": 100.0, "slack_length": 0.105},
        "active_length": {"optimal_range": [0.095, 0.105],
                          "gaussians": [{"amplitude": 1.0, "width": 3000.0, "center": 0.1}]},
        "velocity": {"v_max": 1.0, "n": 3, "epsilon": 1e-3},
    },
    "actuator": {"mass": 0.1},
    "initial": {"length": 0.1},
    "activation": {"type": "step", "time": 0.01, "before": 0.0, "after": 1.0},
    "load": [{"type": "constant", "value": 40.0}],
    "time": {"start": 0.0, "end": 0.05},
    "output": {"interval": 0.001},
}


@pytest.fixture
def watched(tmp_path, monkeypatch):
    """An empty temporary directory as TMPDIR and as the working directory."""
    temp = tmp_path / "tmp"
    work = tmp_path / "work"
    temp.mkdir()
    work.mkdir()
    monkeypatch.setenv("TMPDIR", str(temp))
    monkeypatch.chdir(work)
    yield temp, work
    assert sorted(os.listdir(temp)) == [], "files left in TMPDIR"
    assert sorted(os.listdir(work)) == [], "files left in the working directory"


def test_run_and_sensitivities_write_nothing(watched):
    scenario = musclesim.scenario_from_dict(SCENARIO)
    plain = scenario.run()
    with_sensitivities = scenario.run(sensitivities=["model.f_iso", "actuator.mass"])
    assert len(plain) == 51 and plain.status == "completed"
    # the same trajectory with and without sensitivities: their error control changes the
    # steps, so only to the solver's accuracy (rtol 1e-6 a step; the global error of this
    # 50 ms run is a few of them, 5e-7 m on 0.13 m seen)
    np.testing.assert_allclose(with_sensitivities["length"], plain["length"], rtol=1e-5)
    assert "d_length/d_model.f_iso" in with_sensitivities.columns


def test_run_many_and_sweep_write_nothing(watched):
    base = musclesim.scenario_from_dict(SCENARIO)
    loads = [20.0, 40.0, 60.0]
    runs = musclesim.run_many([base.copy().set("load[0].value", f) for f in loads], threads=2)
    summary = musclesim.sweep({"base": base, "parameters": {"load[0].value": loads},
                               "metrics": ["final_length"]}, threads=2)
    # each point's final length is the last row of the same run made alone
    np.testing.assert_array_equal(summary["final_length"], [r["length"][-1] for r in runs])


def test_identification_writes_nothing(watched):
    truth = musclesim.scenario_from_dict(SCENARIO).set("model.f_iso", 90.0)
    measured = truth.run()
    start = musclesim.scenario_from_dict(SCENARIO)
    fit = musclesim.identify_series(start, [{"t": measured["t"], "length": measured["length"]}],
                                    ["model.f_iso"])
    # noise-free data made by the model itself: the estimate is the truth to the solver's
    # accuracy (rtol 1e-6 on the lengths, 0.1% on a parameter seen through them)
    assert fit.estimates["model.f_iso"] == pytest.approx(90.0, rel=1e-3)
    assert fit.scenario.parameter("model.f_iso").value == fit.estimates["model.f_iso"]
