#!/usr/bin/env bash
# A part that owns its options (issue 37), from the command line: the example trigger travel_span
# is listed with its option, named in a config, swept on its own key, and a bad value of that key
# is one clear error before any work.
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

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all part-option cases passed"
