#!/bin/sh
# What accuracy costs, in one command: runs benchmarks/work_precision (one state of the
# paper's case on meshes 5x24 ... 65x528 at solver tolerances 1e-4 ... 1e-12) and turns
# its CSV into the figure and tables of benchmarks/README.md.
#
#   scripts/work_precision.sh [--build DIR] [--out DIR] [--meshes LIST]
#
#   --build DIR    a Release build tree with benchmarks/work_precision (default: build)
#   --out DIR      where the CSV and the figure go (default: results/work_precision)
#   --meshes LIST  e.g. 5x24,9x66,17x132 for a quick look (default: up to 65x528,
#                  about 8 minutes and 1.5 GB on a 2-core machine)
#
# Writes OUT/state.csv and OUT/work_precision_state.png, and prints the tables. Exit
# status: 0 done; 1 a step failed; 2 bad usage.
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
build="build"
out="results/work_precision"
meshes=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --meshes) meshes="$2"; shift 2 ;;
    *) sed -n '5,11p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
  esac
done
binary="$build/benchmarks/work_precision"
if [ ! -x "$binary" ]; then
  echo "work_precision.sh: no $binary; build first (cmake --build $build)" >&2
  exit 1
fi
mkdir -p "$out"
if [ -n "$meshes" ]; then
  "$binary" "$out/state.csv" --meshes "$meshes" || exit 1
else
  "$binary" "$out/state.csv" || exit 1
fi
/usr/bin/python3 "$root/scripts/work_precision.py" "$out/state.csv" "$out/work_precision_state.png" || exit 1
