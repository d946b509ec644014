#!/usr/bin/env bash
# The top-level proof (tests/formal/top_props.v) on a small generated design:
#   run_top_proof.sh <fpstereo-rtl> <work dir> [--width W] [--ppc N] [--mutate <module suffix> <sed>]
#                    [run_proof.sh options]
# generates `--width 16 --height 4 --dmax 16 --uf 16 --window 3 --median 0 --no-axi-lite` (with
# --width W that width; with --ppc N: N pixels per beat, and at a width of 32 the core in strips,
# docs/ppc-hardware.md) into <work dir>/rtl and runs run_proof.sh with its top; --mutate
# applies the sed expression to the generated <prefix>_<suffix>.v (e.g. axis_skid) and requires
# the proof to fail.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -ge 2 ] || { echo "usage: run_top_proof.sh <fpstereo-rtl> <work dir> [options]" >&2; exit 2; }
rtl_gen="$1"; work="$2"; shift 2
width=16 ppc=1
if [ "${1:-}" = "--width" ]; then
  width="$2"; shift 2
fi
if [ "${1:-}" = "--ppc" ]; then
  ppc="$2"; shift 2
fi
mutate=()
if [ "${1:-}" = "--mutate" ]; then
  mutate=(--mutate "$2" "$3"); shift 3
fi
rm -rf "$work"
mkdir -p "$work"
"$rtl_gen" --width "$width" --height 4 --dmax 16 --uf 16 --window 3 --median 0 --no-axi-lite --ppc "$ppc" -o "$work/rtl" >/dev/null ||
  { echo "run_top_proof: fpstereo-rtl failed" >&2; exit 2; }
top_file=$(ls "$work"/rtl/*_top.v)
top=$(basename "$top_file" .v)
if [ ${#mutate[@]} -gt 0 ]; then
  mutate[1]=$(ls "$work"/rtl/*_"${mutate[1]}".v) || { echo "run_top_proof: no module ${mutate[1]}" >&2; exit 2; }
fi
exec "$here/run_proof.sh" "$@" "${mutate[@]}" --define "FORMAL_TOP=$top" --define "FORMAL_PPC=$ppc" --work "$work/proof" \
  top_props "$here/top_props.v" "$work"/rtl/*.v
