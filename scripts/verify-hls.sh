#!/usr/bin/env bash
# Generates the HLS C++ of one configuration, builds its C-simulation test bench and host program
# with g++ (no Vitis), and checks both against the golden model on image pairs written here:
#   scripts/verify-hls.sh [--build-dir B] [config flags] [-- --left L.png --right R.png]
# The pairs: a random one, a shifted one with 4 gray levels (many ties), a smaller frame than the
# configured one, and a region of the example pair (examples/cones) when the frame fits in it; or,
# after --, the given pair (any format `fpstereo run` reads, at most the configured size), converted
# to the test bench's PGM the way `fpstereo run` reads it.
# For each, `fpstereo run --pfm` writes the reference; the test bench must match every word and
# the host program must write the identical PFM. Exits 0 on success, 1 on any mismatch or failure,
# the generator's status if it rejects the configuration.
set -euo pipefail
fail() { echo "verify-hls: $*" >&2; exit 1; }
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
config_flags=()
user_left="" user_right=""
while [ $# -gt 0 ]; do
  case $1 in
    --build-dir) build=$(cd "${2:-}" 2>/dev/null && pwd) || fail "--build-dir '${2:-}': no such directory"
                 shift 2 ;;
    --) shift
        while [ $# -gt 0 ]; do
          case $1 in
            --left) user_left=${2:-}; shift 2 ;;
            --right) user_right=${2:-}; shift 2 ;;
            *) fail "after --: expected --left L --right R, got '$1'" ;;
          esac
        done ;;
    *) config_flags+=("$1"); shift ;;
  esac
done
if [ -n "$user_left$user_right" ] && { [ -z "$user_left" ] || [ -z "$user_right" ]; }; then
  fail "give both --left and --right"
fi
for tool in fpstereo-rtl fpstereo tests/hls_stimulus; do
  [ -x "$build/$tool" ] || fail "$build/$tool not found: build the project first (scripts/build.sh)"
done

work=$build/hls/$(printf '%s\n' "${config_flags[@]}" | sha1sum | cut -c1-12)
rm -rf "$work"
mkdir -p "$work/pairs"
"$build/fpstereo-rtl" --emit hls "${config_flags[@]}" -o "$work/hls"
make -C "$work/hls" -j2 >"$work/build.log" 2>&1 || { cat "$work/build.log" >&2; fail "building the test bench failed"; }
tb=$(ls "$work"/hls/*_tb)
host=$(ls "$work"/hls/*_host)

config=$("$build/fpstereo" config "${config_flags[@]}")
width=$(sed -n 's/^width = //p' <<<"$config")
height=$(sed -n 's/^height = //p' <<<"$config")

pairs=()
make_pair() {  # name, hls_stimulus arguments
  local name=$1; shift
  "$build/tests/hls_stimulus" "$@" "$work/pairs/$name-left.pgm" "$work/pairs/$name-right.pgm"
  pairs+=("$name")
}
if [ -n "$user_left" ]; then
  make_pair given --from "$user_left" "$user_right"
else
  make_pair random --width "$width" --height "$height" --seed 7
  make_pair ties --width "$width" --height "$height" --seed 11 --levels 4 --shifted 5
  make_pair smaller --width $((width > 12 ? width - 5 : width)) --height $((height > 6 ? height - 3 : height)) --seed 13
fi
if [ -z "$user_left" ] && [ "$width" -le 450 ] && [ "$height" -le 375 ]; then
  make_pair cones --width "$width" --height "$height" --at $(((450 - width) / 2)) $(((375 - height) / 2)) \
    --from "$root/examples/cones/left.png" "$root/examples/cones/right.png"
fi

# Every other output frame (the right view, the confidences) is checked too, test bench and host:
# the test bench lists each frame's option, which `fpstereo run` writes the reference under and
# the test bench and host program read and write it under.
planes=()
while read -r option suffix; do planes+=("$option" "$suffix"); done < <("$tb" --planes)
pixels=0
for name in "${pairs[@]}"; do
  left=$work/pairs/$name-left.pgm right=$work/pairs/$name-right.pgm
  reference=(--pfm "$work/pairs/$name-reference.pfm") tb_extra=() host_extra=()
  for ((p = 0; p < ${#planes[@]}; p += 2)); do
    option=${planes[p]} file=$name${planes[p]#-}
    reference+=("$option" "$work/pairs/$file-reference${planes[p + 1]}")
    tb_extra+=("$option" "$work/pairs/$file-reference${planes[p + 1]}")
    host_extra+=("$option" "$work/pairs/$file-host${planes[p + 1]}")
  done
  "$build/fpstereo" run "${config_flags[@]}" "$left" "$right" "${reference[@]}" >/dev/null
  "$tb" "$left" "$right" "$work/pairs/$name-reference.pfm" "${tb_extra[@]}" ||
    fail "$name: the test bench found mismatches"
  "$host" "$left" "$right" "$work/pairs/$name-host.pfm" "${host_extra[@]}" >/dev/null ||
    fail "$name: the host program failed"
  cmp -s "$work/pairs/$name-host.pfm" "$work/pairs/$name-reference.pfm" ||
    fail "$name: the host program's disparity differs from the reference"
  for ((p = 0; p < ${#planes[@]}; p += 2)); do
    file=$work/pairs/$name${planes[p]#-}
    cmp -s "$file-host${planes[p + 1]}" "$file-reference${planes[p + 1]}" ||
      fail "$name: the host program's ${planes[p]#--} differs from the reference"
  done
  read -r w h < <(sed -n 2p "$work/pairs/$name-reference.pfm")
  pixels=$((pixels + w * h))
done
echo "verify-hls: ${#pairs[@]} pairs (${pairs[*]}), $pixels pixels, zero mismatches (test bench and host)"
