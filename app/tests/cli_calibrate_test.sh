#!/usr/bin/env bash
# anchorbench calibrate (issue 14): bad calibration files are refused before any work (exit 2, one
# line naming the key, nothing written); a calibration killed with -9 resumes from its evaluation
# log to the same bytes as an uninterrupted one; --reuse takes a finished log's evaluations.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

expect_refusal() {  # DESCRIPTION EXPECTED_TEXT CALIBRATION_FILE: nothing written, not even the log
  refused "$1" "$2" "$dir/refused" "$bin" calibrate "$3" --out "$dir/refused" --quiet
  [ -e "$dir/refused.evaluations.csv" ] && fail "$1: the evaluation log was written"
}

small_table "$dir/tiny.yaml"
calibration() {  # extra lines appended to a valid calibration file
  printf 'experiment: tiny.yaml\nseed: 11\nrealizations: 4\nverify_seeds: [2, 3]\n'
  printf 'global: {algorithm: GN_DIRECT_L, max_evaluations: 40}\nlocal: {algorithm: LN_SBPLX, max_evaluations: 20}\n'
  printf 'parameters:\n  - {key: scenario.tunnel.width_m, min: 6, max: 20, provenance: "not stated"}\n'
  printf '  - {key: scenario.trajectory.speed_mps, min: 0.3, max: 1.5, provenance: "not stated"}\n'
  printf '%s\n' "$@"
}

calibration >"$dir/cal.yaml"
sed 's/scenario.trajectory.speed_mps/estimator.filter.tau_m/' "$dir/cal.yaml" >"$dir/estimator_key.yaml"
expect_refusal "an estimator key" "only keys under 'scenario' can be calibrated" "$dir/estimator_key.yaml"
sed 's/verify_seeds: \[2, 3\]/verify_seeds: [2, 11]/' "$dir/cal.yaml" >"$dir/seen_seed.yaml"
expect_refusal "a verification seed the fit uses" "holds the fit's seed 11" "$dir/seen_seed.yaml"
sed 's/min: 6, max: 20/min: 12, max: 20/' "$dir/cal.yaml" >"$dir/outside.yaml"
expect_refusal "the configured value outside the bounds" "the experiment's value 10 lies outside [min, max]" "$dir/outside.yaml"
sed 's/min: 6, max: 20/min: -1, max: 20/' "$dir/cal.yaml" >"$dir/bad_bound.yaml"
expect_refusal "a bound the experiment refuses" "(scenario.tunnel.width_m) at its min" "$dir/bad_bound.yaml"
sed 's/GN_DIRECT_L/GN_CRS2_LM/' "$dir/cal.yaml" >"$dir/stochastic.yaml"
expect_refusal "a stochastic algorithm" "draws from NLopt's process-wide random generator" "$dir/stochastic.yaml"
sed 's/min: 6, max: 20, provenance: "not stated"/min: 6, max: 20, provenance: ""/' "$dir/cal.yaml" >"$dir/no_provenance.yaml"
expect_refusal "a parameter without provenance" "say where the range comes from" "$dir/no_provenance.yaml"

[ -e "$dir/tiny.calibrated.yaml" ] && fail "a refused calibration wrote the calibrated config"

# Uninterrupted.
"$bin" calibrate "$dir/cal.yaml" --out "$dir/whole" --quiet --threads 1 || fail "calibrate"
[ -f "$dir/tiny.calibrated.yaml" ] || fail "no calibrated config next to the experiment"
[ -e "$dir/whole.evaluations.csv" ] && fail "the running log outlived a finished calibration"
evaluations=$(($(wc -l <"$dir/whole/evaluations.csv") - 1))
[ "$evaluations" -gt 20 ] || fail "only $evaluations evaluations"
grep -q "^base: tiny.yaml$" "$dir/tiny.calibrated.yaml" || fail "calibrated config lacks its base"
"$bin" run "$dir/tiny.calibrated.yaml" --out "$dir/calibrated_run" --quiet || fail "the calibrated config does not run"
expect_refusal "a calibrated config that exists" "tiny.calibrated.yaml: exists; add --overwrite" "$dir/cal.yaml"

# Killed with -9 once the log has a few evaluations, then rerun: the same bytes.
mv "$dir/tiny.calibrated.yaml" "$dir/first.calibrated.yaml"
"$bin" calibrate "$dir/cal.yaml" --out "$dir/resumed" --quiet --threads 1 &
pid=$!
for _ in $(seq 1 200); do
  [ "$( { wc -l <"$dir/resumed.evaluations.csv"; } 2>/dev/null || echo 0)" -ge 6 ] && break
  sleep 0.05
done
kill -9 "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
[ -e "$dir/resumed" ] && fail "a killed calibration left a result folder"
known=$("$bin" calibrate "$dir/cal.yaml" --out "$dir/resumed" --threads 1 2>&1 >/dev/null | grep -o '[0-9]* evaluations known' | head -1)
[ -n "$known" ] || fail "the rerun did not resume from the log"
for file in evaluations.csv verification.csv profile.csv calibration.md; do
  cmp -s "$dir/whole/$file" "$dir/resumed/$file" || fail "resumed $file differs from the uninterrupted one"
done
cmp -s "$dir/first.calibrated.yaml" "$dir/tiny.calibrated.yaml" || fail "resumed calibrated config differs"
echo "ok: killed and resumed ($known) to the same bytes"

# --reuse: a finished log spares every evaluation (the fit reruns in no time and writes the same).
rm "$dir/tiny.calibrated.yaml"
"$bin" calibrate "$dir/cal.yaml" --out "$dir/reused" --quiet --reuse "$dir/whole/evaluations.csv" || fail "reuse"
cmp -s "$dir/whole/evaluations.csv" "$dir/reused/evaluations.csv" || fail "reused evaluations differ"
echo "ok: --reuse"

# The log of a killed calibration of other parameters into the same folder: refused, with the way out.
rm -f "$dir/tiny.calibrated.yaml"
printf 'context,evaluation,stage,scenario.other,objective\n' >"$dir/refused.evaluations.csv"
err=$("$bin" calibrate "$dir/cal.yaml" --out "$dir/refused" --quiet 2>&1 >/dev/null)
[ $? -eq 2 ] && grep -qF "remove it to start afresh" <<<"$err" || fail "a foreign running log: $err"
[ -e "$dir/refused" ] && fail "a foreign running log: a folder was written"
rm -f "$dir/refused.evaluations.csv"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all calibrate cases passed"
