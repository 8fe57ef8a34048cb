"""musclesim.run_many and musclesim.sweep: the CLI's results, on threads, the GIL released."""
import csv
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import musclesim

SOURCE = os.environ.get("MUSCLESIM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
SCENARIOS = os.path.join(SOURCE, "scenarios")
CLI = os.environ.get("MUSCLESIM_CLI")


def test_sweep_equals_the_clis_summary(tmp_path):
    sweep_file = os.path.join(SCENARIOS, "force_velocity_sweep.yaml")
    out = tmp_path / "summary.csv"
    subprocess.run([CLI, "sweep", sweep_file, "-o", str(out), "--quiet"], check=True,
                   capture_output=True)
    with open(out, newline="") as file:
        rows = list(csv.reader(file))
    header, body = rows[0], rows[1:]
    summary = musclesim.sweep(sweep_file, threads=2)
    assert list(summary) == header
    for c, name in enumerate(header):
        cli = [row[c] for row in body]
        ours = summary[name]
        assert len(ours) == len(cli)
        if name == "wall_seconds":  # timing: only its sign is reproducible
            assert np.all(ours >= 0)
        elif ours.dtype == object:
            assert list(ours) == cli
        else:
            # the same computation, each point on one thread, printed by the CLI with 17
            # significant digits (a round trip): equal to the last bit
            np.testing.assert_array_equal(ours, np.array(cli, dtype=float), err_msg=name)


def test_run_many_returns_what_the_cli_writes(tmp_path):
    network = os.path.join(SCENARIOS, "force_regulation.yaml")
    single = os.path.join(SCENARIOS, "isometric.yaml")
    jobs = [(network, {"time.end": 0.3}), (single, ["time.end=0.2"])]
    results = musclesim.run_many(jobs, threads=2)
    assert [r["status"] for r in results] == ["completed", "completed"]
    assert results[0]["final_time"] == 0.3 and results[1]["final_time"] == 0.2
    for (path, overrides), result, name in zip(jobs, results, ["net.csv", "single.csv"]):
        sets = [f"{k}={v}" for k, v in overrides.items()] if isinstance(overrides, dict) else overrides
        command = [CLI, "run", path, "-o", str(tmp_path / name)]
        for s in sets:
            command += ["--set", s]
        subprocess.run(command, check=True, capture_output=True)
        with open(tmp_path / name) as file:
            header = file.readline().strip().split(",")
        numeric = [n for n in header if n != "phase" and not n.endswith(".phase")]
        data = np.loadtxt(tmp_path / name, delimiter=",", skiprows=1,
                          usecols=[header.index(n) for n in numeric], ndmin=2)
        for k, column in enumerate(numeric):
            # the same run on the same code: equal to the CSV's 17 significant digits
            np.testing.assert_array_equal(result["columns"][column], data[:, k], err_msg=column)
        assert result["steps"] > 0


def test_a_bad_job_raises_naming_the_key():
    good = (os.path.join(SCENARIOS, "isometric.yaml"), None)
    bad = (os.path.join(SCENARIOS, "isometric.yaml"), ["solver.rtol=-1"])
    with pytest.raises(Exception, match="rtol"):
        musclesim.run_many([good, bad])
    with pytest.raises(ValueError, match="pair"):
        musclesim.run_many([(good[0],)])
    with pytest.raises(ValueError, match="threads"):
        musclesim.run_many([good], threads=-1)


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
