# Sourced by the command-line tests (with the script's own arguments): the executable under test,
# a scratch folder removed at exit, and a failure count with fail().
set -u
bin="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
