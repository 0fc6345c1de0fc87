#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest.
# Usage: bash scripts/run_tests.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
# Benchmarks are built by scripts/run_benchmarks.sh; the test run skips them to stay fast.
bash scripts/build.sh -DCORRIDOR_BUILD_BENCHMARKS=OFF
cd "${BUILD_DIR:-build}"
ctest --output-on-failure -j"$(nproc)" --timeout 600
