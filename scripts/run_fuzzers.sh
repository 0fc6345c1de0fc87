#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan + coverage, into
# build-fuzz/) and runs each one after the other for SECONDS (default 600), with its corpus in
# out/fuzz/<target>/corpus and any finding in out/fuzz/<target>/artifacts. One fuzzer at a time,
# one process each: the machine is shared. A finding is kept by copying the input into
# tests/fuzz/regressions/<target>/, where reliability_fuzz_regression_test replays it.
# Usage: bash scripts/run_fuzzers.sh [SECONDS] [TARGET...]   (targets: camera_yaml recover_depth)
set -euo pipefail
cd "$(dirname "$0")/.."

SECONDS_PER_TARGET=${1:-600}
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -eq 0 ] && TARGETS=(camera_yaml recover_depth)
BUILD_DIR=${FUZZ_BUILD_DIR:-build-fuzz}
CXX_FUZZ=${CXX_FUZZ:-$(command -v clang++-14 || command -v clang++ || true)}
if [ -z "$CXX_FUZZ" ]; then
  echo "run_fuzzers: needs clang++ (apt-get install -y clang-14 libclang-rt-14-dev)" >&2
  exit 2
fi

cmake -S . -B "$BUILD_DIR" -DCMAKE_CXX_COMPILER="$CXX_FUZZ" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" -DCORRIDOR_BUILD_FUZZERS=ON -DCORRIDOR_BUILD_TESTS=OFF \
  -DCORRIDOR_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$BUILD_DIR" -j"${JOBS:-2}" --target fuzz_seeds \
  $(printf 'fuzz_%s ' "${TARGETS[@]}")

mkdir -p out/fuzz
"$BUILD_DIR/tests/fuzz/fuzz_seeds" out/fuzz/recover_depth/seeds out/fuzz/camera_yaml/seeds

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export OPENCV_FOR_THREADS_NUM=1  # One core per fuzzer.
found=0
for target in "${TARGETS[@]}"; do
  dir=out/fuzz/$target
  mkdir -p "$dir/corpus" "$dir/artifacts"
  max_len=4096
  [ "$target" = recover_depth ] && max_len=33000  # Header + 64x64x4 16-bit pixels.
  echo "run_fuzzers: fuzz_$target for ${SECONDS_PER_TARGET} s (log: $dir/log.txt)"
  set +e
  "$BUILD_DIR/tests/fuzz/fuzz_$target" -max_total_time="$SECONDS_PER_TARGET" \
    -max_len="$max_len" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$dir/artifacts/" "$dir/corpus" "$dir/seeds" \
    tests/fuzz/regressions/"$target" >"$dir/log.txt" 2>&1
  code=$?
  set -e
  grep -E "^(stat::number_of_executed_units|stat::new_units_added|Done)" "$dir/log.txt" || true
  if [ $code -ne 0 ]; then
    found=1
    echo "run_fuzzers: fuzz_$target FOUND A PROBLEM (exit $code); inputs in $dir/artifacts:" >&2
    ls "$dir/artifacts" >&2
    grep -m5 -E "ERROR|runtime error|fuzz_$target:" "$dir/log.txt" >&2 || true
  fi
done
exit $found
