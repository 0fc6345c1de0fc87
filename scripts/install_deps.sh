#!/usr/bin/env bash
# Installs the Debian packages corridor-depth needs; does nothing when all are present.
# Run as root (apt-get). Usage: bash scripts/install_deps.sh
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libceres-dev libopencv-dev libgoogle-glog-dev libgflags-dev libyaml-cpp-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  librosbag-storage-dev libsensor-msgs-dev python3-rosbag python3-sensor-msgs
  libroscpp-dev libimage-transport-dev libvisualization-msgs-dev libdiagnostic-msgs-dev
  libtf2-ros-dev libtf2-msgs-dev libstd-msgs-dev libgeometry-msgs-dev python3-rosmaster
  python3 python3-pil python3-dev python3-numpy python3-pytest python3-matplotlib pybind11-dev
  clang-format
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "install_deps: these packages are missing and installing them needs root: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
