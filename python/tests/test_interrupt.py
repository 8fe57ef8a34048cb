"""Ctrl-C stops run_many and sweep: a notebook's interrupt reaches a long C++ call."""
import os
import pathlib
import signal
import threading
import time

import numpy as np
import pytest

import musclesim

SOURCE = pathlib.Path(os.environ.get("MUSCLESIM_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
CONCENTRIC = SOURCE / "scenarios" / "concentric.yaml"
# 600 points of 0.3 s of the concentric scenario: several seconds on two cores, so that the
# interrupt, sent 0.3 s in, lands while the call runs
SWEEP = {"base": CONCENTRIC, "parameters": {"load[0].after": np.linspace(5.0, 95.0, 600).tolist()},
         "metrics": ["final_length"]}


def interrupt_after(seconds):
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_ctrl_c_stops_a_sweep_keeping_its_rows_and_resume_finishes_it(tmp_path):
    output = tmp_path / "summary.csv"
    sweep = dict(SWEEP, base=musclesim.load_scenario(CONCENTRIC).set("time.end", 0.3))
    interrupt_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        musclesim.sweep(sweep, threads=2, output=output)
    # stopped early: the rows done are in output.partial, fewer than the points, and no
    # summary was written
    partial = pathlib.Path(str(output) + ".partial")
    rows = [line for line in partial.read_text().splitlines() if line and not line.startswith("#")]
    assert 0 < len(rows) - 1 < 600 and not output.exists()
    resumed = musclesim.sweep(sweep, threads=2, output=output, resume=True)
    whole = musclesim.sweep(sweep, threads=2)
    assert len(resumed) == 600
    np.testing.assert_array_equal(resumed["final_length"], whole["final_length"])


def test_ctrl_c_stops_run_many_between_jobs():
    jobs = [(CONCENTRIC, {"time.end": 0.3})] * 3000
    start = time.perf_counter()
    musclesim.run_many(jobs[:20], threads=2)
    all_jobs = (time.perf_counter() - start) * len(jobs) / 20  # what the whole list takes
    interrupt_after(0.3)
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        musclesim.run_many(jobs, threads=2)
    # the running jobs finish (milliseconds each), no new one starts: far less than the list
    assert time.perf_counter() - start < 0.5 * all_jobs
