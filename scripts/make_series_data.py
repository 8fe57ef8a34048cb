#!/usr/bin/env python3
"""Writes the synthetic time series of data/ that `musclesim identify` fits: each scenario run
by `musclesim run` as the truth (its parameters are the known ones), one column of its
trajectory kept and seeded Gaussian noise added. Standard library only; the same seed and the
same musclesim give the same files.
    python3 scripts/make_series_data.py [MUSCLESIM]     (default: build/musclesim, else PATH)
"""
import csv
import os
import random
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
DATA = os.path.join(ROOT, "data")

# (scenario, column kept, noise standard deviation, seed, output file, what the truth is)
SERIES = [
    ("quick_release", "length", 2.0e-5, 20261201, "quick_release_length.csv",
     "f_iso = 100 N, v_max = 1 m/s, slack_length = 0.105 m"),
    ("tetanus_transducer", "tension_total", 0.2, 20261202, "tetanus_transducer_tension.csv",
     "f_iso = 100 N, tau_activation = 15 ms, tau_deactivation = 50 ms, "
     "slack_length = 0.105 m, v_max = 1 m/s"),
]


def musclesim():
    if len(sys.argv) > 1:
        return sys.argv[1]
    built = os.path.join(ROOT, "build", "musclesim")
    return built if os.path.exists(built) else (shutil.which("musclesim") or "musclesim")


def truth(binary, scenario, directory):
    """The scenario's trajectory, as rows of dicts."""
    out = os.path.join(directory, scenario + ".csv")
    subprocess.run([binary, "run", os.path.join(ROOT, "scenarios", scenario + ".yaml"),
                    "-o", out, "--quiet"], check=True)
    with open(out) as f:
        return list(csv.DictReader(f))


def main():
    binary = musclesim()
    with tempfile.TemporaryDirectory() as directory:
        for scenario, column, noise, seed, name, parameters in SERIES:
            rng = random.Random(seed)
            rows = truth(binary, scenario, directory)
            with open(os.path.join(DATA, name), "w") as out:
                out.write("# synthetic: %s of `musclesim run scenarios/%s.yaml`, the truth\n"
                          "# (%s),\n"
                          "# plus N(0, (%g)^2) noise, seed %d (scripts/make_series_data.py)\n"
                          % (column, scenario, parameters, noise, seed))
                out.write("t,%s\n" % column)
                for row in rows:
                    value = float(row[column]) + rng.gauss(0.0, noise)
                    out.write("%s,%.17g\n" % (row["t"], value))


if __name__ == "__main__":
    main()
