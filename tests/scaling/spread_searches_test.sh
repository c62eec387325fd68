#!/bin/sh
# A study's searches spread over threads, MPI ranks and the slices of a job array give the
# files of one run on one thread, byte for byte (docs/scaling.md): a small map (coarse
# mesh, 4 speeds x 2 friction coefficients = 8 searches) run
#   - on 1 thread, and on 2 threads;
#   - in 3 slices (twb run --slice K/3), then twb merge;
#   - under mpirun -np 2 (when MPIEXEC is given);
#   - under mpirun -np 2 --resume on a results directory whose journal holds slice 1 of 2
#     (rank 0 reads those searches, the ranks share the others).
# And a reliability study's Monte Carlo samples (coarse mesh, two batches of 50) under
# mpirun -np 2 give the files and the summary of one thread, and both ranks hold the same
# states after each batch (the second batch starts from the states the first found, which
# the ranks share); --slice refuses it, saying why.
# run.json holds timings and is not compared; every CSV is, but for states.csv's wall_ms.
#
#   spread_searches_test.sh TWB SOURCE_DIR WORK_DIR [MPIEXEC]
set -eu
twb=$1
source=$2
work=$3
mpiexec=${4:-}
rm -rf "$work"
mkdir -p "$work"

scene=$source/configs/jackson_green_2006.yaml
run() {
  "$twb" run "$scene" --quiet \
    --set mesh.radial_nodes=5 --set mesh.circumferential_nodes=24 \
    --set 'friction={law: constant, coefficient: 0.1}' \
    --set 'study={type: distress_map, speeds: [400 rad/s, 545 rad/s, 700 rad/s, 953 rad/s], load_start: 60 N, load_end: 900 N, error_estimate: none, parameter: {name: friction_coefficient, values: [0.08, 0.12]}}' \
    "$@" > /dev/null
}

# A CSV file without its wall_ms column (a state's measured time, the one column that is
# not a result).
results_of() {
  awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == "wall_ms") w = k }
           { line = ""; for (k = 1; k <= NF; ++k) if (k != w) line = line (line == "" && k == 1 ? "" : ",") $k; print line }' "$1"
}

same_files() {  # the CSV files of two results directories, byte for byte (wall_ms aside)
  a=$1 b=$2
  list_a=$(cd "$a" && find . -name '*.csv' | sort)
  list_b=$(cd "$b" && find . -name '*.csv' | sort)
  if [ "$list_a" != "$list_b" ]; then echo "different files: $a: $list_a; $b: $list_b"; exit 1; fi
  for f in $list_a; do
    results_of "$a/$f" > "$work/a.csv"
    results_of "$b/$f" > "$work/b.csv"
    cmp "$work/a.csv" "$work/b.csv" || { echo "$b/$f differs from $a/$f"; exit 1; }
  done
}

run --threads 1 --out "$work/one-thread"
rows=$(($(wc -l < "$work/one-thread/distress.csv") - 1))
[ "$rows" -eq 8 ] || { echo "expected 8 distress rows, found $rows"; exit 1; }

run --threads 2 --out "$work/two-threads"
same_files "$work/one-thread" "$work/two-threads"
echo "2 threads: the same files"

for k in 1 2 3; do run --threads 1 --slice "$k/3" --out "$work/slice-$k"; done
[ ! -e "$work/slice-1/distress.csv" ] || { echo "a slice wrote the study's files"; exit 1; }
# A merge with a slice missing names what is missing and writes nothing.
if "$twb" merge --out "$work/incomplete" "$work/slice-1" "$work/slice-2" 2> "$work/incomplete.err"; then
  echo "merge of 2 of 3 slices succeeded"; exit 1
fi
grep -q "in none of the slices' journals" "$work/incomplete.err" || { cat "$work/incomplete.err"; exit 1; }
"$twb" merge --quiet --out "$work/merged" "$work/slice-1" "$work/slice-2" "$work/slice-3" > /dev/null
same_files "$work/one-thread" "$work/merged"
echo "3 slices merged: the same files"

reliability() {
  "$twb" run "$source/configs/studies/reliability.yaml" \
    --set mesh.radial_nodes=5 --set mesh.circumferential_nodes=24 \
    --set 'study.monte_carlo={max_samples: 100}' --set 'study.probabilities=[]' "$@" 2> /dev/null
}
reliability --threads 1 --out "$work/reliability-one" | grep '^reliability' > "$work/reliability-one.txt"
grep -q 'told by their state' "$work/reliability-one.txt" || { cat "$work/reliability-one.txt"; exit 1; }
if "$twb" run "$source/configs/studies/reliability.yaml" --slice 1/2 --out "$work/reliability-slice" \
  2> "$work/reliability-slice.err"; then
  echo "a slice of a reliability study ran"; exit 1
fi
grep -q "cannot share out a reliability study" "$work/reliability-slice.err" || { cat "$work/reliability-slice.err"; exit 1; }

if [ -n "$mpiexec" ]; then
  # Open MPI refuses root unless told; CI runs as root.
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  mpi() { "$mpiexec" -np 2 --oversubscribe "$@"; }
  twb_run_mpi() {
    mpi "$twb" run "$scene" --quiet \
      --set mesh.radial_nodes=5 --set mesh.circumferential_nodes=24 \
      --set 'friction={law: constant, coefficient: 0.1}' \
      --set 'study={type: distress_map, speeds: [400 rad/s, 545 rad/s, 700 rad/s, 953 rad/s], load_start: 60 N, load_end: 900 N, error_estimate: none, parameter: {name: friction_coefficient, values: [0.08, 0.12]}}' \
      "$@" > /dev/null
  }
  twb_run_mpi --out "$work/two-ranks"
  same_files "$work/one-thread" "$work/two-ranks"
  echo "2 MPI ranks: the same files"

  run --threads 1 --slice 1/2 --out "$work/resumed"
  twb_run_mpi --resume --out "$work/resumed"
  same_files "$work/one-thread" "$work/resumed"
  echo "2 MPI ranks resuming half a journal: the same files"

  mpi "$twb" run "$source/configs/studies/reliability.yaml" \
    --set mesh.radial_nodes=5 --set mesh.circumferential_nodes=24 \
    --set 'study.monte_carlo={max_samples: 100}' --set 'study.probabilities=[]' --out "$work/reliability-ranks" \
    --verbose 2> "$work/reliability-ranks.err" | grep '^reliability' > "$work/reliability-ranks.txt"
  same_files "$work/reliability-one" "$work/reliability-ranks"
  cmp "$work/reliability-one.txt" "$work/reliability-ranks.txt" || {
    diff "$work/reliability-one.txt" "$work/reliability-ranks.txt"; exit 1; }
  # After each batch both ranks hold the same states (their progress lines say how many).
  grep '^reliability: .* states held' "$work/reliability-ranks.err" > "$work/held-rank-0.txt" || true
  grep '^twb\[rank 1\]: reliability: .* states held' "$work/reliability-ranks.err" | sed 's/^twb\[rank 1\]: //' \
    > "$work/held-rank-1.txt" || true
  [ "$(wc -l < "$work/held-rank-0.txt")" -eq 2 ] || { cat "$work/reliability-ranks.err"; exit 1; }
  cmp "$work/held-rank-0.txt" "$work/held-rank-1.txt" || {
    diff "$work/held-rank-0.txt" "$work/held-rank-1.txt"; exit 1; }
  echo "a reliability study's samples on 2 MPI ranks: the same files and summary"
fi
