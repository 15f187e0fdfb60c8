#!/usr/bin/env bash
# The hall experiments (docs/halls.md): the AMR and UAV Monte Carlo runs into results/, and one
# simulated-and-replayed example flight or drive per trajectory type for the figures.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/app/anchorbench
for hall in amr_hall amr_hall_height uav_hall table2; do
  "$bin" run "configs/$hall.yaml" --out "results/$hall" --quiet --overwrite
done
example() {  # NAME CONFIG [--set ...]: simulate realization 0, replay it, keep the estimates
  local name=$1 config=$2
  shift 2
  "$bin" simulate "$config" --out "build/examples/$name" --overwrite "$@" >/dev/null
  "$bin" replay --poses "build/examples/$name/poses.csv" --ranges "build/examples/$name/ranges.csv" \
    --anchors "build/examples/$name/anchors.csv" --config "$config" --trace "build/examples/$name/trace.csv" \
    --out "results/examples/$name" --overwrite >/dev/null
}
example amr_covering configs/amr_hall.yaml
example amr_partial configs/amr_hall.yaml --set scenario.trajectory.kind=short
example amr_straight configs/amr_hall.yaml --set scenario.trajectory.kind=straight
example uav configs/uav_hall.yaml
