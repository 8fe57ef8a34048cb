"""musclesim.run_many and musclesim.sweep: the CLI's results, on threads, the GIL released."""
import csv
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import musclesim
from conftest import CLI, SOURCE

SCENARIOS = os.path.join(SOURCE, "scenarios")


def test_sweep_equals_the_clis_summary(tmp_path):
    sweep_file = os.path.join(SCENARIOS, "force_velocity_sweep.yaml")
    out = tmp_path / "summary.csv"
    subprocess.run([CLI, "sweep", sweep_file, "-o", str(out), "--quiet"], check=True,
                   capture_output=True)
    with open(out, newline="") as file:
        rows = list(csv.reader(file))
    header, body = rows[0], rows[1:]
    summary = musclesim.sweep(sweep_file, threads=2)
    assert summary.dtype.names == tuple(header) and summary.shape == (len(body),)
    assert summary["steps"].dtype == np.int64 and summary["status"].dtype.kind == "U"
    for c, name in enumerate(header):
        cli = [row[c] for row in body]
        ours = summary[name]
        assert len(ours) == len(cli)
        if name == "wall_seconds":  # timing: only its sign is reproducible
            assert np.all(ours >= 0)
        elif ours.dtype.kind == "U":
            assert list(ours) == cli
        else:
            # the same computation, each point on one thread, printed by the CLI with 17
            # significant digits (a round trip): equal to the last bit
            np.testing.assert_array_equal(ours, np.array(cli, dtype=float), err_msg=name)


def cli_columns(tmp_path, path, overrides, name):
    """`musclesim run`'s CSV as {column: array} (numbers float64, phase columns str)."""
    sets = [f"{k}={v}" for k, v in overrides.items()] if isinstance(overrides, dict) else overrides
    command = [CLI, "run", path, "-o", str(tmp_path / name)]
    for s in sets:
        command += ["--set", s]
    subprocess.run(command, check=True, capture_output=True)
    with open(tmp_path / name, newline="") as file:
        rows = list(csv.reader(file))
    header, body = rows[0], rows[1:]
    return {n: np.array([row[c] for row in body], dtype=str if n.endswith("phase") else float)
            for c, n in enumerate(header)}


def test_run_many_returns_what_the_cli_writes(tmp_path):
    network = os.path.join(SCENARIOS, "force_regulation.yaml")
    single = os.path.join(SCENARIOS, "isometric.yaml")
    jobs = [(network, {"time.end": 0.3}), (single, ["time.end=0.2"])]
    results = musclesim.run_many(jobs, threads=2)
    assert [r.status for r in results] == ["completed", "completed"]
    assert results[0].stats["final_time"] == 0.3 and results[1].stats["final_time"] == 0.2
    for (path, overrides), result, name in zip(jobs, results, ["net.csv", "single.csv"]):
        cli = cli_columns(tmp_path, path, overrides, name)
        # the same columns in the same order, phase columns included
        assert list(result.columns) == list(cli)
        for column, values in cli.items():
            # the same run on the same code: equal to the CSV's 17 significant digits
            np.testing.assert_array_equal(result[column], values, err_msg=column)
        assert result.stats["steps"] > 0


def test_table_stacks_the_runs_in_job_order(tmp_path):
    single = os.path.join(SCENARIOS, "isometric.yaml")
    network = os.path.join(SCENARIOS, "force_regulation.yaml")
    results = musclesim.run_many([(single, {"time.end": 0.1}), (network, {"time.end": 0.2}),
                                  (single, {"time.end": 0.3})])
    stacked = musclesim.table(results)
    assert stacked.shape == (sum(len(r) for r in results),)
    assert stacked.dtype.names[:2] == ("job", "t") and stacked["job"].dtype == np.int64
    names = set(stacked.dtype.names)
    for k, result in enumerate(results):
        rows = stacked[stacked["job"] == k]
        for column in names - {"job"}:
            if column in result.columns:
                np.testing.assert_array_equal(rows[column], result[column], err_msg=column)
            elif stacked[column].dtype.kind == "U":  # the other kind's column: empty there
                assert (rows[column] == "").all(), column
            else:
                assert np.isnan(rows[column]).all(), column
    # a single actuator's and a network's columns together
    assert {"length", "phase", "tip.position", "muscle.phase"} <= names
    # one call to a DataFrame (pandas: a test dependency, not the module's)
    import pandas
    frame = pandas.DataFrame(stacked)
    assert list(frame.columns) == list(stacked.dtype.names) and len(frame) == len(stacked)
    np.testing.assert_array_equal(frame["length"].to_numpy(), stacked["length"])


def test_a_bad_job_raises_naming_the_key():
    good = (os.path.join(SCENARIOS, "isometric.yaml"), None)
    bad = (os.path.join(SCENARIOS, "isometric.yaml"), ["solver.rtol=-1"])
    with pytest.raises(musclesim.InputError, match="rtol"):
        musclesim.run_many([good, bad])
    for job in [(good[0],), "ab", None]:
        with pytest.raises(TypeError, match="pair"):
            musclesim.run_many([good, job])
    with pytest.raises(TypeError, match="path"):
        musclesim.run_many([(5, None)])
    with pytest.raises(ValueError, match="threads"):
        musclesim.run_many([good], threads=-1)
    with pytest.raises(TypeError, match="threads"):
        musclesim.run_many([good], threads=1.5)
    with pytest.raises(TypeError, match="base"):
        musclesim.sweep({"base": 5, "parameters": {"load[0].after": [1.0]},
                         "metrics": ["final_length"]})


def test_python_runs_while_run_many_integrates():
    # the GIL released: another Python thread makes progress during the C++ call, whatever
    # the load of the machine (held, it could not run between the call's start and end)
    # 200 runs of a few ms: long enough for a ticker to be scheduled on a loaded machine
    jobs = [(os.path.join(SCENARIOS, "force_regulation.yaml"), {"output.interval": 0.5})] * 200
    stamps, done = [], threading.Event()

    def tick():
        while not done.is_set():
            stamps.append(time.perf_counter())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    time.sleep(0.01)
    start = time.perf_counter()
    musclesim.run_many(jobs, threads=1)
    end = time.perf_counter()
    done.set()
    ticker.join()
    middle = [s for s in stamps if start + 0.25 * (end - start) < s < end - 0.25 * (end - start)]
    # a 1 ms sleep takes up to tens of ms on a busy machine: 3 ticks in the middle half
    assert len(middle) >= 3, (len(middle), end - start)


def test_a_dict_sweep_equals_the_file_sweep():
    sweep_file = os.path.join(SCENARIOS, "force_velocity_sweep.yaml")
    from_file = musclesim.sweep(sweep_file)
    as_dict = {"base": os.path.join(SCENARIOS, "concentric.yaml"), "mode": "grid",
               "parameters": {"load[0].after": {"from": 5.0, "to": 95.0, "count": 19}},
               "metrics": ["mean_shortening_velocity", "final_shortening_velocity",
                           "final_length", "peak_tension", "work"],
               "metric_options": {"window": [0.06, 0.07]}, "trajectories": "none"}
    from_dict = musclesim.sweep(as_dict)
    assert from_dict.dtype.names == from_file.dtype.names
    for column in from_file.dtype.names:
        if column != "wall_seconds":  # timing: not reproducible
            np.testing.assert_array_equal(from_dict[column], from_file[column], err_msg=column)


def test_a_scenario_base_keeps_its_set_values_and_matches_single_runs(tmp_path):
    # each point's final length against the same scenario run alone: two routes through
    # the code (the sweep's workers and metrics, Scenario.run's CSV) that must agree
    base = musclesim.load_scenario(os.path.join(SCENARIOS, "concentric.yaml")).set("time.end", 0.08)
    loads = [10.0, 30.0, 50.0]
    output = tmp_path / "summary.csv"
    summary = musclesim.sweep({"base": base, "parameters": {"load[0].after": loads},
                               "metrics": ["final_length"]}, threads=2, output=output)
    assert output.exists()  # written where asked, as -o does
    for load, final_length in zip(loads, summary["final_length"]):
        run = musclesim.load_scenario(os.path.join(SCENARIOS, "concentric.yaml"),
                                      set={"time.end": 0.08, "load[0].after": load}).run()
        assert run.stats["final_time"] == 0.08
        # the last row's length; the summary prints 17 significant digits: a round trip
        assert final_length == run["length"][-1]


def test_a_bad_dict_sweep_names_the_key_and_the_name():
    base = os.path.join(SCENARIOS, "concentric.yaml")
    with pytest.raises(musclesim.InputError) as error:
        musclesim.sweep({"base": base, "parameters": {"load[0].after": [1.0]},
                         "metrics": ["final_length"], "mode": "spiral"}, name="my sweep")
    assert error.value.key == "mode" and "my sweep" in str(error.value)
    assert "spiral" in str(error.value) and "/tmp" not in str(error.value)
    with pytest.raises(TypeError):
        musclesim.sweep(["not", "a", "sweep"])


def test_run_many_adds_sensitivities_as_run_does():
    path = os.path.join(SCENARIOS, "concentric.yaml")
    jobs = [(path, {"time.end": 0.1, "load[0].after": f}) for f in (20.0, 40.0)]
    results = musclesim.run_many(jobs, sensitivities=["model.f_iso"])
    for (job_path, overrides), result in zip(jobs, results):
        alone = musclesim.load_scenario(job_path, set=overrides).run(sensitivities=["model.f_iso"])
        assert list(result.columns) == list(alone.columns)
        assert "d_length/d_model.f_iso" in result.columns
        np.testing.assert_array_equal(result["d_length/d_model.f_iso"],
                                      alone["d_length/d_model.f_iso"])
    with pytest.raises(TypeError, match="sensitivities"):
        musclesim.run_many(jobs, sensitivities="model.f_iso")


def test_a_summary_path_that_cannot_take_it_is_refused_before_any_point(tmp_path):
    base = tmp_path / "base.yaml"
    base.write_text(open(os.path.join(SCENARIOS, "concentric.yaml")).read())
    before = base.read_text()
    sweep = {"base": base, "parameters": {"load[0].after": [10.0, 30.0]}, "metrics": ["final_length"]}
    cases = [(base, "is the base scenario"), (tmp_path, "is a directory"),
             (tmp_path / "no" / "summary.csv", "does not exist")]
    for output, rule in cases:
        with pytest.raises(musclesim.InputError, match=rule):
            musclesim.sweep(sweep, output=output)
    assert base.read_text() == before  # the input the summary would have replaced
    assert not list(tmp_path.glob("*.partial"))  # refused before anything was written
    with pytest.raises(ValueError, match="output"):
        musclesim.sweep(sweep, resume=True)
