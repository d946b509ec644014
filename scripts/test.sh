#!/usr/bin/env bash
# Set up, build and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
# The long fuzz run (label fuzz) is opt-in: ctest --test-dir build -L fuzz
ctest --test-dir build --output-on-failure -j "$(nproc)" -LE "^fuzz$"
