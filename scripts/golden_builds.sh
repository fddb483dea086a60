#!/usr/bin/env bash
# The golden digests (scripts/golden.sh) from several builds of this tree, side by side: the
# results must not depend on how the engine was built (docs/ARCHITECTURE.md "Determinism").
# Builds only the agvbench program of each, in build-golden/NAME, one after another (2 cores:
# about 2 to 4 minutes a build), then checks each against tests/golden/digests.txt and prints a
# table. Exit 1 if any build's digests differ.
#   scripts/golden_builds.sh [NAME...]   default: every build below
# Builds: native-unity, native-files (AGVBENCH_UNITY=OFF), portable-unity (AGVBENCH_NATIVE=OFF:
# x86-64 with SSE2 only), portable-files, avx2-unity (-march=x86-64-v3: AVX2 and FMA without
# AVX-512, as on a CPU that lacks it), clang-unity (clang++, native).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
declare -A flags=(
  [native-unity]="-DAGVBENCH_NATIVE=ON -DAGVBENCH_UNITY=ON"
  [native-files]="-DAGVBENCH_NATIVE=ON -DAGVBENCH_UNITY=OFF"
  [portable-unity]="-DAGVBENCH_NATIVE=OFF -DAGVBENCH_UNITY=ON"
  [portable-files]="-DAGVBENCH_NATIVE=OFF -DAGVBENCH_UNITY=OFF"
  [avx2-unity]="-DAGVBENCH_NATIVE=OFF -DAGVBENCH_UNITY=ON -DCMAKE_CXX_FLAGS=-march=x86-64-v3"
  [clang-unity]="-DAGVBENCH_NATIVE=ON -DAGVBENCH_UNITY=ON -DCMAKE_CXX_COMPILER=clang++"
)
names=("$@")
((${#names[@]})) || names=(native-unity native-files portable-unity portable-files avx2-unity clang-unity)
rc=0
results=()
for name in "${names[@]}"; do
  [ -n "${flags[$name]:-}" ] || { echo "golden_builds: no build named $name" >&2; exit 2; }
  dir=$root/build-golden/$name
  mkdir -p "$dir"
  # shellcheck disable=SC2086  # the flags are words
  if ! cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DAGVBENCH_BUILD_TESTS=OFF \
    -DAGVBENCH_BUILD_PERF=OFF ${flags[$name]} >"$dir.log" 2>&1 ||
    ! cmake --build "$dir" -j "$(nproc)" --target agvbench >>"$dir.log" 2>&1; then
    results+=("$name: build failed ($dir.log)")
    rc=1
    continue
  fi
  if AGVBENCH_GOLDEN_DIR=$dir/golden "$root/scripts/golden.sh" --check "$dir/agvbench" >"$dir/golden.log" 2>&1; then
    results+=("$name: digests equal ($(grep -c ': [0-9a-f]\{64\}$' "$dir/golden.log") configs)")
  else
    results+=("$name: DIGESTS DIFFER ($dir/golden.log)")
    rc=1
  fi
done
printf 'golden_builds: %s\n' "${results[@]}"
exit "$rc"
