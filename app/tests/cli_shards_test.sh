#!/usr/bin/env bash
# Shards and merge (issue 15): `run|sweep|navigate|explore|pdop-study --shard I/N` for every I, then `merge`,
# writes the bytes of the single-process run, for any N and thread count; missing, duplicated,
# mismatched or edited shards are one clear error with nothing written.
# Arguments: the anchorbench executable, the configs folder.
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
configs="$2"

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

# explore's units go the same way (one kind of study of record units, studies/record_study.hpp).
explore="$configs/exploration_uav_hall.yaml"
"$bin" explore "$explore" --realizations 3 --out "$dir/ex_whole" --quiet --threads 2 || fail "explore"
for ((i = 0; i < 3; i++)); do
  "$bin" explore "$explore" --realizations 3 --shard "$i/3" --out "$dir/e3-$i" --quiet --threads 1 \
    || fail "explore shard $i/3"
done
"$bin" merge "$dir/ex_merged" "$dir/e3-2" "$dir/e3-0" "$dir/e3-1" --quiet || fail "merge of explore shards"
for file in exploration.csv exploration_summary.csv exploration.md navigation_error.csv; do
  cmp -s "$dir/ex_whole/$file" "$dir/ex_merged/$file" || fail "3 explore shards: merged $file differs"
done
echo "ok: 3 explore shards merge to the single run's bytes"
expect_refusal "explore and navigate shards together" "is of another run" "$dir/e3-0" "$dir/n4-1"

# And the PDOP study's (one unit per realization), with its settings from the flags.
study="$configs/pdop_study.yaml"
"$bin" pdop-study "$study" --realizations 5 --every 20 --bin-s 5 --out "$dir/p_whole" --quiet --threads 2 ||
  fail "pdop-study"
for ((i = 0; i < 2; i++)); do
  "$bin" pdop-study "$study" --realizations 5 --every 20 --bin-s 5 --shard "$i/2" --out "$dir/p2-$i" --quiet \
    --threads 1 || fail "pdop-study shard $i/2"
done
"$bin" merge "$dir/p_merged" "$dir/p2-1" "$dir/p2-0" --quiet || fail "merge of pdop-study shards"
for file in pdop_trace.csv pdop_study.md; do
  cmp -s "$dir/p_whole/$file" "$dir/p_merged/$file" || fail "2 pdop-study shards: merged $file differs"
done
echo "ok: 2 pdop-study shards merge to the single run's bytes"
expect_refusal "pdop-study and explore shards together" "is of another run" "$dir/p2-0" "$dir/e3-1"

# Every edit of a shard's records.csv is refused, whichever way (issue 33's tampered shards): each
# unit is a block whose checksum binds its text to the unit and the plan.
cp -r "$dir/n4-2" "$dir/n4-2.kept"
plan=$(tail -1 "$dir/n4-2/shard.csv" | cut -d, -f6)
nav_tamper() {  # NAME EXPECTED HOW [FIELD VALUE]: one way of editing shard 2/4's records.csv
  rm -rf "$dir/n4-2" && cp -r "$dir/n4-2.kept" "$dir/n4-2"
  /usr/bin/python3 - "$dir/n4-2/records.csv" "$plan" "${@:3}" <<'PY' || fail "tamper $1: the editor failed"
import sys
path, plan, how, *args = sys.argv[1:]
data = open(path, "rb").read().decode()
blocks, at = [], 0
while at < len(data):
    end = data.index("\n", at)
    kind, key, size, tag = data[at:end].split(",")
    blocks.append([int(key), tag, data[end + 1:end + 1 + int(size)]])
    at = end + 1 + int(size)
def checksum(key, text):
    h = 0xcbf29ce484222325
    for b in (plan + "\n" + str(key) + "\n" + text).encode():
        h = ((h ^ b) * 0x100000001b3) % (1 << 64)
    return "%016x" % h
def edit_field(block, field, value):
    lines = block[2].split("\n")
    fields = lines[0].split(",")
    fields[int(field)] = value
    lines[0] = ",".join(fields)
    block[2] = "\n".join(lines)
first = blocks[0]
if how == "edit":
    edit_field(first, *args)
elif how == "fit":
    edit_field(first, *args)
    first[1] = checksum(first[0], first[2])
elif how == "move":
    first[0] += 1
elif how == "tag":
    first[1] = "0123456789abcdef"
elif how == "drop":
    blocks.pop(0)
elif how == "twice":
    blocks.insert(1, list(first))
out = "".join("unit,%d,%d,%s\n%s" % (k, len(t.encode()), g, t) for k, g, t in blocks)
if how == "torn":
    out = out[:-7]
open(path, "wb").write(out.encode())
PY
  cmp -s "$dir/n4-2.kept/records.csv" "$dir/n4-2/records.csv" && fail "tamper $1 changed nothing"
  expect_refusal "a navigation shard with $1" "$2" "$dir/n4-0" "$dir/n4-1" "$dir/n4-2" "$dir/n4-3"
}
nav_tamper "a negated rmse" "does not match its checksum" edit 3 -1
nav_tamper "an rmse of 1e300" "does not match its checksum" edit 3 1e300
nav_tamper "a fix share of 2" "does not match its checksum" edit 7 2
nav_tamper "its unit moved" "is not a unit of shard 2/4" move
nav_tamper "a unit of another run" "does not match its checksum" tag
nav_tamper "a unit taken out" "shard.csv says" drop
nav_tamper "a unit twice" "is there twice" twice
nav_tamper "its end torn" "is torn" torn
# A value no run writes is refused even with a checksum made to fit it, naming the file and line.
nav_tamper "a fix share of 2 with a checksum made to fit" "records.csv:2: a fix share outside [0, 1]" fit 7 2

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all shard cases passed"
