#!/usr/bin/env bash
# Installs the Debian 12 packages fpstereo needs; does nothing (quietly) when all are present.
#   scripts/setup.sh [--slurm]
# --slurm adds a one-node Slurm (slurmctld, slurmd, munge) for the opt-in test of
# docs/cluster.md, ctest -L slurm; the daemons are not started.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libopencv-dev libfmt-dev catch2 libcli11-dev nlohmann-json3-dev libtomlplusplus-dev
  verilator yosys z3 iverilog tcl
  python3-dev python3-numpy pybind11-dev python3-pybind11 python3-opencv
)
case ${1:-} in
  --slurm) packages+=(slurmctld slurmd slurm-client munge) ;;
  "") ;;
  *) echo "setup: unknown option '$1' (expected --slurm or nothing)" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
