#!/bin/sh
# The columns the Python plotting reads (python/twb/plot/columns.json) are the columns
# twb writes: `twb columns` made from the functions that write the tables.
# Usage: python_columns_test.sh TWB COLUMNS_JSON
set -u
twb=$1
committed=$2
made=$(mktemp)
trap 'rm -f "$made"' EXIT
"$twb" columns >"$made" || { echo "twb columns failed"; exit 1; }
if ! diff -u "$committed" "$made"; then
  echo "python/twb/plot/columns.json is not what twb writes: regenerate it with"
  echo "  twb columns > python/twb/plot/columns.json"
  exit 1
fi
echo "columns.json is what twb columns writes"
