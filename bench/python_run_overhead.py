"""What a run costs from Python beyond the run itself: Scenario.run() on
scenarios/concentric.yaml (its 1 ms grid, 501 rows; and a 10 us grid, 50,001 rows) against
the same run recorded in memory by C++ alone (musclesim._musclesim._cpp_run_seconds), and run_many on 2
threads against `musclesim sweep --jobs 2` over the same 200 points. Prints a table; the
README quotes it. Run with the build tree on the path:
  PYTHONPATH=build/python /usr/bin/python3 bench/python_run_overhead.py [MUSCLESIM]
"""
import os
import platform
import subprocess
import sys
import tempfile
import time

import numpy as np

import musclesim

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
SCENARIO = os.path.join(ROOT, "scenarios", "concentric.yaml")
CLI = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "musclesim")
REPEATS = 30
LOADS = np.linspace(5.0, 95.0, 200)  # N: the sweep's points


def run_times(scenario):
    """Interleaved Python and C++ runs, the seconds of each."""
    python, cpp = [], []
    scenario.run()  # warm up
    for _ in range(REPEATS):
        start = time.perf_counter()
        scenario.run()
        python.append(time.perf_counter() - start)
        cpp += musclesim._musclesim._cpp_run_seconds(scenario, 1)
    return np.array(python), np.array(cpp)


def sweep_times():
    """Seconds per point of the CLI's sweep and of run_many, both on 2 threads."""
    with tempfile.TemporaryDirectory() as directory:
        sweep = os.path.join(directory, "sweep.yaml")
        with open(sweep, "w") as file:
            file.write("base: %s\nparameters:\n  load[0].after: [%s]\nmetrics: [final_length]\n"
                       "output: %s\n" % (SCENARIO, ", ".join(repr(float(f)) for f in LOADS),
                                         os.path.join(directory, "summary.csv")))
        cli, python = [], []
        base = musclesim.load_scenario(SCENARIO)
        for _ in range(5):
            start = time.perf_counter()
            subprocess.run([CLI, "sweep", sweep, "--jobs", "2", "--quiet"], check=True)
            cli.append((time.perf_counter() - start) / len(LOADS))
            jobs = [base.copy().set("load[0].after", float(f)) for f in LOADS]
            start = time.perf_counter()
            musclesim.run_many(jobs, threads=2)
            python.append((time.perf_counter() - start) / len(LOADS))
    return np.array(python), np.array(cli)


def row(label, python, reference):
    ratio = np.min(python) / np.min(reference)
    print(f"{label:<34}{np.min(python) * 1e3:>10.3f}{np.min(reference) * 1e3:>14.3f}{ratio:>8.3f}"
          f"{np.median(python) / np.median(reference):>15.3f}")


def main():
    print(f"machine: {platform.platform()}, {os.cpu_count()} cores, Python {platform.python_version()}")
    print(f"{'case':<34}{'Python ms':>10}{'reference ms':>14}{'ratio':>8}{'median ratio':>15}")
    scenario = musclesim.load_scenario(SCENARIO)
    row("run(), 1 ms grid (501 rows)", *run_times(scenario))
    fine = musclesim.load_scenario(SCENARIO).set("output.interval", 1e-5)
    row("run(), 10 us grid (50,001 rows)", *run_times(fine))
    row("run_many vs sweep, per point, 2 thr", *sweep_times())
    print("reference: the same run in C++ (in memory), or `musclesim sweep --jobs 2`; ratio of "
          "the minima of interleaved trials")


if __name__ == "__main__":
    main()
