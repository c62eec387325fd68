#!/bin/sh
# The sensitivity study of docs/validation.md: how the distress load and the mixed-regime
# friction move with the inputs the paper does not fix (asperity summit parameters,
# thermal modelling choices, the friction law). Each variation is the paper's scene with
# one change, given as --set overrides:
#   - a distress map at 545 and 953 rad/s, 100 N to 600 N (configs/studies/distress_map.yaml)
#   - two operating points at 136 rad/s, 500 N and 1361 N (the mixed regime)
#
#   scripts/sensitivity_study.sh [--twb PATH] [--out DIR]
#
#   --twb PATH   the twb binary (default: build-rel/twb, else build/twb)
#   --out DIR    where results go (default: results/sensitivity)
#
# Writes DIR/<variation>/{map,point-500N,point-1361N}/ and DIR/summary.csv (variation,
# W_d and fold at both speeds, f_eff and fluid share at both points). About 12 min on
# the full mesh (one core). Exit status: 0 every run succeeded; 1 a run failed (the
# others are still written; its cells stay empty); 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
out="results/sensitivity"

. "$root/scripts/find_twb.sh"
study_options sensitivity_study.sh 9,12 "$@"

scene="$root/configs/studies/distress_map.yaml"
hydro='{hydrodynamics: {cavitation: reynolds}}, flow_factors, asperity_contact'
status=0

# run NAME [--set ...]: the distress map and the two 136 rad/s points of one variation.
run() {
  name=$1; shift
  dir="$out/$name"
  mkdir -p "$dir"
  echo "sensitivity_study.sh: $name" >&2
  "$twb" run "$scene" --quiet --out "$dir/map" "$@" \
    --set 'study.speeds=[545 rad/s, 953 rad/s]' --set study.load_start="100 N" \
    --set study.load_end="600 N" > "$dir/map.log" 2>&1 || status=1
  for load in 500 1361; do
    "$twb" run "$scene" --quiet --out "$dir/point-${load}N" "$@" --set 'study={type: point}' \
      --set operating.speed="136 rad/s" --set operating.load="$load N" \
      > "$dir/point-${load}N.log" 2>&1 || status=1
  done
}

run as_shipped
run eta_R_sigma_0.025 --set surfaces.asperities.eta_R_sigma=0.025
run eta_R_sigma_0.1 --set surfaces.asperities.eta_R_sigma=0.1
run summit_radius_10um --set surfaces.asperities.summit_radius="10 um"
run summit_radius_40um --set surfaces.asperities.summit_radius="40 um"
run summit_sigma_0.515um --set surfaces.asperities.summit_sigma="0.515 um"
run viscosity_at_film_node --set "effects=[$hydro, {thermal: {viscosity_temperature: film_node}}]"
run carrier_averaged --set "effects=[$hydro, {thermal: {carrier_temperature: axisymmetric}}]"
for f in 0.1 0.2 0.3; do
  run "friction_constant_$f" --set friction.law=constant --set friction.coefficient="$f"
done

/usr/bin/python3 - "$out" <<'EOF' || status=1
import csv, os, sys
out = sys.argv[1]
columns = ["variation", "W_d_545_N", "fold_545_N", "W_d_953_N", "fold_953_N",
           "f_eff_136_500N", "fluid_share_136_500N", "f_eff_136_1361N", "fluid_share_136_1361N"]
rows = []
for name in sorted(os.listdir(out)):
    d = os.path.join(out, name)
    if not os.path.isdir(d):
        continue
    row = dict.fromkeys(columns, "")
    row["variation"] = name
    try:
        for r in csv.DictReader(open(os.path.join(d, "map", "distress.csv"))):
            speed = str(round(float(r["speed_rad_s"])))
            row[f"W_d_{speed}_N"], row[f"fold_{speed}_N"] = r["W_d_N"], r["fold_N"]
    except OSError:
        pass
    for load in ("500", "1361"):
        try:
            states = list(csv.DictReader(open(os.path.join(d, f"point-{load}N", "states.csv"))))
            row[f"f_eff_136_{load}N"] = states[-1]["f_eff"]
            row[f"fluid_share_136_{load}N"] = states[-1]["fluid_share"]
        except (OSError, IndexError):
            pass
    rows.append(row)
path = os.path.join(out, "summary.csv")
with open(path + ".tmp", "w", newline="") as f:
    w = csv.DictWriter(f, columns)
    w.writeheader()
    w.writerows(rows)
os.replace(path + ".tmp", path)
print(path)
EOF
exit $status
