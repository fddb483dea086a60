#!/usr/bin/env bash
# Regenerate reports/CLAIMS.md: run the paper sweeps (configs/paper-000.json, -002, -003, -004,
# each that exists) with per-run records into reports/out/, then check every claim of
# reports/claims.json against all of them. Builds nothing: give it the agvbench binary.
#
#   reports/make_claims.sh [AGVBENCH_BINARY]          # default build/agvbench
#   REUSE=1 reports/make_claims.sh                    # reuse reports/out/paper-*.json(l) if present
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bin=${1:-build/agvbench}
inputs=()
for p in 000 002 003 004; do
  cfg=configs/paper-$p.json
  if [ ! -f "$cfg" ]; then
    echo "make_claims.sh: $cfg not found: paper $p's claims will read 'not comparable'" >&2
    continue
  fi
  rep=reports/out/paper-$p.json
  runs=reports/out/paper-$p.jsonl
  if [ "${REUSE:-0}" = 1 ] && [ -f "$rep" ] && [ -f "$runs" ]; then
    echo "make_claims.sh: reusing $rep" >&2
  else
    if [ ! -x "$bin" ]; then
      echo "make_claims.sh: no agvbench binary at $bin (build it first)" >&2
      exit 2
    fi
    # A fresh sweep: agvbench refuses to truncate a journal holding records, so the previous
    # one (this script's own output) is removed first.
    rm -f "$runs"
    "$bin" run "$cfg" --out "$rep" --runs-out "$runs"
  fi
  inputs+=("$rep" "$runs")
done
if [ ${#inputs[@]} -eq 0 ]; then
  echo "make_claims.sh: no configs/paper-*.json: nothing to check" >&2
  exit 2
fi
/usr/bin/python3 reports/check_claims.py "${inputs[@]}" --out reports/CLAIMS.md
echo "wrote reports/CLAIMS.md"
