#!/usr/bin/env bash
# The Python package as a user installs it: builds a wheel with the standard backend
# (pyproject.toml, scikit-build-core), installs it into a fresh virtual environment of the
# machine's default python3 (or PYTHON), and runs the Python test suite there against the
# installed package and its `musclesim` command, not against a build tree.
#   scripts/check_wheel.sh            PYTHON=python3.12 scripts/check_wheel.sh
# Needs the C++ libraries of scripts/install-deps.sh; pip fetches the build tools (pinned in
# pyproject.toml) and the test environment's packages (pinned below) from PyPI.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
python=${PYTHON:-python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$python" -m venv "$work/venv"
venv="$work/venv/bin"
"$venv/python" -m pip install -q --upgrade pip
# in build-wheel/, beside build/, with its generator (make compiles from each folder of the
# build tree, ninja from its top: the relative paths ccache compares would differ), its
# compilers by the names CMake gives build/ (ccache tells c++ from g++) and its warnings
# flags, so that ccache (where installed) serves the objects the two builds share rather
# than compiling them again
settings=(-C build-dir=build-wheel -C cmake.define.MUSCLESIM_WARNINGS_AS_ERRORS=ON
          -C cmake.define.CMAKE_C_COMPILER=cc -C cmake.define.CMAKE_CXX_COMPILER=c++)
export CMAKE_GENERATOR="Unix Makefiles" CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}
if command -v ccache >/dev/null; then
  export CCACHE_BASEDIR=$PWD
  settings+=(-C cmake.define.CMAKE_C_COMPILER_LAUNCHER=ccache
             -C cmake.define.CMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# Debian's CMake first on the PATH, as scripts/test.sh uses: scikit-build-core then takes it
# (rather than fetching one), and the compile lines match build/'s to the argument
PATH="/usr/bin:$PATH" "$venv/python" -m pip wheel -q --no-deps "${settings[@]}" -w "$work/dist" .
wheel=$(echo "$work"/dist/musclesim-*.whl)
# the package with its extras, the test tools, and NumPy, pinned: the versions it is tested with
"$venv/python" -m pip install -q "$wheel[plot,pandas,test]" "numpy==2.4.6" "matplotlib==3.11.2" \
  "pandas==3.1.1" "pytest==9.2.0" "mypy==2.4.1"
# outside the repository, so `import musclesim` can only find the installed package
cd "$work"
PATH="$venv:$PATH" MUSCLESIM_SOURCE_DIR="$OLDPWD" MUSCLESIM_CLI="$venv/musclesim" \
  "$venv/python" -m pytest -q -p no:cacheprovider "$OLDPWD/python/tests"
# mypy --strict on the Python examples of the README and the documentation site
MUSCLESIM_SOURCE_DIR="$OLDPWD" "$venv/python" "$OLDPWD/python/tests/typecheck_examples.py"
echo "check_wheel: the wheel installs, passes the Python tests and types its examples in a fresh venv"
