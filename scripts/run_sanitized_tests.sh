#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer + UndefinedBehaviorSanitizer
# (CORRIDOR_SANITIZE, into build-asan/) and runs it with ctest, the Python module's and the ROS
# node's tests among them (the Python tests preload the sanitizer runtime; these two run without
# LeakSanitizer, as ROS 1's own libraries keep memory to the end). Any sanitizer report aborts the
# process, so it fails the test that caused it; the tools the tests start as child processes are
# sanitized too, and an abort there is a signal the reliability tests reject.
# Each test binary is one ctest test here (CORRIDOR_TEST_PER_BINARY): a sanitized binary takes a
# third of a second to start, which once per GoogleTest test was a third of the run. A failure
# prints the binary's whole output, with the failing test's name in it.
# Usage: bash scripts/run_sanitized_tests.sh [extra ctest arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build-asan}
JOBS=${JOBS:-$(nproc)}

export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:abort_on_error=1:print_stacktrace=1}
start=$(date +%s)
# -O1 keeps the build and the run quick; asserts (Eigen's bounds checks) stay on. The gold linker
# (binutils) links the 80-odd sanitized binaries in about half the time of the default one.
LINKER=()
if ld.gold --version >/dev/null 2>&1; then
  LINKER=(-DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=gold -DCMAKE_SHARED_LINKER_FLAGS=-fuse-ld=gold)
fi
GENERATOR=($(bash scripts/cmake_generator.sh "$BUILD_DIR"))
cmake -S . -B "$BUILD_DIR" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" \
  -DCORRIDOR_SANITIZE=ON -DCORRIDOR_WERROR=ON -DCORRIDOR_BUILD_BENCHMARKS=OFF \
  -DCORRIDOR_TEST_PER_BINARY=ON "${LINKER[@]}" \
  >/dev/null
cmake --build "$BUILD_DIR" -j"$JOBS"
built=$(date +%s)
(cd "$BUILD_DIR" && ctest --output-on-failure -j"$JOBS" --timeout 1200 "$@")
echo "run_sanitized_tests: build $((built - start)) s, tests $(($(date +%s) - built)) s"
