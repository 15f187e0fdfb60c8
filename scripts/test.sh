#!/usr/bin/env bash
# The test command (README): set up, build from scratch if needed (warnings as errors), build and run the two
# out-of-tree examples against the installed package, run the whole suite (Release), then the
# sanitizer job (scripts/sanitize.sh: ASan + UBSan build of every test, libFuzzer runs, mutated
# inputs, the clang build's bytes against g++'s).
set -euo pipefail
cd "$(dirname "$0")/.."
# Each phase's wall time on stderr, where the time of the whole goes (README: ~22 min on 2 cores).
phase_start=$SECONDS
phase_done() {
  echo "test.sh: $1 took $((SECONDS - phase_start)) s" >&2
  phase_start=$SECONDS
}
ANCHORBENCH_WERROR=ON bash scripts/build.sh  # a warning fails the build
phase_done "the build"

# The installed package: install, then build the examples against it and run them.
cmake --install build --prefix build/install >/dev/null
for example in custom_solver online_front_end; do
  cmake -S "examples/$example" -B "build/examples/$example" -DCMAKE_PREFIX_PATH="$PWD/build/install" >/dev/null
  cmake --build "build/examples/$example" -j"$(nproc)"
done
build/examples/custom_solver/custom_solver examples/custom_solver/table1_thirds.yaml
build/app/anchorbench simulate configs/tunnel.yaml --out build/examples/tunnel_log --overwrite >/dev/null
build/examples/online_front_end/online_front_end build/examples/tunnel_log/poses.csv build/examples/tunnel_log/ranges.csv
phase_done "the examples"

ctest --test-dir build --output-on-failure -j"$(nproc)"
phase_done "the suite"
bash scripts/sanitize.sh
phase_done "the sanitizer job"
