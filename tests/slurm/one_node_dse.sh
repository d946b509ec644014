#!/usr/bin/env bash
# The opt-in test of docs/cluster.md (ctest -L slurm): starts a one-node Slurm on this machine
# (munged, slurmctld, slurmd, all on their own socket, ports and folders), runs a small sweep as
# an array of 4 with scripts/dse-slurm.sh, checks that the merged CSV equals the same sweep on
# one machine and that a second array finds every record in the shared cache, then stops the
# daemons. Needs root and scripts/setup.sh --slurm.
#   tests/slurm/one_node_dse.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
root=$2
fail() { echo "slurm test: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "needs root: it starts munged, slurmctld and slurmd"
for tool in munged mungekey slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || fail "$tool not found: run scripts/setup.sh --slurm"
done

work=$(mktemp -d /tmp/fpstereo-slurm.XXXXXX)
pids=()
stop() {
  local status=$?
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [ $status -ne 0 ]; then
    for log in "$work"/*.out "$work"/*.log "$work"/cluster/logs/*.log; do
      [ -f "$log" ] && { echo "--- $log"; tail -n 15 "$log"; }
    done >&2
  fi
  rm -rf "$work"
}
trap stop EXIT

# munge, with a key and a socket of its own.
mungekey --create --keyfile="$work/munge.key"
munged --foreground --force --socket="$work/munge.sock" --key-file="$work/munge.key" \
  --log-file="$work/munged.log" --pid-file="$work/munged.pid" --seed-file="$work/munged.seed" >"$work/munged.out" 2>&1 &
pids+=($!)

host=$(hostname -s)
cpus=$(nproc)
export SLURM_CONF=$work/slurm.conf
mkdir -p "$work/state" "$work/spool"
cat >"$SLURM_CONF" <<CONF
ClusterName=fpstereo-test
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
AuthInfo=socket=$work/munge.sock
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
for _ in $(seq 50); do [ -S "$work/munge.sock" ] && break; sleep 0.1; done
[ -S "$work/munge.sock" ] || fail "munged did not start"
slurmctld -D -c >"$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D >"$work/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 60); do
  [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && break
  sleep 1
done
[ "$(sinfo -h -o %T 2>/dev/null)" = idle ] || fail "the node did not come up: sinfo says '$(sinfo -h -o %T 2>&1)'"

# A small sweep: 8 configurations, 8 distinct accuracy runs on Cones.
sweep=("$root/examples/cones" --cost census --window 3,5 --dmax 32,64 --median off,3 --refine none --uf 8
       --resolution 450x375 --jobs 1)
"$build/fpstereo" dse "${sweep[@]}" -o "$work/single.csv" --html '' --cache "$work/single-cache" >/dev/null 2>&1 ||
  fail "the sweep on one machine failed"

"$root/scripts/dse-slurm.sh" --tasks 4 --out "$work/cluster" --wait -- "${sweep[@]}" >/dev/null
for i in 1 2 3 4; do
  grep -q "in shard $i/4" "$work/cluster/logs/shard-$i.log" || fail "task $i did not run as shard $i/4"
done
# The same header and the same rows byte for byte; merge lists them shard by shard, the sweep in
# the order it enumerates them.
same_rows() { cmp <(head -n 1 "$1") <(head -n 1 "$2") && cmp <(tail -n +2 "$1" | sort) <(tail -n +2 "$2" | sort); }
same_rows "$work/single.csv" "$work/cluster/dse.csv" ||
  fail "the merged CSV differs from the one-machine sweep's: $(diff <(sort "$work/single.csv") <(sort "$work/cluster/dse.csv") | head -n 4)"
rows=$(($(wc -l <"$work/single.csv") - 1))
[ "$rows" -eq 8 ] || fail "the sweep has $rows rows, expected 8"
echo "the merged CSV of 4 array tasks has the one-machine sweep's $rows rows, byte for byte"

# Again: every task finds its records in the shared cache, and the result is the same.
cp "$work/cluster/dse.csv" "$work/first.csv"
"$root/scripts/dse-slurm.sh" --tasks 4 --out "$work/cluster" --wait -- "${sweep[@]}" >/dev/null
for i in 1 2 3 4; do
  grep -q "(0 evaluated, 2 cached)" "$work/cluster/logs/shard-$i.log" ||
    fail "task $i of the second array did not take its records from the cache: $(grep 'fpstereo dse:' "$work/cluster/logs/shard-$i.log")"
done
cmp "$work/first.csv" "$work/cluster/dse.csv" || fail "the second array's CSV differs from the first's"
echo "a second array took all 8 records from the shared cache; same CSV"
