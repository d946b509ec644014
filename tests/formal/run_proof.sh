#!/usr/bin/env bash
# One formal proof with Yosys + yosys-smtbmc + z3 (tests/formal/, ctest -L formal):
#   run_proof.sh [options] <wrapper module> <verilog file>...
#   --depth N        bounded model check of N steps (default 20)
#   --induction K    also k-induction over K steps (the properties hold in every reachable state)
#   --mutate FILE SED  prove against a copy of FILE (one of the files) with the sed expression
#                    applied; the proof must then FAIL (exit 0 when it does, 1 when it passes)
#   --work DIR       where the SMT2 file and logs go (default: a temporary directory)
#   --define NAME=VALUE  a Verilog define for read_verilog
# A wrapper may read a submodule's internal signal for the induction: a line
#   // formal-probe: <wire of the wrapper> <instance>.<signal>
# connects that (undriven) wire to the flattened instance's signal.
# Exit 0: proven (or, with --mutate, refuted); 1: the property failed (or the mutant passed);
# 2: usage or tool error.
set -uo pipefail

depth=20
induction=0
mutate_file=""
mutate_sed=""
work=""
defines=""
while [ $# -gt 0 ]; do
  case "$1" in
    --depth) depth="$2"; shift 2 ;;
    --induction) induction="$2"; shift 2 ;;
    --mutate) mutate_file="$2"; mutate_sed="$3"; shift 3 ;;
    --work) work="$2"; shift 2 ;;
    --define) defines+=" -D$2"; shift 2 ;;
    -*) echo "run_proof: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || { echo "usage: run_proof.sh [options] <wrapper> <file>..." >&2; exit 2; }
top="$1"; shift
for tool in yosys yosys-smtbmc z3; do
  command -v "$tool" >/dev/null || { echo "run_proof: $tool not found (scripts/setup.sh installs it)" >&2; exit 2; }
done
if [ -z "$work" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"

# the rules the wrappers share
files=("$(cd "$(dirname "$0")" && pwd)/formal_rules.v")
mutated=0
for f in "$@"; do
  [ -f "$f" ] || { echo "run_proof: no file $f" >&2; exit 2; }
  if [ -n "$mutate_file" ] && [ "$(basename "$f")" = "$(basename "$mutate_file")" ]; then
    copy="$work/$(basename "$f")"
    sed -e "$mutate_sed" "$f" >"$copy"
    if cmp -s "$f" "$copy"; then
      echo "run_proof: the mutation '$mutate_sed' changes nothing in $f" >&2
      exit 2
    fi
    echo "run_proof: mutant of $(basename "$f"):"
    diff "$f" "$copy" | sed 's/^/  /'
    files+=("$copy")
    mutated=1
  else
    files+=("$f")
  fi
done
if [ -n "$mutate_file" ] && [ $mutated -eq 0 ]; then
  echo "run_proof: $mutate_file is not among the files" >&2
  exit 2
fi

probes=""
while read -r wire signal; do
  probes+="connect -nounset -set $wire $signal; "
done < <(sed -n 's|^[[:space:]]*// formal-probe:[[:space:]]*\([^[:space:]]*\)[[:space:]]*\([^[:space:]]*\).*|\1 \2|p' "${files[@]}")

smt="$work/$top.smt2"
if ! yosys -q -l "$work/yosys.log" -p "read_verilog -formal${defines} ${files[*]}; hierarchy -check -top $top; proc; flatten; ${probes}prep -top $top; async2sync; dffunmap; write_smt2 -wires $smt" >/dev/null 2>&1; then
  echo "run_proof: yosys failed:" >&2
  grep -i -E "error" "$work/yosys.log" >&2
  exit 2
fi

# run_smtbmc <label> <args>: 0 passed, 1 failed, 2 tool error
run_smtbmc() {
  local label="$1"; shift
  local log="$work/$label.log"
  local start=$SECONDS
  yosys-smtbmc -s z3 --unroll "$@" --dump-vcd "$work/$label.vcd" "$smt" >"$log" 2>&1
  local rc=$?
  if grep -q "Status: PASSED" "$log"; then
    echo "run_proof: $top $label: PASSED ($((SECONDS - start)) s)"
    return 0
  elif grep -q "Status: FAILED" "$log"; then
    echo "run_proof: $top $label: FAILED ($((SECONDS - start)) s)"
    grep -oE "Assert failed.*|Temporal induction failed!|BMC failed!|Assumptions are unsatisfiable!" "$log" | sort -u | head -4 | sed 's/^/  /'
    return 1
  fi
  echo "run_proof: $top $label: yosys-smtbmc error (exit $rc):" >&2
  tail -5 "$log" >&2
  return 2
}

result=0
run_smtbmc "bmc-$depth" -t "$depth"
result=$?
if [ $result -eq 0 ] && [ "$induction" -gt 0 ]; then
  run_smtbmc "induction-$induction" -i -t "$induction"
  result=$?
fi

if [ -n "$mutate_file" ]; then
  case $result in
    0) echo "run_proof: the mutant of $(basename "$mutate_file") passed the proof: the properties miss the bug"; exit 1 ;;
    1) echo "run_proof: the mutant is refuted, as it should be"; exit 0 ;;
    *) exit 2 ;;
  esac
fi
exit $result
