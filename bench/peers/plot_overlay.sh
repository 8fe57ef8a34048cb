#!/usr/bin/env bash
# A peer's stored trajectory on top of musclesim's run of the same case
# (docs/figures/PEER_overlay.png): three quantities against time, the peer's samples as points
# on musclesim's lines, and the largest difference of each relative to its largest magnitude
# in the panel's title. Needs musclesim built and gnuplot; not the peer (its trajectory is the
# stored one, bench/peers/reference/, written by the peer's own script).
#   opensim: the hanging mass on OpenSim's DeGrooteFregly2016Muscle driven through its
#            activation dynamics (opensim_reference.py; bench/peers/opensim_drop_excited.yaml)
#   mujoco:  the eccentric stretch of MuJoCo's muscle, mj_step with RK4 at 5e-5 s
#            (mujoco_convergence.py --references; bench/peers/mujoco_eccentric.yaml)
#   bash bench/peers/plot_overlay.sh PEER [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
peer=${1:?usage: plot_overlay.sh opensim|mujoco [BUILD_DIR]}
build=${2:-build}
case "$peer" in
  opensim)
    reference=opensim_drop_excited scenario=opensim_drop_excited label='OpenSim 4.6'
    title="hanging mass on OpenSim's DeGrooteFregly2016Muscle, excited through its activation dynamics"
    # panels: musclesim's column, the sign taking it to the peer's, the peer's column, name, unit
    panels=("length 1 length actuator_length m" "tension_total 1 tendon_force tendon_force N"
            "activation 1 activation activation -") ;;
  mujoco)
    reference=mujoco_eccentric scenario=mujoco_eccentric label='MuJoCo 4.0, RK4'
    title="a 50 g mass pulled past MuJoCo's muscle's isometric force: an eccentric stretch"
    panels=("length 1 length actuator_length m" "shortening_velocity -1 velocity lengthening_velocity m/s"
            "tension_total -1 force force,_negative_pulling N") ;;
  *) echo "unknown peer '$peer': opensim or mujoco" >&2; exit 2 ;;
esac
command -v gnuplot >/dev/null || { echo "gnuplot is not installed: apt-get install gnuplot-nox" >&2; exit 1; }
[ -x "$build/musclesim" ] || { echo "no $build/musclesim: build musclesim first" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
figure=docs/figures/${peer}_overlay.png
"$build/musclesim" run "bench/peers/$scenario.yaml" -o "$work/musclesim.csv" 2>/dev/null
grep -v '^#' "bench/peers/reference/$reference.csv" > "$work/peer.csv"
grep -v '^#' "$work/musclesim.csv" > "$work/run.csv"
# the largest difference of each plotted quantity, relative to its largest magnitude in the peer's
python3 - "$work" "${panels[@]}" > "$work/differences.txt" <<'PY'
import csv, sys
work = sys.argv[1]
ours = list(csv.DictReader(open(f"{work}/run.csv")))
theirs = list(csv.DictReader(open(f"{work}/peer.csv")))
assert len(ours) == len(theirs), (len(ours), len(theirs))
for panel in sys.argv[2:]:
    mine, sign, peer = panel.split()[:3]
    scale = max(abs(float(r[peer])) for r in theirs)
    worst = max(abs(float(sign) * float(a[mine]) - float(b[peer])) for a, b in zip(ours, theirs))
    print(f"{worst / scale:.1e}")
PY
mapfile -t differences < "$work/differences.txt"
col() { head -1 "$1" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }
t=$(col "$work/run.csv" t)
{
  echo "set terminal pngcairo size 900,900 noenhanced font 'sans,10'"
  echo "set output '$figure'"
  echo "set datafile separator ','; set key autotitle columnhead; set grid; set key top right"
  echo "set multiplot layout 3,1 title \"$title (bench/peers/plot_overlay.sh $peer)\""
  for i in 0 1 2; do
    read -r mine sign theirs name unit <<< "${panels[$i]}"
    [ "$i" = 2 ] && echo "set xlabel 't [s]'" || echo "set xlabel ''"
    echo "set title \"${name//_/ } (largest difference ${differences[$i]} of its largest value)\"; set ylabel '${name//_/ } [$unit]'"
    echo "plot '$work/run.csv' using $t:($sign*column($(col "$work/run.csv" "$mine"))) with lines lw 2 lc 1 title 'musclesim', \\"
    echo "     '$work/peer.csv' using 1:$(col "$work/peer.csv" "$theirs") with points pt 6 ps 0.8 lc 7 title '$label'"
  done
  echo "unset multiplot"
} > "$work/plot.gp"
gnuplot "$work/plot.gp"
echo "written: $figure (largest relative differences: ${differences[*]})"
