"""What the peer comparisons share on musclesim's side: a scenario run by the built program and
timed by its own report (the integration, not reading or writing files), and the reading of a
work-precision curve."""
import csv
import math
import os
import re
import subprocess


def timed_run(program, scenario_text, directory, repeats):
    """Writes `scenario_text` to DIRECTORY/drop.yaml (its output file must be drop.csv), runs it
    `repeats` times and returns (its CSV rows as dicts, the least integration time [s])."""
    path = os.path.join(directory, "drop.yaml")
    with open(path, "w") as f:
        f.write(scenario_text)
    best = math.inf
    for _ in range(repeats):
        done = subprocess.run([program, "run", path], cwd=directory, check=True,
                              capture_output=True, text=True)
        best = min(best, float(re.search(r"([0-9.e+-]+) ms", done.stderr).group(1)) * 1e-3)
    with open(os.path.join(directory, "drop.csv")) as f:
        return list(csv.DictReader(f)), best


def at_error(points, target):
    """The time of the cheapest run whose error is at most `target` (None: none reached it)."""
    reached = [seconds for e, seconds in points if e <= target]
    return min(reached) if reached else None
