#!/usr/bin/env bash
# The main command (README): set up, build, simulate a tunnel realization, replay it with the
# PDOP-gated and the fixed-window strategies, and print the per-anchor results.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
bin=build/experiments/anchorbench
data=build/tunnel_demo   # raw poses/ranges stay out of results/ (summaries only)
"$bin" simulate configs/tunnel.yaml --out "$data"
"$bin" replay --poses "$data/poses.csv" --ranges "$data/ranges.csv" --anchors "$data/anchors.csv" \
  --config configs/tunnel.yaml --out results/tunnel_demo
