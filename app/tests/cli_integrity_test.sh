#!/usr/bin/env bash
# Nothing lost, nothing mixed, nothing accepted that was tampered with (issue 22): one case per
# finding of the audit, named after the promise it keeps. Seeds round-trip exactly; chunk files and
# evaluation logs carry what identifies them and a checksum; merge checks every folder; no command
# removes or replaces a file it reads; errors inside the parallel work end in exit 2 with one line;
# hostile inputs (alias bombs, a million anchors, one time stamp for every row) are refused early.
# Arguments: the anchorbench executable, the configs folder.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
configs="$2"
mounted=""
trap '[ -n "$mounted" ] && umount "$mounted" 2>/dev/null; rm -rf "$dir"' EXIT

small_table "$dir/small.yaml"
run() { "$bin" run "$dir/small.yaml" --realizations 2 --quiet --threads 2 "$@"; }
same() {  # WHAT FOLDER_A FOLDER_B FILE...: the files are byte-identical
  local what="$1" a="$2" b="$3" file
  shift 3
  for file in "$@"; do cmp -s "$a/$file" "$b/$file" || { fail "$what: $file differs"; return; }; done
  echo "ok: $what"
}
fnv1a64() { /usr/bin/python3 -c '
import sys
h = 0xcbf29ce484222325
for b in sys.argv[1].encode():
    h = ((h ^ b) * 0x100000001b3) % (1 << 64)
print("%016x" % h)' "$1"; }

# --- Seeds: every seed the command line accepts round-trips exactly ---------------------------
for seed in 0 2147483648 4294967301 9223372036854775807; do
  run --seed "$seed" --out "$dir/seed$seed" || fail "run --seed $seed"
  [ "$(grep -c "\"seed\": $seed,\$" "$dir/seed$seed/manifest.json")" -eq 2 ] ||
    fail "seed_${seed}_in_the_manifest_and_its_resolved_config: $(grep '"seed"' "$dir/seed$seed/manifest.json")"
  run --seed "$seed" --shard 0/2 --out "$dir/seed$seed-0" && run --seed "$seed" --shard 1/2 --out "$dir/seed$seed-1" ||
    fail "shards at seed $seed"
  grep -qx "seed: $seed" "$dir/seed$seed-0/config.yaml" || fail "seed_${seed}_in_the_shard_config: $(grep seed "$dir/seed$seed-0/config.yaml")"
  "$bin" merge "$dir/seed$seed-m" "$dir/seed$seed-0" "$dir/seed$seed-1" --quiet || fail "merge at seed $seed"
  same "seed_${seed}_round_trips_through_shards_and_merge" "$dir/seed$seed" "$dir/seed$seed-m" attempts.csv summary.csv
done
run --seed 5 --out "$dir/seed5" || fail "run --seed 5"
cmp -s "$dir/seed5/attempts.csv" "$dir/seed4294967301/attempts.csv" && fail "seed_2^32+5_is_not_seed_5: the same attempts"
run --seed 5 --shard 1/2 --out "$dir/seed5-1" || fail "shard at seed 5"
refused "shards_of_seeds_2^32+5_and_5_do_not_merge" "is of another run" "$dir/mixed" \
  "$bin" merge "$dir/mixed" "$dir/seed4294967301-0" "$dir/seed5-1"
printf 'base: small.yaml\nseed: 4294967301\n' >"$dir/big_seed.yaml"
"$bin" run "$dir/big_seed.yaml" --realizations 2 --quiet --out "$dir/yaml_seed" || fail "a seed of 2^32+5 in YAML"
same "a_seed_of_2^32+5_in_yaml_is_the_command_lines" "$dir/seed4294967301" "$dir/yaml_seed" attempts.csv summary.csv
printf 'base: small.yaml\nseed: 9223372036854775808\n' >"$dir/huge_seed.yaml"
expect_exit 2 "a_seed_beyond_2^63-1_in_yaml_is_refused" "key 'seed'" "$bin" run "$dir/huge_seed.yaml" --out "$dir/x"

# A store of another seed (made from a shard folder's chunks) is not resumed by 2^32+5.
make_store() {  # SHARD_FOLDER OUT [WAY]: a chunk store for OUT holding the shard's chunks, chunk 2 damaged the WAY way
  local parts="$2.parts" file
  mkdir -p "$2.chunks" "$parts"
  cp "$1"/chunk-*.csv "$parts/"
  [ -n "${3:-}" ] && tamper "$3" "$parts/chunk-000002.csv"
  for file in "$parts"/chunk-*.csv; do  # the store's blocks: chunk,<index>,<bytes>, and the chunk's text
    printf 'chunk,%d,%d,\n' "$((10#$(basename "$file" .csv | cut -d- -f2)))" "$(wc -c <"$file")"
    cat "$file"
  done >"$2.chunks/chunks.csv"
  rm -r "$parts"
  printf 'identity,chunks,units\n%s,0,0\n' "$(tail -1 "$1/shard.csv" | cut -d, -f6)" >"$2.chunks/plan.csv"
}
run --seed 5 --shard 0/1 --out "$dir/seed5-all" || fail "one shard of all chunks"
make_store "$dir/seed5-all" "$dir/resumed_seed"
refused "a_store_of_seed_5_is_not_resumed_by_seed_2^32+5" "holds chunks of another run" "$dir/resumed_seed" \
  run --seed 4294967301 --out "$dir/resumed_seed" --resume
rm -rf "$dir/resumed_seed.chunks"

# --- Chunks carry their plan, index and checksum ----------------------------------------------
run --seed 6 --shard 0/1 --out "$dir/seed6-all" || fail "shard at seed 6"
tamper() {  # NAME FILE: one way of damaging a chunk file
  case "$1" in
    swapped_lines) awk 'NR == 4 { held = $0; next } NR == 5 { print; print held; next } { print }' "$2" >"$2.new" ;;
    edited_value) awk 'NR == 4 { c = substr($0, length($0), 1); $0 = substr($0, 1, length($0) - 1) (c == "1" ? "2" : "1") } { print }' "$2" >"$2.new" ;;
    blank_line) sed '4a\\' "$2" >"$2.new" ;;
    other_seed) cp "$dir/seed6-all/$(basename "$2")" "$2.new" ;;
    renumbered) cp "$(dirname "$2")/chunk-000000.csv" "$2.new" ;;
  esac
  cmp -s "$2" "$2.new" && fail "tamper $1 changed nothing in $2"
  mv "$2.new" "$2"
}
for way in swapped_lines edited_value blank_line other_seed renumbered; do
  rm -rf "$dir/t0" "$dir/t1"
  cp -r "$dir/seed5-1" "$dir/t1"
  run --seed 5 --shard 0/2 --out "$dir/t0" || fail "shard 0/2"
  tamper "$way" "$dir/t0/chunk-000002.csv"
  refused "merge_refuses_a_chunk_with_${way}" "chunk-000002.csv" "$dir/m_$way" "$bin" merge "$dir/m_$way" "$dir/t0" "$dir/t1"
  make_store "$dir/seed5-all" "$dir/r_$way" "$way"
  err=$(run --seed 5 --out "$dir/r_$way" --resume 2>&1 >/dev/null) || fail "resume over a chunk with $way: $err"
  grep -q "computing them again" <<<"$err" || fail "resume_recomputes_a_chunk_with_${way}: no note: $err"
  same "resume_recomputes_a_chunk_with_${way}" "$dir/seed5" "$dir/r_$way" attempts.csv summary.csv
done
# A store whose file is a folder: refused before any work, naming it. (A chunk that cannot be
# appended mid-run, past the space claimed up front, ends the worker threads with the error:
# LocalExecutor.AnErrorWhileKeepingAChunkEndsTheCall; the CLI offers no way to cause it.)
make_store "$dir/seed5-all" "$dir/r_folder"
rm "$dir/r_folder.chunks/chunks.csv" && mkdir -p "$dir/r_folder.chunks/chunks.csv/x"
expect_exit 2 "a_store_file_that_is_a_folder_is_refused_before_work" "chunks.csv: is not a file" \
  run --seed 5 --out "$dir/r_folder" --resume
[ -e "$dir/r_folder" ] && fail "a_store_file_that_is_a_folder: a result folder was written"
cp -r "$dir/seed5-1" "$dir/f1" && rm "$dir/f1/chunk-000003.csv" && mkdir "$dir/f1/chunk-000003.csv"
run --seed 5 --shard 0/2 --out "$dir/f0" || fail "shard 0/2"
expect_exit 2 "merge_of_a_chunk_path_that_is_a_folder" "chunk-000003.csv" "$bin" merge "$dir/fm" "$dir/f0" "$dir/f1"

# --- merge checks every folder, in any order ---------------------------------------------------
cp -r "$dir/seed5-1" "$dir/g1"
printf 'garbage: [\n' >"$dir/g1/config.yaml"
rm "$dir/g1/axes.txt"
refused "merge_checks_the_second_folders_config" "g1" "$dir/gm" "$bin" merge "$dir/gm" "$dir/f0" "$dir/g1"
refused "merge_checks_the_first_folders_config" "g1" "$dir/gm" "$bin" merge "$dir/gm" "$dir/g1" "$dir/f0"
refused "merge_output_inside_a_shard_folder" "inside" "$dir/f0/m" "$bin" merge "$dir/f0/m" "$dir/f0" "$dir/seed5-1"

# --- Configs: what they say is what runs --------------------------------------------------------
refused "sweep_realizations_axis_and_option_conflict" "--realizations" "$dir/x" \
  "$bin" sweep "$dir/small.yaml" --set realizations=1,2 --realizations 1 --out "$dir/x" --quiet
printf 'seed: 1\n---\nseed: 2\n' >"$dir/two_docs.yaml"
refused "a_second_yaml_document_is_refused" "two_docs.yaml:3: a second YAML document" "$dir/x" \
  "$bin" run "$dir/two_docs.yaml" --out "$dir/x"
printf 'base: small.yaml\nrows:\n  - name: "b\\nc"\n' >"$dir/newline_row.yaml"
refused "a_row_name_with_a_newline_is_refused" "key 'rows[0].name'" "$dir/x" "$bin" run "$dir/newline_row.yaml" --out "$dir/x"
printf 'base: small.yaml\nrows:\n  - name: "a,b"\n' >"$dir/comma_row.yaml"
refused "a_row_name_with_a_comma_is_refused" "key 'rows[0].name'" "$dir/x" "$bin" run "$dir/comma_row.yaml" --out "$dir/x"
{
  printf 'l0: &l0 [x, x, x, x, x, x, x, x, x]\n'
  for i in $(seq 1 10); do printf 'l%d: &l%d [*l%d, *l%d, *l%d, *l%d, *l%d, *l%d, *l%d, *l%d, *l%d]\n' "$i" "$i" $(printf "$((i - 1)) %.0s" $(seq 9)); done
} >"$dir/bomb.yaml"
start=$SECONDS
refused "an_alias_bomb_is_refused" "bomb.yaml" "$dir/x" timeout 20 "$bin" run "$dir/bomb.yaml" --out "$dir/x"
[ $((SECONDS - start)) -le 5 ] || fail "an_alias_bomb_is_refused_at_once: took $((SECONDS - start)) s"
printf 'experiment: small.yaml\n' >"$dir/a_calibration.yaml"
refused "run_of_a_calibration_file_says_so" "anchorbench calibrate" "$dir/x" "$bin" run "$dir/a_calibration.yaml" --out "$dir/x"
printf 'base: small.yaml\nsweep: ~\n' >"$dir/null_sweep.yaml"
refused "a_key_without_a_value_says_so" "key 'sweep': no value" "$dir/x" "$bin" run "$dir/null_sweep.yaml" --out "$dir/x"
refused "set_without_a_value_names_the_option" "--set 'scenario.ranging.sigma_range_m=': no value" "$dir/x" \
  run --set scenario.ranging.sigma_range_m= --out "$dir/x"
refused "set_null_names_the_option" "--set 'scenario.ranging.sigma_range_m=null': no value" "$dir/x" \
  run --set scenario.ranging.sigma_range_m=null --out "$dir/x"
refused "a_number_beyond_the_limit_says_the_limit" "must be a finite number of magnitude at most 1e+300" "$dir/x" \
  run --set scenario.ranging.sigma_range_m=1e308 --out "$dir/x"

# --- No command removes or replaces a file it reads ---------------------------------------------
mkdir -p "$dir/d" "$dir/b"
cp "$dir/small.yaml" "$dir/b/base.yaml"
printf 'base: ../b/base.yaml\nrealizations: 2\n' >"$dir/d/c.yaml"
refused "run_overwrite_never_deletes_a_base" "b/base.yaml" "$dir/b/x" "$bin" run "$dir/d/c.yaml" --out "$dir/b" --overwrite --quiet
[ -f "$dir/b/base.yaml" ] || fail "run_overwrite_never_deletes_a_base: base.yaml is gone"

# --- Calibration logs ------------------------------------------------------------------------------
mkdir -p "$dir/cal"
small_table "$dir/cal/tiny.yaml"
printf 'experiment: tiny.yaml\nseed: 11\nrealizations: 2\nverify_seeds: [2]\nglobal: {algorithm: GN_DIRECT_L, max_evaluations: 6}\nlocal: {algorithm: LN_SBPLX, max_evaluations: 3}\nparameters:\n  - {key: scenario.tunnel.width_m, min: 6, max: 20, provenance: "a test"}\n' >"$dir/cal/cal.yaml"
"$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/whole" --quiet --threads 2 || fail "calibrate"
rm -f "$dir/cal/tiny.calibrated.yaml"
log="$dir/cal/whole/evaluations.csv"
lines_before=$(wc -l <"$log")
refused "calibrate_overwrite_never_replaces_the_reused_log" "whole/evaluations.csv" "$dir/cal/never" \
  "$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/whole" --overwrite --reuse "$log" --quiet
[ "$(wc -l <"$log")" -eq "$lines_before" ] || fail "calibrate_overwrite_never_replaces_the_reused_log: the log changed"
tamper_log() {  # NAME FILE: one way of damaging an evaluation log
  case "$1" in
    edited_cell) awk -F, -v OFS=, 'NR == 3 { $6 = $6 + 0.125 } { print }' "$2" >"$2.new" ;;
    edited_objective) awk -F, -v OFS=, 'NR == 4 { $5 = 0 } { print }' "$2" >"$2.new" ;;
    edited_value) awk -F, -v OFS=, 'NR == 3 { $4 = 11 } { print }' "$2" >"$2.new" ;;
    negative_cell) awk -F, -v OFS=, 'NR == 3 { $6 = -1 } { print }' "$2" >"$2.new" ;;
    nan_cell) awk -F, -v OFS=, 'NR == 3 { $6 = "nan" } { print }' "$2" >"$2.new" ;;
    repeated_point)  # line 2 again with another cell, its checksum made to fit
      local line body
      line=$(sed -n 2p "$2" | awk -F, -v OFS=, '{ $6 = $6 + 1; NF = NF - 1; print }')
      body="$line,$(fnv1a64 "$line")"
      { cat "$2"; printf '%s\n' "$body"; } >"$2.new" ;;
  esac
  cmp -s "$2" "$2.new" && fail "tamper $1 changed nothing"
  mv "$2.new" "$2"
}
for way in edited_cell edited_objective edited_value negative_cell nan_cell repeated_point; do
  cp "$log" "$dir/cal/reuse_$way.csv"
  tamper_log "$way" "$dir/cal/reuse_$way.csv"
  refused "calibrate_refuses_a_reused_log_with_${way}" "reuse_$way.csv:" "$dir/cal/o_$way" \
    "$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/o_$way" --quiet --reuse "$dir/cal/reuse_$way.csv"
  rm -f "$dir/cal/tiny.calibrated.yaml"
  cp "$log" "$dir/cal/run_$way.evaluations.csv"
  tamper_log "$way" "$dir/cal/run_$way.evaluations.csv"
  err=$("$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/run_$way" --quiet 2>&1 >/dev/null)
  if [ $? -ne 2 ] || ! grep -q "cut line" <<<"$err" || grep -q "start afresh" <<<"$err"; then
    fail "calibrate_refuses_a_running_log_with_${way}_and_names_the_line: $err"
  else
    echo "ok: calibrate_refuses_a_running_log_with_${way}_and_names_the_line"
  fi
done
rm -f "$dir/cal/tiny.calibrated.yaml"
sed 's/$/\r/' "$log" >"$dir/cal/crlf.csv"
"$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/crlf" --quiet --reuse "$dir/cal/crlf.csv" ||
  fail "calibrate_reads_a_crlf_log"
same "calibrate_reads_a_crlf_log" "$dir/cal/whole" "$dir/cal/crlf" evaluations.csv
rm -f "$dir/cal/tiny.calibrated.yaml"
{ printf '\xef\xbb\xbf'; cat "$log"; } >"$dir/cal/bom.csv"
"$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/bom" --quiet --reuse "$dir/cal/bom.csv" || fail "calibrate_reads_a_bom_log"
rm -f "$dir/cal/tiny.calibrated.yaml"
refused "reuse_of_a_folder_says_so" "--reuse $dir/cal: is a folder" "$dir/cal/o" \
  "$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/o" --quiet --reuse "$dir/cal"
refused "reuse_of_a_device_says_so" "--reuse /dev/null: is not a regular file" "$dir/cal/o" \
  "$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/o" --quiet --reuse /dev/null
mkdir "$dir/cal/dirlog.evaluations.csv"
refused "a_running_log_that_is_a_folder" "dirlog.evaluations.csv: is a folder" "$dir/cal/dirlog" \
  "$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/dirlog" --quiet
sed 's/GN_DIRECT_L/NOPE/' "$dir/cal/cal.yaml" >"$dir/cal/nope.yaml"
refused "an_unknown_algorithm_says_so" "unknown algorithm 'NOPE'" "$dir/cal/o" \
  "$bin" calibrate "$dir/cal/nope.yaml" --out "$dir/cal/o" --quiet
sed 's/experiment: tiny.yaml/experiment: nope.yaml/' "$dir/cal/cal.yaml" >"$dir/cal/of_a_calibration.yaml"
refused "an_experiment_that_is_a_calibration_file_says_so" "is a calibration file" "$dir/cal/o" \
  "$bin" calibrate "$dir/cal/of_a_calibration.yaml" --out "$dir/cal/o" --quiet
# An experiment whose base is its own calibrated config: rewriting it would make a cycle.
mkdir -p "$dir/cyc"
small_table "$dir/cyc/base.yaml"
printf 'base: base.yaml\n' >"$dir/cyc/tiny.calibrated.yaml"
printf 'base: tiny.calibrated.yaml\n' >"$dir/cyc/tiny.yaml"
cp "$dir/cal/cal.yaml" "$dir/cyc/cal.yaml"
refused "calibrate_never_rewrites_a_base_of_its_experiment" "tiny.calibrated.yaml" "$dir/cyc/o" \
  "$bin" calibrate "$dir/cyc/cal.yaml" --out "$dir/cyc/o" --quiet --overwrite
grep -qx "base: base.yaml" "$dir/cyc/tiny.calibrated.yaml" || fail "calibrate_never_rewrites_a_base_of_its_experiment: rewritten"

# --- Recorded logs -------------------------------------------------------------------------------
"$bin" simulate "$dir/small.yaml" --out "$dir/log" >/dev/null || fail "simulate"
cp "$dir/log/poses.csv" "$dir/p.csv" && cp "$dir/log/ranges.csv" "$dir/r.csv"
refused "replay_trace_inside_the_out_folder" "inside" "$dir/o/trace.csv" \
  "$bin" replay --poses "$dir/p.csv" --ranges "$dir/r.csv" --out "$dir/o" --trace "$dir/o/trace.csv" --overwrite
"$bin" replay --poses "$dir/p.csv" --ranges "$dir/r.csv" --out "$dir/o" --quiet >/dev/null || fail "replay"
refused "replay_trace_inside_an_existing_out_folder" "inside" "$dir/o/trace.csv" \
  "$bin" replay --poses "$dir/p.csv" --ranges "$dir/r.csv" --out "$dir/o" --trace "$dir/o/trace.csv" --overwrite
refused "replay_max_range_nan_is_refused" "--max-range-m" "$dir/o2" \
  "$bin" replay --poses "$dir/p.csv" --ranges "$dir/r.csv" --out "$dir/o2" --max-range-m nan
# One pose far away between two good ones: dropped and counted, the estimates untouched.
awk -F, -v OFS=, 'NR == 41 { print; t = $1; getline; print t + 0.001, $2, 1e6, 0, 0; print; next } { print }' \
  "$dir/p.csv" >"$dir/p_spike.csv"
"$bin" replay --poses "$dir/p_spike.csv" --ranges "$dir/r.csv" --out "$dir/o_spike" --quiet >/dev/null ||
  fail "replay with a pose spike"
tally=$(drop_tally "$dir/o_spike/replay_summary.json" pose_jump)
[ "${tally%% *}" = 1 ] || fail "a_pose_spike_is_dropped_and_counted: pose_jump $tally"
same "a_pose_spike_leaves_the_estimates_as_without_it" "$dir/o" "$dir/o_spike" estimates.csv
tr '\n' '\r' <"$dir/log/anchors.csv" >"$dir/anchors_cr.csv"
"$bin" replay --poses "$dir/p.csv" --ranges "$dir/r.csv" --anchors "$dir/log/anchors.csv" --out "$dir/o_lf" --quiet >/dev/null &&
  "$bin" replay --poses "$dir/p.csv" --ranges "$dir/r.csv" --anchors "$dir/anchors_cr.csv" --out "$dir/o_cr" --quiet >/dev/null ||
  fail "replay with anchors"
same "anchors_with_cr_line_endings_are_read" "$dir/o_lf" "$dir/o_cr" estimates.csv
head -1 "$dir/log/anchors.csv" >"$dir/anchors_header.csv"
refused "anchors_with_a_header_alone_are_refused" "anchors_header.csv: no anchors" "$dir/o3" \
  "$bin" replay --poses "$dir/p.csv" --ranges "$dir/r.csv" --anchors "$dir/anchors_header.csv" --out "$dir/o3"
# A million anchors, and a hundred thousand ranges at one time stamp: refused or done at once.
printf 't,tag_id,x,y,z\n0,0,0,0,0\n1,0,1,0,0\n' >"$dir/p2.csv"
awk 'BEGIN { print "t,tag_id,anchor_id,range"; for (i = 0; i < 1000000; i++) printf "%.6f,0,%d,5\n", i / 1e6, i }' >"$dir/many.csv"
start=$SECONDS
refused "a_million_anchors_are_refused" "anchors" "$dir/o4" timeout 30 "$bin" replay --poses "$dir/p2.csv" --ranges "$dir/many.csv" --out "$dir/o4"
[ $((SECONDS - start)) -le 10 ] || fail "a_million_anchors_are_refused_early: took $((SECONDS - start)) s"
awk 'BEGIN { print "t,tag_id,anchor_id,range"; for (i = 0; i < 99999; i++) printf "0.5,0,%d,%.6f\n", i % 4, 5 + i / 1e5 }' >"$dir/one_time.csv"
start=$SECONDS
timeout 60 "$bin" replay --poses "$dir/p2.csv" --ranges "$dir/one_time.csv" --quiet >/dev/null || fail "99,999 ranges at one time"
[ $((SECONDS - start)) -le 8 ] && echo "ok: ranges_sharing_one_time_stamp_cost_linear_time" ||
  fail "ranges_sharing_one_time_stamp_cost_linear_time: $((SECONDS - start)) s"
awk 'BEGIN { print "t,tag_id,anchor_id,range"; for (i = 0; i < 100001; i++) printf "0.5,0,%d,%.6f\n", i % 4, 5 + i / 1e5 }' >"$dir/one_time2.csv"
start=$SECONDS
refused "more_ranges_at_one_time_than_the_cap_are_refused" "share the time" "$dir/o5" \
  timeout 60 "$bin" replay --poses "$dir/p2.csv" --ranges "$dir/one_time2.csv" --out "$dir/o5"
[ $((SECONDS - start)) -le 5 ] || fail "more_ranges_at_one_time_than_the_cap_are_refused_early: $((SECONDS - start)) s"

# --- A full disk: refused before any work, or one line and exit 2, nothing half-written -----------
mkdir -p "$dir/mnt"
if mount -t tmpfs -o size=236k tmpfs "$dir/mnt" 2>/dev/null; then
  mounted="$dir/mnt"
  expect_exit 2 "full_disk_run_counts_the_chunk_store" "No space left on device" \
    "$bin" run "$configs/table1.yaml" --out "$dir/mnt/o" --realizations 2 --threads 1 --seed 1 --quiet
  expect_exit 2 "full_disk_sweep_counts_the_chunk_store" "No space left on device" \
    "$bin" sweep "$configs/table1.yaml" --set estimator.trigger.pdop_threshold=0.5,1 --out "$dir/mnt/o" \
    --realizations 2 --threads 1 --quiet
  expect_exit 2 "full_disk_shard_counts_the_chunk_store" "No space left on device" \
    "$bin" run "$configs/table1.yaml" --out "$dir/mnt/o" --realizations 2 --threads 1 --shard 0/1 --quiet
  "$bin" run "$configs/table1.yaml" --realizations 2 --shard 0/1 --out "$dir/big_shard" --quiet || fail "a Table I shard"
  shard_kb=$(du -sk "$dir/big_shard" | cut -f1)
  head -c $(((236 - shard_kb / 2) * 1024)) /dev/zero >"$dir/mnt/filler"  # room for half the merged results
  expect_exit 2 "full_disk_merge_reserves_before_it_reads" "No space left on device" \
    "$bin" merge "$dir/mnt/m" "$dir/big_shard" --quiet
  rm "$dir/mnt/filler"
  ls -A "$dir/mnt" | grep -q . && fail "full_disk: left behind: $(ls -A "$dir/mnt")"
  # The calibrated config beside an experiment on a full disk: refused before the first evaluation.
  mkdir -p "$dir/mnt/cal"
  cp "$dir/cal/tiny.yaml" "$dir/cal/cal.yaml" "$dir/mnt/cal/"
  head -c $((220 * 1024)) /dev/zero >"$dir/mnt/filler" 2>/dev/null
  head -c $((64 * 1024)) /dev/zero >>"$dir/mnt/filler" 2>/dev/null
  expect_exit 2 "full_disk_calibrated_config_is_reserved_before_work" "tiny.calibrated.yaml" \
    "$bin" calibrate "$dir/mnt/cal/cal.yaml" --out "$dir/cal/o_full" --quiet
  [ -e "$dir/cal/o_full" ] && fail "full_disk_calibrated_config: a result folder was written"
  expect_exit 2 "full_disk_trace_names_the_users_file" "$dir/mnt/trace.csv: " \
    "$bin" replay --poses "$dir/p.csv" --ranges "$dir/r.csv" --trace "$dir/mnt/trace.csv" --quiet
  ls -A "$dir/mnt" | grep -q tmp && fail "full_disk_trace: a temporary was left"
  umount "$dir/mnt" && mounted=""
else
  echo "skipped: the full-disk cases need to mount a tmpfs (root); this process cannot"
fi

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all integrity cases passed"
