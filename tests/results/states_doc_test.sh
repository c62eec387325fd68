#!/bin/sh
# The table of states.csv's columns in docs/results.md is the one twb declares
# (twb/results/state_quantities.h): `twb columns --markdown`, between the markers.
# Usage: states_doc_test.sh TWB RESULTS_MD
set -u
twb=$1
doc=$2
made=$(mktemp)
committed=$(mktemp)
trap 'rm -f "$made" "$committed"' EXIT
"$twb" columns --markdown >"$made" || { echo "twb columns --markdown failed"; exit 1; }
sed -n '/^<!-- states columns: begin/,/^<!-- states columns: end/p' "$doc" | sed '1d;$d' >"$committed"
if [ ! -s "$committed" ]; then
  echo "no states columns table between its markers in $doc"
  exit 1
fi
if ! diff -u "$committed" "$made"; then
  echo "docs/results.md's table of states.csv is not what twb declares: replace it with"
  echo "  twb columns --markdown"
  exit 1
fi
echo "docs/results.md's states table is what twb declares"
