#!/bin/sh
# How a study's searches scale over cores and ranks, for docs/scaling.md:
#   - an even map: 8 distress searches of similar cost (8 speeds from 900 to 1040 rad/s on
#     the paper's 9 x 66 mesh, no error bar), and the same with W_d's error bar, each run
#     REPS times on 1 thread, on 2 threads and (with mpirun) on 2 MPI ranks of one
#     thread: the median wall time, the speedup over 1 thread and the efficiency
#     (speedup / 2), measured in this one run;
#   - with --design, the shipped design map (configs/studies/design_map.yaml, 200
#     searches) once on 1 thread, 2 threads and 2 ranks, with its speedups.
# Every variant's CSV files are compared with the 1-thread run's, byte for byte.
#
#   scripts/scaling_study.sh [--twb PATH] [--out DIR] [--reps N] [--design]
#
#   --twb PATH   the twb binary (default: build-rel/twb, else build/twb, else twb on PATH)
#   --out DIR    where results go (default: results/scaling)
#   --reps N     repetitions of the even map (default 3; the median is reported)
#   --design     also the 200-search design map (about 5 min on 2 cores)
#
# Writes DIR/scaling.csv (study, runner, repetition, seconds) and prints the Markdown table
# of docs/scaling.md. Exit status: 0 done; 1 a run failed or its files differ; 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
out="results/scaling"
reps=3
design=0
args=""
while [ $# -gt 0 ]; do
  case "$1" in
    --reps) reps=$2; shift 2 ;;
    --design) design=1; shift ;;
    *) args="$args $1"; shift ;;
  esac
done
. "$root/scripts/find_twb.sh"
# shellcheck disable=SC2086
study_options scaling_study.sh 12,17 $args

mpiexec=$(command -v mpirun || true)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
rm -f "$out/failed"
csv="$out/scaling.csv"
echo "study,runner,repetition,seconds" > "$csv"
status=0

launch=""  # empty, or the MPI launcher and its options
even_map() {
  $launch "$twb" run "$root/configs/jackson_green_2006.yaml" --quiet \
    --set 'study={type: distress_map, speeds: [900 rad/s, 920 rad/s, 940 rad/s, 960 rad/s, 980 rad/s, 1000 rad/s, 1020 rad/s, 1040 rad/s], load_start: 60 N, load_end: 2000 N, error_estimate: none}' "$@"
}
# The same 8 searches with W_d's error bar (each fold found again on 17 x 132): longer
# searches, as a designer runs them by default.
even_map_error_bars() {
  $launch "$twb" run "$root/configs/jackson_green_2006.yaml" --quiet \
    --set 'study={type: distress_map, speeds: [900 rad/s, 920 rad/s, 940 rad/s, 960 rad/s, 980 rad/s, 1000 rad/s, 1020 rad/s, 1040 rad/s], load_start: 60 N, load_end: 2000 N}' "$@"
}
design_map() { $launch "$twb" run "$root/configs/studies/design_map.yaml" --quiet "$@"; }

seconds() {  # seconds COMMAND...: its wall time (its output to $out/last.log)
  start=$(date +%s%N)
  if ! "$@" > "$out/last.log" 2>&1; then
    echo "scaling_study.sh: failed: $*" >&2
    cat "$out/last.log" >&2
    touch "$out/failed"
  fi
  end=$(date +%s%N)
  ms=$(( (end - start) / 1000000 ))
  printf '%d.%03d\n' $((ms / 1000)) $((ms % 1000))
}

# A CSV file without states.csv's wall_ms (a measured time, the one column not a result).
results_of() {
  awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == "wall_ms") w = k }
           { s = ""; for (k = 1; k <= NF; ++k) if (k != w) s = s "," $k; print s }' "$1"
}

same() {  # same DIR_A DIR_B: the CSVs byte for byte, wall_ms aside
  for f in $(cd "$1" && find . -name '*.csv'); do
    [ "$(results_of "$1/$f" | cksum)" = "$(results_of "$2/$f" | cksum)" ] ||
      { echo "scaling_study.sh: $2/$f differs from $1/$f" >&2; status=1; }
  done
}

measure() {  # measure STUDY REPS
  study=$1 n=$2
  for r in $(seq 1 "$n"); do
    launch=""
    t=$(seconds $study --threads 1 --out "$out/$study/threads-1"); echo "$study,1 thread,$r,$t" >> "$csv"
    t=$(seconds $study --threads 2 --out "$out/$study/threads-2"); echo "$study,2 threads,$r,$t" >> "$csv"
    same "$out/$study/threads-1" "$out/$study/threads-2"
    if [ -n "$mpiexec" ]; then
      launch="$mpiexec -np 2"
      t=$(seconds $study --out "$out/$study/ranks-2"); echo "$study,2 MPI ranks,$r,$t" >> "$csv"
      same "$out/$study/threads-1" "$out/$study/ranks-2"
    fi
  done
}

measure even_map "$reps"
measure even_map_error_bars "$reps"
[ "$design" -eq 1 ] && measure design_map 1

/usr/bin/python3 - "$csv" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| study | runner | median s (runs) | speedup | efficiency |")
print("|---|---|---|---|---|")
for study in dict.fromkeys(r["study"] for r in rows):
    times = {}
    for r in rows:
        if r["study"] == study:
            times.setdefault(r["runner"], []).append(float(r["seconds"]))
    base = statistics.median(times["1 thread"])
    for runner, t in times.items():
        m = statistics.median(t)
        workers = 1 if runner == "1 thread" else 2
        print(f"| {study} | {runner} | {m:.1f} ({len(t)}) | {base / m:.2f} | {base / m / workers:.2f} |")
PY
[ -e "$out/failed" ] && status=1
exit $status
