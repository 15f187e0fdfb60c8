#!/usr/bin/env bash
# Resume (issue 15): a run, sweep or shard killed with SIGKILL at any moment keeps its finished chunks in
# <out>.chunks/, leaves no result folder, and with --resume ends in the bytes of an uninterrupted
# run; a store of another run, or one left without --resume, is refused with the way out.
# Arguments: the anchorbench executable, the configs folder.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
configs="$2"

chunks_in() { grep -c '^chunk,' "$1/chunks.csv" 2>/dev/null || true; }  # the store's blocks (a torn one too)

# kill_after SECONDS OUT COMMAND...: starts the command, kills it with SIGKILL after SECONDS, and
# checks that it left no result folder but whole chunks.
kill_after() {
  local seconds="$1" out="$2" pid
  shift 2
  "$@" --quiet >/dev/null 2>&1 &
  pid=$!
  sleep "$seconds"
  kill -9 "$pid" 2>/dev/null || fail "$* finished before the kill: make it longer"
  wait "$pid" 2>/dev/null
  [ -e "$out" ] && fail "killed, $out exists"
  echo "ok: killed after ${seconds}s with $(chunks_in "$out.chunks") chunks kept"
}

table="$configs/table1.yaml"
# Small enough to be quick, long enough that a kill after 0.5-0.7 s finds some chunks done and
# some not (the output says how many were kept).
run_realizations=12
sweep_realizations=6
"$bin" run "$table" --realizations "$run_realizations" --out "$dir/whole" --quiet --threads 2 || fail "run"
kill_after 0.7 "$dir/run" "$bin" run "$table" --realizations "$run_realizations" --out "$dir/run" --threads 2
kill_after 0.7 "$dir/run" "$bin" run "$table" --realizations "$run_realizations" --out "$dir/run" --threads 1 --resume
"$bin" run "$table" --realizations "$run_realizations" --out "$dir/run" --quiet --threads 2 --resume || fail "resumed run"
for file in attempts.csv summary.csv summary.md; do
  cmp -s "$dir/whole/$file" "$dir/run/$file" || fail "resumed run: $file differs from the uninterrupted run's"
done
[ -e "$dir/run.chunks" ] && fail "the chunk store outlived the finished run"
echo "ok: a run killed twice and resumed writes the uninterrupted run's bytes"

axis="estimator.trigger.pdop_threshold=0.5,1"
"$bin" sweep "$table" --set "$axis" --realizations "$sweep_realizations" --out "$dir/sweep_whole" --quiet || fail "sweep"
kill_after 0.7 "$dir/sweep" "$bin" sweep "$table" --set "$axis" --realizations "$sweep_realizations" --out "$dir/sweep"
"$bin" sweep "$table" --set "$axis" --realizations "$sweep_realizations" --out "$dir/sweep" --quiet --resume || fail "resumed sweep"
for file in sweep.csv sweep.md; do
  cmp -s "$dir/sweep_whole/$file" "$dir/sweep/$file" || fail "resumed sweep: $file differs"
done
echo "ok: a killed sweep resumed writes the uninterrupted sweep's bytes"

kill_after 0.7 "$dir/left" "$bin" run "$table" --realizations "$run_realizations" --out "$dir/left" --threads 2
refused "an interrupted run's store without --resume" "finished chunks of an interrupted run: --resume" \
  "$dir/left" "$bin" run "$table" --realizations "$run_realizations" --out "$dir/left"
refused "another run's store with --resume" "holds chunks of another run" \
  "$dir/left" "$bin" run "$table" --realizations "$run_realizations" --seed 9 --out "$dir/left" --resume
refused "finished results without --overwrite" "--overwrite" "$dir/whole/never" \
  "$bin" run "$table" --realizations "$run_realizations" --out "$dir/whole" --resume
"$bin" run "$table" --realizations "$run_realizations" --seed 9 --out "$dir/left" --quiet --overwrite || fail "--overwrite"
[ -e "$dir/left.chunks" ] && fail "--overwrite left the old store"

# A shard resumes like a run: killed, resumed, merged with its sibling, the whole run's bytes.
kill_after 0.5 "$dir/shard0" "$bin" run "$table" --realizations "$run_realizations" --shard 0/2 --out "$dir/shard0" --threads 2
"$bin" run "$table" --realizations "$run_realizations" --shard 0/2 --out "$dir/shard0" --quiet --resume || fail "resumed shard"
"$bin" run "$table" --realizations "$run_realizations" --shard 1/2 --out "$dir/shard1" --quiet || fail "shard 1/2"
"$bin" merge "$dir/merged" "$dir/shard1" "$dir/shard0" --quiet || fail "merge"
cmp -s "$dir/whole/attempts.csv" "$dir/merged/attempts.csv" || fail "a resumed shard merged: attempts.csv differs"
echo "ok: a killed shard resumed merges to the whole run's bytes"

# navigate and explore keep their finished units in <out>.chunks/journal.csv: killed, resumed, the
# whole run's bytes; a journal edited after the kill is not trusted (its unit computed again, with
# a note).
journal_units() {
  local n
  n=$(grep -c '^unit,' "$1.chunks/journal.csv" 2>/dev/null)
  echo "${n:-0}"
}
# kill_at_units UNITS COMMAND CONFIG OUT ARGS...: the command (run whole first into OUT_whole) killed
# with SIGKILL once its journal holds UNITS units, then refused without --resume.
kill_at_units() {
  local units="$1" command="$2" config="$3" out="$4" pid
  shift 4
  "$bin" "$command" "$config" --out "${out}_whole" --quiet --threads 2 "$@" || fail "$command"
  "$bin" "$command" "$config" --out "$out" --quiet --threads 2 "$@" >/dev/null 2>&1 &
  pid=$!
  for _ in $(seq 1 100); do [ "$(journal_units "$out")" -ge "$units" ] && break; sleep 0.05; done
  kill -9 "$pid" 2>/dev/null || fail "$command finished before the kill: make it longer"
  wait "$pid" 2>/dev/null
  [ -e "$out" ] && fail "killed $command left a result folder"
  echo "ok: $command killed with $(journal_units "$out") units kept"
  refused "an interrupted $command's journal without --resume" "of an interrupted run: --resume" \
    "$out" "$bin" "$command" "$config" --out "$out" "$@"
}
# resumed_as_whole WHAT OUT FILE...: OUT's files are OUT_whole's, and its journal is gone.
resumed_as_whole() {
  local what="$1" out="$2" file
  shift 2
  for file in "$@"; do
    cmp -s "${out}_whole/$file" "$out/$file" || fail "resumed $what: $file differs from the uninterrupted run's"
  done
  [ -e "$out.chunks" ] && fail "the journal outlived the finished $what"
  echo "ok: a killed $what, resumed, writes the uninterrupted run's bytes"
}

nav="$configs/navigation_uav_hall.yaml"
kill_at_units 3 navigate "$nav" "$dir/nav" --realizations 60
# Edit the first unit's first value after its header: the unit's checksum no longer fits.
sed -i '2s/^\([0-9]*\),\([0-9]*\),\([a-z_]*\),\([0-9]\)/\1,\2,\3,9\4/' "$dir/nav.chunks/journal.csv"
"$bin" navigate "$nav" --realizations 60 --out "$dir/nav" --quiet --threads 1 --resume 2>"$dir/nav_note.txt" ||
  fail "resumed navigate"
grep -q "did not read back" "$dir/nav_note.txt" || fail "an edited journal resumed without a note: $(cat "$dir/nav_note.txt")"
resumed_as_whole "navigate (its journal edited)" "$dir/nav" navigation.csv navigation_summary.csv navigation_error.csv navigation.md

explore="$configs/exploration_uav_hall.yaml"
kill_at_units 2 explore "$explore" "$dir/ex" --realizations 16
"$bin" explore "$explore" --realizations 16 --out "$dir/ex" --quiet --threads 1 --resume || fail "resumed explore"
resumed_as_whole explore "$dir/ex" exploration.csv exploration_summary.csv exploration.md

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all resume cases passed"
