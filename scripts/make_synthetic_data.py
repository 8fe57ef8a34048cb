#!/usr/bin/env python3
"""Writes the derived data files in data/: synthetic measured curves (known model parameters
plus seeded Gaussian noise), among them a tension-velocity curve with an eccentric limit, the
Gordon-Huxley-Julian polygon sampled evenly, and Hill's force-velocity curve. Standard library
only; the same seed gives the same files.
    python3 scripts/make_synthetic_data.py
"""
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "data")

# the canonical actuator of scenarios/*.yaml
K_P, ALPHA, SLACK = 1.0, 100.0, 0.105            # N, 1/m, m
F_ISO, V_MAX, N = 100.0, 1.0, 3                  # N, m/s, -
GAUSSIANS = [(0.35188944617853268, 20635.199147929347, 0.073556703926583866),
             (2.2575025981825489, 4125.1402656159307, 0.097194271247335401),
             (1.3136662819543681, 3009.3607405177986, 0.1301541244400391)]
NOISE = 0.02                                     # standard deviation, fraction of the maximum


def write(name, header, comment, rows):
    with open(os.path.join(DATA, name), "w") as out:
        for line in comment:
            out.write("# " + line + "\n")
        out.write(header + "\n")
        for x, y in rows:
            out.write("%.17g,%.17g\n" % (x, y))


def main():
    rng = random.Random(20261122)
    lengths = [0.09 + 0.0025 * i for i in range(29)]  # 0.09 .. 0.16 m
    passive = [(x, K_P * math.expm1(ALPHA * (x - SLACK)) if x > SLACK else 0.0) for x in lengths]
    top = max(t for _, t in passive)
    write("synthetic_passive.csv", "length,tension",
          ["synthetic passive tension: k_p = 1 N, alpha = 100 /m, slack_length = 0.105 m,",
           "plus N(0, (0.02 * max)^2) noise, seed 20261122 (scripts/make_synthetic_data.py)"],
          [(x, t + rng.gauss(0.0, NOISE * top)) for x, t in passive])

    peak = max(sum(a / math.sqrt(2 * math.pi) * math.exp(-b * (x - d) ** 2 / 2)
                   for a, b, d in GAUSSIANS) for x in [0.095 + 1e-5 * i for i in range(1001)])
    active = []
    for i in range(41):
        x = 0.05 + 0.0035 * i
        f = sum(a / math.sqrt(2 * math.pi) * math.exp(-b * (x - d) ** 2 / 2) for a, b, d in GAUSSIANS)
        active.append((x, F_ISO * f / peak + rng.gauss(0.0, NOISE * F_ISO)))
    write("synthetic_active.csv", "length,tension",
          ["synthetic active tension: f_iso = 100 N times f_L of scenarios/concentric.yaml",
           "(3 Gaussians), plus N(0, 2 N^2) noise, seed 20261122 (scripts/make_synthetic_data.py)"],
          active)

    velocity = []
    for i in range(31):
        v = -0.5 + 0.05 * i
        s = math.copysign(abs(v) ** (1.0 / N), v)
        velocity.append((v, F_ISO * (1 - s / V_MAX ** (1.0 / N)) + rng.gauss(0.0, NOISE * F_ISO)))
    write("synthetic_velocity.csv", "shortening_velocity,tension",
          ["synthetic tension-velocity curve: f_iso = 100 N, v_max = 1 m/s, n = 3 (eq. 12),",
           "eccentric and concentric, plus N(0, 2 N^2) noise, seed 20261122",
           "(scripts/make_synthetic_data.py)"],
          velocity)


def eccentric():
    """The asymmetric tension-velocity curve of docs/model.md section 9 (unregularised): the
    canonical concentric branch, and an eccentric one with v_max_e = 0.5 m/s, n_e = 2 and the
    limit L = 1.8, from -1 to 1 m/s, plus N(0, 1 N^2) noise with its own seed."""
    rng = random.Random(20261123)
    v_max_e, n_e, limit = 0.5, 2, 1.8
    rows = []
    for i in range(41):
        v = -1.0 + 0.05 * i
        if v >= 0:
            g = 1 - (v / V_MAX) ** (1.0 / N)
        else:
            psi = (-v / v_max_e) ** (1.0 / n_e)
            g = 1 + (limit - 1) * math.tanh(psi / (limit - 1))
        rows.append((v, F_ISO * g + rng.gauss(0.0, 1.0)))
    write("eccentric_velocity.csv", "shortening_velocity,tension",
          ["synthetic asymmetric tension-velocity curve (docs/model.md section 9): f_iso = 100 N,",
           "v_max = 1 m/s, n = 3; eccentric v_max = 0.5 m/s, n = 2, limit L = 1.8;",
           "plus N(0, 1 N^2) noise, seed 20261123 (scripts/make_synthetic_data.py)"], rows)


def sampled_ghj():
    """The GHJ breakpoints of data/ghj1966_breakpoints.csv, sampled every 0.05 um."""
    points = []
    with open(os.path.join(DATA, "ghj1966_breakpoints.csv")) as f:
        for line in f:
            if line.startswith("#") or line.startswith("length"):
                continue
            x, y = line.split(",")
            points.append((float(x), float(y)))
    rows = []
    x = points[0][0]
    while x <= points[-1][0] + 1e-12:
        for (x0, y0), (x1, y1) in zip(points, points[1:]):
            if x0 <= x <= x1:
                rows.append((x, y0 + (y1 - y0) * (x - x0) / (x1 - x0)))
                break
        x = round(x + 0.05, 10)
    write("ghj1966_sampled.csv", "length,tension",
          ["the polygon of data/ghj1966_breakpoints.csv sampled every 0.05 um from 1.27 um",
           "(length in micrometres, tension as a fraction of the maximum)",
           "(scripts/make_synthetic_data.py)"], rows)


def hill():
    """Hill's equation (F + a)(v + b) = (F0 + a) b with a/F0 = b/v_max = 0.25."""
    f0, v_max, k = 100.0, 1.0, 0.25
    rows = [(v_max * i / 20, f0 * (1 - i / 20) / (1 + (i / 20) / k)) for i in range(21)]
    write("hill_force_velocity.csv", "shortening_velocity,tension",
          ["Hill's force-velocity equation (A. V. Hill, Proc. R. Soc. B 126:136, 1938),",
           "(F + a)(v + b) = (F0 + a) b with a/F0 = b/v_max = 0.25, F0 = 100 N, v_max = 1 m/s,",
           "concentric side (scripts/make_synthetic_data.py)"], rows)


if __name__ == "__main__":
    sampled_ghj()
    hill()
    main()
    eccentric()
