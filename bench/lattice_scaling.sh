#!/usr/bin/env bash
# Cost of spatial networks against their size (bench/lattice_scaling.cc): an N x N lattice in
# the plane (springs, actuators, gravity) and a chain of N nodes in space, N = 5 .. 60, with the
# sparse (KLU) and band linear solvers. Prints a markdown table (network, N, nodes, states,
# solver, steps, linear setups, ms per run, us per step, ms per simulated second, us per step
# and node, and the ratio of the cost per step and node to the previous N's) with the fitted
# log-log slope of the cost per step against the number of nodes per network and solver, and
# writes it to bench/results/lattice_scaling.md. A run of the largest lattice takes about a
# minute, so each case runs REPEATS times (default 1) and the fastest counts; the table gives
# both wall and CPU time (the process's: less disturbed by other work on a shared machine). A
# run over 120 s is stopped and reported as skipped. Builds the benchmark first (Release) if
# needed.
#   bench/lattice_scaling.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:-build}
repeats=${2:-1}
if [ ! -f "$build/CMakeCache.txt" ] || ! grep -q '^MUSCLESIM_BUILD_BENCHMARKS:BOOL=ON' "$build/CMakeCache.txt"; then
  "$cmake" -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMUSCLESIM_BUILD_BENCHMARKS=ON >/dev/null
fi
"$cmake" --build "$build" -j"$(nproc)" --target lattice_scaling >/dev/null

out=bench/results/lattice_scaling.md
mkdir -p bench/results
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpu=$(sed -n 's/^model name[[:space:]]*: *//p' /proc/cpuinfo | head -1)
machine="$cpu, $(nproc) cores"
load=$(cut -d' ' -f1-3 /proc/loadavg)  # other work on a shared machine inflates wall times

"$build/bench/lattice_scaling" --benchmark_repetitions="$repeats" \
  --benchmark_format=json > "$work/runs.json" 2>/dev/null

"$python" - "$work" "$machine" "$repeats" "$load" > "$out" <<'PY'
import json, math, sys
work, machine, repeats, load = sys.argv[1:5]
best, skipped, evals, klu = {}, {}, {}, {}
for b in json.load(open(f"{work}/runs.json"))["benchmarks"]:
    if b.get("run_type") != "iteration":
        continue
    if b["name"].startswith("BM_LatticeKluFactor"):
        ordering, n = b["label"].split()
        ms = b["cpu_time"] * {"ms": 1.0, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b["time_unit"]]
        klu[(int(n[2:]), ordering)] = dict(b, ms=ms)
        continue
    if b["name"].startswith("BM_LatticeEvaluation"):
        kind, n = b["label"].split()
        key = (kind, int(n[2:]))
        us = b["cpu_time"] * {"ms": 1e3, "us": 1.0, "ns": 1e-3, "s": 1e6}[b["time_unit"]]
        if key not in evals or us < evals[key]["us"]:
            evals[key] = dict(b, us=us)
        continue
    network, n, nodes, solver = b["label"].split()
    key = (network, int(n[2:]), solver)
    if b.get("error_occurred"):
        skipped[key] = b["error_message"]
        continue
    to_ms = {"ms": 1.0, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b["time_unit"]]
    ms_run, cpu_ms_run = b["real_time"] * to_ms, b["cpu_time"] * to_ms
    if key not in best or ms_run < best[key]["ms_run"]:
        best[key] = dict(b, ms_run=ms_run, cpu_ms_run=cpu_ms_run)

print("# Spatial networks against their size (bench/lattice_scaling.cc, bench/lattice_scaling.sh)")
print()
print("lattice2d: N x N nodes 0.1 m apart, 10 g each, the bottom row fixed, springs (1e3 N/m) on")
print("the columns and both diagonals of every cell, actuators (isometric.yaml's model, f_iso = 1 N,")
print("activation 0.5 + 0.5 sin(2 pi 5 t)) on the rows, gravity. chain3d: N nodes on a small helix,")
print("both ends fixed, taut springs with dampers, gravity. 0.05 s of BDF, rtol 1e-6, atol 1e-9,")
print(f"analytic Jacobian. Times: the fastest of {repeats} run(s) per case; wall and the process's CPU")
print(f"time (less disturbed by other work). {machine}, shared with other builds while this ran")
print(f"(load average before the runs: {load}): wall times are inflated, compare the CPU columns.")
print()
print("| network | N | nodes | states | solver | steps | setups | wall ms/run | wall us/step | cpu us/step "
      "| cpu s per simulated s | cpu us/(step node) | ratio to previous N |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
previous = {}
keys = sorted(set(best) | set(skipped), key=lambda k: (k[0] != "lattice2d", k[2] != "sparse", k[2], k[1]))
for key in keys:
    network, n, solver = key
    if key in skipped:
        print(f"| {network} | {n} | | | {solver} | | | {skipped[key]} | | | | | |")
        continue
    r = best[key]
    nodes, steps = int(r["nodes"]), int(r["steps"])
    us_step = r["ms_run"] * 1e3 / steps
    cpu_us_step = r["cpu_ms_run"] * 1e3 / steps
    per_node = cpu_us_step / nodes
    ratio = f"{per_node / previous[(network, solver)]:.2f}" if (network, solver) in previous else "-"
    previous[(network, solver)] = per_node
    print(f"| {network} | {n} | {nodes} | {int(r['states'])} | {solver} | {steps} | {int(r['setups'])} "
          f"| {r['ms_run']:.1f} | {us_step:.1f} | {cpu_us_step:.1f} | {r['cpu_ms_run'] / 1e3 / 0.05:.2f} "
          f"| {per_node:.3f} | {ratio} |")

def slope(points):
    xs = [math.log(x) for x, _ in points]
    ys = [math.log(y) for _, y in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")

print()
print("Log-log slope of the CPU cost per step against the number of nodes (1: linear):")
print()
for network in ("lattice2d", "chain3d"):
    for solver in ("sparse", "band"):
        pts = sorted((int(r["nodes"]), r["cpu_ms_run"] / r["steps"]) for (nw, n, s), r in best.items()
                     if nw == network and s == solver)
        if len(pts) >= 2:
            tail = pts[-3:]
            print(f"- {network}, {solver}: nodes {pts[0][0]}..{pts[-1][0]}: {slope(pts):.2f}; "
                  f"the last three sizes ({tail[0][0]}..{tail[-1][0]} nodes): {slope(tail):.2f}")

print()
print("One right-hand side and one analytic Jacobian of the lattice (BM_LatticeEvaluation), and")
print("the Jacobian's structure: what the linear solvers factor.")
print()
print("| N | nodes | states | Jacobian entries | band width | rhs cpu us | rhs us/node | jacobian cpu us "
      "| jacobian us/node |")
print("|---|---|---|---|---|---|---|---|---|")
for n in sorted({n for _, n in evals}):
    if ("rhs", n) not in evals or ("jacobian", n) not in evals:
        continue
    r, j = evals[("rhs", n)], evals[("jacobian", n)]
    nodes = r["nodes"]
    print(f"| {n} | {int(nodes)} | {int(r['states'])} | {int(r['entries'])} | {int(r['bandwidth'])} "
          f"| {r['us']:.1f} | {r['us'] / nodes:.3f} | {j['us']:.1f} | {j['us'] / nodes:.3f} |")
if klu:
    print()
    print("One KLU factorisation of the lattice's Newton matrix I - gamma J (BM_LatticeKluFactor; built")
    print("when SuiteSparse's klu.h is found) with KLU's two orderings: SUNDIALS' KLU wrapper, which the")
    print("sparse solver uses, orders with COLAMD by default; AMD is KLU's own default.")
    print()
    print("| N | nodes | J entries | ordering | L+U entries | fill (L+U / J) | flops | factor cpu ms |")
    print("|---|---|---|---|---|---|---|---|")
    for (n, ordering), r in sorted(klu.items()):
        print(f"| {n} | {int(r['nodes'])} | {int(r['entries'])} | {ordering} | {int(r['lu_entries'])} "
              f"| {r['lu_entries'] / r['entries']:.1f} | {r['flops']:.3g} | {r['ms']:.2f} |")
PY
cat "$out"
echo "written: $out"
