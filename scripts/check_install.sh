#!/usr/bin/env bash
# Installs a built musclesim into a temporary prefix and builds the examples against it as
# an outside project would (find_package(musclesim)), then runs them:
#   examples/              the whole library (musclesim::musclesim)
#   examples/model_curves  the model layer alone, configured with SUNDIALS and yaml-cpp
#                          made unfindable, and linked without them
#   scripts/check_install.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/toolchain.sh
build=${1:?usage: scripts/check_install.sh BUILD_DIR}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$cmake" --install "$build" --prefix "$work/prefix" > /dev/null
# only public headers are installed: none of the private ones in src/
for private in $(cd src && find . -name '*.h' -printf '%f\n'); do
  if find "$work/prefix/include" -name "$private" | grep -q .; then
    echo "check_install: the private header $private was installed" >&2
    exit 1
  fi
done

# the exported interface names real targets only (no empty $<LINK_ONLY:>)
if grep -q 'LINK_ONLY:>' "$work"/prefix/lib*/cmake/musclesim/*.cmake; then
  echo "check_install: an empty \$<LINK_ONLY:> in the exported targets" >&2
  exit 1
fi

"$cmake" -S examples -B "$work/examples" -DCMAKE_PREFIX_PATH="$work/prefix" > /dev/null
"$cmake" --build "$work/examples" -j"$(nproc)" > /dev/null
"$work/examples/isotonic_in_code" > /dev/null
"$work/examples/scenario_in_code" scenarios/concentric.yaml > /dev/null

"$cmake" -S examples/model_curves -B "$work/model" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_DISABLE_FIND_PACKAGE_SUNDIALS=ON -DCMAKE_DISABLE_FIND_PACKAGE_yaml-cpp=ON --no-warn-unused-cli > /dev/null
"$cmake" --build "$work/model" > /dev/null
"$work/model/model_curves" > /dev/null
link=$(cat "$work/model/CMakeFiles/model_curves.dir/link.txt")
if grep -qiE 'sundials|yaml' <<< "$link"; then
  echo "check_install: the model-only consumer links more than the model layer: $link" >&2
  exit 1
fi
python_note=""
package_dir=$(sed -n 's/^MUSCLESIM_PYTHON_INSTALL_DIR:[A-Z]*=//p' "$build/CMakeCache.txt")
if grep -q '^MUSCLESIM_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
  # the installed Python package imports from the prefix, away from the build tree
  python=$(sed -n 's/^PYTHON_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")
  (cd "$work" && PYTHONPATH="$work/prefix/$package_dir" "$python" -c \
    'import musclesim, sys; sys.exit(0 if "prefix" in musclesim.__file__ else 1)')
  python_note="; the Python package imports from $package_dir"
fi
echo "check_install: installed package OK (whole library; model layer alone without SUNDIALS or yaml-cpp$python_note)"
