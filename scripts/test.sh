#!/usr/bin/env bash
# Set-up, build, then the whole test suite (unit tests, property tests on random maps, MovingAI
# scenarios, CLI bad-input cases, perf smoke runs).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"
