#!/usr/bin/env bash
# The tests that need a plain Release build (build-release-tests/): the Python module (an
# AddressSanitizer build does not import into a plain Python) with its install into a temporary
# prefix, the live ROS node (started with its own rosmaster on a loopback port), and the C++
# install with a consumer program (scripts/check_install.sh). Builds only what they need (no tests
# of their own), at -O1: they check that the module, the node and the install work, not their
# speed, and -O1 compiles in about two thirds of -O3's time. Its own folder, so that build/ keeps
# the optimised build that the tools and benchmarks run from.
# Usage: bash scripts/run_release_tests.sh
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build-release-tests}
start=$(date +%s)
GENERATOR=($(bash scripts/cmake_generator.sh "$BUILD_DIR"))
cmake -S . -B "$BUILD_DIR" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCORRIDOR_WERROR=ON \
  -DCORRIDOR_BUILD_BENCHMARKS=OFF >/dev/null
# Every installed target, for the install check; and the tools the Python tests run.
targets=(corridor_depth corridor_synth corridor_eval corridor_score solver_compare)
labels=()
if grep -q "CORRIDOR_BUILD_PYTHON:BOOL=ON" "$BUILD_DIR/CMakeCache.txt"; then
  targets+=(corridor_depth_python corridor_python_reference)
  labels+=(python)
fi
if grep -q "CORRIDOR_WITH_ROS:BOOL=ON" "$BUILD_DIR/CMakeCache.txt"; then
  # The node and its test binaries: every target of ros/.
  # `help` lists "... NAME" (make) or "NAME: phony" (Ninja).
  targets+=($(cmake --build "$BUILD_DIR" --target help |
    sed -n -E 's/^(\.\.\. )?(ros_[a-z_]*_test|corridor_depth_node|corridor_option_table)(:| |$).*/\2/p' | sort -u))
  labels+=(ros)
fi
if [ ${#labels[@]} -eq 0 ]; then
  echo "run_release_tests: neither the Python module nor the ROS node is configured" >&2
  exit 1
fi
cmake --build "$BUILD_DIR" -j"$(nproc)" --target "${targets[@]}"
built=$(date +%s)
regex=$(IFS='|'; echo "${labels[*]}")
(cd "$BUILD_DIR" && ctest --output-on-failure -j"$(nproc)" --timeout 600 -L "$regex")
bash scripts/check_install.sh "$BUILD_DIR"
echo "run_release_tests: build $((built - start)) s, tests $(($(date +%s) - built)) s"
