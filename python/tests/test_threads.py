"""Every entry point that releases the GIL gives, called from two Python threads at once,
the results it gives called one after the other: optimize (IPOPT's MUMPS keeps state of its
own, so solves take turns), run_many, sweep, identify_series and the stepper."""
import csv  # noqa: F401 - read below
import threading

import numpy as np
import pytest

import musclesim
from conftest import DATA, SCENARIOS

MOVE = SCENARIOS / "antagonist_move.yaml"


def in_two_threads(work):
    """work(0) and work(1) in two threads started together; their results in order."""
    results, errors = [None, None], []
    start = threading.Barrier(2)

    def run(i):
        try:
            start.wait()
            results[i] = work(i)
        except Exception as error:  # noqa: BLE001 - reported below
            errors.append(error)

    threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    return results


def optimize(i):
    target = (0.075, 0.072)[i]
    return musclesim.optimize(
        musclesim.load_scenario(MOVE),
        controls=[{"actuator": "flexor"}, {"actuator": "extensor"}],
        final_values=[{"column": "load.position", "value": target},
                      {"column": "load.velocity", "value": 0.0}], intervals=10)


def test_two_optimizations_in_two_threads_are_the_sequential_ones():
    sequential = [optimize(0), optimize(1)]
    for _ in range(3):  # the crash came in 7 of 9 runs
        concurrent = in_two_threads(optimize)
        for seq, con in zip(sequential, concurrent):
            assert con["solved"] and seq["solved"]
            for name in ("flexor", "extensor"):
                np.testing.assert_array_equal(con["controls"][name], seq["controls"][name])
            assert con["objective"] == seq["objective"]


def test_run_many_and_sweeps_in_two_threads_are_the_sequential_ones():
    scenarios = [musclesim.load_scenario(SCENARIOS / "concentric.yaml",
                                         {"load[0].after": 20.0 + 10.0 * k}) for k in range(4)]

    def many(_):
        return [r["length"] for r in musclesim.run_many(scenarios, threads=2)]

    spec = {"base": str(SCENARIOS / "concentric.yaml"), "mode": "grid",
            "parameters": {"load[0].after": {"from": 20.0, "to": 60.0, "count": 4}},
            "metrics": ["final_length"], "trajectories": "none"}

    def sweep(_):
        return musclesim.sweep(spec, threads=2)["final_length"]

    for work in (many, sweep):
        sequential = [work(0), work(1)]
        for seq, con in zip(sequential, in_two_threads(work)):
            for a, b in zip(np.atleast_1d(seq), np.atleast_1d(con)):
                np.testing.assert_array_equal(a, b)


def test_identification_and_steppers_in_two_threads_are_the_sequential_ones():
    import csv
    with open(DATA / "quick_release_length.csv") as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    measured = {"t": np.array([float(r["t"]) for r in rows]),
                "length": np.array([float(r["length"]) for r in rows]),
                "noise": {"length": 2e-5}}
    base = musclesim.load_scenario(SCENARIOS / "quick_release.yaml")

    def identify(_):
        fit = musclesim.identify_series(
            base, [measured], [{"path": "model.f_iso", "start": 80.0, "bounds": [1.0, 1000.0]},
                               {"path": "model.velocity.v_max", "start": 0.6,
                                "bounds": [0.01, 100.0]}])
        return [p.estimate for p in fit.parameters]

    def step(i):
        stepper = musclesim.Stepper(SCENARIOS / "antagonist_pair.yaml")
        stepper.set_activation("flexor", 0.4 + 0.1 * i)
        for k in range(1, 21):
            stepper.advance(0.005 * k)
        return stepper.state

    for work in (identify, step):
        sequential = [work(0), work(1)]
        for seq, con in zip(sequential, in_two_threads(work)):
            np.testing.assert_array_equal(np.asarray(seq), np.asarray(con))
