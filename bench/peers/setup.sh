#!/usr/bin/env bash
# The peers' virtual environment: OpenSim and MuJoCo from PyPI, pinned in
# bench/peers/requirements.txt, in build-peers/venv of Debian's python3 (made again only when
# the pins change). Prints the venv's python, for the scripts of bench/peers/.
#   bash bench/peers/setup.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
bash scripts/install-deps.sh >/dev/null  # python3-venv among the Debian packages
venv=build-peers/venv
if ! cmp -s bench/peers/requirements.txt "$venv/requirements.txt" 2>/dev/null; then
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  "$venv/bin/python" -m pip install -q -r bench/peers/requirements.txt
  cp bench/peers/requirements.txt "$venv/requirements.txt"
fi
echo "$PWD/$venv/bin/python"
