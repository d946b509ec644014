#!/usr/bin/env bash
# The random RTL sweep: seeded random valid configurations, each generated, checked for port
# connections of the wrong width (scripts/port-widths.sh: iverilog -g2005 and Yosys hierarchy
# -check, no warning), linted with `verilator --lint-only -Wall` and verified bit-exact in
# Verilator (scripts/verify-rtl.sh) on a small frame with idle cycles and backpressure.
#   scripts/random-rtl.sh [--build-dir B] [--tb-opt N] [--strips] SEED [COUNT]
# --strips draws configurations whose core takes ppc pixels a clock in strips (census, rank, SAD,
# ZSAD or SHD, uf = dmax, ppc 2 or 4, rows wide enough for the strips; docs/ppc-hardware.md), which the general
# draw reaches rarely. COUNT (default 1) configurations are drawn from SEED; one the generator refuses (exit 2: an
# invalid combination, which the generator's own tests cover) is drawn again. Prints one line per
# configuration with its flags, so a failure can be repeated with verify-rtl.sh alone (or, for a
# port width, fpstereo-rtl -o DIR and port-widths.sh DIR). --tb-opt goes to verify-rtl.sh. Exits
# 1 if any configuration fails.
set -euo pipefail
fail() { echo "random-rtl: $*" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
if [ "${1:-}" = --build-dir ]; then
  build=$(cd "${2:-}" 2>/dev/null && pwd) || fail "--build-dir '${2:-}': no such directory"
  shift 2
fi
tb_opt=2
if [ "${1:-}" = --tb-opt ]; then
  [[ "${2:-}" =~ ^([0-3]|auto)$ ]] || fail "--tb-opt '${2:-}': expected 0, 1, 2, 3 or auto"
  tb_opt=$2
  shift 2
fi
strips=0
if [ "${1:-}" = --strips ]; then
  strips=1
  shift
fi
seed=${1:-}
count=${2:-1}
[[ $seed =~ ^[0-9]{1,9}$ ]] || fail "SEED must be a number of at most 9 digits (got '$seed')"
[[ $count =~ ^[0-9]{1,4}$ ]] && [ "$count" -ge 1 ] || fail "COUNT must be 1 to 9999 (got '$count')"
[ -x "$build/fpstereo-rtl" ] || fail "$build/fpstereo-rtl not found: build the project first"
work=$(mktemp -d /tmp/random-rtl.XXXXXX)
trap 'rm -rf "$work"' EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM

# Draws from one seeded sequence: no command substitution, whose subshell would reseed RANDOM.
RANDOM=$seed
pick() { local choices=("$@"); REPLY=${choices[RANDOM % ${#choices[@]}]}; }
add() { local flag=$1; shift; pick "$@"; flags+=("$flag" "$REPLY"); }

# One configuration's flags, drawn from the ranges the tests can simulate in seconds.
draw() {
  local dmax divisors=() d paths=() p cost
  pick 16 24 32 48 64; dmax=$REPLY
  for d in 1 2 3 4 6 8 12 16 24 32 48 64; do (( dmax % d == 0 )) && divisors+=("$d"); done
  for p in 0 45 90 135; do (( RANDOM % 2 )) && paths+=("$p"); done
  [ ${#paths[@]} -gt 0 ] || { pick 0 45 90 135; paths=("$REPLY"); }
  # The 180-degree path at one pixel a clock, a time in four (a ppc drawn later redraws it).
  (( strips == 0 && RANDOM % 4 == 0 )) && paths+=(180)
  if (( strips )); then
    # ppc strips of segments of 3 pixels at least: rows of 48 to 127 pixels, frames that follow on.
    flags=(--width $((48 + RANDOM % 80)) --height $((10 + RANDOM % 17)) --dmax "$dmax" --uf "$dmax"
           --paths "$(IFS=,; echo "${paths[*]}")" --min-disp $((RANDOM % 41 - 20)))
    local uf=$dmax
    add --cost census rank sad zsad shd
    cost=$REPLY
  else
    flags=(--width $((dmax / 2 + 16 + RANDOM % 40)) --height $((5 + RANDOM % 8)) --dmax "$dmax"
           --paths "$(IFS=,; echo "${paths[*]}")" --min-disp $((RANDOM % 17 - 8)))
    add --uf "${divisors[@]}"
    local uf=$REPLY
    add --cost census rank sad zsad shd
    cost=$REPLY
  fi
  add --window 3 5 7
  # (SHD over 1 x 1 is census, which in strips would be drawn as census.)
  if (( strips )) && [ "$cost" = shd ]; then add --shd-window 3 5; else add --shd-window 1 3 5; fi
  add --p2-adapt 0 0 3 8
  add --lr none none lr1 lr2
  [ "$REPLY" = none ] || add --right-view off on
  add --lr-threshold 0 1 2
  add --uniqueness 0 0 10 30
  add --median 0 3 5
  add --gap-interp off on linear
  add --subpixel-bits 0 0 2 4
  add --subpixel-fit equiangular parabola
  add --confidence off on
  # (SAD and ZSAD have no fused cost: draw no weight the generator refuses.)
  if [ "$cost" = sad ] || [ "$cost" = zsad ]; then add --fused-weight 0; else add --fused-weight 0 0 1 4 11 32; fi
  add --fused-trunc 8 32 255
  add --fused-term intensity gradient
  # The speckle filter's stage takes a word once in 4 clocks (dmax / uf >= 4).
  if (( dmax / uf >= 4 )); then
    add --speckle-size 0 0 2 5 12
    add --speckle-range 0 1 2
  fi
  # Pixels per beat need uf = dmax (a width that is not a whole number of beats is redrawn).
  if (( strips )); then
    add --ppc 2 4
  elif (( uf == dmax )); then
    add --ppc 1 2 4
  fi
}

failed=0
for ((i = 0; i < count; ++i)); do
  for ((attempt = 0; ; ++attempt)); do
    [ $attempt -lt 100 ] || fail "no valid configuration in 100 draws"
    draw
    status=0
    rm -rf "$work/rtl"
    "$build/fpstereo-rtl" "${flags[@]}" -o "$work/rtl" >/dev/null 2>&1 || status=$?
    [ $status -eq 2 ] || break
  done
  [ $status -eq 0 ] || fail "fpstereo-rtl ${flags[*]}: exit $status"
  pick 3 16 256
  bench=(--levels "$REPLY" --idle 0.3 --backpressure 0.3 --seed $((RANDOM + 1)))
  log=$("$root/scripts/port-widths.sh" "$work/rtl" 2>&1 &&
        "$root/scripts/verify-rtl.sh" --build-dir "$build" --tb-opt "$tb_opt" "${flags[@]}" -- "${bench[@]}" 2>&1) &&
    result=PASS ||
    { result=FAIL; failed=1; }
  echo "random-rtl seed $seed #$i: $result: scripts/verify-rtl.sh ${flags[*]} -- ${bench[*]}"
  [ $result = PASS ] || echo "$log" | tail -20
done
exit $failed
