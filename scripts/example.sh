#!/usr/bin/env bash
# The main job on the bundled example (Middlebury Cones): set up, build, run the golden model
# with the paper's C2 configuration, write the disparity images, and score them.
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
