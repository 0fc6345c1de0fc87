#!/usr/bin/env bash
# Installs what is missing, checks the formatting, builds the whole test suite with
# AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/, -O1), the Python module and the ROS
# node included, and runs it with ctest: any sanitizer report fails the test that caused it. Then
# installs that build into a temporary prefix and checks it as a user would (check_install.sh).
# This is what CI's .ci/run calls.
# CORRIDOR_SANITIZE=0 runs the whole suite on the plain Release build (build/) instead, in less
# than half the time (docs/results.md, "Test suite").
# Usage: bash scripts/run_tests.sh [extra ctest arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/check_format.sh
if [ "${CORRIDOR_SANITIZE:-1}" != 0 ]; then
  bash scripts/run_sanitized_tests.sh "$@"
  exec bash scripts/check_install.sh "${BUILD_DIR:-build-asan}"
fi
# Benchmarks are built by scripts/run_benchmarks.sh; the test run skips them to stay fast.
bash scripts/build.sh -DCORRIDOR_BUILD_BENCHMARKS=OFF
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure -j"$(nproc)" --timeout 600 "$@")
bash scripts/check_install.sh "${BUILD_DIR:-build}"
