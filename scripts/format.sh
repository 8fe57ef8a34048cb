#!/usr/bin/env bash
# Lays out every C++ file under version control as .clang-format says (Google's style, 100
# columns), with Debian's clang-format-14 so that every machine formats alike.
#   scripts/format.sh           rewrite the files in place
#   scripts/format.sh --check   change nothing; list the files that differ and exit 1 (CI)
set -euo pipefail
cd "$(dirname "$0")/.."

formatter=clang-format-14
if ! command -v "$formatter" >/dev/null; then
  echo "format: $formatter is missing: scripts/install-deps.sh installs it" >&2
  exit 2
fi

mapfile -t files < <(git ls-files '*.cc' '*.h')
if [ "${1:-}" = "--check" ]; then
  differing=()
  for f in "${files[@]}"; do
    if ! "$formatter" --style=file "$f" | cmp -s - "$f"; then differing+=("$f"); fi
  done
  if [ ${#differing[@]} -gt 0 ]; then
    echo "format: ${#differing[@]} file(s) differ from .clang-format's layout" \
         "(scripts/format.sh rewrites them):" >&2
    printf '  %s\n' "${differing[@]}" >&2
    exit 1
  fi
  echo "format: ${#files[@]} files laid out as .clang-format says"
else
  "$formatter" --style=file -i "${files[@]}"
fi
