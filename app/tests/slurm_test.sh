#!/usr/bin/env bash
# scripts/slurm/ against a real Slurm (issue 15): the test starts munged, slurmctld and slurmd on
# localhost in a scratch folder (its own key, socket, ports and state), submits a 3-shard array
# with its dependent merge through submit.sh (twice: the second keeps the whole shards), and an MPI
# job of one rank per core through mpi.sbatch, and checks both
# results against the plain run byte for byte. It stops the daemons it started, by their pids.
# Skips (exit 77) with the reason only when the daemons are not installed or cannot start.
# Arguments: anchorbench, anchorbench-mpi, the source folder.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
mpi_bin="$2"
source_dir="$3"
skip() { echo "SKIP: $*"; exit 77; }

for tool in munged slurmctld slurmd sbatch sinfo scontrol; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (scripts/setup.sh installs slurm-wlm and munge)"
done
pids=()
# Lets the jobs end first (a batch step reports to slurmctld after its files are written), then
# stops the daemons the test started, and any step daemon of this test's jobs (run in its folder).
stop_daemons() {
  for _ in $(seq 60); do
    [ -z "$(squeue -h 2>/dev/null)" ] && break
    sleep 0.5
  done
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in $(pgrep -x slurmstepd); do
    [[ "$(readlink "/proc/$pid/cwd")" == "$dir"* ]] && kill -9 "$pid" 2>/dev/null  # it ignores SIGTERM
  done
  rm -rf "$dir"
}
trap stop_daemons EXIT

# The daemons, each with its pid file in the scratch folder.
slurm="$dir/slurm"
mkdir -p "$slurm/state" "$slurm/spool"
head -c 1024 /dev/urandom >"$slurm/munge.key"
chmod 600 "$slurm/munge.key"
munged --force --socket="$slurm/munge.socket" --key-file="$slurm/munge.key" --log-file="$slurm/munged.log" \
  --pid-file="$slurm/munged.pid" --seed-file="$slurm/munged.seed" || skip "munged does not start: $(cat "$slurm/munged.log")"
pids+=("$(cat "$slurm/munged.pid")")
port=$((20000 + RANDOM % 20000))
host=$(hostname -s)
cat >"$slurm/slurm.conf" <<CONF
ClusterName=anchorbench-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$slurm/munge.socket
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
StateSaveLocation=$slurm/state
SlurmdSpoolDir=$slurm/spool
SlurmctldPidFile=$slurm/slurmctld.pid
SlurmdPidFile=$slurm/slurmd.pid
SlurmctldLogFile=$slurm/slurmctld.log
SlurmdLogFile=$slurm/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$(free -m | awk '/^Mem:/ {print int($2 * 0.9)}') State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP OverSubscribe=FORCE
CONF
export SLURM_CONF="$slurm/slurm.conf"
slurmctld -f "$SLURM_CONF" || skip "slurmctld does not start: $(tail -n 5 "$slurm/slurmctld.log")"
for _ in $(seq 50); do [ -s "$slurm/slurmctld.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$slurm/slurmctld.pid")")
slurmd -f "$SLURM_CONF" || skip "slurmd does not start: $(tail -n 5 "$slurm/slurmd.log")"
for _ in $(seq 50); do [ -s "$slurm/slurmd.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$slurm/slurmd.pid")")
for _ in $(seq 60); do
  sinfo -h -o %t 2>/dev/null | grep -qx idle && break
  sleep 0.5
done
sinfo -h -o %t | grep -qx idle || skip "the node does not come up: $(tail -n 5 "$slurm/slurmd.log")"
echo "ok: munged, slurmctld and slurmd up on port $port"

# wait_for FILE SECONDS: until FILE exists; fails after SECONDS, or as soon as the queue is empty
# without it (a job that failed).
wait_for() {
  for _ in $(seq $(($2 * 2))); do
    [ -e "$1" ] && return 0
    if [ -z "$(squeue -h 2>/dev/null)" ]; then
      sleep 1
      [ -e "$1" ] && return 0
      break
    fi
    sleep 0.5
  done
  fail "no $1: $(squeue 2>&1; tail -n 3 "$slurm/slurmctld.log"; cat "$dir"/*/logs/*.log "$dir"/*.log 2>/dev/null | tail -n 20)"
  return 1
}

small_table "$dir/small.yaml"
"$bin" run "$dir/small.yaml" --out "$dir/plain" --quiet --threads 2 || fail "plain run"
# job WHAT FILE COMMAND...: submits with COMMAND, then waits for FILE; false (and a failure) if
# either fails.
job() {
  local what="$1" file="$2"
  shift 2
  "$@" >"$dir/submit.log" 2>&1 || { fail "$what: not submitted: $(cat "$dir/submit.log")"; return 1; }
  wait_for "$file" 120
}
submit=("$source_dir/scripts/slurm/submit.sh" 3 "$dir/array" run "$dir/small.yaml")
if job "array" "$dir/array/merged/summary.md" env ANCHORBENCH="$bin" bash "${submit[@]}"; then
  for file in attempts.csv summary.csv summary.md; do
    cmp -s "$dir/plain/$file" "$dir/array/merged/$file" || fail "array + merge: $file differs from the plain run's"
  done
  echo "ok: a 3-shard array and its dependent merge give the plain run's bytes"
fi

# Resubmitted, the whole shards are kept: only the merge runs again (into a new folder).
rm -rf "$dir/array/merged"
if job "array again" "$dir/array/merged/summary.md" env ANCHORBENCH="$bin" bash "${submit[@]}"; then
  grep -q "is whole already" "$dir/array/logs/shard-1.log" || fail "a resubmitted shard ran again"
  cmp -s "$dir/plain/summary.md" "$dir/array/merged/summary.md" || fail "resubmitted: summary.md differs"
  echo "ok: resubmitted, the whole shards are kept"
fi

if [ -x "$mpi_bin" ]; then
  if job "MPI" "$dir/mpi/summary.md" env ANCHORBENCH_MPI="$mpi_bin" sbatch --ntasks="$(nproc)" --cpus-per-task=1 \
    --output="$dir/mpi.log" "$source_dir/scripts/slurm/mpi.sbatch" run "$dir/small.yaml" --out "$dir/mpi"; then
    cmp -s "$dir/plain/attempts.csv" "$dir/mpi/attempts.csv" || fail "MPI under Slurm: attempts.csv differs"
    echo "ok: an MPI job under Slurm gives the plain run's bytes"
  fi
fi

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all Slurm cases passed"
