#!/usr/bin/env bash
# `musclesim plot` of planar lattices (scripts/make_lattice.py) of N x N nodes, N = 10, 32,
# 100: the path figure and a 4-frame figure of a two-row run, wall time each (gnuplot
# included). Many nodes and elements are drawn as one curve per kind rather than a titled
# curve each, which for the 32 x 32 lattice took 120 s (src/plot/time_panels.h).
#   bench/plot_scaling.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:-build}
"$cmake" -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
"$cmake" --build "$build" -j"$(nproc)" --target musclesim_cli >/dev/null

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
seconds() { local start end; start=$(date +%s.%N); "$@" >/dev/null 2>&1; end=$(date +%s.%N)
            echo "$end - $start" | bc -l; }
echo "| lattice | nodes | elements | path figure [s] | 4 frames [s] |"
echo "|---|---|---|---|---|"
for n in 10 32 100; do
  "$python" scripts/make_lattice.py "$n" |
    sed 's/^time: .*/time: {start: 0.0, end: 1.0e-6}/; s/^output: .*/output: {interval: 1.0e-6}/' \
    > "$work/lattice.yaml"
  "$build/musclesim" run "$work/lattice.yaml" -o "$work/run.csv" --quiet
  elements=$(grep -c "type: " "$work/lattice.yaml")
  path=$(seconds "$build/musclesim" plot "$work/run.csv" -o "$work/path.png")
  frames=$(seconds "$build/musclesim" plot "$work/run.csv" --scenario "$work/lattice.yaml" \
    --frame-count 4 -o "$work/frames.png")
  printf "| %d x %d | %d | %d | %.2f | %.2f |\n" "$n" "$n" $((n * n)) "$elements" "$path" "$frames"
done
