#!/usr/bin/env bash
# Set-up, build, then the default sweep: prints a summary table and writes
# reports/out/report.json. Extra arguments go to `agvbench run` (e.g. configs/quick.json).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec build/agvbench run "$@"
