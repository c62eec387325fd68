#!/bin/sh
# The wear-in study of docs/validation.md ("Wear-in: what running in does to the failure
# load"): the paper's washer with wear (configs/studies/life.yaml: 545 rad/s, 150 N, k =
# 1.4e-17 m^3/(N m) on both faces) run in for 2000 h at each of six gear tilts, each life
# searching the failure load (every criterion) new and worn on 9x66; then at the paper's
# tilt (2 mrad) the distress load with its error bar, new and worn (a load sweep of
# configs/effects/wear.yaml, --continue-from that life).
#
#   scripts/wear_in_study.sh [--twb PATH] [--out DIR]
#
#   --twb PATH   the twb binary (default: build-rel/twb, else build/twb)
#   --out DIR    where results go (default: results/wear_in)
#
# Writes DIR/life_<tilt>/ (life.csv, worn_profile.csv, ...), DIR/new_sweep/,
# DIR/worn_sweep/ and DIR/summary.csv (tilt, W_fail new and worn and their criteria, the
# deepest depth of each face). About a minute on one core. Exit status: 0 every run
# succeeded; 1 a run failed (see DIR/<run>.log); 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
out="results/wear_in"

. "$root/scripts/find_twb.sh"
study_options wear_in_study.sh 9,12 "$@"

mkdir -p "$out"
status=0
summary="$out/summary.csv"
echo "tilt_mrad,W_fail_new_N,criterion_new,W_fail_worn_N,criterion_worn,worn_rest_um,worn_turn_um" > "$summary"
for tilt in 0.25 0.5 1 2 4 8; do
  echo "wear_in_study.sh: life at $tilt mrad" >&2
  run="$out/life_$tilt"
  "$twb" run "$root/configs/studies/life.yaml" --quiet --out "$run" --set "geometry.gear.tilt=$tilt mrad" \
    --set "study.report_every=2000 h" > "$out/life_$tilt.log" 2>&1 || status=1
  # life.csv: t_h, rest max, ..., turn max (5th), ..., W_fail_N (15th), failure_criterion (16th)
  awk -F, -v tilt="$tilt" 'NR == 2 { wn = $15; cn = $16 } NR > 2 { ww = $15; cw = $16; r = $2; t = $5 }
    END { printf "%s,%s,%s,%s,%s,%s,%s\n", tilt, wn, cn, ww, cw, r, t }' "$run/life.csv" >> "$summary" || status=1
done
echo "wear_in_study.sh: the distress load new and worn in at 2 mrad" >&2
"$twb" run "$root/configs/effects/wear.yaml" --quiet --out "$out/new_sweep" > "$out/new_sweep.log" 2>&1 || status=1
"$twb" run "$root/configs/effects/wear.yaml" --quiet --out "$out/worn_sweep" --continue-from "$out/life_2" \
  > "$out/worn_sweep.log" 2>&1 || status=1
cat "$summary"
exit $status
