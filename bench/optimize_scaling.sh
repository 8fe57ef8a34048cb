#!/usr/bin/env bash
# What exact derivatives buy an optimal control solve (bench/optimize_scaling.cc): the
# antagonist pair's move on N = 25 .. 200 intervals and the suspended mass on N = 25 .. 100,
# with CVODES sensitivities and with difference quotients. Writes the Markdown table, headed
# by the machine, to bench/results/optimize_scaling.md. Builds the program first (Release) if
# needed. About 10 minutes on 2 cores.
#   bench/optimize_scaling.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:-build}
if [ ! -f "$build/CMakeCache.txt" ] || ! grep -q '^MUSCLESIM_BUILD_BENCHMARKS:BOOL=ON' "$build/CMakeCache.txt"; then
  "$cmake" -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMUSCLESIM_BUILD_BENCHMARKS=ON >/dev/null
fi
"$cmake" --build "$build" -j"$(nproc)" --target optimize_scaling >/dev/null
out=bench/results/optimize_scaling.md
mkdir -p bench/results
cpu=$(sed -n 's/^model name[[:space:]]*: *//p' /proc/cpuinfo | head -1)
{
  echo "# Optimal control: exact derivatives against difference quotients"
  echo
  echo "\`bash bench/optimize_scaling.sh\` on $cpu, $(nproc) cores ($(date -u +%Y-%m-%d))."
  echo "The intervals integrate in parallel on every core; IPOPT's tolerance 1e-8, a"
  echo "limited-memory Hessian, the same start for both derivatives."
  echo
  "$build/bench/optimize_scaling"
} > "$out.partial"
mv "$out.partial" "$out"
cat "$out"
