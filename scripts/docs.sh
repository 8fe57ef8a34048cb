#!/usr/bin/env bash
# Builds the documentation site (mkdocs.yml, docs/) into site/ with MkDocs in a virtual
# environment of its own (build-docs/venv, made once), in strict mode: a warning, a broken
# link or a broken anchor fails the build. The pages' command and code blocks are run by the
# test suite (tests/readme_commands.sh, python/tests/test_readme.py), not here.
set -euo pipefail
cd "$(dirname "$0")/.."
venv=build-docs/venv
if [ ! -x "$venv/bin/mkdocs" ]; then
  python3 -m venv "$venv"
  "$venv/bin/python" -m pip install -q "mkdocs==1.6.1"
fi
"$venv/bin/mkdocs" build --strict --clean --site-dir site
echo "docs.sh: the site is in site/ (open site/index.html)"
