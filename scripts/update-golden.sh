#!/usr/bin/env bash
# Regenerates the golden files of the emitted Verilog, tests/golden/*.v (the configurations are
# listed in tests/rtl_golden_files.cmake, which also normalises the version), with B/fpstereo-rtl:
#   scripts/update-golden.sh [--build-dir B]
# B defaults to build in the repository; fpstereo-rtl is brought up to date there first. Review
# the result with `git diff tests/golden` and commit it with the change that caused it.
set -euo pipefail
fail() { echo "update-golden: $*" >&2; exit 1; }
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
while [ $# -gt 0 ]; do
  case $1 in
    --build-dir) build=$(cd "${2:-}" 2>/dev/null && pwd) || fail "--build-dir '${2:-}': no such directory"
                 shift 2 ;;
    *) fail "unknown argument '$1' (usage: scripts/update-golden.sh [--build-dir B])" ;;
  esac
done
[ -f "$build/CMakeCache.txt" ] || fail "$build is not a configured build directory: run scripts/build.sh first"
cmake --build "$build" --target fpstereo-rtl >/dev/null || fail "building fpstereo-rtl in $build failed"
mkdir -p "$root/tests/golden"
cmake -DFPSTEREO_RTL="$build/fpstereo-rtl" -DGOLDEN_DIR="$root/tests/golden" -DUPDATE=ON \
  -P "$root/tests/rtl_golden_files.cmake"
