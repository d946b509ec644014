#!/usr/bin/env bash
# Synthesises Verilog with Yosys (synth_xilinx -abc9) and reports resources as a share of one part,
# the abc9 logic delay and LUT levels, and which memories did not become block RAM.
# Usage: scripts/synth-yosys.sh [--family xcup|xc7] [--part NAME] [--uram] [--hierarchical]
#                               [--top MODULE] [--log FILE] [--netlist FILE.json] [--kv]
#                               FILE.v|FILE.sv|filelist.f ...
# A filelist holds one path per line (relative to the filelist; '#' and '//' start comments).
# --netlist writes the mapped netlist (Yosys JSON), which `fpstereo synth` reads for the paths.
# --uram lets Yosys map large memories to UltraRAM (synth_xilinx -uram; parts that have it).
# --hierarchical maps each module once per parameter set, then flattens the mapped netlist: for
# designs too large to flatten first (less memory and time; no optimisation across modules).
# Exit status: 0 done, 2 bad usage, missing input or Yosys failure (one line on stderr).
set -euo pipefail

die() { echo "synth-yosys: $*" >&2; exit 2; }

family="" part="" top="" log="" netlist="" kv=0 uram=0 hierarchical=0
files=()
while [ $# -gt 0 ]; do
  case "$1" in
    --family|--part|--top|--log|--netlist)
      [ $# -ge 2 ] || die "$1 needs a value"
      case "$1" in
        --family) family=$2 ;; --part) part=$2 ;; --top) top=$2 ;; --log) log=$2 ;; --netlist) netlist=$2 ;;
      esac
      shift 2 ;;
    --kv) kv=1; shift ;;
    --uram) uram=1; shift ;;
    --hierarchical) hierarchical=1; shift ;;
    -h|--help) sed -n '2,12s/^# \{0,1\}//p' "$0"; exit 0 ;;
    -*) die "unknown option $1" ;;
    *) files+=("$1"); shift ;;
  esac
done

command -v yosys >/dev/null || die "yosys not found (Debian: apt-get install yosys)"

# The parts and their totals: constraints/fpga_parts.txt, the one table (fpstereo embeds it too).
part_table="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/constraints/fpga_parts.txt"
[[ -f $part_table && -r $part_table ]] || die "cannot read the part table $part_table"
# The rows, without the header and blank lines; the distinct values of column $1 in table order.
part_rows() { awk 'NF && $1 !~ /^#/' "$part_table"; }
column_values() { part_rows | awk -v c="$1" '!seen[$c]++ { printf "%s%s", sep, $c; sep = " " }'; }

families=$(column_values 2)
[ -z "$family" ] || [[ " $families " == *" $family "* ]] || die "unknown family '$family' ($families)"
# Without --part the part follows the family, so the percentages never mix families.
if [ -z "$part" ]; then
  part=$(part_rows | awk -v f="$family" 'f == "" || $2 == f { print $1; exit }')
fi
row=$(part_rows | awk -v p="$part" '$1 == p { print $2, $3, $4, $5, $6, $7, $8 }')
[ -n "$row" ] || die "unknown part '$part' ($(column_values 1))"
read -r part_family p_lut p_ff p_bram36 p_dsp p_lutram p_uram <<<"$row"
[ -z "$family" ] || [ "$family" = "$part_family" ] || die "part $part is $part_family, not $family"
family=$part_family
if [ $uram = 1 ] && [ "$p_uram" = 0 ]; then
  die "--uram: part $part has no UltraRAM (parts with it: $(part_rows | awk '$8 > 0 { printf "%s%s", s, $1; s = " " }'))"
fi

[ ${#files[@]} -gt 0 ] || die "no input files (try --help)"

# Expands filelists; every source must be readable before Yosys starts.
sources=()
add_source() { [[ -f $1 && -r $1 ]] || die "cannot read $1${2:+ (listed in $2)}"; sources+=("$1"); }
for f in "${files[@]}"; do
  if [[ "$f" == *.f ]]; then
    [[ -f $f && -r $f ]] || die "cannot read filelist $f"
    dir=$(dirname "$f")
    while IFS= read -r line || [ -n "$line" ]; do
      line=${line%%#*}; line=${line%%//*}
      line=$(echo "$line" | sed 's/^[[:space:]]*//; s/[[:space:]]*$//')
      [ -n "$line" ] || continue
      [[ "$line" == /* ]] || line="$dir/$line"
      add_source "$line" "$f"
    done <"$f"
  else
    add_source "$f"
  fi
done
[ ${#sources[@]} -gt 0 ] || die "no sources in ${files[*]}"

# Deferred reading (below) leaves Yosys no elaborated modules to pick a top from: without --top
# the top is the first module of the first source (fpstereo-rtl's filelist lists the top first).
if [ -z "$top" ]; then
  top=$(sed -n 's/^[[:space:]]*module[[:space:]]\{1,\}\([A-Za-z_][A-Za-z0-9_$]*\).*/\1/p' "${sources[0]}" | head -n 1)
  [ -n "$top" ] || die "no module in ${sources[0]}; pass --top"
fi

tmp=$(mktemp -d /tmp/synth-yosys.XXXXXX)
keep_log=1
trap 'rm -rf "$tmp"; [ $keep_log = 1 ] || rm -f "$log"' EXIT
# A signal ends the script through its EXIT trap, so nothing temporary stays behind.
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM
if [ -z "$log" ]; then
  log=$(mktemp /tmp/synth-yosys.XXXXXX.log); keep_log=0
else
  ( : >"$log" ) 2>/dev/null || die "cannot write log $log"; keep_log=1
fi
[ -z "$netlist" ] || ( : >"$netlist" ) 2>/dev/null || die "cannot write netlist $netlist"

# -flatten: one netlist, so abc9 sees (and times) paths across module boundaries, as Vivado's
# default flattening does. The run is split at 'coarse' only to list the memories (name, width,
# depth) while they are still memory objects. Any command between the halves may move ABC's
# LUT count by a few tenths of a percent (Yosys' internal ordering shifts); nothing else changes.
# --hierarchical instead maps each module once per parameter set, so a design of many identical
# lanes needs a fraction of the memory; the mapped netlist is flattened before it is counted and
# written, so every figure (and fpstereo's path depth) is of the whole design, but abc9 neither
# optimises nor times across module boundaries: LUTs and depth are at or above a flat run's.
synth="synth_xilinx -family $family -abc9${top:+ -top $top}"
[ $hierarchical = 1 ] || synth="$synth -flatten"
[ $uram = 0 ] || synth="$synth -uram"
# -defer: modules are elaborated only with the parameters they are instantiated with; elaborating
# a generic module with its defaults would reach generate branches whose submodules a
# configuration does not emit (e.g. the census lanes of a SAD design).
{
  for s in "${sources[@]}"; do
    if [[ "$s" == *.sv ]]; then echo "read_verilog -defer -sv \"$s\""; else echo "read_verilog -defer \"$s\""; fi
  done
  echo "$synth -run :coarse"
  echo "tee -q -o $tmp/mems.txt dump m:*"
  echo "$synth -run coarse:"
  [ $hierarchical = 0 ] || { echo "flatten"; echo "opt_clean"; }
  echo "tee -q -o $tmp/stat.txt stat -tech xilinx"
  [ -z "$netlist" ] || echo "write_json \"$netlist\""
} >"$tmp/run.ys"

status=0
yosys -q -l "$log" -s "$tmp/run.ys" >/dev/null 2>&1 || status=$?
if [ $status -ne 0 ]; then
  if [ $status -gt 128 ]; then  # killed: the kernel's out-of-memory killer sends SIGKILL
    err="killed by signal $((status - 128))$([ $status != 137 ] || echo ' (SIGKILL: out of memory?)')"
  else
    err=$(grep -m1 "ERROR:" "$log" || true)
  fi
  keep_log=1  # named in the message
  die "yosys failed: ${err:-see log} (log: $log)"
fi

# One awk pass over the three files emits key=value lines; the table is formatted from them.
report=$(awk -v part="$part" -v family="$family" -v p_lut="$p_lut" -v p_ff="$p_ff" \
    -v p_bram36="$p_bram36" -v p_dsp="$p_dsp" -v p_lutram="$p_lutram" -v p_uram="$p_uram" \
    -v hierarchical="$hierarchical" '
  function pct(n, d) { return sprintf("%.1f", d ? 100 * n / d : 0) }
  # A memory'"'"'s name: flat, its hierarchical name in the one module; with --hierarchical, one per
  # module and parameter set, named by the module and, for a parameterised one, its hash'"'"'s first
  # 8 digits ("$paramod$<hash>\\name"): "name$1a2b3c4d.mem".
  function mem_name(module, mem) {
    if (!hierarchical) return mem
    if (module ~ /^\$paramod\$/) {
      hash = substr(module, 10, 8); sub(/^[^\\]*\\/, "", module); module = module "$" hash
    }
    sub(/^\\/, "", module)
    return module "." mem
  }
  # LUTs each distributed-RAM or SRL primitive occupies (UG474, UG574).
  function lutram_luts(c) {
    if (c ~ /^(SRL16E?|SRLC16E?|SRLC32E|RAM(16|32|64)X1S(_1)?)$/) return 1
    if (c ~ /^(RAM(16|32|64)X1D(_1)?|RAM128X1S(_1)?|RAM(16|32|64)X2S)$/) return 2
    if (c ~ /^(RAM32M|RAM64M|RAM128X1D|RAM256X1S|RAM(16|32)X4S)$/) return 4
    if (c ~ /^(RAM32M16|RAM64M8|RAM256X1D|RAM512X1S|RAM64X8SW|RAM32X16DR8|RAM(16|32)X8S)$/) return 8
    return 0
  }
  FILENAME ~ /mems.txt$/ && $1 == "module" { module = $2; next }
  FILENAME ~ /mems.txt$/ && $1 == "memory" {
    w = s = 0
    for (i = 2; i < NF; i++) { if ($i == "width") w = $(i+1); if ($i == "size") s = $(i+1) }
    name = $NF; sub(/^\\/, "", name); name = mem_name(module, name)
    width[name] = w; depth[name] = s; order[++nmem] = name
    next
  }
  # stat lists each module; with kept hierarchy (keep_hierarchy) the "design hierarchy" section
  # follows with the totals over all instances: its first line names the top.
  FILENAME ~ /stat.txt$/ && /^=== design hierarchy ===$/ { split("", cnt); hier = 1; next }
  FILENAME ~ /stat.txt$/ && /^=== .* ===$/ { top = $2; next }
  FILENAME ~ /stat.txt$/ && hier == 1 && NF == 2 { top = $1; hier = 2; next }
  FILENAME ~ /stat.txt$/ && NF == 2 && $2 ~ /^[0-9]+$/ && $1 ~ /^[A-Z][A-Z0-9_]*$/ {
    cnt[$1] += $2; next
  }
  # memory_libmap names each memory and its target; what it leaves to FF mapping is logic.
  /^mapping memory .* via / {
    m = $3; mod = m; sub(/\..*/, "", mod); sub(/^[^.]*\./, "", m); m = mem_name(mod, m); t = $5
    map[m] = t ~ /BLOCKRAM/ ? "bram" : t ~ /LUTRAM/ ? "lutram" : t ~ /URAM/ ? "uram" : t
    if (!(m in width)) order[++nmem] = m
    next
  }
  /^using FF mapping for memory / {
    m = $6; mod = m; sub(/\..*/, "", mod); sub(/^[^.]*\./, "", m); m = mem_name(mod, m)
    map[m] = "ff"; if (!(m in width)) order[++nmem] = m; next
  }
  # abc9 prints one Del line per mapping round and one "Mapping (K=" summary per run: the last
  # Del before a summary is that run'"'"'s result.
  /^ABC: .*Del = / { for (i = 1; i < NF; i++) if ($i == "Del") del = $(i+2) + 0; next }
  /^ABC: Mapping \(K=/ {
    runs++; if (del > delay) delay = del
    for (i = 1; i < NF; i++) {
      if ($i == "lev" && $(i+2) + 0 > lev) lev = $(i+2) + 0
      if ($i == "levB" && $(i+2) + 0 > levb) levb = $(i+2) + 0
    }
  }
  END {
    for (c in cnt) {
      n = cnt[c]
      if (c ~ /^LUT[1-6]$/) lutk[substr(c, 4)] += n
      else if (c == "INV") lutk[1] += n       # Vivado implements a leftover INV as a LUT1
      else if (c ~ /^(FD[RSCP]E(_1)?|LD[CP]E)$/) ff += n
      else if (c ~ /^RAMB18E[12]$/) bram18 += n
      else if (c ~ /^RAMB36E[12]$/) bram36 += n
      else if (c ~ /^DSP48E[12]$/) dsp += n
      else if (c == "URAM288") uram += n
      else if (c == "CARRY4") carry4 += n
      else if (c == "CARRY8") carry8 += n
      else if (lutram_luts(c)) { lutram += n * lutram_luts(c); lutram_cells = lutram_cells " " c "x" n }
      if (c ~ /^LD[CP]E$/) latches += n
    }
    small = lutk[1] + lutk[2] + lutk[3] + lutk[4] + lutk[5]
    lut = small + lutk[6]
    lut_min = lutk[6] + int((small + 1) / 2)
    eq = bram36 + bram18 / 2
    print "top=" top; print "family=" family; print "part=" part; print "hierarchical=" hierarchical
    print "lut=" lut+0; print "lut_pct=" pct(lut, p_lut)
    printf "lut_by_inputs=%d/%d/%d/%d/%d/%d\n", lutk[1], lutk[2], lutk[3], lutk[4], lutk[5], lutk[6]
    print "lut_min=" lut_min; print "lut_min_pct=" pct(lut_min, p_lut)
    print "lutram=" lutram+0; print "lutram_pct=" pct(lutram, p_lutram)
    print "lutram_cells=" substr(lutram_cells, 2)
    print "lut_total=" lut + lutram; print "lut_total_pct=" pct(lut + lutram, p_lut)
    print "ff=" ff+0; print "ff_pct=" pct(ff, p_ff); print "latches=" latches+0
    print "bram18=" bram18+0; print "bram18_pct=" pct(bram18, 2 * p_bram36)
    print "bram36=" bram36+0; print "bram36_pct=" pct(bram36, p_bram36)
    print "bram36_equiv=" eq; print "bram36_equiv_pct=" pct(eq, p_bram36)
    print "uram=" uram+0; print "uram_pct=" pct(uram, p_uram)
    print "dsp=" dsp+0; print "dsp_pct=" pct(dsp, p_dsp)
    print "carry4=" carry4+0; print "carry8=" carry8+0
    print "carry4_equiv=" carry4 + 2 * carry8; print "carry_pct=" pct(carry4 + 2 * carry8, p_lut / 4)
    print "delay_ps=" (runs ? delay + 0 : "na"); print "levels=" (runs ? lev + 0 : "na")
    print "levels_with_carry=" (runs ? (levb ? levb : lev + 0) : "na"); print "abc9_runs=" runs+0
    print "part_lut=" p_lut; print "part_ff=" p_ff; print "part_bram36=" p_bram36
    print "part_dsp=" p_dsp; print "part_lutram=" p_lutram; print "part_uram=" p_uram
    for (k = 1; k <= nmem; k++) {
      m = order[k]; bits = width[m] * depth[m]
      dims = (m in width) ? depth[m] "x" width[m] : "?"
      to = (m in map) ? map[m] : "removed"
      print "mem." m "=" dims ":" to
      if (to != "bram" && to != "uram" && to != "removed" && bits > 4096)
        print "warning=memory " m " (" depth[m] " x " width[m] " = " bits " bits) became " \
          (to == "ff" ? "flip-flops" : toupper(to)) ", not block RAM" \
          (to == "lutram" ? " (Yosys uses BRAM only for a registered read)" : "")
    }
    if (latches) print "warning=" latches " latches (LDCE/LDPE), counted as FF"
  }' "$tmp/mems.txt" "$tmp/stat.txt" "$log")

# Warnings go to stderr in both formats, so stdout stays one format.
grep '^warning=' <<<"$report" | sed 's/^warning=/synth-yosys: warning: /' >&2 || true
if [ $kv = 1 ]; then
  grep -v '^warning=' <<<"$report"
  exit 0
fi

awk -F= '
  { v[$1] = substr($0, length($1) + 2) }
  $1 ~ /^mem\./ { mem[++n] = substr($1, 5); memv[n] = v[$1] }
  function row(name, used, avail, p, note) {
    printf "  %-13s %9s %8s %6s %%   %s\n", name, used, avail, p, note
  }
  END {
    printf "%s on %s (%s), Yosys synth_xilinx -abc9 %s\n", v["top"], v["part"], v["family"], \
      v["hierarchical"] ? "per module, then flattened" : "-flatten"
    printf "  %-13s %9s %8s %8s\n", "resource", "used", "of", "util"
    row("LUT", v["lut"], v["part_lut"], v["lut_pct"], "LUT1..LUT6 cells " v["lut_by_inputs"])
    row("LUT min", v["lut_min"], v["part_lut"], v["lut_min_pct"], "LUT6 + half of LUT1..5 (ideal pairing)")
    row("LUTRAM", v["lutram"], v["part_lutram"], v["lutram_pct"], "LUTs as memory: " (v["lutram_cells"] == "" ? "none" : v["lutram_cells"]))
    row("LUT+LUTRAM", v["lut_total"], v["part_lut"], v["lut_total_pct"], "like Vivado \"CLB LUTs\"")
    row("FF", v["ff"], v["part_ff"], v["ff_pct"], "FDRE/FDSE/FDCE/FDPE" (v["latches"] + 0 ? " + latches" : ""))
    row("BRAM18", v["bram18"], 2 * v["part_bram36"], v["bram18_pct"], "RAMB18E1/E2")
    row("BRAM36", v["bram36"], v["part_bram36"], v["bram36_pct"], "RAMB36E1/E2")
    row("BRAM36 equiv", v["bram36_equiv"], v["part_bram36"], v["bram36_equiv_pct"], "BRAM36 + BRAM18/2")
    row("URAM", v["uram"], v["part_uram"], v["uram_pct"], "URAM288")
    row("DSP", v["dsp"], v["part_dsp"], v["dsp_pct"], "DSP48E1/E2")
    row("CARRY4 equiv", v["carry4_equiv"], v["part_lut"] / 4, v["carry_pct"], \
        "CARRY4 " v["carry4"] " + 2 x CARRY8 " v["carry8"] " (4 carry bits per 4 LUTs)")
    printf "  %-13s %9s ps            abc9 model (7-series): clk-to-Q + LUTs + carry, no routing\n", "delay", v["delay_ps"]
    printf "  %-13s %9s               %s with carry chains\n", "LUT levels", v["levels"], v["levels_with_carry"]
    if (n) print "memories (words x bits -> mapped to):"
    for (i = 1; i <= n; i++) { split(memv[i], a, ":"); printf "  %-40s %12s -> %s\n", mem[i], a[1], a[2] }
  }' <<<"$report"
