#!/usr/bin/env bash
# The test command (README): set up, build from scratch if needed, build and run the out-of-tree
# example against the installed package, then run the whole suite (ctest's summary closes it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh

# The installed package: install, build the out-of-tree example solver against it, run it.
cmake --install build --prefix build/install >/dev/null
cmake -S examples/custom_solver -B build/example -DCMAKE_PREFIX_PATH="$PWD/build/install" >/dev/null
cmake --build build/example -j"$(nproc)"
build/example/custom_solver configs/table1.yaml

ctest --test-dir build --output-on-failure -j"$(nproc)"
