#!/usr/bin/env bash
# The test command (README): set up, build from scratch if needed, run the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
