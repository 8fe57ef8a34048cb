#!/usr/bin/env bash
# Fuzzes the readers: builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan) in a
# build directory of their own and runs each for SECONDS (default 60), starting from the seeds
# in tests/fuzz/corpus/<reader>/. Fails if any target finds a crash, a sanitizer report, an
# exception other than InputError/ParameterError, a timeout or a memory blow-up; the inputs
# that did are kept in BUILD/findings/<reader>/.
#   scripts/fuzz.sh [SECONDS] [READER...]     readers: scenario model sweep identify
#                                             identify_series network controller sensitivity
#                                             problem import
# BUILD is build-fuzz/ beside the sources, or $MUSCLESIM_FUZZ_BUILD (CI: build-sanitize/).
set -euo pipefail

seconds=${1:-60}
shift || true
readers=("$@")
[ ${#readers[@]} -eq 0 ] && readers=(scenario model sweep identify identify_series network controller sensitivity problem import)
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "fuzz.sh: SECONDS must be a whole number >= 1, not '$seconds'" >&2
  exit 2
fi

root=$(cd "$(dirname "$0")/.." && pwd)
build=${MUSCLESIM_FUZZ_BUILD:-$root/build-fuzz}
source "$root/scripts/toolchain.sh"

# a build directory already configured for fuzzing (as `scripts/test.sh --sanitize` makes
# build-sanitize/) is used as it is: only the fuzz targets are compiled
if ! grep -qx 'MUSCLESIM_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  # --fresh: a cache made by another compiler would lose every option below
  "$cmake" --fresh -S "$root" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMUSCLESIM_FUZZ=ON -DMUSCLESIM_BUILD_TESTS=OFF \
    -DMUSCLESIM_BUILD_BENCHMARKS=OFF -DMUSCLESIM_BUILD_EXAMPLES=OFF -DMUSCLESIM_BUILD_CLI=OFF \
    >/dev/null
fi
"$cmake" --build "$build" -j2 --target "${readers[@]/#/fuzz_}"

# the fuzzers' own files (inputs written for the readers) stay in the build directory
export TMPDIR="$build/tmp"
mkdir -p "$TMPDIR"
failed=()
for reader in "${readers[@]}"; do
  corpus="$build/corpus/$reader"      # grows as the fuzzer learns; the seeds stay as they are
  findings="$build/findings/$reader/"
  mkdir -p "$corpus" "$findings"
  echo "fuzz.sh: $reader for $seconds s"
  # -timeout: one input reading for 30 s is a finding (a reader must refuse absurd sizes);
  # -rss_limit_mb: as is 2 GiB of memory
  if ! "$build/tests/fuzz/fuzz_$reader" -max_total_time="$seconds" -timeout=30 \
      -rss_limit_mb=2048 -artifact_prefix="$findings" -print_final_stats=1 \
      "$corpus" "$root/tests/fuzz/corpus/$reader" 2>"$build/fuzz_$reader.log"; then
    failed+=("$reader")
    tail -n 40 "$build/fuzz_$reader.log" >&2
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz_$reader.log" || true
  fi
done

if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: findings in: ${failed[*]} (inputs in $build/findings/)" >&2
  exit 1
fi
echo "fuzz.sh: no findings in ${readers[*]} ($seconds s each)"
