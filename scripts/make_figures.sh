#!/usr/bin/env bash
# Makes the README's figures in docs/figures/ from the canonical scenarios.
#   scripts/make_figures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:-build}
"$cmake" -S . -B "$build" >/dev/null
"$cmake" --build "$build" -j"$(nproc)" --target musclesim_cli >/dev/null
musclesim="$build/musclesim"
out=docs/figures
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

"$musclesim" run scenarios/sine_load.yaml -o "$work/sine_load.csv" --quiet
"$musclesim" plot "$work/sine_load.csv" -o "$out/sine_load.png" \
  --title "scenarios/sine_load.yaml: a 60 +- 50 N, 2 Hz load on the active actuator"
"$musclesim" plot --curves scenarios/concentric.yaml -o "$out/curves.png" --size 1000x500 \
  --title "the canonical actuator's model (scenarios/concentric.yaml)"
"$musclesim" sweep scenarios/stiffness_sweep.yaml -o "$work/stiffness.csv" --quiet
"$musclesim" plot "$work/stiffness.csv" --x model.velocity.epsilon --y steps \
  --color model.velocity.n -o "$out/stiffness.png" --size 1000x500 \
  --title "CVODE steps of scenarios/isometric.yaml against eps, by n"
"$musclesim" run scenarios/stiffness_modulation.yaml -o "$work/stiffness_modulation.csv" --quiet
"$musclesim" plot "$work/stiffness_modulation.csv" -o "$out/stiffness_modulation.png" --size 1000x800 \
  --title "scenarios/stiffness_modulation.yaml: 2 N pulses at co-contraction 0.1, 0.4, 0.7"
echo "figures written to $out/"
