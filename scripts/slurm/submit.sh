#!/usr/bin/env bash
# Submits an anchorbench run or sweep as a Slurm array of N shards and a merge job that waits for
# all of them (afterok); prints the two job ids. The results go to OUT/merged.
#   scripts/slurm/submit.sh N OUT run configs/table1.yaml [options...]
#   scripts/slurm/submit.sh 16 sweeps/pdop sweep configs/table1.yaml --set estimator.trigger.pdop_threshold=0.5:3:0.25
# sbatch options go in SBATCH_* variables (SBATCH_PARTITION, SBATCH_TIMELIMIT, ...) or in the
# #SBATCH lines of shard.sbatch and merge.sbatch. Resubmitting the same line after a failure
# redoes only the shards that are not whole.
set -euo pipefail
if [ $# -lt 4 ] || ! [[ "$1" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 N OUT run|sweep CONFIG [options...]" >&2
  exit 2
fi
count="$1"
out="$2"
shift 2
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out/logs"
shards=$(sbatch --parsable --array="0-$((count - 1))" --output="$out/logs/shard-%a.log" \
  "$here/shard.sbatch" "$out" "$@")
merge=$(sbatch --parsable --dependency="afterok:${shards%%;*}" --output="$out/logs/merge.log" \
  "$here/merge.sbatch" "$out" "$count")
echo "shards: job ${shards%%;*} (array 0-$((count - 1))); merge: job ${merge%%;*} -> $out/merged"
