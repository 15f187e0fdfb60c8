#!/usr/bin/env bash
# Parts that own their options (issue 37), from the command line: the example trigger travel_span
# and the example environment ceiling_grid are listed with their options, named in a config,
# swept on their own keys, and a bad value of such a key is one clear error before any work.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

"$bin" list | grep -qF "estimator.travel_span.span_m (default 10)" || fail "list does not show travel_span's option"

small_table "$dir/small.yaml"
printf 'base: small.yaml\nestimator: {triggers: [pdop_closest_point, travel_span]}\n' >"$dir/span.yaml"
"$bin" sweep "$dir/span.yaml" --set estimator.travel_span.span_m=2,40 --out "$dir/swept" --quiet ||
  fail "sweep of estimator.travel_span.span_m"
# A longer span waits for more of the path: later against the oracle, and closer to the truth.
/usr/bin/python3 - "$dir/swept/sweep.csv" <<'PY' || fail "the span does not change travel_span's results as it should"
import csv, sys
rows = {(r["estimator.travel_span.span_m"], r["row"]): r
        for r in csv.DictReader(open(sys.argv[1])) if r["method"] == "travel_span"}
short, long = rows[("2", "1")], rows[("40", "1")]
assert float(long["latency_med"]) > float(short["latency_med"]), (short["latency_med"], long["latency_med"])
assert float(long["avg_m"]) < float(short["avg_m"]), (short["avg_m"], long["avg_m"])
print("ok: span 2 m -> 40 m: latency", short["latency_med"], "->", long["latency_med"],
      ", mean error", short["avg_m"], "->", long["avg_m"])
PY
grep -qF '"estimator.travel_span.span_m=2,40"' "$dir/swept/manifest.json" || fail "the manifest lacks the axis"

refused "a span of 0" "key 'estimator.travel_span.span_m': must be > 0" "$dir/zero" \
  "$bin" sweep "$dir/span.yaml" --set estimator.travel_span.span_m=0,1 --out "$dir/zero" --quiet
refused "a key travel_span does not own" "key 'estimator.travel_span.span': unknown key" "$dir/typo" \
  "$bin" run "$dir/span.yaml" --set estimator.travel_span.span=3 --out "$dir/typo" --quiet

# The example environment: named, its options set and swept like a trigger's.
"$bin" list | grep -qF "scenario.ceiling_grid.rows (default 3)" || fail "list does not show ceiling_grid's options"
printf 'seed: 3\nrealizations: 2\nscenario:\n  environment: ceiling_grid\n  trajectory: {hall_duration_s: 40, rate_hz: 5}\n' \
  >"$dir/grid.yaml"
"$bin" sweep "$dir/grid.yaml" --set scenario.ceiling_grid.rows=2,5 --out "$dir/grid" --quiet || fail "sweep of rows"
/usr/bin/python3 - "$dir/grid/sweep.csv" <<'PY' || fail "the grid's rows do not set its anchors"
import csv, sys
oracle = {r["scenario.ceiling_grid.rows"]: int(r["oracle_n"]) for r in csv.DictReader(open(sys.argv[1]))
          if r["method"] == "pdop_closest_point"}
# 2 realizations of rows x 2 columns anchors, each with an oracle time or not: at most that many.
assert oracle["2"] <= 2 * 2 * 2 < oracle["5"] <= 2 * 5 * 2, oracle
print("ok: ceiling_grid rows 2 -> 5: anchors with an oracle time", oracle["2"], "->", oracle["5"])
PY
"$bin" simulate "$dir/grid.yaml" --set scenario.ceiling_grid.columns=3 --out "$dir/grid_log" ||
  fail "simulate in ceiling_grid"
[ "$(tail -n +2 "$dir/grid_log/anchors.csv" | wc -l)" -eq 9 ] || fail "simulate: not 3 x 3 anchors"
# navigate and pdop-study take --set like run (the navigation study needs its section).
printf 'base: grid.yaml\nnavigation: {}\n' >"$dir/grid_nav.yaml"
"$bin" navigate "$dir/grid_nav.yaml" --set scenario.ceiling_grid.rows=4 --out "$dir/grid_nav" --quiet ||
  fail "navigate --set in ceiling_grid"
grep -qF '"--set scenario.ceiling_grid.rows=4"' "$dir/grid_nav/manifest.json" || fail "navigate's manifest lacks its --set"
"$bin" pdop-study "$dir/grid.yaml" --set scenario.ceiling_grid.rows=4 --out "$dir/grid_pdop" --quiet ||
  fail "pdop-study --set in ceiling_grid"
refused "an unknown environment" "key 'scenario.environment': unknown environment 'mine'" "$dir/mine" \
  "$bin" run "$dir/grid.yaml" --set scenario.environment=mine --out "$dir/mine" --quiet
refused "a grid of 0 rows" "key 'scenario.ceiling_grid.rows': must be in [1, 100]" "$dir/rows0" \
  "$bin" run "$dir/grid.yaml" --set scenario.ceiling_grid.rows=0 --out "$dir/rows0" --quiet

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all part-option cases passed"
