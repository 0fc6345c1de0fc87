#!/usr/bin/env bash
# Installs a built tree into a temporary prefix and checks it as a user of the library would: the
# installed headers are exactly include/corridor_depth/ and include only each other;
# examples/cpp_consumer configures with find_package(corridor_depth), links corridor_depth::core,
# builds, loads no ROS library, needs no gflags itself, and recovers a real photo's depth; the
# Python module, when built, imports from the prefix and recovers the same photo. A sanitized build
# (run_tests.sh checks build-asan/) links the consumer with the sanitizers and preloads their
# runtime into Python.
# Usage: bash scripts/check_install.sh [BUILD_DIR (default build)]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${1:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$BUILD_DIR" --prefix "$work/prefix" >/dev/null
python3 - "$work/prefix/include" include/corridor_depth <<'PY'
import os, re, sys
root, public = sys.argv[1], sys.argv[2]
problems = []
# The installed headers are exactly the public ones, under <corridor_depth/...>.
installed = sorted(os.path.relpath(os.path.join(f, n), root)
                   for f, _, names in os.walk(root) for n in names)
expected = sorted(os.path.join("corridor_depth", n) for n in os.listdir(public) if n.endswith(".h"))
if installed != expected:
    extra = sorted(set(installed) - set(expected))
    lost = sorted(set(expected) - set(installed))
    problems.append(f"installed headers differ from include/corridor_depth: extra {extra}, missing {lost}")
for name in installed:
    text = open(os.path.join(root, name)).read()
    for include in re.findall(r'#include "([^"]+)"', text):
        if not os.path.exists(os.path.join(root, include)):
            problems.append(f"{name} includes {include}, which is not installed")
if problems:
    sys.exit("check_install:\n  " + "\n  ".join(problems))
print(f"check_install: {len(installed)} public headers, each including only public headers")
PY
consumer_flags=()
python_env=()
if grep -q "^CORRIDOR_SANITIZE:BOOL=ON" "$BUILD_DIR/CMakeCache.txt"; then
  # The build's own sanitizer link flag and Python preload (CMakeLists.txt). The driver links
  # libasan with --no-as-needed left on for the libraries after it: turned back.
  link_flag=$(sed -n 's/^CORRIDOR_SANITIZER_LINK_FLAG:INTERNAL=//p' "$BUILD_DIR/CMakeCache.txt")
  preload=$(sed -n 's/^CORRIDOR_SANITIZER_PRELOAD:INTERNAL=//p' "$BUILD_DIR/CMakeCache.txt")
  consumer_flags=("-DCMAKE_EXE_LINKER_FLAGS=$link_flag -Wl,--as-needed")
  python_env=(LD_PRELOAD="$preload" ASAN_OPTIONS=detect_leaks=0)
fi
cmake -S examples/cpp_consumer -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release "${consumer_flags[@]}" >/dev/null
cmake --build "$work/consumer" -j"$(nproc)" >/dev/null
if ldd "$work/consumer/corridor_consumer" | grep -E "libros|librosbag|libroscpp"; then
  echo "check_install: the consumer loads ROS libraries" >&2
  exit 1
fi
# The consumer needs no gflags itself (Ceres's glog may still load it underneath).
if readelf -d "$work/consumer/corridor_consumer" | grep -E "NEEDED.*libgflags"; then
  echo "check_install: the consumer itself needs gflags" >&2
  exit 1
fi
out=$("$work/consumer/corridor_consumer" tests/data/real-corridors/rtabmap_3.jpg 60 1.0)
echo "$out"
fraction=$(echo "$out" | sed -n 's/.*depth_fraction=\([0-9.]*\).*/\1/p')
python3 -c "import sys; sys.exit(0 if float('$fraction') > 0.5 else 1)" || {
  echo "check_install: the consumer's depth covers only $fraction of the photo" >&2
  exit 1
}
# The Python module, when it was built: imported from the installed prefix.
site=$(find "$work/prefix" -name "corridor_depth*.so" -printf "%h\n" | head -1)
# The Python the module was built for (numpy may be missing from another one on PATH).
python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$BUILD_DIR/CMakeCache.txt")
if [ -n "$site" ]; then
  env "${python_env[@]}" PYTHONPATH="$site" "${python:-python3}" - "$site" tests/data/real-corridors/rtabmap_3.jpg <<'PY'
import sys
import numpy as np
import corridor_depth as cd
assert cd.__file__.startswith(sys.argv[1]), cd.__file__
image = cd.read_image(sys.argv[2])
res = cd.recover_depth(image, cd.Camera.from_hfov(60.0, image.shape[1], image.shape[0]),
                       camera_height=1.0)
assert res.ok, res.status
fraction = float(np.isfinite(res.depth).mean())
assert fraction > 0.5, fraction
print(f"check_install: Python module from {sys.argv[1]}: depth on {fraction:.3f} of the photo")
PY
fi
echo "check_install: installed, consumer built and ran"
