#!/usr/bin/env bash
# Installs what is missing, builds everything with warnings as errors and runs the whole
# test suite with ctest (which also runs the examples/ programs), then builds the examples
# against the installed package.
#   scripts/test.sh              Release build with MPI in build/ (tests run mpirun -n 2)
#   scripts/test.sh --sanitize   Debug build with AddressSanitizer + UBSan in build-sanitize/
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
source scripts/toolchain.sh

case "${1:-}" in
  "") dir=build; options=(-DMUSCLESIM_WITH_MPI=ON) ;;
  --sanitize)
    # clang, with libFuzzer's coverage as well (MUSCLESIM_FUZZ): the same objects serve
    # scripts/fuzz.sh's targets, which then compile only themselves. The Python module stays
    # out: an ASan-built extension cannot load into an uninstrumented interpreter
    dir=build-sanitize
    options=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug
             -DMUSCLESIM_SANITIZE=ON -DMUSCLESIM_FUZZ=ON -DMUSCLESIM_BUILD_BENCHMARKS=OFF
             -DMUSCLESIM_PYTHON=OFF -DMUSCLESIM_BUILD_CLI=ON -DMUSCLESIM_BUILD_EXAMPLES=ON)
    # a directory configured before with another compiler (GCC, as this build once was):
    # CMake would drop its cache and every option with it, so it starts afresh
    if [ -f "$dir/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' "$dir/CMakeCache.txt"; then
      options+=(--fresh)
    fi ;;
  *) echo "usage: scripts/test.sh [--sanitize]" >&2; exit 2 ;;
esac

jobs=$(nproc)
"$cmake" -S . -B "$dir" -DMUSCLESIM_WARNINGS_AS_ERRORS=ON -DMUSCLESIM_BUILD_TESTS=ON \
  -DPYTHON_EXECUTABLE="$python" "${launcher[@]}" "${options[@]}"
"$cmake" --build "$dir" -j"$jobs"
"$ctest" --test-dir "$dir" --output-on-failure -j"$jobs"
# the installed package, used from outside as find_package(musclesim) (Release build only)
if [ "$dir" = build ]; then bash scripts/check_install.sh "$dir"; fi
