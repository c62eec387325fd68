#!/bin/sh
# The figures of Jackson & Green (2006) in one command: runs the paper's study scenes of
# configs/studies/ and plots them with scripts/twb_plot.py (docs/figures.md).
#
#   scripts/paper_figures.sh [--twb PATH] [--out DIR] [--quick] [--format LIST]
#
#   --twb PATH     the twb binary (default: build-rel/twb, else build/twb)
#   --out DIR      where results and figures go (default: results/paper)
#   --quick        a coarse mesh (5 x 24 nodes instead of 9 x 66) for a fast look; the
#                  curves keep their shape, distress moves by some per cent
#   --format LIST  figure formats for twb_plot.py (default: png,svg)
#
# Writes DIR/results/<scene>/ (states.csv, distress.csv, ... of each study) and
# DIR/figures/: fig06 ... fig15, distress_map, transient_trajectory and
# sliding_comparison, with each study's own full set of figures in
# DIR/figures/<scene>/. Exit status: 0 all studies ran and every figure was written;
# 1 a study reported a solver failure or a figure is missing (the rest is still
# written); 2 bad usage.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
twb=""
out="results/paper"
quick=""
format="png,svg"

usage() {
  sed -n '5,11p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

while [ $# -gt 0 ]; do
  case "$1" in
    --twb) [ $# -ge 2 ] || usage; twb=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    --format) [ $# -ge 2 ] || usage; format=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    -h|--help) usage ;;
    *) echo "paper_figures.sh: unknown argument '$1'" >&2; usage ;;
  esac
done

. "$root/scripts/find_twb.sh"
find_twb paper_figures.sh

set -- # the mesh overrides of --quick, as positional parameters
if [ -n "$quick" ]; then
  set -- --set mesh.radial_nodes=5 --set mesh.circumferential_nodes=24
fi

status=0
start=$(date +%s)
# paper_load_sweeps: Figs. 6-14, the distress map and the runaway transients;
# friction_coefficient: Fig. 15; sliding_choice: which film slides.
for scene in paper_load_sweeps friction_coefficient sliding_choice; do
  echo "paper_figures.sh: $scene ($(( $(date +%s) - start )) s so far)" >&2
  mkdir -p "$out/results/$scene" || exit 2
  if ! "$twb" run "$root/configs/studies/$scene.yaml" --out "$out/results/$scene" "$@" \
      > "$out/results/$scene/twb.log" 2>&1; then
    echo "paper_figures.sh: twb reported a failure for $scene; see $out/results/$scene/twb.log" >&2
    status=1
  fi
  if ! "$root/scripts/twb_plot.py" "$out/results/$scene" --out "$out/figures/$scene" \
      --format "$format" > /dev/null; then
    status=1
  fi
done

# One directory with every figure: the sweeps' set, Fig. 15 and the sliding comparison.
figures="$out/figures"
for f in "$figures"/paper_load_sweeps/* "$figures"/friction_coefficient/fig15_stribeck_by_friction.* \
    "$figures"/sliding_choice/sliding_comparison.*; do
  if [ -f "$f" ]; then cp "$f" "$figures/"; fi
done
for stem in fig06_f_eff_vs_load fig07_mean_temperature_vs_load fig08_hmin_over_sigma_vs_load \
    fig09_gamma_x_ratio_vs_load fig10_gamma_y_ratio_vs_load fig11_fluid_share_vs_load \
    fig12_contact_share_vs_load fig13_contact_share_vs_hmin fig14_stribeck fig15_stribeck_by_friction \
    distress_map sliding_comparison; do
  first=${format%%,*}
  if [ ! -f "$figures/$stem.$first" ]; then
    echo "paper_figures.sh: $stem.$first was not written" >&2
    status=1
  fi
done
echo "paper_figures.sh: figures in $figures ($(( $(date +%s) - start )) s)" >&2
exit $status
