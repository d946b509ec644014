#!/usr/bin/env bash
# Accuracy of the options beyond the paper against OpenCV's StereoSGBM (MODE_SGBM and MODE_HH4),
# per dataset of a stereo data folder, for the two KITTI sets pooled and for every pair pooled,
# as the table of docs/accuracy.md, "Accuracy beyond the paper" (markdown on stdout):
#   bench/accuracy-beyond.sh [--build-dir B] [--speckle | --fused | --path180 | --gap] [DATA]
# (DATA: ../shared/data/stereo)
# With --speckle, the table of docs/accuracy.md, "Speckle filter": A4 with speckle sizes 0, 50,
# 100, 200 and ranges 1, 2, against MODE_HH4 without and with OpenCV's speckle filter (100, 2).
# With --fused, the table of docs/accuracy.md, "Fused matching cost": A4 and A4 with the fused
# cost's two chosen settings, without and with the speckle filter (100, 2), against MODE_HH4
# without and with its own.
# With --path180, the table of docs/accuracy.md, "Right-to-left path": A4 with the 180-degree path
# added (and paths 0,90,180 and the 45/135 variants), without and with the speckle filter
# (100, 2) and the fused cost, against MODE_HH4 without and with its own speckle filter.
# With --gap, the table of docs/accuracy.md, "The linear gap fill": A6, A5 and A7 with the linear
# gap fill (the presets), with the smaller end's fill, and without gap interpolation, against
# MODE_HH4 without and with its own speckle filter.
# Each cell comes from `fpstereo eval` (pixel counts pooled over the group's pairs); "filled" is
# after KITTI background interpolation of invalid pixels.
set -euo pipefail
fail() { echo "accuracy-beyond: $*" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
data=$root/../shared/data/stereo
speckle=0
fused=0
path180=0
gap=0
while [ $# -gt 0 ]; do
  case $1 in
    --build-dir) build=$(cd "${2:-}" 2>/dev/null && pwd) || fail "--build-dir '${2:-}': no such directory"
                 shift 2 ;;
    --speckle) speckle=1; shift ;;
    --fused) fused=1; shift ;;
    --path180) path180=1; shift ;;
    --gap) gap=1; shift ;;
    -*) fail "unknown option '$1'" ;;
    *) data=$1; shift ;;
  esac
done
[ $((speckle + fused + path180 + gap)) -gt 1 ] && fail "--speckle, --fused, --path180 and --gap each make a table of their own: give one"
[ -x "$build/fpstereo" ] || fail "$build/fpstereo not found: build the project first (scripts/build.sh)"
[ -d "$data" ] || fail "no data folder '$data'"
data=$(cd "$data" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A group of datasets pooled: one pairs.csv naming the files by absolute path.
pool() {
  local name=$1; shift
  mkdir -p "$work/$name"
  echo "pair,left,right,gt_occ,gt_noc,noc_mask,gt_scale,gt_invalid,max_disp_px" > "$work/$name/pairs.csv"
  for set in "$@"; do
    tail -n +2 "$data/$set/pairs.csv" | awk -F, -v d="$data/$set" 'BEGIN { OFS = "," }
      NF > 1 { for (i = 2; i <= 6; i++) if ($i != "") $i = d "/" $i; print }' >> "$work/$name/pairs.csv"
  done
}

sets=()
for d in "$data"/*/; do [ -f "$d/pairs.csv" ] && sets+=("$(basename "$d")"); done
[ ${#sets[@]} -gt 0 ] || fail "no dataset with pairs.csv under '$data'"
groups=()
for s in "${sets[@]}"; do groups+=("$data/$s"); done
kitti=()
for s in "${sets[@]}"; do case $s in kitti*) kitti+=("$s") ;; esac; done
if [ ${#kitti[@]} -gt 1 ]; then pool kitti_pooled "${kitti[@]}"; groups+=("$work/kitti_pooled"); fi
pool all_pooled "${sets[@]}"
groups+=("$work/all_pooled")

methods=("C2" "C2 --p2-adapt 4" "C2 --subpixel-bits 4" "C4" "A2" "A3" "A4")
baselines=("sgbm" "hh4")
if [ $speckle = 1 ]; then
  methods=("A4")
  for size in 50 100 200; do
    for range in 1 2; do methods+=("A4 --speckle-size $size --speckle-range $range"); done
  done
  baselines=("hh4" "hh4 --sgbm-speckle-window 100 --sgbm-speckle-range 2")
fi
if [ $fused = 1 ]; then
  # The two settings chosen on KITTI 2012, Middlebury 2001/03 and FlyingThings3D (docs/accuracy.md),
  # without and with the speckle filter.
  methods=()
  for filter in "" " --speckle-size 100 --speckle-range 2"; do
    methods+=("A4$filter" "A4$filter --fused-term intensity --fused-weight 4 --fused-trunc 32"
              "A4$filter --fused-term gradient --fused-weight 4 --fused-trunc 16")
  done
  baselines=("hh4" "hh4 --sgbm-speckle-window 100 --sgbm-speckle-range 2")
fi

if [ $path180 = 1 ]; then
  # The settings were chosen on KITTI 2012, Middlebury 2001/03 and FlyingThings3D (docs/accuracy.md).
  speckle_on=" --speckle-size 100 --speckle-range 2"
  intensity=" --fused-term intensity --fused-weight 4 --fused-trunc 32"
  gradient=" --fused-term gradient --fused-weight 4 --fused-trunc 16"
  methods=("A4" "A4 --paths 0,45,90,135,180" "A4 --paths 0,90,180" "A4$speckle_on")
  for paths in 0,45,90,135,180 0,90,180 0,45,90,180 0,90,135,180; do methods+=("A4$speckle_on --paths $paths"); done
  methods+=("A4$speckle_on$intensity" "A4$speckle_on$intensity --paths 0,45,90,135,180"
            "A4$speckle_on$gradient --paths 0,45,90,135,180" "A4$speckle_on$intensity --paths 0,90,180")
  baselines=("hh4" "hh4 --sgbm-speckle-window 100 --sgbm-speckle-range 2")
fi

if [ $gap = 1 ]; then
  methods=()
  for preset in A6 A5 A7; do
    methods+=("$preset --gap-interp off" "$preset --gap-interp on" "$preset")
  done
  baselines=("hh4" "hh4 --sgbm-speckle-window 100 --sgbm-speckle-range 2")
fi

# The overall line of the first (ours) or second (the baseline) method: the filled columns.
row() {  # dataset label, method label, eval output, which line (1 ours, 2 baseline)
  local pairs cells
  pairs=$(printf '%s\n' "$3" | sed -n 's/^overall (\([0-9]*\) pair.*/\1/p')
  cells=$(printf '%s\n' "$3" | grep -A"$4" '^overall' | tail -1 |
          awk '{ printf "%s | %s | %s | %s | %s | %s | %s", $10, $11, $13, $15, $3, $8, $12 }')
  echo "| $1 ($pairs) | $2 | $cells |"
}

echo "| dataset (pairs) | method | D1-noc, filled | D1, filled | bad-2, filled | MAE px, filled | D1, valid only | density % | bad-1, filled |"
echo "|---|---|---|---|---|---|---|---|---|"
for g in "${groups[@]}"; do
  label=$(basename "$g")
  for b in "${baselines[@]}"; do
    # shellcheck disable=SC2086
    out=$("$build/fpstereo" eval "$g" --preset C2 --baseline opencv-sgbm --sgbm-mode $b)
    row "$label" "OpenCV $b" "$out" 2
  done
  for m in "${methods[@]}"; do
    # shellcheck disable=SC2086
    out=$("$build/fpstereo" eval "$g" --preset $m)
    row "$label" "$m" "$out" 1
  done
done
