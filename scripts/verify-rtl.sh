#!/usr/bin/env bash
# Generates the RTL for one configuration, lints it, builds its Verilator test bench and runs it.
#   scripts/verify-rtl.sh [--build-dir B] [--tb-opt N] [config flags] [-- test bench args]
#   scripts/verify-rtl.sh [--build-dir B] [--tb-opt N] --rtl-dir DIR [-- test bench args]
# B (default: build in the repository) must hold a built fpstereo-rtl. Everything goes to
# B/rtl/<hash of the config flags>/{rtl,tb}. With --rtl-dir, DIR holds a design already
# generated with fpstereo-rtl -o DIR (perhaps altered since, as tests/rtl_timing_check.cmake
# does): it is linted and verified as it is, and the test bench goes to B/rtl/<hash of DIR>/tb.
# --tb-opt N (0 to 3, default 2) compiles the bench and its Verilated model with -ON; auto (the
# test suite's) takes 0 for a design of fewer than 3,000 cycles a frame and 1 for the others: a
# test's few frames simulate in seconds, so the build is most of its time, -O0 builds in half the
# time of -O1 and runs about five times slower, and the cycles a frame say which one weighs more
# (the build and a cycle's simulation both grow with the design).
# Exits with the test bench's status (0 pass, 1 mismatch, protocol, register or timing error,
# 2 bad input, 3 timeout), the generator's status if it fails (2 for a bad configuration), or 1
# when linting or building fails.
set -euo pipefail
fail() { echo "verify-rtl: $*" >&2; exit 1; }
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
rtl_dir=
tb_opt=2
config_flags=()
tb_args=()
while [ $# -gt 0 ]; do
  case $1 in
    --build-dir) build=$(cd "${2:-}" 2>/dev/null && pwd) || fail "--build-dir '${2:-}': no such directory"
                 shift 2 ;;
    --tb-opt) [[ "${2:-}" =~ ^([0-3]|auto)$ ]] || fail "--tb-opt '${2:-}': expected 0, 1, 2, 3 or auto"
              tb_opt=$2; shift 2 ;;
    --rtl-dir) rtl_dir=$(cd "${2:-}" 2>/dev/null && pwd) || fail "--rtl-dir '${2:-}': no such directory"
               shift 2 ;;
    --) shift; tb_args=("$@"); break ;;
    *) config_flags+=("$1"); shift ;;
  esac
done
[ -x "$build/fpstereo-rtl" ] || fail "$build/fpstereo-rtl not found: build the project first (scripts/build.sh)"

if [ -n "$rtl_dir" ]; then
  [ ${#config_flags[@]} -eq 0 ] || fail "--rtl-dir takes no config flags: ${config_flags[*]}"
  [ -f "$rtl_dir/filelist.f" ] || fail "$rtl_dir/filelist.f is missing: run fpstereo-rtl -o $rtl_dir first"
  work=$build/rtl/$(printf 'rtl-dir %s\n' "$rtl_dir" | sha1sum | cut -c1-12)
  rtl=$rtl_dir
  tb=$work/tb
  # 1. The design is there; a different set of files needs a freshly configured test bench.
  mkdir -p "$work"
  cmp -s "$rtl/filelist.f" "$work/filelist.f" || rm -rf "$tb"
  cp "$rtl/filelist.f" "$work/filelist.f"
else
  work=$build/rtl/$(printf '%s\n' "${config_flags[@]}" | sha1sum | cut -c1-12)
  rtl=$work/rtl
  tb=$work/tb

  # 1. Generate into a fresh directory, then copy over only what changed, so that an unchanged
  #    design is neither re-verilated nor recompiled.
  rm -rf "$work/rtl.new"
  "$build/fpstereo-rtl" "${config_flags[@]}" -o "$work/rtl.new"
  mkdir -p "$rtl"
  # A different set of files needs a freshly configured test bench (verilate() lists them then).
  cmp -s "$work/rtl.new/filelist.f" "$rtl/filelist.f" || rm -rf "$tb"
  for f in "$work/rtl.new"/*; do cmp -s "$f" "$rtl/${f##*/}" || cp "$f" "$rtl/"; done
  for f in "$rtl"/*; do [ -e "$work/rtl.new/${f##*/}" ] || rm "$f"; done
  rm -rf "$work/rtl.new"
fi

# The top's banner states its cycles a frame (fpstereo-rtl's "expected cycles per frame").
if [ "$tb_opt" = auto ]; then
  top=$rtl/$(awk '!/^ *$/ && !/^ *\/\// { print; exit }' "$rtl/filelist.f")
  cycles=$(grep -o -m 1 'expected cycles per frame without stalls: [0-9]*' "$top" | grep -o '[0-9]*$') ||
    fail "$top states no cycles per frame for --tb-opt auto"
  if [ "$cycles" -lt 3000 ]; then tb_opt=0; else tb_opt=1; fi
fi

# 2. Lint: any warning fails.
lint=$(cd "$rtl" && verilator --lint-only -Wall -f filelist.f 2>&1) || { echo "$lint" >&2; fail "lint failed in $rtl"; }

# 3. Configure (once) and build the test bench, showing the log only when it fails.
#    A bench built at another --tb-opt is configured again (and rebuilt).
if ! grep -qx -- "FPSTEREO_TB_OPT:STRING=-O$tb_opt" "$tb/CMakeCache.txt" 2>/dev/null; then
  cmake -S "$root/verilator_tb" -B "$tb" -G Ninja -DRTL_DIR="$rtl" -DFPSTEREO_BUILD_DIR="$build" \
    -DFPSTEREO_SOURCE_DIR="$root" -DFPSTEREO_TB_OPT="-O$tb_opt" >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; rm -rf "$tb"; fail "configuring the test bench failed"; }
fi
cmake --build "$tb" -j "$(nproc)" >"$work/build.log" 2>&1 ||
  { cat "$work/build.log" >&2; fail "building the test bench failed"; }

# 4. Run it.
exec "$tb/fpstereo-tb" "${tb_args[@]}"
