#!/bin/sh
# The wear-in study of docs/validation.md ("Wear-in: what running in does to the failure
# load"): the paper's washer with wear (configs/studies/life.yaml: 545 rad/s, k = 1.4e-17
# m^3/(N m) on both faces) new, its failure load (every criterion) against the gear's tilt
# (a distress map of configs/effects/wear.yaml); then at each tilt run in for 2000 h at
# three quarters of that failure load, each life searching the failure load again when
# worn; then at the paper's tilt (2 mrad, run in at the scene's 150 N) the distress load
# with its error bar, new and worn (load sweeps, --continue-from that life); then the
# Stribeck curve at 545 rad/s (load sweeps in 2-N steps) new, after that life, after the
# same life with the sliding faces running in to 0.2 um (surfaces.<body>.run_in_rq), and of
# washers whose faces have run in everywhere (a new washer of Rq 0.3, 0.2 and 0.1 um with
# the summits scaled as running-in scales them: R by Rq new/Rq, sigma_s with Rq).
#
#   scripts/wear_in_study.sh [--twb PATH] [--out DIR]
#
#   --twb PATH   the twb binary (default: build-rel/twb, else build/twb)
#   --out DIR    where results go (default: results/wear_in)
#
# Writes DIR/new_map/, DIR/life_<tilt>/ (life.csv, worn_profile.csv, ...), DIR/life_paper/,
# DIR/new_sweep/, DIR/worn_sweep/, DIR/summary.csv (tilt, the load run in at, W_fail new
# and worn and their criteria, each face's deepest depth), DIR/stribeck_<case>/ and
# DIR/stribeck.csv (case, the cool branch's least f_eff, its load, Z*N/P and h_min/sigma, and
# the last cool load, W_d to the 2-N step) with its figure DIR/wear_in_stribeck.png.
# About four minutes on one core.
# Exit status: 0 every run succeeded; 1 a run failed (see DIR/<run>.log); 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
out="results/wear_in"

. "$root/scripts/find_twb.sh"
study_options wear_in_study.sh 10,13 "$@"

mkdir -p "$out"
status=0
tilts="0.25 0.5 1 2 4 8"
echo "wear_in_study.sh: the new washer's failure load against the tilt" >&2
"$twb" run "$root/configs/effects/wear.yaml" --quiet --out "$out/new_map" \
  --set "study={type: distress_map, speeds: [545 rad/s], load_start: 10 N, load_end: 2000 N, error_estimate: none,
         parameter: {name: geometry.gear.tilt, values: [$(echo $tilts | sed 's/ / mrad, /g') mrad]}}" \
  > "$out/new_map.log" 2>&1 || status=1
summary="$out/summary.csv"
echo "tilt_mrad,load_N,W_fail_new_N,criterion_new,W_fail_worn_N,criterion_worn,worn_rest_um,worn_turn_um" > "$summary"
for tilt in $tilts; do
  # distress.csv: speed, the tilt (rad), W_fail_N, criterion, ...
  load=$(awk -F, -v t="$tilt" 'NR > 1 && sprintf("%.6g", 1000 * $2) == sprintf("%.6g", t) { printf "%.4g", 0.75 * $3 }' \
    "$out/new_map/distress.csv")
  [ -n "$load" ] || { status=1; continue; }
  echo "wear_in_study.sh: life at $tilt mrad, $load N" >&2
  run="$out/life_$tilt"
  "$twb" run "$root/configs/studies/life.yaml" --quiet --out "$run" --set "geometry.gear.tilt=$tilt mrad" \
    --set "operating.load=$load N" --set "study.report_every=2000 h" > "$out/life_$tilt.log" 2>&1 || status=1
  # life.csv's columns by their names (docs/results.md): the first row is the new washer's
  awk -F, -v tilt="$tilt" -v load="$load" 'NR == 1 { for (k = 1; k <= NF; ++k) at[$k] = k; next }
    { w = $(at["W_fail_N"]); c = $(at["failure_criterion"]) }
    NR == 2 { wn = w; cn = c } NR > 2 { ww = w; cw = c; r = $(at["worn_depth_rest_max_um"]); t = $(at["worn_depth_turn_max_um"]) }
    END { printf "%s,%s,%s,%s,%s,%s,%s,%s\n", tilt, load, wn, cn, ww, cw, r, t }' "$run/life.csv" >> "$summary" \
    || status=1
done
echo "wear_in_study.sh: the distress load new and run in at 150 N, 2 mrad" >&2
"$twb" run "$root/configs/studies/life.yaml" --quiet --out "$out/life_paper" > "$out/life_paper.log" 2>&1 || status=1
"$twb" run "$root/configs/effects/wear.yaml" --quiet --out "$out/new_sweep" > "$out/new_sweep.log" 2>&1 || status=1
"$twb" run "$root/configs/effects/wear.yaml" --quiet --out "$out/worn_sweep" --continue-from "$out/life_paper" \
  > "$out/worn_sweep.log" 2>&1 || status=1
echo "wear_in_study.sh: the Stribeck curve new, worn and run in" >&2
"$twb" run "$root/configs/studies/life.yaml" --quiet --out "$out/life_run_in" --set "surfaces.carrier.run_in_rq=0.2 um" \
  --set "surfaces.washer.run_in_rq=0.2 um" > "$out/life_run_in.log" 2>&1 || status=1
stribeck="study={type: load_sweep, load_start: 100 N, load_end: 600 N, load_steps: 251, error_estimate: none}"
stribeck_run() {  # case, then twb's options
  case_name=$1
  shift
  "$twb" run "$root/configs/effects/wear.yaml" --quiet --out "$out/stribeck_$case_name" --set "$stribeck" "$@" \
    > "$out/stribeck_$case_name.log" 2>&1 || status=1
}
stribeck_run new
stribeck_run worn --continue-from "$out/life_paper"
stribeck_run worn_run_in --continue-from "$out/life_run_in" --set "surfaces.carrier.run_in_rq=0.2 um" \
  --set "surfaces.washer.run_in_rq=0.2 um"
for rq in 0.3 0.2 0.1; do
  # Ra of a Gaussian face, 0.798 Rq; the summit radius 20 um over Rq/Rq new
  faces="{Ra: $(awk -v q=$rq 'BEGIN { print 0.798 * q }') um, Rq: $rq um, wear_rate: 1.4e-17 m^3/(N m)}"
  stribeck_run "run_in_$rq" --set "surfaces.carrier=$faces" --set "surfaces.washer=$faces" \
    --set "surfaces.asperities.summit_radius=$(awk -v q=$rq 'BEGIN { print 20 * 0.515 / q }') um"
done
echo "case,f_eff_least,load_N,stribeck,hmin_over_sigma,last_cool_load_N" > "$out/stribeck.csv"
for case_name in new worn worn_run_in run_in_0.3 run_in_0.2 run_in_0.1; do
  awk -F, -v c="$case_name" 'NR == 1 { for (k = 1; k <= NF; ++k) at[$k] = k; next }
    $(at["branch"]) == "cool" { last = $(at["load_N"]); f = $(at["f_eff"]) + 0
      if (best == "" || f < best) { best = f; load = last; zn = $(at["stribeck"]); h = $(at["hmin_over_sigma"]) } }
    END { printf "%s,%.4g,%.5g,%.4g,%.4g,%.5g\n", c, best, load, zn, h, last }' "$out/stribeck_$case_name/states.csv" \
    >> "$out/stribeck.csv" || status=1
done
python3 "$root/scripts/wear_in_stribeck.py" "$out" || status=1
cat "$summary" "$out/stribeck.csv"
exit $status
