#!/usr/bin/env bash
# Prints the CMake generator arguments for the build folder $1: Ninja when it is installed and
# the folder is new or already a Ninja build (it schedules the many small test targets better
# than make and skips make's per-target dependency scans); nothing otherwise, so that a folder
# configured with another generator keeps it.
# Usage: GENERATOR=($(bash scripts/cmake_generator.sh BUILD_DIR))
set -euo pipefail
cache="$1/CMakeCache.txt"
command -v ninja >/dev/null 2>&1 || exit 0
if [ ! -f "$cache" ] || grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$cache"; then
  echo "-G Ninja"
fi
