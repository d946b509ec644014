#!/usr/bin/env bash
# Runs `fpstereo dse` as a Slurm job array and merges the shards (docs/cluster.md):
#   scripts/dse-slurm.sh [--tasks N] [--out DIR] [--wait] [--sbatch "OPTIONS"] -- DSE ARGUMENTS
# DIR (default out/dse-slurm, on a folder every node sees) receives shard-<i>.csv per task, the
# shared caches (DIR/cache: accuracy records and, with --yosys-front, Yosys reports), the logs
# (DIR/logs) and, from a job that runs after every task succeeded, the merged DIR/dse.csv and
# DIR/dse.html. The DSE arguments are those of `fpstereo dse` (dataset folders, axes,
# constraints, --yosys-front ...) without --shard, -o/--csv, --html and --cache, which this sets.
# --sbatch passes options to both sbatch calls (partition, account, time limit). --wait returns
# when the merge is done, with its status. Prints the two job ids. Exits 2 for bad arguments, 1
# when sbatch fails (or, with --wait, the sweep does).
set -euo pipefail
fail() { echo "dse-slurm: $*" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
fpstereo=$root/build/fpstereo
tasks=4
out=out/dse-slurm
wait=
sbatch_options=()
while [ $# -gt 0 ]; do
  case $1 in
    --tasks) tasks=${2:-}; shift 2 ;;
    --out) out=${2:-}; shift 2 ;;
    --wait) wait=--wait; shift ;;
    --sbatch) read -r -a sbatch_options <<<"${2:-}"; shift 2 ;;
    --) shift; break ;;
    *) fail "unknown option '$1' (the dse arguments go after --)" ;;
  esac
done
[[ $tasks =~ ^[1-9][0-9]*$ ]] || fail "--tasks '$tasks': expected a positive number"
[ $# -gt 0 ] || fail "no dse arguments after -- (at least a dataset folder)"
for a in "$@"; do
  case $a in
    --shard|--shard=*|-o|--csv|--csv=*|--html|--html=*|--cache|--cache=*) fail "'$a' is set by this script" ;;
  esac
done
[ -x "$fpstereo" ] || fail "$fpstereo not found: build the project first (scripts/build.sh)"
command -v sbatch >/dev/null || fail "sbatch not found: no Slurm here (scripts/setup.sh --slurm installs it)"
mkdir -p "$out/logs" "$out/cache"
out=$(cd "$out" && pwd)
rm -f "$out"/shard-*.csv "$out/dse.csv" "$out/dse.html"

# Both caches under one shared folder: --cache for the accuracy records, XDG_CACHE_HOME for
# `fpstereo synth` (which --yosys-front runs). Records are written whole and renamed into place,
# so tasks on several nodes may fill them at once.
export XDG_CACHE_HOME=$out/cache
q() { printf ' %q' "$@"; }
array=$(sbatch --parsable --job-name=fpstereo-dse --array=1-"$tasks" --output="$out/logs/shard-%a.log" \
  "${sbatch_options[@]}" \
  --wrap "exec$(q "$fpstereo" dse --shard auto --cache "$out/cache/dse" --html '') -o $(q "$out")/shard-\${SLURM_ARRAY_TASK_ID}.csv$(q "$@")")
array=${array%%;*}

# The merge takes the report's options (part, constraints, --yosys-front: Yosys runs again only
# where no shard did, the rest are cache hits).
report=()
while [ $# -gt 0 ]; do
  case $1 in
    --yosys-front) report+=("$1"); shift ;;
    --part|--max-lut|--max-ff|--max-bram|--max-dsp|--min-fps|--top|--yosys-limit) report+=("$1" "${2:-}"); shift 2 ;;
    --part=*|--max-*=*|--min-fps=*|--top=*|--yosys-limit=*) report+=("$1"); shift ;;
    *) shift ;;
  esac
done
shards=()
for i in $(seq 1 "$tasks"); do shards+=("$out/shard-$i.csv"); done
merge=$(sbatch --parsable --job-name=fpstereo-dse-merge --dependency=afterok:"$array" --kill-on-invalid-dep=yes \
  --output="$out/logs/merge.log" $wait "${sbatch_options[@]}" \
  --wrap "exec$(q "$fpstereo" dse merge "${shards[@]}" -o "$out/dse.csv" --html "$out/dse.html" "${report[@]}")") ||
  { echo "dse-slurm: the sweep failed: see $out/logs" >&2; exit 1; }
echo "dse-slurm: array job $array ($tasks tasks), merge job ${merge%%;*}; results in $out/dse.csv"
