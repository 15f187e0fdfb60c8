#!/usr/bin/env bash
# Runs the Google Benchmark programs and Table I (the paper's two columns, as cluster.csv) on 1 and
# 2 threads, and writes results/benchmarks/
# (or --out DIR): solvers.csv/.md (every registered solver and a plain Eigen dense LS on the same
# samples, as ratios), micro.csv (the per-sample costs), table1_threads.csv (speed-up),
# replay.csv (replay throughput and peak memory on logs of 1e6 and 1e7 ranges), live_latency.csv
# (the live front end as the ROS node steps it: range in to event out, AddRange), replay_triggers.csv
# (every trigger's replay of a long multi-tag log, as a ratio to the paper's), cluster.csv (Table I
# as 2, 4, 8 shards + merge and as MPI jobs, against the plain run) and machine.md
# (where it ran). Timings, not bytes: they differ from run to run, the ratios much less.
#   bash scripts/benchmarks.sh [--out DIR] [--quick] [--build DIR]
# --quick: a smoke run (numbers meaningless); --build DIR: use the programs built there, build nothing.
set -euo pipefail
cd "$(dirname "$0")/.."
out=results/benchmarks
min_time=0.2
repetitions=3
realizations=
replay_sizes="1e6 1e7"
python_ranges=1e6
live_duration_s=60
build=
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --quick) min_time=0.001; repetitions=1; live_duration_s=5; realizations="--realizations 2"; replay_sizes="1e4 1e5"; python_ranges=1e4; shift ;;
    --build) build=$2; shift 2 ;;
    *) echo "benchmarks.sh: unknown option $1 (--out DIR, --quick, --build DIR)" >&2; exit 2 ;;
  esac
done
benches="bench_compare bench_solver bench_pdop bench_filters bench_triggers bench_front_end bench_guidance bench_ingest"
if [ -z "$build" ]; then
  build=build
  bash scripts/build.sh anchorbench anchorbench-mpi _anchorbench $benches bench_live  # anchorbench-mpi: cluster.csv; _anchorbench: python.csv
fi
mkdir -p "$(dirname "$out")"
staging=$(mktemp -d "$(dirname "$out")/.$(basename "$out").partial-XXXXXX")
trap 'rm -rf "$staging"' EXIT

for bench in $benches; do
  "$build/bench/$bench" --benchmark_min_time="$min_time" --benchmark_repetitions="$repetitions" \
    --benchmark_report_aggregates_only=true --benchmark_format=json >"$staging/$bench.json"
done
# The live front end's latency (a minute at the log's rate, then 10x, then unpaced).
"$build/bench/bench_live" --duration-s "$live_duration_s" --out "$staging/live_latency.csv"
for threads in 1 2; do
  # shellcheck disable=SC2086  # $realizations is empty or two words
  "$build/app/anchorbench" run configs/table1.yaml --threads "$threads" --quiet $realizations \
    --set 'estimator.triggers=[fixed_window,pdop_closest_point]' --out "$staging/table1_threads_$threads"
done
# shellcheck disable=SC2086  # $replay_sizes is a list
/usr/bin/python3 scripts/replay_throughput.py "$build/app/anchorbench" "$staging" $replay_sizes
/usr/bin/python3 scripts/replay_triggers.py "$build/app/anchorbench" "$staging" "$repetitions"
# shellcheck disable=SC2086  # $realizations is empty or two words
if compgen -G "$build/python/anchorbench/_anchorbench*.so" >/dev/null; then  # built with ANCHORBENCH_PYTHON
  PYTHONPATH="$build/python" /usr/bin/python3 scripts/python_overhead.py "$build/app/anchorbench" "$staging" "$python_ranges"
fi
/usr/bin/python3 scripts/cluster_overhead.py "$build/app/anchorbench" "$staging" $realizations
/usr/bin/python3 scripts/benchmark_tables.py "$staging"
rm -rf "$staging"/*.json "$staging"/table1_threads_*
chmod 755 "$staging"  # mktemp -d makes it private
rm -rf "$out"
mv "$staging" "$out"
trap - EXIT
echo "benchmarks written to $out/"
