#!/usr/bin/env bash
# Set-up, build, then the default sweep: prints a summary table and writes
# reports/out/default.json. Extra arguments go to `agvbench run` (e.g. configs/quick.json).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh agvbench
exec build/agvbench run "$@"
