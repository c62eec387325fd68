#!/bin/sh
# The path-dependence study of docs/validation.md ("Path dependence"): the paper's washer
# brought to one operating point, 175 N at 545 rad/s, by four duty cycles
# (configs/studies/path_dependence/): the speed first or the load first, and through a
# brief or a long overload past W_d; then the table and the figure of where each ended
# (scripts/path_dependence_summary.py).
#
#   scripts/path_dependence_study.sh [--twb PATH] [--out DIR]
#
#   --twb PATH   the twb binary (default: build-rel/twb, else build/twb)
#   --out DIR    where results go (default: results/path_dependence)
#
# Writes DIR/<path>/ (trajectory.csv, cycle_events.csv, ...), DIR/summary.csv and
# DIR/path_dependence.png. About 30 seconds. Exit status: 0 every run succeeded; 1 a run
# or the summary failed (see DIR/<path>.log); 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
out="results/path_dependence"

. "$root/scripts/find_twb.sh"
study_options path_dependence_study.sh 8,11 "$@"

mkdir -p "$out"
status=0
for path in speed_first load_first brief_overload long_overload; do
  echo "path_dependence_study.sh: $path" >&2
  "$twb" run "$root/configs/studies/path_dependence/$path.yaml" --quiet --out "$out/$path" \
    > "$out/$path.log" 2>&1 || status=1
done
/usr/bin/python3 "$root/scripts/path_dependence_summary.py" "$out" || status=1
exit $status
