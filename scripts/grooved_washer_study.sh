#!/bin/sh
# The grooved-washer study of docs/validation.md ("Grooved washers"): the paper's washer
# with the gear sliding over it, flat and with six radial grooves, unfed and fed with oil
# at 0.5 bar, with and without the oil carrying its heat (configs/studies/grooved/), each
# a distress map at the paper's four speeds, and the fed, oil-cooled washer at 545 rad/s
# against the grooves' count, width, depth and a dam's radius; then the tables and figures
# (scripts/grooved_washer_summary.py).
#
#   scripts/grooved_washer_study.sh [--twb PATH] [--out DIR]
#
#   --twb PATH   the twb binary (default: build-rel/twb, else build/twb)
#   --out DIR    where results go (default: results/grooved)
#
# Writes DIR/<variant>/ (distress.csv, states.csv, ...), DIR/summary.csv,
# DIR/grooved_washers.png, DIR/groove_parameters.csv and DIR/groove_parameters.png.
# About 6 minutes on two cores (the four groove maps 0.5 to 2.5 each). Exit status: 0 every run
# succeeded; 1 a run or the summary failed (see DIR/<variant>.log); 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
out="results/grooved"

. "$root/scripts/find_twb.sh"
study_options grooved_washer_study.sh 8,11 "$@"

mkdir -p "$out"
status=0
for variant in flat flat_convection grooved fed fed_convection groove_count groove_width groove_depth groove_dam; do
  echo "grooved_washer_study.sh: $variant" >&2
  "$twb" run "$root/configs/studies/grooved/$variant.yaml" --quiet --out "$out/$variant" \
    > "$out/$variant.log" 2>&1 || status=1
done
/usr/bin/python3 "$root/scripts/grooved_washer_summary.py" "$out" || status=1
exit $status
