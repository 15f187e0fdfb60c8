#!/usr/bin/env bash
# The main command (README): set up, build the anchorbench executable, and reproduce the paper's
# Table I (4 rows x 100 realizations x 30 anchors, PDOP-gated vs fixed window) into
# results/table1/: attempts.csv, summary.csv, summary.md (paper vs ours), manifest.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh anchorbench
build/experiments/anchorbench run configs/table1.yaml --out results/table1
