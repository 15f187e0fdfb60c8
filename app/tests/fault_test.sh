#!/usr/bin/env bash
# Faults (issue 11): `run` and `sweep` killed with SIGKILL at random moments leave their result
# folder either the old complete result or the new complete result, never a mix, and the next run
# removes what the killed ones left; a full disk is an error before any work, with the reason,
# and the earlier results intact. Usage: fault_test.sh ANCHORBENCH [SECONDS]
set -u
bin="$1"
budget_s="${2:-40}"
dir=$(mktemp -d)
mounted=""
cleanup() { [ -n "$mounted" ] && umount "$mounted" 2>/dev/null; rm -rf "$dir"; }
trap cleanup EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

printf 'seed: 1\nrealizations: 30\nbootstrap_resamples: 50\nscenario:\n  tunnel: {length_m: 100, num_anchors: 6}\n' >"$dir/c.yaml"
# The deterministic part of a result folder (manifest.json and timing.csv hold times), and its file list.
fingerprint() { (cd "$1" 2>/dev/null && ls && cat "${@:2}") | md5sum; }

# kill_loop NAME "FILES" "ARGS_A" "ARGS_B" COMMAND...: alternate between the results of COMMAND
# with ARGS_A and with ARGS_B, killing most attempts.
kill_loop() {
  local name="$1" files_text="$2" args_a="$3" args_b="$4"
  shift 4
  local files
  read -r -a files <<<"$files_text"
  local out="$dir/$name" ref_a="$dir/${name}_a" ref_b="$dir/${name}_b"
  # shellcheck disable=SC2086
  "$@" $args_a --out "$ref_a" >/dev/null 2>&1 && "$@" $args_b --out "$ref_b" >/dev/null 2>&1 || { fail "$name: reference runs"; return; }
  local a b
  a=$(fingerprint "$ref_a" "${files[@]}")
  b=$(fingerprint "$ref_b" "${files[@]}")
  cp -r "$ref_a" "$out"
  local state="$a" next="b" tries=0 old=0 new=0 deadline=$((SECONDS + budget_s / 2))
  while [ $SECONDS -lt $deadline ]; do
    local args="$args_b"; [ "$next" = "a" ] && args="$args_a"
    # shellcheck disable=SC2086
    "$@" $args --out "$out" --overwrite >/dev/null 2>&1 &
    local pid=$!
    sleep "0.$(printf '%03d' $((RANDOM % 250)))"
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    tries=$((tries + 1))
    local now
    now=$(fingerprint "$out" "${files[@]}")
    local expected_new; [ "$next" = "b" ] && expected_new="$b" || expected_new="$a"
    if [ "$now" = "$state" ]; then
      old=$((old + 1))
    elif [ "$now" = "$expected_new" ]; then
      new=$((new + 1)); state="$now"; [ "$next" = "b" ] && next="a" || next="b"
    else
      fail "$name: after a kill the folder is neither the old nor the new result: $(ls -a "$out")"
      break
    fi
    [ -f "$out/manifest.json" ] && [ -f "$out/timing.csv" ] || fail "$name: a file of the result is missing"
  done
  # shellcheck disable=SC2086
  "$@" $args_a --out "$out" --overwrite >/dev/null 2>&1 || fail "$name: run after the kills"
  if ls -a "$dir" | grep -qE "^\.$name\.(partial|old)-"; then fail "$name: leftovers of killed runs remain"; fi
  echo "ok: $name killed $tries times: $old left the old result, $new the new one, 0 mixed"
}

kill_loop run "attempts.csv summary.csv summary.md" "--seed 1" "--seed 2" "$bin" run "$dir/c.yaml" --quiet --threads 1
kill_loop sweep "sweep.csv sweep.md" "--set estimator.trigger.pdop_threshold=0.5,1" \
  "--set estimator.trigger.pdop_threshold=1,2" "$bin" sweep "$dir/c.yaml" --quiet --threads 1

# A full disk: a small tmpfs, where the test may mount one.
mkdir -p "$dir/mnt"
if mount -t tmpfs -o size=200k tmpfs "$dir/mnt" 2>/dev/null; then
  mounted="$dir/mnt"
  "$bin" run "$dir/c.yaml" --out "$dir/mnt/o" --quiet --realizations 5 || fail "a run that fits the disk"
  before=$(fingerprint "$dir/mnt/o" attempts.csv summary.csv)
  # Twelve times the attempts: more than the disk has left, which the reservation finds at once.
  err=$("$bin" run "$dir/c.yaml" --out "$dir/mnt/o" --quiet --seed 7 --realizations 60 --overwrite 2>&1 >/dev/null)
  status=$?
  [ $status -eq 2 ] || fail "full disk: exit $status, expected 2: $err"
  grep -q "No space left on device" <<<"$err" || fail "full disk: the message does not say why: $err"
  [ "$(fingerprint "$dir/mnt/o" attempts.csv summary.csv)" = "$before" ] || fail "full disk: the earlier results changed"
  ls -a "$dir/mnt" | grep -q "partial" && fail "full disk: a partial folder was left"
  echo "ok: full disk refused before any work: $err"
  umount "$dir/mnt" && mounted=""
  if mount -t tmpfs -o ro,size=64k tmpfs "$dir/mnt" 2>/dev/null; then
    mounted="$dir/mnt"
    start=$SECONDS
    err=$("$bin" run "$dir/c.yaml" --out "$dir/mnt/o" --quiet 2>&1 >/dev/null)
    status=$?
    [ $status -eq 2 ] && grep -q "Read-only file system" <<<"$err" || fail "read-only disk: exit $status: $err"
    [ $((SECONDS - start)) -le 2 ] || fail "read-only disk: found only after the work"
    echo "ok: read-only disk refused before any work: $err"
  fi
else
  echo "skipped: the full-disk case needs to mount a tmpfs (root); this process cannot"
fi

[ $failures -eq 0 ] && echo "all fault cases passed"
exit $failures
