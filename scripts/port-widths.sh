#!/usr/bin/env bash
# Checks a generated design for port connections of the wrong width, which Verilator's -Wall
# lint does not report: compiles it with `iverilog -g2005` (any warning fails) and elaborates it
# in Yosys as scripts/synth-yosys.sh reads it (read_verilog -defer, hierarchy -check; any
# "Resizing cell port" fails). No synthesis: a few seconds per design.
#   scripts/port-widths.sh DIR
# DIR holds a design written by fpstereo-rtl -o DIR; its filelist.f lists the top first.
# Exits 0 when both tools are silent, 1 naming the tool and its first warning, 2 on bad input
# or when a tool fails to read the design.
set -euo pipefail
die() { echo "port-widths: $*" >&2; exit 2; }
[ $# -eq 1 ] || die "usage: scripts/port-widths.sh DIR"
dir=$1
[ -f "$dir/filelist.f" ] || die "$dir/filelist.f is missing: run fpstereo-rtl -o $dir first"
for tool in iverilog yosys; do
  command -v $tool >/dev/null || die "$tool not found (Debian: scripts/setup.sh installs it)"
done
cd "$dir"
mapfile -t sources < <(grep '\.v$' filelist.f)
[ ${#sources[@]} -gt 0 ] || die "no Verilog files in $dir/filelist.f"
top=$(sed -n 's/^[[:space:]]*module[[:space:]]\{1,\}\([A-Za-z_][A-Za-z0-9_$]*\).*/\1/p' "${sources[0]}" | head -n 1)
[ -n "$top" ] || die "no module in $dir/${sources[0]}"

work=$(mktemp -d /tmp/port-widths.XXXXXX)
trap 'rm -rf "$work"' EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM

status=0
iverilog -g2005 -o /dev/null "${sources[@]}" >"$work/iverilog.log" 2>&1 || status=$?
[ $status -eq 0 ] || die "iverilog failed on $dir: $(head -n 1 "$work/iverilog.log")"
if [ -s "$work/iverilog.log" ]; then
  echo "port-widths: iverilog: $(head -n 1 "$work/iverilog.log")" >&2
  exit 1
fi

{
  for s in "${sources[@]}"; do echo "read_verilog -defer \"$s\""; done
  echo "hierarchy -check -top $top"
} >"$work/hierarchy.ys"
yosys -q -l "$work/yosys.log" -s "$work/hierarchy.ys" >/dev/null 2>&1 ||
  die "yosys failed on $dir: $(grep -m1 'ERROR:' "$work/yosys.log" || echo 'see its log')"
resized=$(grep -m1 'Resizing cell port' "$work/yosys.log" || true)
if [ -n "$resized" ]; then
  echo "port-widths: yosys: $resized" >&2
  exit 1
fi
