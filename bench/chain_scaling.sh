#!/usr/bin/env bash
# Cost of a chain of N actuators in series against N, per linear solver (bench/chain_benchmark.cc):
# musclesim's CVODE with dense, band, sparse and small (where 2N <= 16 states), and, when the
# benchmark was built with Boost, Boost.Odeint's rosenbrock4 with dense ublas matrices at the
# same tolerances (N = 1, 10, 100). Prints a table (N, tool, solver, steps, RHS, Jacobian
# evaluations, linear setups, wall us per run and per step, CPU us per step, the final state's
# relative error against a tight reference, and Odeint's difference from CVODE) with the fitted
# log-log slope of the cost per step against N per solver, and writes it to
# bench/results/chain_scaling.txt and the figure of the time per step, wall and CPU,
# docs/figures/chain_scaling.png (gnuplot). Times are the minimum over REPEATS repetitions
# (the machine may be shared: the fastest run is the one least disturbed). Dense at N = 1000 runs
# once: a run over 20 s is stopped and reported as skipped. Builds the benchmark first (Release)
# if needed.
#   bench/chain_scaling.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:-build}
repeats=${2:-7}
if [ ! -f "$build/CMakeCache.txt" ] || ! grep -q '^MUSCLESIM_BUILD_BENCHMARKS:BOOL=ON' "$build/CMakeCache.txt"; then
  "$cmake" -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMUSCLESIM_BUILD_BENCHMARKS=ON >/dev/null
fi
"$cmake" --build "$build" -j"$(nproc)" --target chain_benchmark >/dev/null
command -v gnuplot >/dev/null || { echo "gnuplot is not installed: apt-get install gnuplot-nox" >&2; exit 1; }

out=bench/results/chain_scaling.txt
figure=docs/figures/chain_scaling.png
mkdir -p bench/results docs/figures
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpu=$(sed -n 's/^model name[[:space:]]*: *//p' /proc/cpuinfo | head -1)
machine="$cpu, $(nproc) cores"
load=$(cut -d' ' -f1-3 /proc/loadavg)  # other work on a shared machine inflates wall times

# every case (Odeint's too) but dense at N = 1000 repeated; that one once (it is expected to hit the budget)
"$build/bench/chain_benchmark" --benchmark_filter='BM_ChainRun/N:(1|10|100)/|/N:1000/solver:[12]|BM_ChainOdeint' \
  --benchmark_min_time=0.2 --benchmark_repetitions="$repeats" --benchmark_format=json \
  > "$work/repeated.json" 2>/dev/null
"$build/bench/chain_benchmark" --benchmark_filter='BM_ChainRun/N:1000/solver:0' \
  --benchmark_format=json > "$work/once.json" 2>/dev/null

"$python" - "$work" "$machine" "$repeats" "$load" > "$out" <<'PY'
import json, math, sys
work, machine, repeats, load = sys.argv[1:5]
best, skipped = {}, {}
for name in ("repeated.json", "once.json"):
    for b in json.load(open(f"{work}/{name}"))["benchmarks"]:
        if b.get("run_type") != "iteration":
            continue
        n, solver = b["label"].split()
        key = (int(n[2:]), solver)
        if b.get("error_occurred"):
            skipped[key] = b["error_message"]
            continue
        to_us = {"ms": 1e3, "us": 1.0, "ns": 1e-3, "s": 1e6}[b["time_unit"]]
        us_run, cpu_us_run = b["real_time"] * to_us, b["cpu_time"] * to_us
        if key not in best or us_run < best[key]["us_run"]:
            cpu = best[key]["cpu_us_step"] if key in best else math.inf
            tool = "odeint" if b["name"].startswith("BM_ChainOdeint") else "musclesim"
            best[key] = dict(b, us_run=us_run, us_step=us_run / b["steps"], cpu_us_step=cpu,
                             tool=tool)
        best[key]["cpu_us_step"] = min(best[key]["cpu_us_step"], cpu_us_run / b["steps"])

solvers = ["dense", "band", "sparse", "small", "rosenbrock4-dense"]
tools = {"rosenbrock4-dense": "odeint"}
print(f"# Chain of N actuators in series (bench/chain_benchmark.cc): scenarios/isometric.yaml's model,")
print(f"# 1 g per node, 0.1 N s/m dampers, f_iso at the free end, activation 0 -> 1 at 0.05 s, 0.5 s,")
print(f"# rtol 1e-6, atol 1e-10, analytic Jacobian. musclesim: CVODE's BDF, per linear solver (small:")
print(f"# up to 16 states). odeint: Boost.Odeint's rosenbrock4 (dense output, dense ublas LU), restarted")
print(f"# at the breakpoint; steps: accepted steps, jac and setups: attempted steps. Wall time per run")
print(f"# and per step: minimum over {repeats} repetitions; cpu us/step: the process's CPU time, less")
print(f"# disturbed by other work on a shared machine. error: the final state's largest relative")
print(f"# difference from CVODE at rtol 1e-10 (a state below atol/rtol against atol/rtol); vs cvode:")
print(f"# the same between Odeint's and CVODE's final states at these tolerances.")
print(f"# {machine}; load average before the runs: {load}.")
print(f"{'N':>5} {'tool':>9} {'solver':>17} {'steps':>6} {'rhs':>6} {'jac':>4} {'setups':>6} {'us/run':>11} "
      f"{'us/step':>9} {'cpu us/step':>12} {'error':>8} {'vs cvode':>8}")
for n in sorted({k[0] for k in list(best) + list(skipped)}):
    for s in solvers:
        tool = tools.get(s, "musclesim")
        if (n, s) in best:
            r = best[(n, s)]
            versus = f"{r['vs_cvode']:>8.1e}" if "vs_cvode" in r else f"{'-':>8}"
            print(f"{n:>5} {tool:>9} {s:>17} {int(r['steps']):>6} {int(r['rhs']):>6} {int(r['jac']):>4} "
                  f"{int(r['setups']):>6} {r['us_run']:>11.1f} {r['us_step']:>9.2f} {r['cpu_us_step']:>12.2f} "
                  f"{r['error']:>8.1e} {versus}")
        elif (n, s) in skipped:
            print(f"{n:>5} {tool:>9} {s:>17}  {skipped[(n, s)]}")
            with open(f"{work}/skipped.txt", "a") as f:
                f.write(f"{s} at N = {n}: {skipped[(n, s)]}\n")

def slope(points):
    # least squares of log(us/step) against log(N)
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(c) for _, c in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")

print()
print("log-log slope of the cost per step against N (1: linear; at N = 1 the per-step overhead")
print("dominates, so the fit from N = 10 shows the growth):")
for s in solvers:
    points = sorted((n, r["us_step"]) for (n, sv), r in best.items() if sv == s)
    line = f"  {s:>17}:"
    for column, label in (("us_step", "wall"), ("cpu_us_step", "cpu")):
        pts = sorted((n, r[column]) for (n, sv), r in best.items() if sv == s)
        tail = [p for p in pts if p[0] >= 10]
        if len(pts) >= 2:
            line += f" {label} N = {pts[0][0]}..{pts[-1][0]}: {slope(pts):.2f}"
        if len(tail) >= 2:
            line += f", N = {tail[0][0]}..{tail[-1][0]}: {slope(tail):.2f};"
    if len(points) == 1:
        line += f" one point (N = {points[0][0]})"
    if points:
        print(line.rstrip(";"))
    with open(f"{work}/{s}.dat", "w") as f:
        for n, _ in points:
            f.write(f"{n} {best[(n, s)]['us_step']} {best[(n, s)]['cpu_us_step']}\n")
# the figure's reference line, proportional to N through band's wall time at the largest N
band = sorted((n, r["us_step"]) for (n, sv), r in best.items() if sv == "band")
with open(f"{work}/reference.txt", "w") as f:
    f.write(f"{band[-1][1] / band[-1][0] if band else 1.0}\n")
PY
cat "$out"

# per solver that has points (a solver skipped at every N has none): wall time solid, CPU dashed
plots=()
color=1
for s in dense band sparse small rosenbrock4-dense; do
  if [ -s "$work/$s.dat" ]; then
    title=$s
    # odeint in red (gnuplot's colour 7): its default 5, yellow, is hard to see
    [ "$s" = rosenbrock4-dense ] && { title="odeint $s"; color=7; }
    plots+=("'$work/$s.dat' using 1:2 with linespoints lw 2 pt 7 lc $color title '$title (wall)'")
    plots+=("'$work/$s.dat' using 1:3 with linespoints lw 1 dt 2 pt 6 lc $color title '$title (cpu)'")
  fi
  color=$((color + 1))
done
{
  echo "set terminal pngcairo size 900,600 noenhanced font 'sans,10'"
  echo "set output '$figure'"
  echo "set logscale xy; set grid; set format x '%g'; set format y '%g'"
  echo "set xrange [0.7:1500]"
  echo "set xlabel 'segments N (2N states)'"
  echo "set ylabel 'time per internal step [us] (minimum of $repeats runs)'"
  echo "set title \"chain of N actuators (bench/chain_benchmark.cc): cost per step by linear solver, and Odeint's rosenbrock4\\n$machine\""
  echo "set key top left"
  if [ -s "$work/skipped.txt" ]; then  # a case not drawn says why
    echo "set label \"$(paste -sd';' "$work/skipped.txt" | sed 's/"/\\"/g')\" at graph 0.98, 0.04 right"
  fi
  printf 'plot '
  (IFS=,; printf '%s' "${plots[*]}")
  echo ", $(cat "$work/reference.txt") * x with lines dt 2 lc 'gray' title 'proportional to N'"
} > "$work/plot.gp"
gnuplot "$work/plot.gp"
echo "written: $out, $figure"
