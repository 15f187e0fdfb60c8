#!/usr/bin/env bash
# Installs what is missing, then configures and builds (Release, with the Python module and the ROS node) in build/: everything, or only
# the targets given as arguments (e.g. `bash scripts/build.sh anchorbench`).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# ANCHORBENCH_WERROR=ON (the test command sets it): every warning is an error. A unity build (each
# target's sources compiled a few to a translation unit, the headers parsed once per unit): from
# scratch on 2 cores 671 -> 445 s with the libraries and tools unity-built, the tests 206 -> 123 s
# more; the same bytes out. A file-local name must be unique in its target (the build says where not).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DANCHORBENCH_PYTHON=ON -DANCHORBENCH_ROS=ON -DCMAKE_UNITY_BUILD=ON \
  -DANCHORBENCH_WERROR="${ANCHORBENCH_WERROR:-OFF}" >/dev/null
if [ $# -gt 0 ]; then
  cmake --build build -j"$(nproc)" --target "$@"
else
  cmake --build build -j"$(nproc)"
fi
