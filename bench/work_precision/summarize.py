#!/usr/bin/python3
"""Reads the work-precision rows (work_precision and scipy_peer output) and prints, for each
scenario and each achieved error level, every configuration's wall time interpolated at that
error (log-log, between the two runs that bracket it) and its ratio to musclesim's default
(BDF, analytic Jacobian). After each table: musclesim's default time over Odeint's at each
level (below 1: musclesim faster), and both tools' accepted internal steps at that level
(interpolated the same way; the `steps` column, which SciPy's rows leave empty). Standard
library only.
    summarize.py rows.csv
"""
import csv
import math
import sys
from collections import defaultdict

LEVELS = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8]
BASE = "musclesim bdf-analytic"
PEER = "odeint rosenbrock4"


def value_at(points, level):
    """The value at achieved error `level`, from (error, value) points, interpolated log-log
    between the two runs that bracket it; None outside them."""
    points = sorted((e, v) for e, v in points if e > 0 and math.isfinite(e) and v > 0)
    for (e0, v0), (e1, v1) in zip(points, points[1:]):
        lo, hi = min(e0, e1), max(e0, e1)
        if lo <= level <= hi and e0 != e1:
            w = (math.log(level) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(v0) + w * (math.log(v1) - math.log(v0)))
    return None


def cell(value, fmt):
    return "not reached" if value is None else fmt % value


def main():
    times = defaultdict(lambda: defaultdict(list))
    steps = defaultdict(lambda: defaultdict(list))
    with open(sys.argv[1]) as f:
        for r in csv.DictReader(f):
            name = r["tool"] + " " + r["method"]
            error = float(r["error"])
            times[r["scenario"]][name].append((error, float(r["wall_seconds"])))
            if r.get("steps"):
                steps[r["scenario"]][name].append((error, float(r["steps"])))
    for scenario, configs in times.items():
        print("\n#### %s: wall time at equal achieved error (ratio to %s)\n" % (scenario, BASE))
        print("| configuration | " + " | ".join("error %.0e" % l for l in LEVELS) + " |")
        print("|---|" + "---|" * len(LEVELS))
        base = {l: value_at(configs[BASE], l) for l in LEVELS}
        for name in sorted(configs, key=lambda n: (not n.startswith("musclesim"), n)):
            cells = []
            for level in LEVELS:
                t = value_at(configs[name], level)
                if t is None:
                    cells.append("not reached")
                elif base[level]:
                    cells.append("%.3g ms (%.2fx)" % (1e3 * t, t / base[level]))
                else:
                    cells.append("%.3g ms" % (1e3 * t))
            print("| %s | %s |" % (name, " | ".join(cells)))
        if PEER in configs:
            peer = {l: value_at(configs[PEER], l) for l in LEVELS}
            ratios = [None if base[l] is None or peer[l] is None else base[l] / peer[l]
                      for l in LEVELS]
            print("\n%s time / %s time: %s" % (BASE, PEER, ", ".join(
                "%.0e: %s" % (l, cell(r, "%.2f")) for l, r in zip(LEVELS, ratios))))
            for name in (BASE, PEER):
                print("%s accepted steps: %s" % (name, ", ".join(
                    "%.0e: %s" % (l, cell(value_at(steps[scenario][name], l), "%.0f"))
                    for l in LEVELS)))


if __name__ == "__main__":
    main()
