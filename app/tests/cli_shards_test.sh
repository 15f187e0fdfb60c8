#!/usr/bin/env bash
# Shards and merge (issue 15): `run|sweep --shard I/N` for every I, then `merge`, writes the bytes
# of the single-process run or sweep, for any N and thread count; missing, duplicated or
# mismatched shards are one clear error with nothing written.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

expect_refusal() {  # DESCRIPTION EXPECTED_TEXT SHARD_DIR...
  local what="$1" expected="$2"
  shift 2
  refused "$what" "$expected" "$dir/refused" "$bin" merge "$dir/refused" "$@"
}

small_table "$dir/small.yaml"
"$bin" run "$dir/small.yaml" --out "$dir/whole" --quiet --threads 2 || fail "run"
for n in 1 3 5 14 20; do
  shards=()
  for ((i = 0; i < n; i++)); do
    "$bin" run "$dir/small.yaml" --shard "$i/$n" --out "$dir/s$n-$i" --quiet --threads $((1 + i % 2)) || fail "shard $i/$n"
    shards+=("$dir/s$n-$i")
  done
  "$bin" merge "$dir/merged$n" "${shards[@]}" --quiet || fail "merge of $n"
  for file in attempts.csv summary.csv summary.md; do
    cmp -s "$dir/whole/$file" "$dir/merged$n/$file" || fail "$n shards: merged $file differs from the single run's"
  done
  echo "ok: $n shards merge to the single run's bytes"
done

# Given in any order, the same bytes.
"$bin" merge "$dir/reversed" "$dir/s3-2" "$dir/s3-0" "$dir/s3-1" --quiet || fail "merge in another order"
cmp -s "$dir/whole/summary.csv" "$dir/reversed/summary.csv" || fail "order of the shards changed the result"

expect_refusal "a missing shard" "shard 1/3 is missing" "$dir/s3-0" "$dir/s3-2"
expect_refusal "a duplicated shard" "is given twice" "$dir/s3-0" "$dir/s3-0" "$dir/s3-1" "$dir/s3-2"
expect_refusal "shards of different splits" "is of another run" "$dir/s3-0" "$dir/s5-1" "$dir/s3-2"
"$bin" run "$dir/small.yaml" --shard 1/3 --seed 6 --out "$dir/other_seed" --quiet || fail "run seed 6"
expect_refusal "a shard of another config" "is of another run" "$dir/s3-0" "$dir/other_seed" "$dir/s3-2"
sed -i 's/^seed: 5$/seed: 6/' "$dir/s3-0/config.yaml"
expect_refusal "an edited config" "(edited after the run?)" "$dir/s3-0" "$dir/s3-1" "$dir/s3-2"
rm "$dir/s5-2/chunk-000002.csv"
expect_refusal "a shard with a chunk missing" "chunk-000002.csv: missing; shard 2/5 holds it" \
  "$dir/s5-0" "$dir/s5-1" "$dir/s5-2" "$dir/s5-3" "$dir/s5-4"
head -n 3 "$dir/s5-3/chunk-000003.csv" >"$dir/cut.csv" && mv "$dir/cut.csv" "$dir/s5-3/chunk-000003.csv"
expect_refusal "a chunk cut short" "chunk-000003.csv:1: its lines do not match its checksum" \
  "$dir/s5-0" "$dir/s5-1" "$dir/s5-3" "$dir/s5-2" "$dir/s5-4"
# A sweep's shards merge to the sweep's bytes.
axis="estimator.trigger.pdop_threshold=0.5,1,2"
"$bin" sweep "$dir/small.yaml" --set "$axis" --out "$dir/sweep" --quiet || fail "sweep"
for n in 3 7; do
  shards=()
  for ((i = 0; i < n; i++)); do
    "$bin" sweep "$dir/small.yaml" --set "$axis" --shard "$i/$n" --out "$dir/w$n-$i" --quiet || fail "sweep shard $i/$n"
    shards+=("$dir/w$n-$i")
  done
  "$bin" merge "$dir/sweep_merged$n" "${shards[@]}" --quiet || fail "merge of $n sweep shards"
  for file in sweep.csv sweep.md; do
    cmp -s "$dir/sweep/$file" "$dir/sweep_merged$n/$file" || fail "$n sweep shards: merged $file differs"
  done
  echo "ok: $n sweep shards merge to the sweep's bytes"
done
expect_refusal "a run's and a sweep's shards" "is of another run" "$dir/w3-0" "$dir/s3-1" "$dir/s3-2"

refused "a shard index out of range" "'3/3' is not a shard I/N" "$dir/bad" "$bin" run "$dir/small.yaml" --shard 3/3 --out "$dir/bad"
refused "a shard that is not I/N" "'x' is not a shard I/N" "$dir/bad" "$bin" run "$dir/small.yaml" --shard x --out "$dir/bad"

# The navigation study (issue 27): its (row, realization) units in shards, merged to the bytes of
# the single process, whatever the split and threads; an edited records file is refused.
{ sed 's/^realizations: 5$/realizations: 3/' "$dir/small.yaml"; printf 'navigation: {}\n'; } >"$dir/navigated.yaml"
"$bin" navigate "$dir/navigated.yaml" --out "$dir/nav_whole" --quiet --threads 2 || fail "navigate"
for n in 1 4 7; do
  shards=()
  for ((i = 0; i < n; i++)); do
    "$bin" navigate "$dir/navigated.yaml" --shard "$i/$n" --out "$dir/n$n-$i" --quiet --threads $((1 + i % 2)) \
      || fail "navigate shard $i/$n"
    shards+=("$dir/n$n-$i")
  done
  "$bin" merge "$dir/nav_merged$n" "${shards[@]}" --quiet || fail "merge of $n navigation shards"
  for file in navigation.csv navigation_summary.csv navigation_error.csv navigation.md; do
    cmp -s "$dir/nav_whole/$file" "$dir/nav_merged$n/$file" || fail "$n navigation shards: merged $file differs"
  done
  echo "ok: $n navigation shards merge to the single run's bytes"
done
expect_refusal "a navigation shard missing" "shard 2/4 is missing" "$dir/n4-0" "$dir/n4-1" "$dir/n4-3"
sed -i '2d' "$dir/n4-1/navigation_records.csv"
expect_refusal "a navigation shard with a record taken out" "do not hold each of its methods once" \
  "$dir/n4-0" "$dir/n4-1" "$dir/n4-2" "$dir/n4-3"
"$bin" navigate "$dir/navigated.yaml" --shard 1/4 --out "$dir/n4-1" --quiet --overwrite || fail "navigate shard 1/4"
# Every edit of a record is refused by its checksum (issue 33's tampered shards), whichever field.
cp -r "$dir/n4-2" "$dir/n4-2.kept"
nav_tamper() {  # NAME AWK_PROGRAM: one way of editing shard 2/4's records
  rm -rf "$dir/n4-2" && cp -r "$dir/n4-2.kept" "$dir/n4-2"
  awk -F, -v OFS=, "$2" "$dir/n4-2.kept/navigation_records.csv" >"$dir/n4-2/navigation_records.csv"
  cmp -s "$dir/n4-2.kept/navigation_records.csv" "$dir/n4-2/navigation_records.csv" && fail "tamper $1 changed nothing"
  expect_refusal "a navigation record with $1" "does not match its checksum" "$dir/n4-0" "$dir/n4-1" "$dir/n4-2" "$dir/n4-3"
}
nav_tamper "a negated rmse" 'NR == 2 { $4 = -$4 } { print }'
nav_tamper "an rmse of 1e300" 'NR == 2 { $4 = "1e300" } { print }'
nav_tamper "a fix share of 2" 'NR == 2 { $8 = 2 } { print }'
nav_tamper "dropped bins" 'NR == 2 { sub(/;[^;]*$/, "", $11) } { print }'
nav_tamper "its unit moved" 'NR == 2 { $2 = 1 } { print }'
nav_tamper "two lines' units swapped" 'NR == 2 { a = $0; getline; b = $0; split(a, x, ","); split(b, y, ","); sub(/^[^,]*,[^,]*,[^,]*/, y[1] "," y[2] "," y[3], a); sub(/^[^,]*,[^,]*,[^,]*/, x[1] "," x[2] "," x[3], b); print b; print a; next } { print }'
nav_tamper "a line of another run" 'NR == 2 { $NF = "0123456789abcdef" } { print }'
# A value no run writes is refused even with a checksum made to fit it.
rm -rf "$dir/n4-2" && cp -r "$dir/n4-2.kept" "$dir/n4-2"
plan=$(tail -1 "$dir/n4-2/shard.csv" | cut -d, -f6)
/usr/bin/python3 - "$dir/n4-2/navigation_records.csv" "$plan" <<'PY'
import sys
path, plan = sys.argv[1], sys.argv[2]
lines = open(path).read().splitlines()
fields = lines[1].split(",")[:-1]
fields[7] = "2"  # a fix share of 2
text = ",".join(fields)
h = 0xcbf29ce484222325
for b in (plan + "\n" + text).encode():
    h = ((h ^ b) * 0x100000001b3) % (1 << 64)
lines[1] = text + ",%016x" % h
open(path, "w").write("\n".join(lines) + "\n")
PY
expect_refusal "a fix share of 2 with a checksum made to fit" "a fix share outside [0, 1]" \
  "$dir/n4-0" "$dir/n4-1" "$dir/n4-2" "$dir/n4-3"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all shard cases passed"
