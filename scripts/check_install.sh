#!/usr/bin/env bash
# Installs a built tree into a temporary prefix and checks it as a user of the library would: every
# installed header's includes are installed too, examples/cpp_consumer configures with
# find_package(corridor_depth), builds, loads no ROS library, and recovers a real photo's depth.
# Usage: bash scripts/check_install.sh [BUILD_DIR (default build)]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${1:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$BUILD_DIR" --prefix "$work/prefix" >/dev/null
python3 - "$work/prefix/include/corridor_depth" <<'PY'
import os, re, sys
root = sys.argv[1]
missing = []
for folder, _, files in os.walk(root):
    for name in files:
        path = os.path.join(folder, name)
        for include in re.findall(r'#include "([^"]+)"', open(path).read()):
            if not os.path.exists(os.path.join(root, include)):
                missing.append(f"{os.path.relpath(path, root)} includes {include}")
if missing:
    sys.exit("check_install: installed headers include headers that are not installed:\n  " +
             "\n  ".join(missing))
PY
cmake -S examples/cpp_consumer -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" -j"$(nproc)" >/dev/null
if ldd "$work/consumer/corridor_consumer" | grep -E "libros|librosbag|libroscpp"; then
  echo "check_install: the consumer loads ROS libraries" >&2
  exit 1
fi
out=$("$work/consumer/corridor_consumer" tests/data/real-corridors/rtabmap_3.jpg 60 1.0)
echo "$out"
fraction=$(echo "$out" | sed -n 's/.*depth_fraction=\([0-9.]*\).*/\1/p')
python3 -c "import sys; sys.exit(0 if float('$fraction') > 0.5 else 1)" || {
  echo "check_install: the consumer's depth covers only $fraction of the photo" >&2
  exit 1
}
echo "check_install: installed, consumer built and ran"
