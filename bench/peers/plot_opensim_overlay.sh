#!/usr/bin/env bash
# The two tools' trajectories on top of each other (docs/figures/opensim_overlay.png): the
# hanging mass on OpenSim's DeGrooteFregly2016Muscle driven through its activation dynamics,
# as OpenSim 4.6 integrated it (bench/peers/reference/opensim_drop_excited.csv, written by
# bench/peers/opensim_reference.py) and as musclesim runs it now
# (bench/peers/opensim_drop_excited.yaml): the actuator's length, the tendon force and the
# activation against time, OpenSim's samples as points on musclesim's lines, and the largest
# difference of each relative to its range in the panel's title. Needs musclesim built and
# gnuplot; not OpenSim (its trajectory is the stored one).
#   bash bench/peers/plot_opensim_overlay.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
command -v gnuplot >/dev/null || { echo "gnuplot is not installed: apt-get install gnuplot-nox" >&2; exit 1; }
[ -x "$build/musclesim" ] || { echo "no $build/musclesim: build musclesim first" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
figure=docs/figures/opensim_overlay.png
reference=bench/peers/reference/opensim_drop_excited.csv
"$build/musclesim" run bench/peers/opensim_drop_excited.yaml -o "$work/musclesim.csv" 2>/dev/null
grep -v '^#' "$reference" > "$work/opensim.csv"
grep -v '^#' "$work/musclesim.csv" > "$work/run.csv"
# the largest difference of each plotted quantity, relative to its largest magnitude in OpenSim's
python3 - "$work" > "$work/differences.txt" <<'PY'
import csv, sys
work = sys.argv[1]
ours = list(csv.DictReader(open(f"{work}/run.csv")))
theirs = list(csv.DictReader(open(f"{work}/opensim.csv")))
assert len(ours) == len(theirs), (len(ours), len(theirs))
for mine, peer in (("length", "length"), ("tension_total", "tendon_force"),
                   ("activation", "activation")):
    scale = max(abs(float(r[peer])) for r in theirs)
    worst = max(abs(float(a[mine]) - float(b[peer])) for a, b in zip(ours, theirs))
    print(f"{worst / scale:.1e}")
PY
read -r d_length d_force d_activation < <(paste -sd' ' "$work/differences.txt")
col() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
t=$(col "$work/run.csv" t)
panel() {  # title, musclesim's column, OpenSim's column, y label
  echo "set title \"$1\"; set ylabel '$4'"
  echo "plot '$work/run.csv' using $t:$(col "$work/run.csv" "$2") with lines lw 2 lc 1 title 'musclesim', \\"
  echo "     '$work/opensim.csv' using 1:$(col "$work/opensim.csv" "$3") every 2 with points pt 6 ps 0.8 lc 7 title 'OpenSim 4.6'"
}
{
  echo "set terminal pngcairo size 900,900 noenhanced font 'sans,10'"
  echo "set output '$figure'"
  echo "set datafile separator ','; set key autotitle columnhead; set grid; set key top right"
  echo "set multiplot layout 3,1 title \"hanging mass on OpenSim's DeGrooteFregly2016Muscle, excited through its activation dynamics (bench/peers/plot_opensim_overlay.sh)\""
  echo "set xlabel ''"
  panel "actuator length (largest difference $d_length of its largest value)" length length "length [m]"
  panel "tendon force (largest difference $d_force)" tension_total tendon_force "force [N]"
  echo "set xlabel 't [s]'"
  panel "activation (largest difference $d_activation)" activation activation "activation [-]"
  echo "unset multiplot"
} > "$work/plot.gp"
gnuplot "$work/plot.gp"
echo "written: $figure (largest relative differences: length $d_length, force $d_force, activation $d_activation)"
