#!/usr/bin/env bash
# Builds the documentation site (mkdocs.yml, docs/) into site/ with MkDocs in a virtual
# environment of its own (build-docs/venv, made again only when the pinned tools below
# change), in strict mode: a warning, a broken link or a broken anchor fails the build. The
# Python API page comes from the package's docstrings (mkdocstrings, reading python/ without
# importing it); the C++ reference is Doxygen's (Doxyfile), written into site/api/cpp/doxygen/
# afterwards, its warnings failing the build too. The pages' command and code blocks are run
# by the test suite (tests/readme_commands.sh, python/tests/test_readme.py), not here.
set -euo pipefail
cd "$(dirname "$0")/.."
# Doxygen and python3-venv are Debian packages, installed with the others when missing
bash scripts/install-deps.sh >/dev/null

# MkDocs, mkdocstrings with its Python handler, and Griffe (griffelib), the handler's loader
requirements=(mkdocs==1.6.1 mkdocstrings==1.0.8 mkdocstrings-python==2.0.11 griffelib==2.4.1)
venv=build-docs/venv
if [ "$(cat "$venv/requirements.txt" 2>/dev/null)" != "$(printf '%s\n' "${requirements[@]}")" ]; then
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/python" -m pip install -q "${requirements[@]}"
  printf '%s\n' "${requirements[@]}" >"$venv/requirements.txt"
fi

"$venv/bin/mkdocs" build --strict --clean --site-dir site
# the C++ reference, beside its page (site/api/cpp/index.html) that links to it
doxygen Doxyfile
# the page's links into it are raw HTML, which MkDocs does not check
for target in $(grep -o 'href="doxygen/[^"#]*' site/api/cpp/index.html | cut -d'"' -f2); do
  if [ ! -f "site/api/cpp/$target" ]; then
    echo "docs.sh: docs/api/cpp.md links to $target, which Doxygen did not make" >&2
    exit 1
  fi
done
echo "docs.sh: the site is in site/ (open site/index.html)"
