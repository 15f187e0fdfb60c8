#!/usr/bin/env bash
# Nothing lost, nothing half-written (issue 11): one regression case per finding, each named after
# what it protects. Every bad input must exit 2 with one line naming the place, write nothing, and
# never crash (exit codes other than 0 and 2 fail the case).
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

checksum() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 md5sum) | md5sum; }
no_leftovers() {  # no hidden partial/old siblings and no temporaries beside the target
  if ls -a "$(dirname "$1")" | grep -qE "^\.$(basename "$1")\.(partial|old)-|\.tmp\.[0-9]+$"; then
    fail "$2: leftovers beside $1: $(ls -a "$(dirname "$1")")"
  fi
}

printf 'seed: 1\nrealizations: 2\nbootstrap_resamples: 20\nscenario:\n  tunnel: {length_m: 60, num_anchors: 3}\n' >"$dir/small.yaml"

# --- Result folders: whole or absent, never mixed, never overwritten unasked -----------------
"$bin" run "$dir/small.yaml" --out "$dir/r" --quiet || fail "first run"
before=$(checksum "$dir/r")
expect_exit 2 "rerun_refuses_earlier_results_without_overwrite" "holds earlier results; add --overwrite" \
  "$bin" run "$dir/small.yaml" --out "$dir/r" --quiet --seed 9
[ "$(checksum "$dir/r")" = "$before" ] || fail "refused rerun changed the folder"
"$bin" run "$dir/small.yaml" --out "$dir/r" --quiet --seed 9 --overwrite || fail "rerun with --overwrite"
[ "$(checksum "$dir/r")" != "$before" ] || fail "--overwrite did not replace the results"
no_leftovers "$dir/r" "rerun"
"$bin" sweep "$dir/small.yaml" --set estimator.trigger.pdop_threshold=0.5,1 --out "$dir/r" --quiet --overwrite \
  || fail "sweep over a run's folder"
[ -e "$dir/r/attempts.csv" ] && fail "sweep_into_a_runs_folder_leaves_no_run_files: attempts.csv survived"
[ -e "$dir/r/sweep.csv" ] || fail "sweep_into_a_runs_folder: no sweep.csv"
mkdir -p "$dir/.r.partial-999999999" "$dir/.r.old-999999999"  # what killed runs would leave
"$bin" run "$dir/small.yaml" --out "$dir/r" --quiet --overwrite || fail "run after killed runs"
no_leftovers "$dir/r" "stale_siblings_of_killed_runs_are_removed"

"$bin" simulate "$dir/small.yaml" --out "$dir/log" >/dev/null || fail "simulate"
expect_exit 2 "simulate_refuses_to_overwrite_recordings" "holds earlier results" \
  "$bin" simulate "$dir/small.yaml" --out "$dir/log" --seed 4
expect_exit 2 "replay_trace_never_replaces_an_input" "is an input of this run" \
  "$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges.csv" --trace "$dir/log/ranges.csv" --overwrite
head -1 "$dir/log/ranges.csv" | grep -q "^t,tag_id,anchor_id,range$" || fail "the input ranges.csv was damaged"
expect_exit 2 "replay_out_never_replaces_a_folder_holding_an_input" "an input of this run" \
  "$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges.csv" --out "$dir/log" --overwrite
"$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges.csv" --trace "$dir/trace.csv" >/dev/null \
  || fail "replay with a trace"
expect_exit 2 "replay_trace_refuses_an_existing_file_without_overwrite" "exists; add --overwrite" \
  "$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges.csv" --trace "$dir/trace.csv"

# --- Impossible settings and sizes: refused before any work --------------------------------------
expect_exit 2 "ransac_with_no_possible_clean_subset" "key 'estimator.filter.ransac.subset_size'" \
  "$bin" run "$dir/small.yaml" --set estimator.filter.ransac.scheme=full_solve --set estimator.filter.ransac.subset_size=200 \
  --set estimator.filter.ransac.outlier_fraction=0.99 --out "$dir/x"
expect_exit 2 "outlier_probability_beyond_what_bursts_can_produce" "must be <= L/(L+1)" \
  "$bin" run "$dir/small.yaml" --set scenario.ranging.outlier_probability=0.99 --out "$dir/x"
expect_exit 2 "retry_growth_that_would_overflow" "key 'estimator.initializer.retry_growth': must be in (1, 100]" \
  "$bin" run "$dir/small.yaml" --set estimator.initializer.retry_growth=1e300 --out "$dir/x"
expect_exit 2 "navigate_without_a_navigation_section" "no 'navigation' section" \
  "$bin" navigate "$dir/small.yaml" --out "$dir/x"
expect_exit 2 "replay_navigate_without_a_folder_for_its_tables" "--navigate: writes its tables into --out" \
  "$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges.csv" --navigate
{ cat "$dir/small.yaml"; printf 'navigation: {sigma_heading_rad_per_sqrt_s: -1}\n'; } >"$dir/drift.yaml"
expect_exit 2 "navigate_with_a_negative_drift" "key 'navigation.sigma_heading_rad_per_sqrt_s'" \
  "$bin" navigate "$dir/drift.yaml" --out "$dir/x"
expect_exit 2 "pdop_study_bin_too_small_for_an_integer" "--bin-s: expected a finite number from 0.01 to 120" \
  "$bin" pdop-study "$dir/small.yaml" --bin-s 1e-300 --out "$dir/x"
expect_exit 2 "pdop_study_every_zero_in_the_config" "key 'pdop_study.every': must be in [1, 1000000]" \
  "$bin" pdop-study "$dir/small.yaml" --set pdop_study.every=0 --out "$dir/x"
expect_exit 2 "threads_beyond_what_the_machine_can_run" "--threads 100000: at most" \
  "$bin" run "$dir/small.yaml" --threads 100000 --out "$dir/x"
expect_exit 2 "omp_num_threads_beyond_what_the_machine_can_run" "OMP_NUM_THREADS=100000" \
  env OMP_NUM_THREADS=100000 "$bin" run "$dir/small.yaml" --out "$dir/x"
expect_exit 2 "a_tunnel_longer_than_the_work_limit" "the limits are 1e7 and 2e7" \
  "$bin" run "$dir/small.yaml" --set scenario.tunnel.length_m=1e5 --set scenario.trajectory.speed_mps=0.01 --out "$dir/x"
expect_exit 2 "a_crawling_speed" "the limits are 1e7 and 2e7" \
  "$bin" run "$dir/small.yaml" --set scenario.trajectory.speed_mps=1e-300 --out "$dir/x"
expect_exit 2 "a_hall_run_of_eleven_days_at_10_hz" "the limits are 1e7 and 2e7" \
  "$bin" run "$dir/small.yaml" --set scenario.environment=hall --set scenario.trajectory.hall_duration_s=1e6 --out "$dir/x"
expect_exit 2 "realizations_times_rows_beyond_memory" "attempts (rows x realizations x anchors x triggers)" \
  "$bin" run "$dir/small.yaml" --realizations 100000000 --out "$dir/x"
expect_exit 2 "a_sweep_grid_of_a_hundred_million_points" "grid points; at most 10000" \
  "$bin" sweep "$dir/small.yaml" --set estimator.trigger.pdop_threshold=0.0001:1:0.0001 \
  --set estimator.filter.tau_m=0.0001:1:0.0001 --out "$dir/x"
[ -e "$dir/x" ] && fail "an output folder was created for refused input"

# --- YAML ---------------------------------------------------------------------------------------
printf 'seed: 1\nseed: 2\n' >"$dir/dup.yaml"
expect_exit 2 "duplicate_keys_name_both_lines" "dup.yaml:2: key 'seed' appears twice (lines 1 and 2)" \
  "$bin" run "$dir/dup.yaml" --out "$dir/x"
printf 'scenario:\n  ranging: {sigma_range_m: 0.1, sigma_range_m: oops}\n' >"$dir/dup2.yaml"
expect_exit 2 "a_duplicate_key_with_an_invalid_second_value" "appears twice" "$bin" run "$dir/dup2.yaml" --out "$dir/x"
printf '? [a, b]\n: 1\n' >"$dir/listkey.yaml"
expect_exit 2 "a_list_as_a_key" "listkey.yaml:1: a key must be a name, got a list" "$bin" run "$dir/listkey.yaml" --out "$dir/x"
printf 'base: .\n' >"$dir/basedot.yaml"
expect_exit 2 "base_that_is_a_folder" "is not a config file" "$bin" run "$dir/basedot.yaml" --out "$dir/x"
printf 'base: /dev/null\n' >"$dir/basenull.yaml"
expect_exit 2 "base_that_is_not_a_file" "/dev/null: is not a config file" "$bin" run "$dir/basenull.yaml" --out "$dir/x"
printf 't,tag_id,anchor_id,range\n0,0,1,5\n' >"$dir/data.csv"
printf 'base: data.csv\n' >"$dir/basecsv.yaml"
expect_exit 2 "base_that_is_a_csv" "data.csv: expected a mapping of config keys" "$bin" run "$dir/basecsv.yaml" --out "$dir/x"
python3 -c "print('a:\n' + ''.join(' ' * i + 'k%d:\n' % i for i in range(1, 1000)))" >"$dir/deep.yaml" 2>/dev/null \
  || { printf 'a:\n'; for i in $(seq 1 999); do printf "%${i}sk$i:\n" ''; done; } >"$dir/deep.yaml"
expect_exit 2 "a_thousand_nested_levels" "nested deeper than the YAML reader allows" "$bin" run "$dir/deep.yaml" --out "$dir/x"

# --- The command line: one exit-code convention ----------------------------------------------
expect_exit 2 "a_negative_seed_is_not_wrapped" "expected a whole number from 0" \
  "$bin" run "$dir/small.yaml" --seed -1 --out "$dir/x"
expect_exit 2 "zero_realizations_say_so_plainly" "expected a whole number from 1 to 100000000, got '0'" \
  "$bin" run "$dir/small.yaml" --realizations 0 --out "$dir/x"
expect_exit 2 "an_unknown_option" "--bogus" "$bin" run "$dir/small.yaml" --bogus
expect_exit 2 "no_command" "" "$bin"
expect_exit 0 "help_is_not_an_error" "" "$bin" --help
"$bin" --help | grep -q "Exit codes: 0 done; 2 bad input" || fail "--help documents the exit codes"

# --- Messages stay one printable line; tables stay readable ----------------------------------
printf 't,tag_id,anchor_id,range\n0,0,1,\001\033[31m\n' >"$dir/control.csv"
expect_exit 2 "control_bytes_in_a_csv_are_escaped" "'\\x01\\x1B[31m' is not a number" \
  "$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/control.csv"
printf 't,tag_id,x,y,z\n1e300,0,0,0,0\n2e300,0,30,4,2\n' >"$dir/far_poses.csv"
{ printf 't,tag_id,anchor_id,range\n'; for i in $(seq 1 40); do printf '1.%02de300,0,7,%s\n' "$i" "$((10 + i % 7))"; done; } >"$dir/far_ranges.csv"
table=$("$bin" replay --poses "$dir/far_poses.csv" --ranges "$dir/far_ranges.csv" 2>/dev/null)
[ "$(awk '{ if (length($0) > m) m = length($0) } END { print m }' <<<"$table")" -lt 200 ] \
  || fail "replay_table_prints_huge_times_compactly: $table"

[ $failures -eq 0 ] && echo "all reliability cases passed"
exit $failures
