#!/usr/bin/python3
"""The README's stiffness table from bench/results/step_cost.csv: for the isometric scenario
with the analytic Jacobian, the largest Jacobian eigenvalue over the run against the steps
BDF and Adams take, for n = 1 and n = 3 across epsilon.
    stiffness_table.py step_cost.csv
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
pick = {(r["method"], r["n"], r["epsilon"]): r for r in rows
        if r["scenario"] == "isometric" and r["jacobian"] == "analytic"}
print("| n | eps [m/s] | largest eigenvalue [1/s] | BDF steps | Adams steps | BDF us/step | model share of BDF time |")
print("|---|---|---|---|---|---|---|")
for n in ("1", "3", "5"):
    for eps in ("0.01", "0.001", "0.0001", "1e-05", "1e-06"):
        bdf, adams = pick[("bdf", n, eps)], pick[("adams", n, eps)]
        print("| %s | %s | %.3g | %s | %s | %s | %.0f%% |" % (
            n, eps, float(bdf["max_eigenvalue"]), bdf["steps"], adams["steps"],
            bdf["us_per_step"], 100 * float(bdf["model_share"])))
