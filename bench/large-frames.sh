#!/usr/bin/env bash
# Large frames through the RTL, bit for bit against the golden model: census 7x7, dmax 128,
# uf 128 at 1920x1080 and at 3840x2160, on Middlebury 2005 Reindeer (a real pair) enlarged 3x and
# 6x (bilinear) and cropped to the frame. Each run streams four frames back to back without stalls
# (cycles per frame, steady state) and one with 10 % idle and backpressure. About 4 and 20 minutes
# of simulation on an idle 2-core machine; needs ../shared/data/stereo.
#   bench/large-frames.sh [--build-dir B] [1080p|4k ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
if [ "${1:-}" = --build-dir ]; then build=$(cd "$2" && pwd); shift 2; fi
pair=$root/../shared/data/stereo/middlebury_2005_2006_half
[ -d "$pair" ] || { echo "large-frames: $pair not found" >&2; exit 2; }
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1080p 4k)
for size in "${sizes[@]}"; do
  case $size in
    1080p) geometry=(--width 1920 --height 1080); factor=3 ;;
    4k) geometry=(--width 3840 --height 2160); factor=6 ;;
    *) echo "large-frames: unknown size '$size' (1080p or 4k)" >&2; exit 2 ;;
  esac
  echo "== $size"
  "$root/scripts/verify-rtl.sh" --build-dir "$build" --cost census --window 7 --dmax 128 --uf 128 \
    "${geometry[@]}" -- --left "$pair/left/Reindeer/view1.png" --right "$pair/right/Reindeer/view5.png" \
    --upscale "$factor" --crop --frames 1 --idle 0.1 --backpressure 0.1 | grep -v '^\['
done
