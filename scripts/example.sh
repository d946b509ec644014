#!/usr/bin/env bash
# The main job on the bundled example (Middlebury Cones): set up, build, run the golden model
# with the paper's C2 configuration, write the disparity images, score them, emit the Verilog,
# and check the hardware: C2 at Cones' frame size, verilated, streams the pair and must give the
# golden model's output bit for bit at the cycles per frame its banner states.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
mkdir -p out
build/fpstereo run --preset C2 examples/cones/left.png examples/cones/right.png \
  -o out/cones_disparity.png --colour out/cones_colour.png
build/fpstereo eval examples/cones --preset C2 --baseline opencv-sgbm
echo "wrote out/cones_disparity.png (KITTI 16-bit) and out/cones_colour.png"
build/fpstereo-rtl --preset C2 > out/c2_top.v
echo "wrote out/c2_top.v (the C2 pipeline in Verilog; see its banner)"

# The hardware on Cones: the test bench's full report goes to out/rtl_cones.log, its verdict here.
echo "verilating C2 at Cones' 450x375 and streaming the pair through it (about 2 minutes the first time)..."
log=out/rtl_cones.log
start=$SECONDS
status=0
scripts/verify-rtl.sh --preset C2 --width 450 --height 375 -- \
  --left examples/cones/left.png --right examples/cones/right.png --idle 0 --backpressure 0 >"$log" 2>&1 ||
  status=$?
sed -n 's/^\(PASS\|FAIL\)/RTL check: \1/p' "$log"
if [ $status -ne 0 ]; then
  echo "RTL check failed (exit $status); the test bench's report:" >&2
  tail -n 20 "$log" >&2
  exit $status
fi
grep '^timing:' "$log"
cycles=$(sed -n 's/^timing: as the design states (\([0-9]*\) cycles per frame.*/\1/p' "$log")
kitti=$(sed -n 's/.*expected cycles per frame without stalls: \([0-9]*\).*/\1/p' out/c2_top.v | head -n 1)
awk -v c="$cycles" -v k="$kitti" -v s=$((SECONDS - start)) 'BEGIN {
  printf "at 300 MHz: %.1f frames/s at 450x375; out/c2_top.v (1242x375, %d cycles per frame): %.1f frames/s (RTL check: %d s)\n",
         300e6 / c, k, 300e6 / k, s }'
