#!/usr/bin/env bash
# Every benchmark of musclesim in one command (not part of CI's test run), under 15 minutes
# on 2 cores. Installs what it needs (Boost.Odeint, SciPy, gnuplot), builds in Release and
# writes bench/results/:
#   micro.txt            ns per tension, RHS and Jacobian evaluation; fit times
#   step_cost.csv        every scenario x method x Jacobian x epsilon x n (bench/step_cost.cc)
#   step_cost_table.md   the canonical scenarios at their own settings
#   sensitivity_cost.md  a run with k forward sensitivities against the plain run
#   stiffness.md         largest Jacobian eigenvalue against BDF and Adams steps, by eps and n
#   work_precision.csv   error against wall time for musclesim, Boost.Odeint and SciPy
#   work_precision.md    wall time at equal error, as ratios to musclesim's default
#   docs/figures/work_precision_<scenario>.png   the work-precision plots (gnuplot), on the site
#   sweep_throughput.md  runs per second of a 10,000-point sweep
#   chain_scaling.txt    cost per step of a chain of N actuators against N, per linear solver and
#                        against Boost.Odeint (and docs/figures/chain_scaling.png)
#   machine.txt          what it ran on
#   bench/run.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:-build-bench}
out=bench/results
mkdir -p "$out"

bash scripts/install-deps.sh
need=()
for p in libboost-dev python3-scipy python3-yaml gnuplot-nox; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
  sudo_cmd=(); [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${need[@]}"
fi

"$cmake" -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMUSCLESIM_BUILD_BENCHMARKS=ON \
  -DMUSCLESIM_BUILD_TESTS=OFF -DMUSCLESIM_WITH_MPI=ON >/dev/null
"$cmake" --build "$build" -j"$(nproc)" >/dev/null

{
  echo "date: $(date -u +%Y-%m-%d)"
  echo "cpu: $(lscpu | sed -n 's/^Model name: *//p') ($(nproc) cores)"
  echo "compiler: $(g++ --version | head -1)"
  echo "sundials: $(dpkg-query -W -f='${Version}' libsundials-dev), boost: $(dpkg-query -W -f='${Version}' libboost-dev), scipy: $($python -c 'import scipy; print(scipy.__version__)')"
} > "$out/machine.txt"

echo "== micro-benchmarks"
{
  "$build/bench/tension_benchmark" --benchmark_min_time=0.2
  "$build/bench/actuator_benchmark" --benchmark_min_time=0.2
  "$build/bench/gaussian_fit_benchmark"
} > "$out/micro.txt" 2>&1

echo "== step cost"
"$build/bench/step_cost" scenarios > "$out/step_cost.csv"
bash bench/step_cost_table.sh "$build" > "$out/step_cost_table.md"
"$build/bench/sensitivity_cost" > "$out/sensitivity_cost.md"
"$python" bench/stiffness_table.py "$out/step_cost.csv" > "$out/stiffness.md"

echo "== work-precision"
rows="$out/work_precision.csv"
: > "$rows"
# SciPy's peer handles the constant and step inputs of the first three only; its rows leave
# the last column (steps) empty
for s in isometric concentric eccentric twitches sine_load activation_ramp hanging_mass; do
  reference=$(mktemp)
  "$build/bench/work_precision" "scenarios/$s.yaml" "$reference" > "$out/wp_$s.csv" 2>> "$out/machine.txt"
  case $s in
    isometric|concentric|eccentric)
      "$python" bench/work_precision/scipy_peer.py "scenarios/$s.yaml" "$reference" |
        tail -n +2 | sed 's/$/,/' >> "$out/wp_$s.csv" ;;
  esac
  rm -f "$reference"
  if [ ! -s "$rows" ]; then head -1 "$out/wp_$s.csv" > "$rows"; fi
  tail -n +2 "$out/wp_$s.csv" >> "$rows"
  rm -f "$out/wp_$s.csv"
  # one curve per configuration, error against time, log-log
  curves=$(mktemp -d)
  awk -F, -v s="$s" -v dir="$curves" 'NR > 1 && $1 == s {
      file = dir "/" $2 "_" $3 ".dat"; print $5, $8 > file }' "$rows"
  {
    echo "set terminal pngcairo size 1000,700 noenhanced font 'sans,10'"
    echo "set output 'docs/figures/work_precision_$s.png'"
    echo "set logscale xy; set grid; set format x '%g'; set format y '%g'"
    echo "set xlabel 'achieved error (max relative error of length and tension)'"
    echo "set ylabel 'wall time per run [s] (median)'"
    echo "set title 'work-precision: scenarios/$s.yaml, rtol 1e-3 to 1e-11 ($(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores)'"
    echo "set key outside right top"
    printf 'plot '
    first=1
    for file in "$curves"/*.dat; do
      name=$(basename "$file" .dat)
      [ $first -eq 1 ] || printf ', \\\n  '
      first=0
      printf "'%s' using 1:2 with linespoints lw 2 title '%s'" "$file" "${name/_/ }"
    done
    echo
  } > "$curves/plot.gp"
  gnuplot "$curves/plot.gp"
  rm -rf "$curves"
done
"$python" bench/work_precision/summarize.py "$rows" > "$out/work_precision.md"

echo "== sweep throughput"
bash bench/sweep_throughput.sh "$build" > "$out/sweep_throughput.md"

echo "== networks: a chain of N segments"
bash bench/chain_scaling.sh "$build" 5 > /dev/null

echo "results in $out/"
