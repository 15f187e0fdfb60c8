#!/usr/bin/env bash
# anchorbench calibrate (issue 14): bad calibration files are refused before any work (exit 2, one
# line naming the key, nothing written); a calibration killed with -9 resumes from its evaluation
# log to the same bytes as an uninterrupted one; --reuse takes a finished log's evaluations.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

expect_refusal() {  # DESCRIPTION EXPECTED_TEXT CALIBRATION_FILE
  local err status
  err=$("$bin" calibrate "$3" --out "$dir/refused" --quiet 2>&1 >/dev/null)
  status=$?
  if [ "$status" -ne 2 ]; then
    fail "$1: exit $status, expected 2: $err"
  elif ! grep -qF -- "$2" <<<"$err"; then
    fail "$1: message lacks '$2': $err"
  elif [ "$(wc -l <<<"$err")" -ne 1 ]; then
    fail "$1: expected one line, got: $err"
  elif [ -e "$dir/refused" ] || [ -e "$dir/refused.evaluations.csv" ]; then
    fail "$1: something was written"
  else
    echo "ok: $1"
  fi
}

# A small table: 2 rows of a short tunnel, 3 realizations (the paper's cells are made up).
cat >"$dir/tiny.yaml" <<'YAML'
seed: 1
realizations: 3
bootstrap_resamples: 50
scenario:
  tunnel: {length_m: 60, width_m: 10, num_anchors: 4}
  trajectory: {kind: random, rate_hz: 5}
  ranging: {sigma_range_m: 0.1, outlier_probability: 0.02}
rows:
  - name: "1"
    paper:
      fixed: {avg_m: 0.2, med_m: 0.05, init: 12, gt1m: 1, ratio_pct: 8}
      gated: {avg_m: 0.1, med_m: 0.05, init: 6, gt1m: 0, ratio_pct: 0}
  - name: "2"
    scenario: {ranging: {sigma_range_m: 0.3}}
    paper:
      fixed: {avg_m: 0.4, med_m: 0.1, init: 12, gt1m: 2, ratio_pct: 16}
      gated: {avg_m: 0.2, med_m: 0.1, init: 5, gt1m: 0, ratio_pct: 0}
YAML
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

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all calibrate cases passed"
