# Sourced by the command-line tests (with the script's own arguments): the executable under test,
# a scratch folder removed at exit, and a failure count with fail().
set -u
bin="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# drop_tally FILE REASON: a replay_summary.json's count (read as JSON, never by its layout) of REASON over every anchor and tag, and
# the first line it names: "COUNT FIRST".
drop_tally() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
tallies = [reasons[sys.argv[2]] for group in ("range_drops_by_anchor", "pose_drops_by_tag")
           for reasons in j[group].values() if sys.argv[2] in reasons]
print(sum(t["count"] for t in tallies), tallies[0]["first"] if tallies else "")
PY
}

# small_table FILE: a small two-row table of a short tunnel (a few seconds per run), with made-up
# paper cells on both rows.
small_table() {
  cat >"$1" <<'YAML'
seed: 5
realizations: 5
bootstrap_resamples: 100
scenario:
  tunnel: {length_m: 60, width_m: 10, num_anchors: 4}
  trajectory: {kind: random, rate_hz: 5}
  ranging: {sigma_range_m: 0.1, outlier_probability: 0.02}
rows:
  - name: "1"
    paper:
      fixed: {avg_m: 0.2, med_m: 0.05, init: 20, gt1m: 1, ratio_pct: 5}
      gated: {avg_m: 0.1, med_m: 0.05, init: 8, gt1m: 0, ratio_pct: 0}
  - name: "2"
    scenario: {ranging: {sigma_range_m: 0.3}}
    paper:
      fixed: {avg_m: 0.4, med_m: 0.1, init: 20, gt1m: 2, ratio_pct: 10}
      gated: {avg_m: 0.2, med_m: 0.1, init: 6, gt1m: 0, ratio_pct: 0}
YAML
}

# refused DESCRIPTION EXPECTED_TEXT UNWRITTEN COMMAND...: the command exits 2 with one line holding
# the text, and the path UNWRITTEN does not exist afterwards.
refused() {
  local what="$1" expected="$2" unwritten="$3" err status
  shift 3
  err=$("$@" 2>&1 >/dev/null)
  status=$?
  if [ "$status" -ne 2 ]; then
    fail "$what: exit $status, expected 2: $err"
  elif ! grep -qF -- "$expected" <<<"$err"; then
    fail "$what: message lacks '$expected': $err"
  elif [ "$(wc -l <<<"$err")" -ne 1 ]; then
    fail "$what: expected one line, got: $err"
  elif [ -e "$unwritten" ]; then
    fail "$what: $unwritten was written"
  else
    echo "ok: $what"
  fi
}

# expect_exit CODE DESCRIPTION EXPECTED_TEXT COMMAND...: the exit code, the text in one line of
# stderr, no control bytes in it.
expect_exit() {
  local code="$1" what="$2" expected="$3"
  shift 3
  local err status
  err=$("$@" 2>&1 >/dev/null)
  status=$?
  if [ "$status" -ne "$code" ]; then
    fail "$what: exit $status, expected $code: $err"
  elif [ -n "$expected" ] && ! grep -qF -- "$expected" <<<"$err"; then
    fail "$what: message lacks '$expected': $err"
  elif [ "$code" -ne 0 ] && [ "$(wc -l <<<"$err")" -ne 1 ]; then
    fail "$what: expected one line, got: $err"
  elif LC_ALL=C grep -q '[[:cntrl:]]' <<<"${err//$'\n'/}"; then
    fail "$what: control bytes in the message"
  else
    echo "ok: $what"
  fi
}
