#!/usr/bin/env bash
# Installs the Debian packages agvbench needs (only the missing ones), then configures and builds
# it in ./build. Works on a bare Debian 12 as root (or with sudo).
# Usage: scripts/setup.sh [TARGET...]   (default: everything; scripts/sweep.sh builds agvbench only)
# Env:   AGVBENCH_APT_ALSO="PACKAGE..." more packages to install while the build runs (.ci/run
#        names its later stages' packages there, so that their download overlaps the compile).
set -euo pipefail
cd "$(dirname "$0")/.."

# What the build needs, installed first.
build_packages=(g++ cmake ninja-build pkg-config git python3
  libeigen3-dev libtbb-dev nlohmann-json3-dev libbenchmark-dev libgtest-dev
  libcli11-dev libpcg-cpp-dev libboost-dev libnanoflann-dev
  libsqlite3-dev libssl-dev libompl-dev libyaml-cpp-dev libpng-dev zlib1g-dev
  pybind11-dev pybind11-json-dev python3-dev python3-numpy)
# What only the tests and report scripts run (plots, the HTML report in Chromium, sqlite3, the
# Python module's pytest suite and its DataFrames):
# installed while the build compiles, which has no use for them.
run_packages=(python3-matplotlib python3-plotly chromium sqlite3 python3-pandas python3-pytest)
scripts/apt_need.sh "${build_packages[@]}"

apt_log=$(mktemp)
trap 'rm -f "$apt_log"' EXIT
# shellcheck disable=SC2086  # AGVBENCH_APT_ALSO is a list of package names
scripts/apt_need.sh "${run_packages[@]}" ${AGVBENCH_APT_ALSO:-} >"$apt_log" 2>&1 &
apt_pid=$!

jobs=$(nproc 2>/dev/null || echo 2)
build_rc=0
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null || build_rc=$?
if ((build_rc == 0)); then
  if (($#)); then
    cmake --build build -j "$jobs" --target "$@" || build_rc=$?
  else
    cmake --build build -j "$jobs" || build_rc=$?
  fi
fi
apt_rc=0
wait "$apt_pid" || apt_rc=$?
cat "$apt_log" >&2
((apt_rc == 0)) || { echo "setup: installing ${run_packages[*]} ${AGVBENCH_APT_ALSO:-} failed" >&2; exit "$apt_rc"; }
exit "$build_rc"
