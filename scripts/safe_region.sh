#!/bin/sh
# A designer's safe operating region in one command: runs a distress-curve scene (W_d as
# a curve in speed, one curve per value of a second parameter, each with its cusp) and
# draws it with scripts/twb_plot.py (docs/figures.md, fold_curve).
#
#   scripts/safe_region.sh [--twb PATH] [--scene FILE] [--out DIR] [--rpm] [--format LIST] [--set path=value ...]
#
#   --twb PATH     the twb binary (default: build-rel/twb, else build/twb)
#   --scene FILE   a distress_curve scene (default: configs/studies/safe_region_friction.yaml)
#   --out DIR      results and figures (default: results/safe_region)
#   --rpm          speeds in rpm on the figures
#   --format LIST  figure formats for twb_plot.py (default: png,svg)
#   --set ...      passed to twb run, e.g. --set 'study.family.values=[0.1, 0.3]'
#
# Writes DIR/ (fold_curve.csv, distress.csv, ...) and DIR/figures/fold_curve.{png,svg}.
# Exit status: 0 done; 1 twb or the plot failed (see DIR/twb.log); 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
scene="$root/configs/studies/safe_region_friction.yaml"
out="results/safe_region"
rpm=""
format="png,svg"

usage() {
  sed -n '6,14p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

overrides=""
while [ $# -gt 0 ]; do
  case "$1" in
    --twb) [ $# -ge 2 ] || usage; twb=$2; shift 2 ;;
    --scene) [ $# -ge 2 ] || usage; scene=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    --format) [ $# -ge 2 ] || usage; format=$2; shift 2 ;;
    --rpm) rpm="--rpm"; shift ;;
    --set) [ $# -ge 2 ] || usage; overrides="$overrides$(printf '%s\n' "$2")
"; shift 2 ;;
    -h|--help) usage ;;
    *) echo "safe_region.sh: unknown argument '$1'" >&2; usage ;;
  esac
done

. "$root/scripts/find_twb.sh"
find_twb safe_region.sh

# The overrides, one per line, back into arguments.
set --
old_ifs=$IFS
IFS='
'
for o in $overrides; do set -- "$@" --set "$o"; done
IFS=$old_ifs

mkdir -p "$out" || exit 2
echo "safe_region.sh: running $scene (progress in $out/twb.log)" >&2
if ! "$twb" run "$scene" --out "$out" "$@" > "$out/twb.log" 2>&1; then
  echo "safe_region.sh: twb failed; see $out/twb.log" >&2
  exit 1
fi
grep '^fold curve' "$out/twb.log" >&2
python=/usr/bin/python3
[ -x "$python" ] || python=python3
if ! "$python" "$root/scripts/twb_plot.py" "$out" --out "$out/figures" --format "$format" $rpm > /dev/null; then
  echo "safe_region.sh: the plot failed" >&2
  exit 1
fi
echo "$out/figures/fold_curve.${format%%,*}"
