#!/usr/bin/env bash
# Prints the README's step-cost table: every canonical scenario with BDF and Adams, analytic
# and difference-quotient (DQ) Jacobian, the median of 5 repetitions. Builds the benchmark
# first (Release).
#   bench/step_cost_table.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:-build}
"$cmake" -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMUSCLESIM_BUILD_BENCHMARKS=ON >/dev/null
"$cmake" --build "$build" -j"$(nproc)" --target simulation_benchmark >/dev/null
"$build/bench/simulation_benchmark" --benchmark_min_time=0.1 --benchmark_repetitions=5 \
  --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null |
"$python" -c '
import csv, sys
runs = {}
for r in csv.DictReader(sys.stdin):
    if not r.get("label") or not r["name"].strip("\"").endswith("_median"):
        continue
    name, method, jac = r["label"].strip("\"").split()
    runs.setdefault(name, {})[(method, jac)] = r
print("| scenario | BDF analytic | BDF DQ | Adams analytic | Adams DQ |")
print("|---|---|---|---|---|")
for name, d in runs.items():
    cells = []
    for key in [("bdf", "analytic"), ("bdf", "dq"), ("adams", "analytic"), ("adams", "dq")]:
        r = d[key]
        cells.append("%.2f ms, %d steps, %d RHS, %d Jac, %.2f us/step" % (
            float(r["real_time"]), float(r["steps"]), float(r["rhs"]), float(r["jac"]),
            float(r["time_per_step"]) * 1e6))
    print("| %s | %s |" % (name, " | ".join(cells)))
'
