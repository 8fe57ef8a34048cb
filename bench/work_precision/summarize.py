#!/usr/bin/python3
"""Reads the work-precision rows (work_precision and scipy_peer output) and prints, for each
scenario and each achieved error level, every configuration's wall time interpolated at that
error (log-log, between the two runs that bracket it) and its ratio to musclesim's default
(BDF, analytic Jacobian). Standard library only.
    summarize.py rows.csv
"""
import csv
import math
import sys
from collections import defaultdict

LEVELS = [1e-4, 1e-6, 1e-8]
BASE = "musclesim bdf-analytic"


def time_at(points, level):
    """Wall time at achieved error `level`, from (error, time) points; None outside them."""
    points = sorted((e, t) for e, t in points if e > 0 and math.isfinite(e))
    for (e0, t0), (e1, t1) in zip(points, points[1:]):
        lo, hi = min(e0, e1), max(e0, e1)
        if lo <= level <= hi and e0 != e1:
            w = (math.log(level) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + w * (math.log(t1) - math.log(t0)))
    return None


def main():
    curves = defaultdict(lambda: defaultdict(list))
    with open(sys.argv[1]) as f:
        for r in csv.DictReader(f):
            curves[r["scenario"]][r["tool"] + " " + r["method"]].append(
                (float(r["error"]), float(r["wall_seconds"])))
    for scenario, configs in curves.items():
        print("\n#### %s: wall time at equal achieved error (ratio to %s)\n" % (scenario, BASE))
        print("| configuration | " + " | ".join("error %.0e" % l for l in LEVELS) + " |")
        print("|---|" + "---|" * len(LEVELS))
        base = {l: time_at(configs[BASE], l) for l in LEVELS}
        for name in sorted(configs, key=lambda n: (not n.startswith("musclesim"), n)):
            cells = []
            for level in LEVELS:
                t = time_at(configs[name], level)
                if t is None:
                    cells.append("not reached")
                elif base[level]:
                    cells.append("%.3g ms (%.2fx)" % (1e3 * t, t / base[level]))
                else:
                    cells.append("%.3g ms" % (1e3 * t))
            print("| %s | %s |" % (name, " | ".join(cells)))


if __name__ == "__main__":
    main()
