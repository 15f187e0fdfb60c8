#!/usr/bin/env bash
# scripts/benchmarks.sh end to end on the programs of this build (--quick: the numbers mean
# nothing): every table is written, every registered solver is in the side-by-side table next to
# the Eigen baseline, and nothing is left behind when it stops half way.
set -euo pipefail
source_dir=$1
build_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bash "$source_dir/scripts/benchmarks.sh" --quick --build "$build_dir" --out "$work/benchmarks" >/dev/null
python=
compgen -G "$build_dir/python/anchorbench/_anchorbench*.so" >/dev/null && python=python.csv  # the Python module built
for file in solvers.csv solvers.md micro.csv table1_threads.csv machine.md $python; do
  [ -s "$work/benchmarks/$file" ] || { echo "missing $file"; exit 1; }
done
for solver in "eigen_dense_ls (baseline)" ls_single ls_double lm_l2 lm_huber lm_cauchy lm_adaptive nlopt:LN_BOBYQA \
  "ransac_minimal(lm_adaptive)" "ransac_full_solve(lm_adaptive)"; do
  for outliers in 5 10 20; do
    [ "$(grep -cF "$solver,10000,$outliers," "$work/benchmarks/solvers.csv")" = 1 ] ||
      { echo "no $solver at 10000 samples and $outliers% outliers"; exit 1; }
  done
done
grep -q "^bench_pdop,BM_ClosestPointPdopPerSample/1000000," "$work/benchmarks/micro.csv" || { echo "no PDOP row"; exit 1; }
[ "$(wc -l <"$work/benchmarks/table1_threads.csv")" = 3 ] || { echo "table1_threads.csv: expected 2 rows"; exit 1; }
csv="$work/benchmarks/cluster.csv"
[ "$(grep -c '^shards,' "$csv")" = 3 ] || { echo "cluster.csv: not 3 shard rows"; exit 1; }
grep -q ',0$' "$csv" && { echo "cluster.csv: results differ from the plain run's"; exit 1; }
# A bad option stops it before any work, with exit 2 and nothing written.
status=0
bash "$source_dir/scripts/benchmarks.sh" --bogus --out "$work/never" 2>/dev/null || status=$?
[ "$status" = 2 ] && [ ! -e "$work/never" ] || { echo "bad option: exit $status"; exit 1; }
[ -z "$(find "$work" -name '.benchmarks.partial-*')" ] || { echo "staging folder left behind"; exit 1; }
echo "benchmarks script ok"
