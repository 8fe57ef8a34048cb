#!/usr/bin/env python3
"""Writes scenarios/lattice.yaml: a soft body of N x N point masses in the plane, joined by
springs along its rows, columns and both diagonals of every cell, clamped by its left column
and hung under gravity. Beside every horizontal spring an actuator contracts; the activations
travel from the clamp to the tip as a wave, in antiphase between the body's lower and upper
halves, so that the body bends one way and the other like a swimming tail.

    python3 scripts/make_lattice.py [N] > scenarios/lattice.yaml
"""
import math
import sys

SPACING = 0.05         # m, between neighbouring nodes
MASS = 0.02            # kg, each free node
STIFFNESS = 2000.0     # N/m, a row's or column's spring
SHEAR_STIFFNESS = 1000.0  # N/m, a diagonal spring
FREQUENCY = 2.0        # Hz, of the activation wave
MEAN, SWING = 0.25, 0.25  # the activations' mean and amplitude


def name(row, col):
    return f"n{row}_{col}"


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10
    wavelength = n - 1  # columns: one whole wave along the body
    out = []
    add = out.append
    add(f"# A soft body of {n} x {n} point masses ({MASS} kg each, {SPACING} m apart) in the x-y plane,")
    add("# written by scripts/make_lattice.py. Springs join each node to its neighbours along")
    add(f"# rows and columns ({STIFFNESS:g} N/m) and across both diagonals of every cell")
    add(f"# ({SHEAR_STIFFNESS:g} N/m); the left column is clamped and gravity pulls the body down.")
    add("# Beside every horizontal spring an actuator (a muscle of optimal length 0.05 m) contracts")
    add(f"# with activation {MEAN} +- {SWING} sin(2 pi {FREQUENCY:g} t - phase): the phase grows by one")
    add("# wave along the body and the upper half runs in antiphase with the lower, so the body")
    add("# bends up and down in a wave that travels from the clamp to the tip. The test in")
    add("# tests/scenario/spatial_scenarios_test.cc checks the energy balance of docs/model.md 7.5")
    add("# and 12.5 over the run.")
    add("#   musclesim run scenarios/lattice.yaml")
    add("name: lattice")
    add("dimensions: 2")
    add("gravity: [0.0, -9.81]                                                  # m/s^2")
    add("models:")
    add("  muscle:")
    add("    # the canonical actuator's curves (scenarios/isometric.yaml) at half the length")
    add("    f_iso: 20.0                                              # N")
    add("    passive: {k_p: 1.0, alpha: 200.0, slack_length: 0.0525}  # N, 1/m, m")
    add("    active_length:")
    add("      optimal_range: [0.0475, 0.0525]                         # m")
    add("      gaussians:")
    canonical = [(0.35188944617853268, 20635.199147929347, 0.073556703926583866),
                 (2.2575025981825489, 4125.1402656159307, 0.097194271247335401),
                 (1.3136662819543681, 3009.3607405177986, 0.1301541244400391)]
    for amplitude, width, center in canonical:
        add(f"        - {{amplitude: {amplitude!r}, width: {width * 4.0!r}, center: {center * 0.5!r}}}")
    add("    velocity: {v_max: 0.5, n: 1, epsilon: 1.0e-3}             # m/s, -, m/s")
    add("nodes:                                                       # kg, m")
    for row in range(n):
        for col in range(n):
            x, y = col * SPACING, row * SPACING
            if col == 0:
                add(f"  - {{name: {name(row, col)}, fixed: [{x!r}, {y!r}]}}")
            else:
                add(f"  - {{name: {name(row, col)}, mass: {MASS}, position: [{x!r}, {y!r}]}}")
    add("elements:")
    diagonal = SPACING * math.sqrt(2.0)
    for row in range(n):
        for col in range(n):
            a = name(row, col)
            if col + 1 < n:
                b = name(row, col + 1)
                add(f"  - {{name: h{row}_{col}, type: spring, from: {a}, to: {b}, stiffness: {STIFFNESS}, rest_length: {SPACING}}}")
            if row + 1 < n:
                b = name(row + 1, col)
                add(f"  - {{name: v{row}_{col}, type: spring, from: {a}, to: {b}, stiffness: {STIFFNESS}, rest_length: {SPACING}}}")
            if row + 1 < n and col + 1 < n:
                add(f"  - {{name: d{row}_{col}, type: spring, from: {a}, to: {name(row + 1, col + 1)}, stiffness: {SHEAR_STIFFNESS}, rest_length: {diagonal!r}}}")
                add(f"  - {{name: e{row}_{col}, type: spring, from: {name(row, col + 1)}, to: {name(row + 1, col)}, stiffness: {SHEAR_STIFFNESS}, rest_length: {diagonal!r}}}")
    for row in range(n):
        upper = row >= n / 2
        for col in range(n - 1):
            phase = 2.0 * math.pi * col / wavelength + (math.pi if upper else 0.0)
            add(f"  - {{name: m{row}_{col}, type: actuator, from: {name(row, col)}, to: {name(row, col + 1)}, model: muscle,")
            add(f"     activation: {{type: sine, offset: {MEAN}, amplitude: {SWING}, frequency: {FREQUENCY}, phase: {-phase!r}}}}}")
    add("time: {start: 0.0, end: 1.0}                                           # s")
    add("solver: {method: bdf, rtol: 1.0e-6, atol: 1.0e-9, jacobian: analytic, linear_solver: auto}")
    add("output: {file: lattice.csv, interval: 0.01}")
    print("\n".join(out))


if __name__ == "__main__":
    main()
