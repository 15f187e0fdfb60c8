#!/usr/bin/env bash
# MPI (issue 15): `mpirun -n K anchorbench-mpi run|sweep|calibrate|navigate|explore|pdop-study` writes the
# plain binary's bytes (run for K = 2 and 3 and 1 or 2 threads a rank, sweep, calibrate and navigate for
# K = 3, explore and pdop-study for K = 2); bad input
# ends every rank with exit 2 (no hang); a rank killed mid-run fails the job with no result
# folder, and --resume finishes it to the same bytes.
# Arguments: the plain anchorbench, anchorbench-mpi, the configs folder.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
mpi_bin="$2"
configs="$3"
# Oversubscribed (more ranks than this machine's cores), unbound (a rank's threads may use any core),
# and allowed as root (CI runs as root).
mpi() { timeout 120 mpirun --allow-run-as-root --oversubscribe --bind-to none -n "$@"; }

small_table "$dir/small.yaml"
"$bin" run "$dir/small.yaml" --out "$dir/plain" --quiet --threads 2 || fail "plain run"
for ranks in 2 3; do
  for threads in 1 2; do
    mpi "$ranks" "$mpi_bin" run "$dir/small.yaml" --out "$dir/mpi$ranks-$threads" --quiet --threads "$threads" \
      >/dev/null 2>&1 || fail "mpirun -n $ranks run"
    for file in attempts.csv summary.csv summary.md; do
      cmp -s "$dir/plain/$file" "$dir/mpi$ranks-$threads/$file" || fail "-n $ranks, $threads threads: $file differs"
    done
    echo "ok: mpirun -n $ranks, $threads threads a rank: the plain run's bytes"
  done
done

# The largest seed travels to the workers in the plan's text exactly (issue 22).
"$bin" run "$dir/small.yaml" --seed 9223372036854775807 --out "$dir/plain_big_seed" --quiet --threads 2 || fail "plain run"
mpi 2 "$mpi_bin" run "$dir/small.yaml" --seed 9223372036854775807 --out "$dir/mpi_big_seed" --quiet --threads 1 \
  >/dev/null 2>&1 || fail "mpirun -n 2 run --seed 2^63-1"
for file in attempts.csv summary.csv; do
  cmp -s "$dir/plain_big_seed/$file" "$dir/mpi_big_seed/$file" || fail "seed 2^63-1 under MPI: $file differs"
done
echo "ok: seed_2^63-1_round_trips_through_mpi_plans"

axis="estimator.trigger.pdop_threshold=0.5,1,2"
"$bin" sweep "$dir/small.yaml" --set "$axis" --out "$dir/sweep_plain" --quiet || fail "plain sweep"
mpi 3 "$mpi_bin" sweep "$dir/small.yaml" --set "$axis" --out "$dir/sweep_mpi" --quiet --threads 1 >/dev/null 2>&1 ||
  fail "mpirun sweep"
for file in sweep.csv sweep.md; do
  cmp -s "$dir/sweep_plain/$file" "$dir/sweep_mpi/$file" || fail "mpirun sweep: $file differs"
done
echo "ok: mpirun -n 3 sweep: the plain sweep's bytes"

# A calibration: every evaluation a plan of its own, sent to the workers.
for way in plain mpi; do
  mkdir -p "$dir/cal_$way"
  small_table "$dir/cal_$way/tiny.yaml"
  {
    printf 'experiment: tiny.yaml\nseed: 11\nrealizations: 3\nverify_seeds: [2]\n'
    printf 'global: {algorithm: GN_DIRECT_L, max_evaluations: 8}\nlocal: {algorithm: LN_SBPLX, max_evaluations: 4}\n'
    printf 'parameters:\n  - {key: scenario.tunnel.width_m, min: 6, max: 20, provenance: "a test"}\n'
  } >"$dir/cal_$way/cal.yaml"
done
"$bin" calibrate "$dir/cal_plain/cal.yaml" --out "$dir/cal_plain/out" --quiet --threads 2 || fail "plain calibrate"
mpi 3 "$mpi_bin" calibrate "$dir/cal_mpi/cal.yaml" --out "$dir/cal_mpi/out" --quiet --threads 1 >/dev/null 2>&1 ||
  fail "mpirun calibrate"
for file in out/evaluations.csv out/verification.csv out/calibration.md tiny.calibrated.yaml; do
  # The two name their own folder: the rest must be the same bytes.
  cmp -s <(sed "s#$dir/cal_plain#CAL#g" "$dir/cal_plain/$file") <(sed "s#$dir/cal_mpi#CAL#g" "$dir/cal_mpi/$file") ||
    fail "mpirun calibrate: $file differs"
done
echo "ok: mpirun -n 3 calibrate: the plain calibration's bytes"

# navigate and explore: their units handed out to the ranks like chunks (one study of record units each).
{ sed 's/^realizations: 5$/realizations: 3/' "$dir/small.yaml"; printf 'navigation: {}\n'; } >"$dir/navigated.yaml"
"$bin" navigate "$dir/navigated.yaml" --out "$dir/nav_plain" --quiet --threads 2 || fail "plain navigate"
explore="$configs/exploration_uav_hall.yaml"
"$bin" explore "$explore" --realizations 3 --out "$dir/ex_plain" --quiet --threads 2 || fail "plain explore"
mpi 3 "$mpi_bin" navigate "$dir/navigated.yaml" --out "$dir/nav_mpi" --quiet --threads 1 >/dev/null 2>&1 ||
  fail "mpirun navigate"
mpi 2 "$mpi_bin" explore "$explore" --realizations 3 --out "$dir/ex_mpi" --quiet --threads 2 >/dev/null 2>&1 ||
  fail "mpirun explore"
"$bin" pdop-study "$configs/pdop_study.yaml" --realizations 6 --every 20 --out "$dir/pdop_plain" --quiet ||
  fail "plain pdop-study"
mpi 2 "$mpi_bin" pdop-study "$configs/pdop_study.yaml" --realizations 6 --every 20 --out "$dir/pdop_mpi" --quiet \
  --threads 2 >/dev/null 2>&1 || fail "mpirun pdop-study"
for study in nav ex pdop; do
  for file in "$dir/${study}_plain"/*; do
    name=$(basename "$file")
    [ "$name" = manifest.json ] && continue
    cmp -s "$file" "$dir/${study}_mpi/$name" || fail "mpirun $study: $name differs"
  done
done
echo "ok: mpirun navigate (-n 3), explore and pdop-study (-n 2): the plain runs' bytes"

err=$(mpi 3 "$mpi_bin" run "$dir/missing.yaml" --out "$dir/never" 2>&1)
status=$?
[ "$status" -eq 2 ] || fail "bad input under mpirun: exit $status, expected 2"
grep -qF "missing.yaml: cannot open" <<<"$err" || fail "bad input under mpirun: $err"
echo "ok: bad input ends the job with exit 2"

# A rank killed mid-run: the job fails, nothing is presented as complete, and --resume finishes it.
table="$configs/table1.yaml"
"$bin" run "$table" --realizations 40 --out "$dir/table_plain" --quiet --threads 2 || fail "plain table run"
mpi 3 "$mpi_bin" run "$table" --realizations 40 --out "$dir/table" --quiet --threads 1 >"$dir/killed.log" 2>&1 &
job=$!
sleep 1.5
# A worker rank: one of the job's processes whose environment says it is not rank 0.
victim=""
for pid in $(pgrep -xf "$mpi_bin run $table --realizations 40 --out $dir/table --quiet --threads 1"); do
  tr '\0' '\n' <"/proc/$pid/environ" | grep -qx 'OMPI_COMM_WORLD_RANK=[1-9]' && victim=$pid
done
[ -n "$victim" ] && kill -9 "$victim" || fail "no worker rank found to kill"
wait "$job"
status=$?
[ "$status" -ne 0 ] || fail "a killed rank: mpirun exited 0"
grep -q "exited on signal 9" "$dir/killed.log" || fail "a killed rank: mpirun did not say which rank died: $(cat "$dir/killed.log")"
[ -e "$dir/table" ] && fail "a killed rank: $dir/table exists"
sleep 1
left=$(pgrep -af -- "--out $dir/table ")
[ -n "$left" ] && fail "a killed rank: processes left behind: $left"
echo "ok: a rank killed: exit $status, no result folder, $(grep -c '^chunk,' "$dir/table.chunks/chunks.csv") chunks kept"
mpi 2 "$mpi_bin" run "$table" --realizations 40 --out "$dir/table" --quiet --threads 2 --resume >/dev/null 2>&1 ||
  fail "mpirun --resume"
for file in attempts.csv summary.md; do
  cmp -s "$dir/table_plain/$file" "$dir/table/$file" || fail "resumed under MPI: $file differs"
done
echo "ok: resumed under MPI: the plain run's bytes"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all MPI cases passed"
