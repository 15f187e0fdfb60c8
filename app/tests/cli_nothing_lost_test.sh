#!/usr/bin/env bash
# Nothing lost on the surfaces added since the first audit (issue 33): every path a command reads,
# the whole base chain included, is kept whatever it writes or removes; a reused log is never
# consumed; a folder under a chunk store's name that is not a store is never removed; a log given
# twice or through a pipe, a null section, a repeated row name and an unbounded value are one line
# and exit 2; Ctrl-C leaves no partial folder.
# Arguments: the anchorbench executable.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

small_table "$dir/small.yaml"
mkdir -p "$dir/c" "$dir/b"
cp "$dir/small.yaml" "$dir/b/base.yaml"
printf 'base: ../b/base.yaml\nrealizations: 2\n' >"$dir/c/c.yaml"

# --- The base chain of simulate's and replay's configs ---------------------------------------------
refused "simulate_overwrite_never_deletes_a_base" "b/base.yaml" "$dir/b/poses.csv" \
  "$bin" simulate "$dir/c/c.yaml" --out "$dir/b" --overwrite
[ -f "$dir/b/base.yaml" ] || fail "simulate_overwrite_never_deletes_a_base: base.yaml is gone"
"$bin" simulate "$dir/small.yaml" --out "$dir/log" >/dev/null || fail "simulate"
refused "replay_overwrite_never_deletes_a_base" "b/base.yaml" "$dir/b/estimates.csv" \
  "$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges.csv" --config "$dir/c/c.yaml" --out "$dir/b" --overwrite
[ -f "$dir/b/base.yaml" ] || fail "replay_overwrite_never_deletes_a_base: base.yaml is gone"

# --- A chunk store's place holding something else ------------------------------------------------
mkdir -p "$dir/res.chunks" && echo "mine" >"$dir/res.chunks/notes.txt"
refused "a_folder_named_like_a_store_is_kept" "holds something else" "$dir/res" \
  "$bin" run "$dir/small.yaml" --realizations 1 --out "$dir/res" --quiet
refused "a_folder_named_like_a_store_is_kept_even_with_overwrite" "holds something else" "$dir/res" \
  "$bin" run "$dir/small.yaml" --realizations 1 --out "$dir/res" --quiet --overwrite
[ -f "$dir/res.chunks/notes.txt" ] || fail "a_folder_named_like_a_store_is_kept: notes.txt is gone"
echo "mine" >"$dir/res2.chunks"
refused "a_file_named_like_a_store_is_kept" "holds something else" "$dir/res2" \
  "$bin" run "$dir/small.yaml" --realizations 1 --out "$dir/res2" --quiet
[ -f "$dir/res2.chunks" ] || fail "a_file_named_like_a_store_is_kept: the file is gone"

# --- calibrate --reuse of its own running log --------------------------------------------------------
mkdir -p "$dir/cal"
small_table "$dir/cal/tiny.yaml"
printf 'experiment: tiny.yaml\nseed: 11\nrealizations: 2\nverify_seeds: [2]\nglobal: {algorithm: GN_DIRECT_L, max_evaluations: 3}\nlocal: {algorithm: LN_SBPLX, max_evaluations: 2}\nparameters:\n  - {key: scenario.tunnel.width_m, min: 6, max: 20, provenance: "a test"}\n' >"$dir/cal/cal.yaml"
"$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/whole" --quiet --threads 2 || fail "calibrate"
rm -f "$dir/cal/tiny.calibrated.yaml"
cp "$dir/cal/whole/evaluations.csv" "$dir/cal/o.evaluations.csv"
cp "$dir/cal/o.evaluations.csv" "$dir/cal/kept.csv"
refused "calibrate_never_consumes_the_reused_log" "is the running log of this --out" "$dir/cal/o" \
  "$bin" calibrate "$dir/cal/cal.yaml" --out "$dir/cal/o" --reuse "$dir/cal/o.evaluations.csv" --quiet
cmp -s "$dir/cal/o.evaluations.csv" "$dir/cal/kept.csv" || fail "calibrate_never_consumes_the_reused_log: the log changed"

# --- Logs read twice: one file twice, a pipe ---------------------------------------------------------
refused "a_ranges_file_given_twice_is_refused" "is given twice" "$dir/o1" \
  "$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges.csv" --ranges "$dir/log/ranges.csv" --out "$dir/o1"
ln -s "$dir/log/ranges.csv" "$dir/ranges_link.csv"
refused "a_ranges_file_given_twice_through_a_link_is_refused" "is given twice" "$dir/o1" \
  "$bin" replay --poses "$dir/log/poses.csv" --ranges "$dir/log/ranges.csv" --ranges "$dir/ranges_link.csv" --out "$dir/o1"
refused "a_pipe_is_named_as_one" "is not a regular file (a pipe or a device)" "$dir/o1" \
  "$bin" replay --poses <(cat "$dir/log/poses.csv") --ranges "$dir/log/ranges.csv" --out "$dir/o1"

# --- Configs: a null section, a repeated row name, values beyond their range ------------------------
for section in scenario estimator; do
  printf 'base: small.yaml\n%s: ~\n' "$section" >"$dir/null_$section.yaml"
  refused "a_null_${section}_is_refused_as_a_null_seed_is" "key '$section': no value" "$dir/o2" \
    "$bin" run "$dir/null_$section.yaml" --out "$dir/o2" --quiet
done
sed 's/  - name: "2"/  - name: "1"/' "$dir/small.yaml" >"$dir/twice.yaml"
refused "a_row_name_given_twice_is_refused" "both named '1'" "$dir/o2" "$bin" run "$dir/twice.yaml" --out "$dir/o2" --quiet
{ cat "$dir/small.yaml"; printf 'navigation: {error_bin_s: 1e-5}\n'; } >"$dir/bins.yaml"
refused "error_bins_below_10_ms_are_refused" "error_bin_s': must be in [0.01, 1e6]" "$dir/o2" \
  "$bin" navigate "$dir/bins.yaml" --out "$dir/o2" --quiet
printf 'base: small.yaml\nnavigation: {error_bin_s: 0.01}\nscenario: {trajectory: {speed_mps: 0.01}}\n' >"$dir/many_bins.yaml"
refused "more_error_bins_than_1e5_are_refused" "at most 1e5" "$dir/o2" "$bin" navigate "$dir/many_bins.yaml" --out "$dir/o2" --quiet
{ cat "$dir/small.yaml"; printf 'exploration: {policies: [pattern, random]}\n'; } >"$dir/explore_bad.yaml"
refused "an_unknown_exploration_policy_is_refused" "exploration.policies': unknown policy 'random'" "$dir/o2" \
  "$bin" explore "$dir/explore_bad.yaml" --out "$dir/o2" --quiet
refused "explore_without_an_exploration_section_is_refused" "no 'exploration' section" "$dir/o2" \
  "$bin" explore "$dir/small.yaml" --out "$dir/o2" --quiet
printf 'base: small.yaml\nnavigation: {}\n' >"$dir/nav.yaml"
for key in navigation.sigma_bias_mps_per_sqrt_s navigation.sigma_start_m scenario.ranging.sigma_range_m \
  scenario.tunnel.width_m estimator.filter.tau_m; do
  refused "${key}_of_1e300_is_refused" "key '$key': must be in" "$dir/o2" \
    "$bin" run "$dir/nav.yaml" --set "$key=1e300" --out "$dir/o2" --quiet
done

# --- Ctrl-C: exit 130, no partial folder, the finished chunks kept ----------------------------------
"$bin" run "$dir/small.yaml" --realizations 20000 --out "$dir/int" --quiet --threads 2 &
pid=$!
sleep 2
kill -INT "$pid"
wait "$pid"
status=$?
[ "$status" -eq 130 ] || fail "ctrl_c_exits_130: exit $status"
ls -A "$dir" | grep -q "^\.int\.partial" && fail "ctrl_c_leaves_no_partial_folder: $(ls -A "$dir")"
[ -e "$dir/int" ] && fail "ctrl_c_writes_no_result_folder"
[ -f "$dir/int.chunks/plan.csv" ] || fail "ctrl_c_keeps_the_finished_chunks"
[ "$failures" -eq 0 ] && echo "ok: ctrl_c_ends_a_run_with_nothing_half_written"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all nothing-lost cases passed"
