#!/bin/sh
# What accuracy costs, in one command: runs benchmarks/work_precision for one state of
# the paper's case (meshes 5x24 ... 65x528, solver tolerances 1e-4 ... 1e-12) and for
# W_d at the paper's speeds (meshes 5x33 ... 65x528), and turns the CSVs into the
# figures and tables of benchmarks/README.md.
#
#   scripts/work_precision.sh [--build DIR] [--out DIR] [--quick]
#
#   --build DIR  a Release build tree with benchmarks/work_precision (default: build)
#   --out DIR    where the CSVs and the figures go (default: results/work_precision)
#   --quick      meshes up to 17x132 only, W_d at 545 rad/s only (seconds, for a check);
#                without it about 6 minutes and 2 GB on a 2-core machine
#
# Writes OUT/state.csv, OUT/distress.csv, OUT/work_precision_state.png and
# OUT/work_precision_distress.png, and prints the tables. Exit status: 0 done; 1 a
# step failed; 2 bad usage.
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
build="build"
out="results/work_precision"
state_meshes="5x24,5x33,9x66,17x132,33x264,65x528"
distress_meshes="5x33,9x66,17x132,33x264,65x528"
speeds="545,953,1367"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --quick) state_meshes="5x24,9x66,17x132"; distress_meshes="5x33,9x66,17x132"; speeds="545"; shift ;;
    *) sed -n '6,12p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
  esac
done
binary="$build/benchmarks/work_precision"
if [ ! -x "$binary" ]; then
  echo "work_precision.sh: no $binary; build first (cmake --build $build)" >&2
  exit 1
fi
mkdir -p "$out"
"$binary" "$out/state.csv" --meshes "$state_meshes" || exit 1
"$binary" "$out/distress.csv" --distress --meshes "$distress_meshes" --speeds "$speeds" || exit 1
/usr/bin/python3 "$root/scripts/work_precision.py" "$out/state.csv" "$out/work_precision_state.png" \
  "$out/distress.csv" "$out/work_precision_distress.png" || exit 1
