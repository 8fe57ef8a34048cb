#!/usr/bin/env bash
# `musclesim import` of an OpenSim model holding N rigid DeGrooteFregly2016Muscles, N = 1,000
# to 10,000: wall time and time per muscle, the fastest of three runs each. Checking each
# output against the others was quadratic (10,000 muscles took over 300 s); it is linear now.
#   bench/import_scaling.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:-build}
"$cmake" -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
"$cmake" --build "$build" -j"$(nproc)" --target musclesim_cli >/dev/null

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| muscles | wall time [s] | per muscle [ms] |"
echo "|---|---|---|"
for n in 1000 2000 5000 10000; do
  "$python" - "$n" "$work/model.osim" <<'PY'
import sys
n, path = int(sys.argv[1]), sys.argv[2]
muscle = ('<DeGrooteFregly2016Muscle name="m{}"><max_isometric_force>400</max_isometric_force>'
          '<optimal_fiber_length>0.1</optimal_fiber_length><tendon_slack_length>0.05'
          '</tendon_slack_length><ignore_tendon_compliance>true</ignore_tendon_compliance>'
          '</DeGrooteFregly2016Muscle>')
with open(path, "w") as f:
    f.write('<?xml version="1.0"?>\n<OpenSimDocument Version="40600"><Model name="m">'
            '<ForceSet><objects>\n')
    f.write("\n".join(muscle.format(i) for i in range(n)))
    f.write('\n</objects></ForceSet></Model></OpenSimDocument>\n')
PY
  best=
  for _ in 1 2 3; do
    rm -rf "$work/out" && mkdir "$work/out"
    start=$(date +%s.%N)
    "$build/musclesim" import "$work/model.osim" -o "$work/out" 2>/dev/null
    end=$(date +%s.%N)
    t=$(echo "$end - $start" | bc -l)
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then best=$t; fi
  done
  printf "| %d | %.2f | %.3f |\n" "$n" "$best" "$(echo "1000 * $best / $n" | bc -l)"
done
