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

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all shard cases passed"
