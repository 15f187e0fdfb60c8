#!/usr/bin/env bash
# Converts and replays every case of the Hanyang outdoor UWB dataset (../shared/data/hanyang-uwb)
# with the PDOP-gated initializer, the bias-aware triggers and the fixed window:
# results/hanyang/<case>/estimates.csv and results/hanyang/summary.md; again with the mirror check
# on (configs/hanyang_height_check.yaml): results/hanyang_height_check/<case>/, and with the surveyed
# heights as priors (configs/hanyang_height_prior.yaml): results/hanyang_height_prior/<case>/, and
# with the navigation filter on each trigger's anchors (configs/hanyang_navigation.yaml, synthetic
# odometry): results/hanyang_navigation/<case>/.
# Skips (exit 0) when the dataset is not beside the checkout.
set -euo pipefail
cd "$(dirname "$0")/.."
data=${HANYANG_DATA:-../shared/data/hanyang-uwb}
if [ ! -d "$data" ]; then
  echo "hanyang: $data not found; skipped" >&2
  exit 0
fi
bin=build/app/anchorbench
for case_dir in "$data"/*/Trajectory_*/Case_*; do
  name=$(echo "${case_dir#"$data"/}" | tr '/' '_')   # e.g. LOS_Trajectory_A_Case_1
  "$bin" convert-hanyang "$case_dir" --out "build/hanyang/$name" --overwrite >/dev/null
  "$bin" replay --poses "build/hanyang/$name/poses.csv" --ranges "build/hanyang/$name/ranges.csv" \
    --anchors "build/hanyang/$name/anchors.csv" --config configs/hanyang.yaml \
    --trace "build/hanyang/$name/trace.csv" --out "results/hanyang/$name" --overwrite >/dev/null 2>&1
  "$bin" replay --poses "build/hanyang/$name/poses.csv" --ranges "build/hanyang/$name/ranges.csv" \
    --anchors "build/hanyang/$name/anchors.csv" --config configs/hanyang_height_check.yaml \
    --out "results/hanyang_height_check/$name" --overwrite --quiet >/dev/null
  "$bin" replay --poses "build/hanyang/$name/poses.csv" --ranges "build/hanyang/$name/ranges.csv" \
    --anchors "build/hanyang/$name/anchors.csv" --config configs/hanyang_height_prior.yaml \
    --out "results/hanyang_height_prior/$name" --overwrite --quiet >/dev/null
  "$bin" replay --poses "build/hanyang/$name/poses.csv" --ranges "build/hanyang/$name/ranges.csv" \
    --anchors "build/hanyang/$name/anchors.csv" --config configs/hanyang_navigation.yaml --navigate \
    --out "results/hanyang_navigation/$name" --overwrite --quiet >/dev/null
done
/usr/bin/python3 plot_scripts/hanyang_summary.py
