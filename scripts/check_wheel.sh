#!/usr/bin/env bash
# The Python package as a user installs it: builds a wheel with the standard backend
# (pyproject.toml, scikit-build-core), installs it into a fresh virtual environment of the
# machine's default python3 (or PYTHON), and runs the Python test suite there against the
# installed package and its `musclesim` command, not against a build tree.
#   scripts/check_wheel.sh            PYTHON=python3.12 scripts/check_wheel.sh
# Needs the C++ libraries of scripts/install-deps.sh; pip fetches the build tools (pinned in
# pyproject.toml) and the test's NumPy and pytest from PyPI.
set -euo pipefail
cd "$(dirname "$0")/.."
python=${PYTHON:-python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$python" -m venv "$work/venv"
venv="$work/venv/bin"
"$venv/python" -m pip install -q --upgrade pip
"$venv/python" -m pip wheel -q --no-deps -w "$work/dist" .
"$venv/python" -m pip install -q "$work"/dist/musclesim-*.whl "pytest>=7"
# outside the repository, so `import musclesim` can only find the installed package
cd "$work"
PATH="$venv:$PATH" MUSCLESIM_SOURCE_DIR="$OLDPWD" MUSCLESIM_CLI="$venv/musclesim" \
  "$venv/python" -m pytest -q -p no:cacheprovider "$OLDPWD/python/tests"
echo "check_wheel: the wheel installs and passes the Python tests in a fresh venv"
