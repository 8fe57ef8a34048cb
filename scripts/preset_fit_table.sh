#!/usr/bin/env bash
# How well m Gaussians reproduce each standard active force-length curve: the table of README
# "The closed-form fit". For every preset and m = 2, 3, 4 it runs `musclesim fit` with
#   fit: {target: preset, name: NAME, optimal_length: 1, count: m}
# (lengths normalised, sigma = 1) and prints, as a Markdown table,
#   relative residual  the fit's relative_residual, integral((f - preset)^2) / integral(preset^2)
#   max abs error      the largest |f - preset| on 0 <= l / l_opt <= 2 at 2001 points: the
#                      fitted sum f evaluated here from the printed components, the preset
#                      from `musclesim curves --preset NAME --length 0:2:2001`
# A residual below 1e-12 or an error below 1e-6 is roundoff and the optimiser's tolerance
# (thelen2003 is one Gaussian): it prints as "< 1e-12" or "< 1e-6".
#   scripts/preset_fit_table.sh          (uses `musclesim` on PATH, or $MUSCLESIM)
set -euo pipefail

musclesim=${MUSCLESIM:-musclesim}
work=$(mktemp -d "${TMPDIR:-/tmp}/preset_fit_table.XXXXXX")
trap 'rm -rf "$work"' EXIT

echo "| preset | Gaussians | relative residual | max abs error |"
echo "|---|---|---|---|"
for preset in degroote2016 thelen2003 gordon1966 mujoco; do
  "$musclesim" curves --preset "$preset" --length 0:2:2001 -o "$work/curve.csv"
  for count in 2 3 4; do
    cat >"$work/fit.yaml" <<EOF
model:
  f_iso: 1.0
  passive: {k_p: 0.0, alpha: 1.0, slack_length: 1.0}
  active_length:
    optimal_range: [0.95, 1.05]
    fit: {target: preset, name: $preset, optimal_length: 1.0, count: $count}
  velocity: {v_max: 1.0, n: 3, epsilon: 1.0e-3}
EOF
    "$musclesim" fit "$work/fit.yaml" -o "$work/fit.out"
    # components "  - {amplitude: a, width: b, center: d}", then "relative_residual: r"
    awk -v preset="$preset" -v count="$count" '
      function show(x, bound) { return x + 0 < bound + 0 ? "< " bound : sprintf("%.3g", x) }
      BEGIN { n = 0; worst = 0 }
      FNR == NR && /amplitude:/ {
        line = $0
        gsub(/[{},]/, " ", line)
        split(line, word, " ")
        for (i = 1; i in word; i++) {
          if (word[i] == "amplitude:") a[n] = word[i + 1]
          if (word[i] == "width:") b[n] = word[i + 1]
          if (word[i] == "center:") d[n] = word[i + 1]
        }
        n++
        next
      }
      FNR == NR && /^relative_residual:/ { residual = $2; next }
      FNR == NR { next }
      FNR > 1 {
        split($0, column, ",")
        x = column[1]
        # psi_k = a_k / sqrt(2 pi sigma) exp(-b_k (x - d_k)^2 / (2 sigma)), sigma = 1
        f = 0
        for (k = 0; k < n; k++) {
          f += a[k] / sqrt(2 * 3.141592653589793) * exp(-b[k] * (x - d[k])^2 / 2)
        }
        error = f - column[3]
        if (error < 0) error = -error
        if (error > worst) worst = error
      }
      END {
        printf "| %s | %d | %s | %s |\n", preset, count, show(residual, "1e-12"),
               show(worst, "1e-6")
      }
    ' "$work/fit.out" "$work/curve.csv"
  done
done
