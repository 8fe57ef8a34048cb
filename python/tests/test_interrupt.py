"""Ctrl-C stops run_many and sweep: a notebook's interrupt reaches a long C++ call."""
import contextlib
import os
import pathlib
import signal
import threading
import time

import pytest

import musclesim
from conftest import CLI, SOURCE

CONCENTRIC = SOURCE / "scenarios" / "concentric.yaml"
# 200000 points of 0.3 s of the concentric scenario: tens of seconds on two cores, so that the
# interrupt, sent once the first rows are in, lands while the sweep runs
SWEEP = {"parameters": {"load[0].after": {"from": 5.0, "to": 95.0, "count": 400},
                        "model.f_iso": {"from": 80.0, "to": 120.0, "count": 500}},
         "metrics": ["final_length"]}


@contextlib.contextmanager
def interrupt_after(seconds):
    """Ctrl-C `seconds` into the block; never after it (a stray one would end the session)."""
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        yield
    finally:
        timer.cancel()
        timer.join()


def rows_in(partial):
    if not partial.exists():
        return 0
    return sum(1 for line in partial.read_text().splitlines() if line and line[0].isdigit())


def test_ctrl_c_stops_a_sweep_keeping_its_rows(tmp_path):
    output = tmp_path / "summary.csv"
    partial = pathlib.Path(str(output) + ".partial")
    sweep = dict(SWEEP, base=musclesim.load_scenario(CONCENTRIC).set("time.end", 0.3))

    stop = threading.Event()

    def interrupt_once_rows_are_in():
        while rows_in(partial) == 0:
            if stop.wait(0.01):
                return  # the sweep ended first: no signal after it
        os.kill(os.getpid(), signal.SIGINT)

    sender = threading.Thread(target=interrupt_once_rows_are_in)
    sender.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            musclesim.sweep(sweep, threads=2, output=output)
    finally:
        stop.set()
        sender.join()
    # stopped early: the rows done stay in output.partial, far fewer than the points, and no
    # summary was written
    assert 0 < rows_in(partial) < 200000 and not output.exists()
    # the partial file belongs to the interrupted sweep: without resume it is refused, naming
    # the way on (resume itself is the library's, tested with the CLI)
    with pytest.raises(musclesim.InputError, match="resume"):
        musclesim.sweep(sweep, threads=2, output=output)


def test_ctrl_c_stops_run_many_between_jobs():
    jobs = [(CONCENTRIC, {"time.end": 0.3})] * 6000
    start = time.perf_counter()
    musclesim.run_many(jobs[:40], threads=2)
    all_jobs = (time.perf_counter() - start) * len(jobs) / 40  # what the whole list takes
    start = time.perf_counter()
    with interrupt_after(0.3), pytest.raises(KeyboardInterrupt):
        musclesim.run_many(jobs, threads=2)
    # the running jobs finish (milliseconds each), no new one starts: far less than the list
    assert time.perf_counter() - start < 0.5 * all_jobs


def test_ctrl_c_during_the_last_points_is_still_a_keyboard_interrupt():
    # one long point (seconds): Ctrl-C lands while it runs, the point finishes, the summary is
    # whole, and the interrupt is still raised (not lost, not a SystemError)
    sweep = {"base": SOURCE / "scenarios" / "antagonist_pair.yaml",
             "parameters": {"time.end": [2500.0]}, "metrics": ["peak_tension"],
             "metric_options": {"element": "flexor"}}
    with interrupt_after(0.3), pytest.raises(KeyboardInterrupt):
        musclesim.sweep(sweep, threads=1)
