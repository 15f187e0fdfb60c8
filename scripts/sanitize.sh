#!/usr/bin/env bash
# The sanitizer job of the test command (README): builds everything but the benchmarks with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer (float-cast-overflow included; not inside Eigen's
# own functions, cmake/ubsan_ignore.txt says why) into build-asan/, runs every unit test and the
# command-line tests there, then runs each libFuzzer harness for FUZZ_SECONDS (default 30) from the
# committed seed corpus. Any sanitizer report, leak, crash or exception other than the project's
# InputError fails it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
fuzz_seconds=${FUZZ_SECONDS:-30}
build_start=$SECONDS  # each phase's wall time on stderr, as scripts/test.sh prints its own
# Line tables, not full debug information: a report's stack still names every file and line, and the
# build is shorter (on a clean clone 670 -> 600 s); unity-built as scripts/build.sh's, and with
# Eigen out of UBSan (cmake/ubsan_ignore.txt), 356 s.
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANCHORBENCH_SANITIZE=ON -DCMAKE_UNITY_BUILD=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DANCHORBENCH_FUZZ=ON -DANCHORBENCH_BUILD_BENCHMARKS=OFF -DANCHORBENCH_MPI=OFF -DANCHORBENCH_PYTHON=ON >/dev/null
cmake --build build-asan -j"$(nproc)"
echo "sanitize.sh: the clang build took $((SECONDS - build_start)) s" >&2
suite_start=$SECONDS

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Every test but those about processes and the file system rather than memory, which run in the
# Release suite: the fault test (kill -9, tmpfs), resume (kill -9), and Slurm (daemons). The pytest
# suite (the Python API, the bag tool and their property tests) runs on the sanitized module with
# clang's ASan runtime preloaded into Debian's python3 (python/CMakeLists.txt). Without
# MPI here (-DANCHORBENCH_MPI=OFF): OpenMPI's own allocations would be reported as leaks; the
# chunks it carries are the work layer's, tested here.
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -E "^(cli\.faults|cli\.resume|scripts\.slurm)$"
echo "sanitize.sh: the suite under ASan took $((SECONDS - suite_start)) s" >&2

for harness in csv config; do
  corpus=$(mktemp -d)  # new inputs go here, not into the committed corpus
  log=$(mktemp)
  if ! "build-asan/fuzz/fuzz_$harness" -max_total_time="$fuzz_seconds" -max_len=4096 -rss_limit_mb=2048 -timeout=10 \
    -artifact_prefix=build-asan/ "$corpus" "fuzz/corpus/$harness" >"$log" 2>&1; then
    tail -40 "$log"
    echo "fuzz_$harness: FAILED (the input that broke it is in build-asan/)" >&2
    exit 1
  fi
  runs=$(grep -oE "Done [0-9]+ runs in [0-9]+ second" "$log" | grep -oE "[0-9]+" | head -1)
  echo "fuzz_$harness: $runs executions in ${fuzz_seconds} s ($((runs / fuzz_seconds)) exec/s), no crash, no leak"
  rm -rf "$corpus" "$log"
done

# Mutated configs, CSV files and command lines against the sanitizer build: exit 0 or one line and
# exit 2, never a crash.
/usr/bin/python3 scripts/mutate_inputs.py build-asan/app/anchorbench "${MUTATION_CASES:-300}" 1

# The same bytes from another compiler: clang (with sanitizers) against the Release build (g++).
if [ -x build/app/anchorbench ]; then
  folder=$(mktemp -d)
  build-asan/app/anchorbench run configs/table1.yaml --realizations 3 --out "$folder/clang" --quiet
  build/app/anchorbench run configs/table1.yaml --realizations 3 --out "$folder/gcc" --quiet
  cmp "$folder/clang/attempts.csv" "$folder/gcc/attempts.csv"
  echo "Table I (3 realizations): clang and g++ builds write the same attempts.csv"
  rm -rf "$folder"
fi
