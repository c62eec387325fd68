#!/bin/sh
# A table a doc shows between its markers ("<!-- NAME: begin" and "<!-- NAME: end") is
# the one twb prints: the doc cannot drift from what the code declares.
# Usage: doc_table_test.sh DOC NAME TWB ARGS...  (e.g. docs/results.md "states columns"
# twb columns --markdown)
set -u
doc=$1
name=$2
shift 2
made=$(mktemp)
committed=$(mktemp)
trap 'rm -f "$made" "$committed"' EXIT
"$@" >"$made" || { echo "$* failed"; exit 1; }
sed -n "/^<!-- $name: begin/,/^<!-- $name: end/p" "$doc" | sed '1d;$d' >"$committed"
if [ ! -s "$committed" ]; then
  echo "no table '$name' between its markers in $doc"
  exit 1
fi
if ! diff -u "$committed" "$made"; then
  echo "$doc's table '$name' is not what twb declares: replace it with the output of"
  echo "  $*"
  exit 1
fi
echo "$doc's table '$name' is what twb declares"
