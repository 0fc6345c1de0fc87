#!/usr/bin/env bash
# Configures and builds corridor-depth (Release, warnings as errors) into build/.
# Usage: bash scripts/build.sh [extra cmake arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
GENERATOR=($(bash scripts/cmake_generator.sh "$BUILD_DIR"))
cmake -S . -B "$BUILD_DIR" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=Release -DCORRIDOR_WERROR=ON "$@" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
