#!/bin/sh
# The runs that show a restructuring changed no result (issue: the house): 16 runs of
# the shipped scenes and studies, each effect on, with full precision, into OUT/<name>.
# Run it with the build before and after a change and compare:
#
#   sh scripts/same_results_runs.sh BEFORE/twb /tmp/before
#   sh scripts/same_results_runs.sh AFTER/twb /tmp/after
#   python3 scripts/same_results.py /tmp/before /tmp/after
#
# About 4 minutes on two cores (two runs at a time).
set -u
if [ $# -ne 2 ]; then
  echo "usage: sh scripts/same_results_runs.sh TWB_BINARY OUT_DIR" >&2
  exit 2
fi
TWB=$1
OUT=$2
CONFIGS=$(cd "$(dirname "$0")/../configs" && pwd)
PAPER=$CONFIGS/jackson_green_2006.yaml
rm -rf "$OUT"
mkdir -p "$OUT"
run() {
  name=$1
  shift
  if "$TWB" run "$@" --out "$OUT/$name" -q --full-precision --threads 1 > "$OUT/$name.log" 2>&1; then
    echo "$name: ok"
  else
    echo "$name: exit $? (see $OUT/$name.log)"
  fi
}
point="study={type: point}"
run paper "$PAPER" &
run bronze "$CONFIGS/washers/bronze_cusn8.yaml"
wait
for f in "$CONFIGS"/effects/*.yaml; do run "effect_$(basename "$f" .yaml)" "$f"; done
run load_sweep_545 "$CONFIGS/studies/load_sweep_545.yaml" &
run transient_545 "$CONFIGS/studies/transient_step_545.yaml"
wait
run sliding_choice "$CONFIGS/studies/sliding_choice.yaml" &
run friction "$CONFIGS/studies/friction_coefficient.yaml"
wait
# Thermal deformation and mass-conserving cavitation, which no shipped scene turns on.
run deform "$PAPER" --set "$point" --set "operating.load=150 N" --set output.fields=true --set \
  "effects=[{hydrodynamics: {cavitation: reynolds}}, flow_factors, asperity_contact, {thermal: {viscosity_temperature: surface_mean}}, thermal_deformation]" &
run jfo "$PAPER" --set "$point" --set "operating.load=300 N" --set output.fields=true --set \
  "effects=[{hydrodynamics: {cavitation: jfo}}, flow_factors, asperity_contact, {thermal: {viscosity_temperature: film_node}}]"
wait
run paper_fields "$PAPER" --set "$point" --set "operating.load=500 N" --set output.fields=true &
# A fed grooved washer with convection: the relief's halves and parts in every kernel.
run fed_grooved "$CONFIGS/washers/fed_grooved_bronze.yaml"
wait
run bronze_curve "$CONFIGS/washers/bronze_cusn8.yaml" --set \
  "study={type: distress_curve, parameter: speed, from: 1000 rpm, to: 6000 rpm, load_start: 100 N, load_end: 4000 N}"
wait
