#!/usr/bin/env bash
# Real logs as they come (docs/real_data.md): a log with every kind of bad row replays to exactly
# the estimates of its clean version, counts what it dropped, and --strict refuses it; conflicting
# poses and late rows follow their policies; one file per anchor and a sort window give the same
# bytes as the clean single file; a malformed file is one error with file:line and no output.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

# expect_refusal DESCRIPTION EXPECTED_TEXT COMMAND...: exit 2, one line naming the place, no output.
expect_refusal() {
  local what="$1" expected="$2"
  shift 2
  local err code
  err=$("$@" --out "$dir/refused" 2>&1 >/dev/null)
  code=$?
  if [ $code -ne 2 ]; then fail "$what: exit code $code: $err"
  elif ! grep -qF -- "$expected" <<<"$err"; then fail "$what: message lacks '$expected': $err"
  elif [ "$(wc -l <<<"$err")" -ne 1 ]; then fail "$what: expected one line, got: $err"
  elif [ -e "$dir/refused" ]; then fail "$what: output written"
  else echo "ok: $what -> $err"
  fi
}

printf 'seed: 3\nscenario:\n  tunnel: {length_m: 80, num_anchors: 5}\n' >"$dir/small.yaml"
"$bin" simulate "$dir/small.yaml" --out "$dir/sim" >/dev/null || { echo "FAIL: simulate"; exit 1; }
poses="$dir/sim/poses.csv" ranges="$dir/sim/ranges.csv"
"$bin" replay --poses "$poses" --ranges "$ranges" --out "$dir/clean" --quiet >/dev/null || fail "clean replay"
grep -q '"dropped": 0,' "$dir/clean/replay_summary.json" || fail "clean log: drops counted"

# The messy log: every pose row three times (one per range at that instant, as some recorders
# write), and after every 7th range a garbage row (negative, nan, zero, 5 km, an exact repeat).
awk 'NR == 1 { print; next } { print; print; print }' "$poses" >"$dir/messy_poses.csv"
awk -F, 'NR == 1 { print; next } { print }
         NR % 7 == 0 { k = (NR / 7) % 5
                       bad = k == 0 ? "-11.12" : k == 1 ? "nan" : k == 2 ? "0" : k == 3 ? "5000" : $4
                       print $1 "," $2 "," $3 "," bad }' "$ranges" >"$dir/messy_ranges.csv"
"$bin" replay --poses "$dir/messy_poses.csv" --ranges "$dir/messy_ranges.csv" --out "$dir/messy" >/dev/null \
  2>"$dir/messy.err" || fail "messy replay"
cmp -s "$dir/clean/estimates.csv" "$dir/messy/estimates.csv" || fail "messy log: estimates differ from the clean log's"
grep -q "rows dropped" "$dir/messy.err" || fail "messy log: no summary on stderr: $(cat "$dir/messy.err")"
for reason in range_not_positive range_not_finite range_beyond_max duplicate_range repeated_pose; do
  grep -q "\"$reason\"" "$dir/messy/replay_summary.json" || fail "messy log: no $reason in replay_summary.json"
  grep -q "| $reason |" "$dir/messy/replay_summary.md" || fail "messy log: no $reason in replay_summary.md"
done
pose_rows=$(($(wc -l <"$poses") - 1))
[ "$(drop_tally "$dir/messy/replay_summary.json" repeated_pose)" = "$((2 * pose_rows)) $dir/messy_poses.csv:3" ] ||
  fail "messy log: repeated poses not counted with their first line"
expect_refusal "strict: a bad range is an error" "messy_ranges.csv:8: range nan is not finite (--strict)" \
  "$bin" replay --poses "$poses" --ranges "$dir/messy_ranges.csv" --strict
expect_refusal "strict: a repeated pose is an error" "messy_poses.csv:3: tag 0 repeats its pose of line 2 (--strict)" \
  "$bin" replay --poses "$dir/messy_poses.csv" --ranges "$ranges" --strict

# Two positions of one tag at one time: an error, unless a policy is chosen.
awk -F, 'NR == 1 { print; next } { print } NR == 10 { print $1 "," $2 "," $3 + 0.5 "," $4 "," $5 }' "$poses" \
  >"$dir/conflict_poses.csv"
expect_refusal "conflicting poses" "conflict_poses.csv:11: tag 0 has another pose at t=" \
  "$bin" replay --poses "$dir/conflict_poses.csv" --ranges "$ranges"
for policy in first average; do
  "$bin" replay --poses "$dir/conflict_poses.csv" --ranges "$ranges" --repeated-poses "$policy" --quiet \
    --out "$dir/conflict_$policy" >/dev/null || fail "--repeated-poses $policy"
done
cmp -s "$dir/clean/estimates.csv" "$dir/conflict_first/estimates.csv" || fail "--repeated-poses first changed estimates"
tally=$(drop_tally "$dir/conflict_average/replay_summary.json" averaged_pose)
[ "${tally%% *}" = 1 ] || fail "averaged pose not counted: $tally"

# Ranges out of order: swap neighbours at every 50th row (late by one row: 0.1 s at 10 Hz, beyond
# the default window of 0.1 s by a rounding, within 1 s).
awk 'NR == 1 { print; next } NR % 50 == 0 { held = $0; next } { print } held != "" { print held; held = "" }' \
  "$ranges" >"$dir/late_ranges.csv"
expect_refusal "late ranges" "more than --sort-window-s 0.1 late" "$bin" replay --poses "$poses" --ranges "$dir/late_ranges.csv"
expect_refusal "late ranges, no sorting" "time goes backwards" "$bin" replay --poses "$poses" --ranges "$dir/late_ranges.csv" \
  --out-of-order error
"$bin" replay --poses "$poses" --ranges "$dir/late_ranges.csv" --sort-window-s 1 --quiet --out "$dir/sorted" \
  >/dev/null || fail "--out-of-order sort"
cmp -s <(cut -d, -f1-5 "$dir/clean/estimates.csv") <(cut -d, -f1-5 "$dir/sorted/estimates.csv") \
  || fail "--out-of-order sort: not the clean log's initializations"
"$bin" replay --poses "$poses" --ranges "$dir/late_ranges.csv" --out-of-order drop --quiet --out "$dir/dropped" \
  >/dev/null || fail "--out-of-order drop"
grep -q '"late_range"' "$dir/dropped/replay_summary.json" || fail "late ranges not counted"

# One file per anchor, no tag or anchor column, other column names: the same estimates.
mkdir -p "$dir/split"
awk -F, -v d="$dir/split" 'NR == 1 { next } { print $1 "," $4 >> (d "/anchor_" $3 ".csv") }' "$ranges"
for f in "$dir"/split/anchor_*.csv; do { echo "timestamp,distance"; cat "$f"; } >"$f.tmp" && mv "$f.tmp" "$f"; done
sed '1s/.*/stamp,tag,px,py,pz/' "$poses" >"$dir/renamed_poses.csv"
# shellcheck disable=SC2046  # one argument per file
"$bin" replay --poses "$dir/renamed_poses.csv" --ranges $(ls "$dir"/split/anchor_*.csv) --quiet --out "$dir/split_out" \
  >/dev/null || fail "one file per anchor"
cmp -s "$dir/clean/estimates.csv" "$dir/split_out/estimates.csv" || fail "one file per anchor: other estimates"

# A malformed file stays an error, whatever the policy.
printf 't,tag_id,anchor_id,range\n0,0,1,5\n0.1,0,1,5.x\n' >"$dir/malformed.csv"
expect_refusal "malformed number" "malformed.csv:3: column 'range': '5.x' is not a number" \
  "$bin" replay --poses "$poses" --ranges "$dir/malformed.csv" --out-of-order drop --repeated-poses average

# The navigation filter on a log (--navigate): the log's tag with each trigger's anchors and
# synthetic odometry, the same bytes on any thread count; the replay's own files unchanged.
printf 'seed: 3\nrealizations: 4\nestimator: {triggers: [fixed_window, pdop_closest_point]}\nnavigation: {sigma_range_m: 0.1}\n' \
  >"$dir/navigated.yaml"
for threads in 1 2; do
  OMP_NUM_THREADS=$threads "$bin" replay --poses "$poses" --ranges "$ranges" --anchors "$dir/sim/anchors.csv" \
    --config "$dir/navigated.yaml" --navigate --quiet --out "$dir/navigated_$threads" >/dev/null || fail "--navigate"
done
for f in navigation.csv navigation_summary.csv navigation_error.csv navigation.md; do
  cmp -s "$dir/navigated_1/$f" "$dir/navigated_2/$f" || fail "--navigate: $f differs between 1 and 2 threads"
done
# 4 draws x (2 triggers, the true anchors, none) and the header
[ "$(wc -l <"$dir/navigated_1/navigation.csv")" -eq 17 ] || fail "--navigate: $(wc -l <"$dir/navigated_1/navigation.csv") lines"
awk -F, '$3 == "true_anchors" && $8 < 0.9 { bad = 1 } END { exit bad }' "$dir/navigated_1/navigation.csv" \
  || fail "--navigate: the true anchors from t = 0 give a fix less than 90% of the time"
"$bin" replay --poses "$poses" --ranges "$ranges" --anchors "$dir/sim/anchors.csv" --config "$dir/navigated.yaml" \
  --quiet --out "$dir/not_navigated" >/dev/null || fail "replay without --navigate"
cmp -s "$dir/not_navigated/estimates.csv" "$dir/navigated_1/estimates.csv" || fail "--navigate changed the estimates"
[ -e "$dir/not_navigated/navigation.csv" ] && fail "navigation files without --navigate"
expect_refusal "navigate a log without a navigation section" "the default config: --navigate needs a 'navigation' section" \
  "$bin" replay --poses "$poses" --ranges "$ranges" --navigate
printf 'navigation: {}\n' >"$dir/no_noise.yaml"
expect_refusal "navigate a log without the filter's range noise" "key 'navigation.sigma_range_m': must be set" \
  "$bin" replay --poses "$poses" --ranges "$ranges" --config "$dir/no_noise.yaml" --navigate

[ "$failures" -eq 0 ] && echo "all real-log cases passed"
exit "$failures"
