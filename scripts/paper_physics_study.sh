#!/bin/sh
# What the physics the paper names but its model left out does to the distress load,
# for docs/validation.md ("Physics the paper names"): the paper's scene as shipped
# (rigid), with thermal_deformation (docs/physics.md section 11; laterally free faces, the
# default, and laterally constrained ones), with summit statistics from the example
# profile (section 13, configs/profiles/ground_steel_combined.csv), and with
# mass-conserving cavitation (section 12) whose cavity is at -0.3 bar and at a vacuum, each
#   - a distress map at 545 and 953 rad/s from 100 N (configs/studies/distress_map.yaml),
#     with W_d's Richardson error bar (the fold again on 17 x 132);
#   - the cool branch at 545 rad/s from 20 N to 180 N (17 states): lift against h_min/sigma.
#
#   scripts/paper_physics_study.sh [--twb PATH] [--out DIR]
#
#   --twb PATH   the twb binary (default: build-rel/twb, else build/twb)
#   --out DIR    where results go (default: results/paper_physics)
#
# Writes DIR/<variation>/{map,branch}/, DIR/summary.csv (W_d on 9 x 66, extrapolated,
# its error, at both speeds) and DIR/lift_hmin.png. About 45 s on one core. Exit
# status: 0 every run succeeded; 1 a run failed (the others are still written); 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
out="results/paper_physics"

. "$root/scripts/find_twb.sh"
study_options paper_physics_study.sh 11,14 "$@"

map="$root/configs/studies/distress_map.yaml"
sweep="$root/configs/jackson_green_2006.yaml"
paper='{hydrodynamics: {cavitation: reynolds}}, flow_factors, asperity_contact, thermal'
status=0

# run NAME EFFECTS [--set ...]: the distress map and the cool branch of one variation.
run() {
  name=$1 effects=$2
  shift 2
  dir="$out/$name"
  mkdir -p "$dir"
  echo "paper_physics_study.sh: $name" >&2
  "$twb" run "$map" --quiet --out "$dir/map" --set "effects=[$effects]" "$@" \
    --set 'study.speeds=[545 rad/s, 953 rad/s]' --set study.load_start="100 N" \
    --set study.load_end="600 N" > "$dir/map.log" 2>&1 || status=1
  "$twb" run "$sweep" --quiet --out "$dir/branch" --set "effects=[$effects]" "$@" \
    --set study.load_start="20 N" --set study.load_end="180 N" --set study.load_steps=17 \
    --set study.error_estimate=none > "$dir/branch.log" 2>&1 || status=1
}

run rigid "$paper"
run free "$paper, thermal_deformation"
run constrained "$paper, {thermal_deformation: {face_expansion: constrained}}"
run example_profile "$paper" --set "surfaces.asperities={profile: $root/configs/profiles/ground_steel_combined.csv}"
jfo='{hydrodynamics: {cavitation: jfo, cavity_pressure: CAVITY}}, flow_factors, asperity_contact, thermal'
run jfo_cavity_-0.3bar "$(echo "$jfo" | sed 's/CAVITY/-0.3 bar/')"
run jfo_cavity_vacuum "$(echo "$jfo" | sed 's/CAVITY/-1 atm/')"

/usr/bin/python3 - "$out" <<'PY' || status=1
import csv, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
variations = ["rigid", "free", "constrained", "example_profile", "jfo_cavity_-0.3bar", "jfo_cavity_vacuum"]
columns = ["variation"] + [f"{q}_{s}" for s in (545, 953)
                           for q in ("W_d_N", "W_d_extrapolated_N", "W_d_error_N")]
rows = []
for name in variations:
    row = dict.fromkeys(columns, "")
    row["variation"] = name
    try:
        for r in csv.DictReader(open(os.path.join(out, name, "map", "distress.csv"))):
            s = round(float(r["speed_rad_s"]))
            for q in ("W_d_N", "W_d_extrapolated_N", "W_d_error_N"):
                row[f"{q}_{s}"] = r[q]
    except OSError:
        pass
    rows.append(row)
path = os.path.join(out, "summary.csv")
with open(path + ".tmp", "w", newline="") as f:
    w = csv.DictWriter(f, columns)
    w.writeheader()
    w.writerows(rows)
os.replace(path + ".tmp", path)

fig, ax = plt.subplots(figsize=(5.5, 4))
for name, style in zip(variations[:3], ("k-o", "C0-s", "C3-^")):
    try:
        states = [r for r in csv.DictReader(open(os.path.join(out, name, "branch", "states.csv")))
                  if r["converged"] == "1"]
    except OSError:
        continue
    h = [float(r["hmin_over_sigma"]) for r in states]
    lift = [float(r["load_N"]) * float(r["fluid_share"]) for r in states]
    ax.plot(h, lift, style, ms=3, label={"rigid": "none (rigid)", "free": "free faces",
                                        "constrained": "constrained faces"}[name])
ax.set_xlabel("h_min / sigma (sliding film)")
ax.set_ylabel("fluid lift (N)")
ax.set_title("545 rad/s, cool branch, 9 x 66")
ax.legend(title="thermal deformation")
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(os.path.join(out, "lift_hmin.png"), dpi=120)
print(path)
PY
exit $status
