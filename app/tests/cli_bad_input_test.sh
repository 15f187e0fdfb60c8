#!/usr/bin/env bash
# Command-line bad input: each case must exit non-zero with one clear message naming the place,
# and must not leave output files behind.
set -u
bin="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0

# expect_error DESCRIPTION EXPECTED_TEXT COMMAND...
expect_error() {
  local what="$1" expected="$2"
  shift 2
  local err
  err=$("$@" 2>&1 >/dev/null)
  local code=$?
  if [ $code -eq 0 ]; then
    echo "FAIL: $what: exit code 0"; failures=$((failures + 1))
  elif ! grep -qF -- "$expected" <<<"$err"; then
    echo "FAIL: $what: message lacks '$expected': $err"; failures=$((failures + 1))
  elif [ "$(wc -l <<<"$err")" -ne 1 ]; then
    echo "FAIL: $what: expected one line, got: $err"; failures=$((failures + 1))
  else
    echo "ok: $what -> $err"
  fi
}

printf 'seed: 1\nscenario:\n  ranging:\n    sigma_range_m: -1\n' >"$dir/neg.yaml"
printf 'seed: 1\nbogus: 2\n' >"$dir/unknown.yaml"
printf 'seed: 1\nscenario:\n  tunnel:\n    length_m: 60\n    num_anchors: 4\n' >"$dir/ok.yaml"
expect_error "negative sigma" "key 'scenario.ranging.sigma_range_m': must be in [0, 100]" "$bin" simulate "$dir/neg.yaml" --out "$dir/sim"
expect_error "unknown key" "key 'bogus': unknown key" "$bin" simulate "$dir/unknown.yaml" --out "$dir/sim"
expect_error "missing config" "cannot open the config file" "$bin" simulate "$dir/none.yaml" --out "$dir/sim"
[ -e "$dir/sim" ] && { echo "FAIL: output folder created on bad input"; failures=$((failures + 1)); }

"$bin" simulate "$dir/ok.yaml" --out "$dir/sim" >/dev/null || { echo "FAIL: simulate"; exit 1; }
printf 't,tag_id,anchor_id,range\n0,0,1,5\n0.1,0,1,abc\n' >"$dir/bad_ranges.csv"
printf 't,tag_id,anchor_id,range\n1,0,1,5\n0.5,0,1,5\n' >"$dir/back_ranges.csv"
printf 't,tag_id,x,y\n0,0,1,2\n' >"$dir/bad_poses.csv"
expect_error "non-number range" "bad_ranges.csv:3: column 'range': 'abc' is not a number" \
  "$bin" replay --poses "$dir/sim/poses.csv" --ranges "$dir/bad_ranges.csv" --out "$dir/out1"
expect_error "time backwards" "back_ranges.csv:3: t=0.5 comes after t=1, more than --sort-window-s 0.1 late" \
  "$bin" replay --poses "$dir/sim/poses.csv" --ranges "$dir/back_ranges.csv"
expect_error "missing column" "bad_poses.csv:1: missing column 'z'" \
  "$bin" replay --poses "$dir/bad_poses.csv" --ranges "$dir/sim/ranges.csv"
expect_error "bad config in replay" "key 'scenario.ranging.sigma_range_m'" \
  "$bin" replay --poses "$dir/sim/poses.csv" --ranges "$dir/sim/ranges.csv" --config "$dir/neg.yaml"
[ -e "$dir/out1/estimates.csv" ] && { echo "FAIL: estimates written on bad input"; failures=$((failures + 1)); }
printf 'estimator:\n  triggers: [fixed_window, pdop_true]\n' >"$dir/oracle.yaml"
expect_error "oracle trigger without anchors.csv" "trigger 'pdop_true': needs the true anchor position" \
  "$bin" replay --poses "$dir/sim/poses.csv" --ranges "$dir/sim/ranges.csv" --config "$dir/oracle.yaml" \
  --trace "$dir/oracle_out/trace.csv" --out "$dir/oracle_out"
[ -e "$dir/oracle_out" ] && { echo "FAIL: output folder created for a replay that cannot run"; failures=$((failures + 1)); }
expect_error "unknown trigger" "key 'estimator.triggers': unknown trigger 'pdop_best'" \
  "$bin" run "$dir/ok.yaml" --set 'estimator.triggers=[fixed_window, pdop_best]' --out "$dir/run_out"
[ -e "$dir/run_out" ] && { echo "FAIL: output folder created on a bad --set"; failures=$((failures + 1)); }

# And the good path writes exactly what it promises.
"$bin" replay --poses "$dir/sim/poses.csv" --ranges "$dir/sim/ranges.csv" --anchors "$dir/sim/anchors.csv" \
  --trace "$dir/trace.csv" --out "$dir/out" >/dev/null || { echo "FAIL: replay"; failures=$((failures + 1)); }
[ "$(head -1 "$dir/trace.csv")" = "t,tag_id,anchor_id,range,accepted,n_accepted,pdop" ] || { echo "FAIL: trace header"; failures=$((failures + 1)); }
[ "$(($(wc -l <"$dir/trace.csv")))" -eq "$(($(wc -l <"$dir/sim/ranges.csv")))" ] || { echo "FAIL: one trace row per range"; failures=$((failures + 1)); }
# The certificate's trace: one row per evaluation, each naming the test that held the anchor back
# (or "fired"), one "fired" row per certified anchor in estimates.csv.
"$bin" replay --quiet --poses "$dir/sim/poses.csv" --ranges "$dir/sim/ranges.csv" --certificate-trace "$dir/cert.csv" \
  --out "$dir/out_cert" >/dev/null || { echo "FAIL: replay --certificate-trace"; failures=$((failures + 1)); }
[ "$(head -1 "$dir/cert.csv" | cut -d, -f1-7)" = "t,anchor_id,method,samples,blocked_by,value,limit" ] || { echo "FAIL: certificate trace header"; failures=$((failures + 1)); }
bad_tests=$(tail -n +2 "$dir/cert.csv" | cut -d, -f5 | grep -cvE '^(solve|region|region_ends|mirror|alternative|doubling|stability|fired)$' || true)
[ "$bad_tests" -eq 0 ] || { echo "FAIL: certificate trace names $bad_tests unknown tests"; failures=$((failures + 1)); }
fired=$(tail -n +2 "$dir/cert.csv" | grep -c ',certified,[0-9]*,fired,' || true)
certified=$(grep -c ',certified,1,' "$dir/out_cert/estimates.csv" || true)
[ "$fired" -eq "$certified" ] || { echo "FAIL: $fired fired rows, $certified certified anchors"; failures=$((failures + 1)); }
printf 'anchor_id,x,y,z\n900,0,0,0\n901,1,1,1\n' >"$dir/other_site.csv"
expect_error "anchors of another site" "none of its 2 (ids 900 to 901) is an anchor the log ranges" "$bin" replay \
  --poses "$dir/sim/poses.csv" --ranges "$dir/sim/ranges.csv" --anchors "$dir/other_site.csv"
# The terminal table keeps its columns apart with epoch times (1.69e9 s): as many fields per row as
# the header has.
awk -F, -v CONVFMT=%.3f 'NR == 1 { print; next } { $1 = $1 + 1691181966; print }' OFS=, "$dir/sim/poses.csv" >"$dir/epoch_poses.csv"
awk -F, -v CONVFMT=%.3f 'NR == 1 { print; next } { $1 = $1 + 1691181966; print }' OFS=, "$dir/sim/ranges.csv" >"$dir/epoch_ranges.csv"
"$bin" replay --quiet --poses "$dir/epoch_poses.csv" --ranges "$dir/epoch_ranges.csv" >"$dir/epoch_table.txt" ||
  { echo "FAIL: replay of the epoch log"; failures=$((failures + 1)); }
awk 'NR == 1 { n = NF; next } NF != n { bad++ } END { exit bad > 0 }' "$dir/epoch_table.txt" ||
  { echo "FAIL: the terminal table runs columns together"; cat "$dir/epoch_table.txt"; failures=$((failures + 1)); }
expect_error "certificate trace is the trace" "is also --trace" "$bin" replay --poses "$dir/sim/poses.csv" --ranges "$dir/sim/ranges.csv" \
  --trace "$dir/same.csv" --certificate-trace "$dir/same.csv"
[ "$(head -1 "$dir/out/estimates.csv")" = "anchor_id,method,initialized,t_init,n_used,pdop_est,pdop_true,x,y,z,bias,err_m,status,err_xy,err_z,bias_aware_hdop,bias_aware_vdop,scale,blocked_by,blocked_value,blocked_limit,samples_needed,evidence_explained,t_first,t_oracle,latency,radius99_m" ] || { echo "FAIL: estimates header"; failures=$((failures + 1)); }
grep -qi nan "$dir/out/estimates.csv" && { echo "FAIL: NaN in estimates"; failures=$((failures + 1)); }
ls "$dir"/*.tmp.* "$dir"/out/*.tmp.* >/dev/null 2>&1 && { echo "FAIL: temporary files left"; failures=$((failures + 1)); }
"$bin" replay --help >/dev/null || { echo "FAIL: replay --help"; failures=$((failures + 1)); }
"$bin" simulate --help >/dev/null || { echo "FAIL: simulate --help"; failures=$((failures + 1)); }

# run: bad configs fail before any trial, and a good run writes its four files.
printf 'seed: 1\nrealizations: 0\n' >"$dir/zero.yaml"
printf 'seed: 1\nrows:\n  - name: a\n    scenario: {ranging: {sigma_rang_m: 1}}\n' >"$dir/badrow.yaml"
expect_error "zero realizations" "key 'realizations': must be in [1," "$bin" run "$dir/zero.yaml" --out "$dir/run0"
expect_error "bad row key" "key 'rows[0].scenario.ranging.sigma_rang_m': unknown key" "$bin" run "$dir/badrow.yaml" --out "$dir/run0"
[ -e "$dir/run0/attempts.csv" ] && { echo "FAIL: attempts written on bad config"; failures=$((failures + 1)); }
printf 'seed: 1\nrealizations: 3\nscenario:\n  tunnel: {length_m: 60, num_anchors: 3}\n' >"$dir/small.yaml"
quiet_output=$("$bin" run "$dir/small.yaml" --out "$dir/run" --quiet 2>&1)
[ -z "$quiet_output" ] || { echo "FAIL: --quiet printed: $quiet_output"; failures=$((failures + 1)); }
for f in attempts.csv summary.csv summary.md manifest.json; do
  [ -s "$dir/run/$f" ] || { echo "FAIL: run did not write $f"; failures=$((failures + 1)); }
done
case "$(head -1 "$dir/run/summary.csv")" in  # exactly these leading columns; more may follow
  row,method,avg_m,med_m,init,gt1m,ratio_pct,avg_lo,avg_hi,ratio_lo,ratio_hi*) ;;
  *) echo "FAIL: summary header"; failures=$((failures + 1)) ;;
esac
summary_line=$("$bin" run "$dir/small.yaml" --out "$dir/run" --overwrite 2>&1 >/dev/null)
grep -q "realizations in" <<<"$summary_line" || { echo "FAIL: no summary line when stderr is not a terminal: $summary_line"; failures=$((failures + 1)); }

# sweep: every grid point is validated before any trial; results do not depend on threads.
expect_error "sweep unknown key" "key 'estimator.trigger.pdop_treshold': unknown key" \
  "$bin" sweep "$dir/small.yaml" --set estimator.trigger.pdop_treshold=0.5,1 --out "$dir/sw0"
expect_error "sweep bad value" "key 'estimator.trigger.pdop_threshold': must be in (0, 1e6]" \
  "$bin" sweep "$dir/small.yaml" --set estimator.trigger.pdop_threshold=1,0 --out "$dir/sw0"
expect_error "sweep bad range" "a range is START:STOP:STEP" \
  "$bin" sweep "$dir/small.yaml" --set estimator.trigger.pdop_threshold=1:2 --out "$dir/sw0"
expect_error "sweep without axes" "nothing to sweep" "$bin" sweep "$dir/small.yaml" --out "$dir/sw0"
[ -e "$dir/sw0/sweep.csv" ] && { echo "FAIL: sweep wrote output on bad input"; failures=$((failures + 1)); }
"$bin" sweep "$dir/small.yaml" --set estimator.trigger.pdop_threshold=0.5,2 --set scenario.ranging.sigma_range_m=0.1,0.3 \
  --out "$dir/sw1" --threads 1 --quiet || { echo "FAIL: sweep 1 thread"; failures=$((failures + 1)); }
"$bin" sweep "$dir/small.yaml" --set estimator.trigger.pdop_threshold=0.5,2 --set scenario.ranging.sigma_range_m=0.1,0.3 \
  --out "$dir/sw2" --threads 2 --quiet || { echo "FAIL: sweep 2 threads"; failures=$((failures + 1)); }
cmp -s "$dir/sw1/sweep.csv" "$dir/sw2/sweep.csv" || { echo "FAIL: sweep.csv differs between 1 and 2 threads"; failures=$((failures + 1)); }
[ "$(wc -l <"$dir/sw1/sweep.csv")" -eq 13 ] || { echo "FAIL: sweep.csv should have 4 points x 3 methods (the default triggers) + header"; failures=$((failures + 1)); }
# The manifest records what the command line changed: the realizations that ran, and the axes.
"$bin" sweep "$dir/small.yaml" --set estimator.trigger.pdop_threshold=0.5,2 --realizations 2 --out "$dir/sw4" --quiet \
  || { echo "FAIL: sweep with --realizations"; failures=$((failures + 1)); }
for expected in '"realizations": 2' '"--realizations 2"' '"--set estimator.trigger.pdop_threshold=0.5,2"'; do
  grep -qF -- "$expected" "$dir/sw4/manifest.json" || { echo "FAIL: sweep manifest lacks $expected"; failures=$((failures + 1)); }
done
axes=$(/usr/bin/python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["sweep_axes"])' "$dir/sw4/manifest.json")
[ "$axes" = "['estimator.trigger.pdop_threshold=0.5,2']" ] || { echo "FAIL: sweep manifest's axes: $axes"; failures=$((failures + 1)); }

"$bin" list | grep -q "lm_adaptive" || { echo "FAIL: list does not show lm_adaptive"; failures=$((failures + 1)); }
"$bin" sweep "$dir/small.yaml" --set estimator.solver=lm_l2,nlopt:LN_BOBYQA --out "$dir/sw3" --quiet \
  || { echo "FAIL: sweep over solvers"; failures=$((failures + 1)); }

[ $failures -eq 0 ] && echo "all CLI bad-input cases passed"
exit $failures
