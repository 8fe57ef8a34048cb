#!/usr/bin/env bash
# Runs every command block of the README and of the documentation site's pages (docs/, every
# page but the generated reports in docs/reports/) as written, so that their examples keep
# working.
#   tests/readme_commands.sh SOURCE_DIR MUSCLESIM_BINARY [--with-mpi]
#
# What it runs: every fenced block whose info string is `sh`. Other fences (```text,
# ```yaml, ```cmake, ...) are not commands; a fence without an info string is an error, so
# that no block is left unmarked. An HTML comment on the line just above a fence changes
# what happens to that block:
#   <!-- readme-test: skip REASON -->     not run (the build and test commands themselves)
#   <!-- readme-test: needs mpi -->       run only with --with-mpi (MUSCLESIM_WITH_MPI=ON)
#   <!-- readme-test: needs gnuplot -->   run only when gnuplot is installed
#   <!-- readme-test: file NAME -->       the block is a file (e.g. ```yaml) that the README
#                                         asks the reader to save as NAME; it is written
#                                         before every block runs
#
# Each block runs on its own, with `bash -e -o pipefail`, in a fresh temporary directory
# holding a copy of scenarios/, data/, docs/ and scripts/, as if from the repository root;
# `musclesim` is the given binary, through a symlink on PATH. Nothing is written to the
# repository.
# A failing block is reported with its README line range and the line that failed.
set -euo pipefail

if [ $# -lt 2 ] || [ $# -gt 3 ] || { [ $# -eq 3 ] && [ "$3" != --with-mpi ]; }; then
  echo "usage: $0 SOURCE_DIR MUSCLESIM_BINARY [--with-mpi]" >&2
  exit 2
fi
source_dir=$(cd "$1" && pwd)
binary=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
with_mpi=no
[ $# -eq 3 ] && with_mpi=yes
# the README first, then the site's pages in a fixed order; `file NAME` blocks are shared
documents=(README.md)
while IFS= read -r page; do documents+=("$page"); done < <(
  cd "$source_dir" && find docs -name '*.md' -not -path 'docs/reports/*' | LC_ALL=C sort)
[ -x "$binary" ] || { echo "not an executable: $binary" >&2; exit 2; }

work=$(mktemp -d "${TMPDIR:-/tmp}/readme_commands.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin" "$work/files" "$work/blocks"
ln -s "$binary" "$work/bin/musclesim"

# --- split the README into blocks: blocks/N.sh (commands) or files/NAME, plus a manifest
# of "N first_line last_line needs" lines for the command blocks
manifest=$work/manifest
: >"$manifest"
count=0
errors=0
for doc in "${documents[@]}"; do
line_no=0
marker=""
marker_line=0
in_block=no
while IFS= read -r line || [ -n "$line" ]; do
  line_no=$((line_no + 1))
  if [ "$in_block" = yes ]; then
    if [[ "$line" =~ ^\`\`\`[[:space:]]*$ ]]; then
      in_block=no
      if [ "$kind" = run ]; then
        echo "$count $first $((line_no - 1)) $needs $doc" >>"$manifest"
      fi
    else
      printf '%s\n' "$line" >>"$target"
    fi
    continue
  fi
  if [[ "$line" =~ ^\<!--\ readme-test:\ (.*)\ --\>$ ]]; then
    marker=${BASH_REMATCH[1]}
    marker_line=$line_no
    continue
  fi
  if [[ "$line" =~ ^\`\`\`(.*)$ ]]; then
    info=${BASH_REMATCH[1]}
    in_block=yes
    first=$((line_no + 1))
    kind=ignore
    needs=none
    target=/dev/null
    case "$marker" in
      "") ;;
      skip | "skip "*) info=skipped ;;
      "needs mpi") needs=mpi ;;
      "needs gnuplot") needs=gnuplot ;;
      file\ *)
        name=${marker#file }
        if [[ ! "$name" =~ ^[A-Za-z0-9_.-]+$ ]]; then
          echo "$doc:$marker_line: bad file name in marker: $name" >&2
          errors=$((errors + 1))
        else
          target=$work/files/$name
          : >"$target"
        fi
        info=file ;;
      *)
        echo "$doc:$marker_line: unknown marker: $marker" >&2
        errors=$((errors + 1)) ;;
    esac
    marker=""
    case "$info" in
      "")
        echo "$doc:$line_no: a fence without an info string (sh to run it, text if not)" >&2
        errors=$((errors + 1)) ;;
      sh)
        count=$((count + 1))
        kind=run
        target=$work/blocks/$count.sh
        : >"$target" ;;
    esac
    continue
  fi
  # a marker applies to the fence right below it and to nothing else
  if [ -n "$marker" ]; then
    echo "$doc:$marker_line: marker not followed by a fence" >&2
    errors=$((errors + 1))
    marker=""
  fi
done <"$source_dir/$doc"
if [ "$in_block" = yes ]; then
  echo "$doc:$((first - 1)): a fence that is never closed" >&2
  errors=$((errors + 1))
fi
done
[ "$errors" -eq 0 ] || exit 1
[ "$count" -gt 0 ] || { echo "no sh block found" >&2; exit 1; }

have_gnuplot=no
command -v gnuplot >/dev/null && have_gnuplot=yes

# --- run each command block in its own directory
failed=0
ran=0
while read -r n from to needs doc; do
  where="$doc lines $from-$to (sh block $n)"
  if [ "$needs" = mpi ] && [ "$with_mpi" = no ]; then
    echo "skipped  $where: needs MPI (MUSCLESIM_WITH_MPI=OFF)"
    continue
  fi
  if [ "$needs" = gnuplot ] && [ "$have_gnuplot" = no ]; then
    echo "skipped  $where: needs gnuplot, not installed"
    continue
  fi
  dir=$work/run$n
  mkdir "$dir"
  cp -R "$source_dir/scenarios" "$source_dir/data" "$source_dir/docs" "$source_dir/scripts" "$dir/"
  cp -R "$work/files/." "$dir/"
  # the block's first line is line 2 of the script, so README line = from + LINENO - 2
  {
    echo 'trap '\''echo "$LINENO" >"$README_TEST_FAILED_AT"'\'' ERR'
    cat "$work/blocks/$n.sh"
  } >"$work/blocks/$n.run"
  start=$SECONDS
  if (cd "$dir" && PATH="$work/bin:$PATH" README_TEST_FAILED_AT="$work/failed_at" \
        timeout 300 bash -e -o pipefail "$work/blocks/$n.run") </dev/null >"$work/log" 2>&1; then
    echo "ok       $where ($((SECONDS - start)) s)"
    ran=$((ran + 1))
  else
    status=$?
    failed=$((failed + 1))
    if [ -s "$work/failed_at" ]; then
      at=$(($(cat "$work/failed_at") + from - 2))
      echo "FAILED   $where: line $at exited with $status:"
      echo "    $(sed -n "${at}p" "$source_dir/$doc")"
    else
      echo "FAILED   $where: exited with $status (timed out or killed)"
    fi
    sed 's/^/    | /' "$work/log" | tail -n 20
  fi
  rm -f "$work/failed_at"
done <"$manifest"

echo "README and site command blocks: $ran ran, $failed failed, $((count - ran - failed)) skipped"
[ "$failed" -eq 0 ]
