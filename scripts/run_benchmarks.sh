#!/usr/bin/env bash
# Builds, runs corridor_benchmarks with repetitions and prints the Markdown table of medians.
# Usage: bash scripts/run_benchmarks.sh [repetitions, default 5] [extra benchmark flags]
# Writes out/benchmarks/corridor_benchmarks.json. Benchmarks are noisy on a shared machine:
# compare medians, and instruction counts (see benchmarks/corridor_benchmarks.cc) when in doubt.
set -euo pipefail
cd "$(dirname "$0")/.."
REPETITIONS=${1:-5}
shift || true
bash scripts/build.sh -DCORRIDOR_BUILD_BENCHMARKS=ON
BUILD_DIR=${BUILD_DIR:-build}
mkdir -p out/benchmarks
JSON=out/benchmarks/corridor_benchmarks.json
"$BUILD_DIR/benchmarks/corridor_benchmarks" --benchmark_repetitions="$REPETITIONS" \
  --benchmark_report_aggregates_only=true --benchmark_out="$JSON" \
  --benchmark_out_format=json "$@" >/dev/null
python3 scripts/benchmark_table.py "$JSON"
echo "(raw results: $JSON)"
