#!/usr/bin/env bash
# Set up, build and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
# Opt-in: the long fuzz run (ctest -L fuzz) and the one-node Slurm cluster (ctest -L slurm, docs/cluster.md)
ctest --test-dir build --output-on-failure -j "$(nproc)" -LE "^(fuzz|slurm|rtl-random|rtl-speckle|resource-data)$"
