#!/usr/bin/env bash
# Installs the Debian packages agvbench needs (only the missing ones), then configures and builds
# it in ./build. Works on a bare Debian 12 as root (or with sudo).
# Usage: scripts/setup.sh [TARGET...]   (default: everything; scripts/sweep.sh builds agvbench only)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake ninja-build pkg-config git
  libeigen3-dev libtbb-dev nlohmann-json3-dev libbenchmark-dev libgtest-dev
  libcli11-dev libpcg-cpp-dev libboost-dev libnanoflann-dev python3 python3-matplotlib
  python3-plotly chromium
  libsqlite3-dev sqlite3 libssl-dev
  libompl-dev
  libyaml-cpp-dev libpng-dev)
scripts/apt_need.sh "${packages[@]}"

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
if (($#)); then
  cmake --build build -j "$jobs" --target "$@"
else
  cmake --build build -j "$jobs"
fi
