#!/usr/bin/env bash
# Installs what is missing, then configures and builds (Release, with the Python module and the ROS node) in build/: everything, or only
# the targets given as arguments (e.g. `bash scripts/build.sh anchorbench`).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# ANCHORBENCH_WERROR=ON (the test command sets it): every warning is an error.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DANCHORBENCH_PYTHON=ON -DANCHORBENCH_ROS=ON \
  -DANCHORBENCH_WERROR="${ANCHORBENCH_WERROR:-OFF}" >/dev/null
if [ $# -gt 0 ]; then
  cmake --build build -j"$(nproc)" --target "$@"
else
  cmake --build build -j"$(nproc)"
fi
