#!/usr/bin/env bash
# Large frames through the RTL, bit for bit against the golden model: census 7x7, dmax 128,
# uf 128 at 1920x1080 and at 3840x2160, on Middlebury 2005 Reindeer (a real pair) enlarged 3x and
# 6x (bilinear) and cropped to the frame. Each run streams four frames back to back without stalls
# (cycles per frame, steady state) and one with 10 % idle and backpressure. About 4 and 20 minutes
# of simulation on an idle 2-core machine; needs ../shared/data/stereo. The -ppc sizes take beats of
# 2 (or 4) pixels with the core in strips (docs/ppc-hardware.md: census with the median, as C2);
# 1080p-ppc4 at 64 disparities; 1080p-ppc2-lr1 with LR1 and the right view (as C3, and the right
# view's stream checked too); 1080p-ppc2-lr2 with LR2 and the right view (as C4); 1080p-ppc2-sad
# with SAD 5x5 (its window costs a beat a step, the cost words in the strips' RAMs);
# 1080p-ppc4-shd with SHD 3x3 over census 5x5 codes and the fused cost at 64 disparities (the
# codes in windows of 4 columns a step first); 1080p-ppc2-sad-lr2 with SAD 5x5, LR2 and the right
# view at 64 disparities (the match side's window costs with the images swapped).
#   bench/large-frames.sh [--build-dir B] [1080p|4k|1080p-ppc2|4k-ppc2|1080p-ppc4|1080p-ppc2-lr1|1080p-ppc2-lr2|1080p-ppc2-sad|1080p-ppc4-shd|1080p-ppc2-sad-lr2 ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
if [ "${1:-}" = --build-dir ]; then build=$(cd "$2" && pwd); shift 2; fi
pair=$root/../shared/data/stereo/middlebury_2005_2006_half
[ -d "$pair" ] || { echo "large-frames: $pair not found" >&2; exit 2; }
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1080p 4k)
for size in "${sizes[@]}"; do
  range=(--dmax 128 --uf 128)
  cost=(--cost census --window 7)
  case $size in
    1080p) geometry=(--width 1920 --height 1080); factor=3 ;;
    4k) geometry=(--width 3840 --height 2160); factor=6 ;;
    1080p-ppc2) geometry=(--width 1920 --height 1080 --ppc 2); factor=3 ;;
    4k-ppc2) geometry=(--width 3840 --height 2160 --ppc 2); factor=6 ;;
    1080p-ppc4) geometry=(--width 1920 --height 1080 --ppc 4); factor=3; range=(--dmax 64 --uf 64) ;;
    1080p-ppc2-lr1) geometry=(--width 1920 --height 1080 --ppc 2 --lr lr1 --right-view on); factor=3 ;;
    1080p-ppc2-lr2) geometry=(--width 1920 --height 1080 --ppc 2 --lr lr2 --right-view on); factor=3 ;;
    1080p-ppc2-sad) geometry=(--width 1920 --height 1080 --ppc 2); factor=3; cost=(--cost sad --window 5) ;;
    1080p-ppc4-shd) geometry=(--width 1920 --height 1080 --ppc 4); factor=3; range=(--dmax 64 --uf 64)
                    cost=(--cost shd --window 5 --shd-window 3 --fused-weight 4) ;;
    1080p-ppc2-sad-lr2) geometry=(--width 1920 --height 1080 --ppc 2 --lr lr2 --right-view on); factor=3
                        range=(--dmax 64 --uf 64); cost=(--cost sad --window 5) ;;
    *) echo "large-frames: unknown size '$size' (1080p, 4k, 1080p-ppc2, 4k-ppc2, 1080p-ppc4, 1080p-ppc2-lr1, 1080p-ppc2-lr2, 1080p-ppc2-sad, 1080p-ppc4-shd or 1080p-ppc2-sad-lr2)" >&2
       exit 2 ;;
  esac
  echo "== $size"
  "$root/scripts/verify-rtl.sh" --build-dir "$build" "${cost[@]}" "${range[@]}" \
    "${geometry[@]}" -- --left "$pair/left/Reindeer/view1.png" --right "$pair/right/Reindeer/view5.png" \
    --upscale "$factor" --crop --frames 1 --idle 0.1 --backpressure 0.1 | grep -v '^\['
done
