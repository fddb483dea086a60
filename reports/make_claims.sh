#!/usr/bin/env bash
# Regenerate reports/CLAIMS.md: run both set-ups of every paper with per-run records into
# reports/out/ (the papers' own set-ups configs/paper-000.json, -002, -003, -004, -004-nodes, and
# our random-map protocol configs/paper-000-random.json, -002-, -003-, -004-random), then grade
# every claim of reports/claims.json on each set-up. Builds nothing: give it the agvbench binary.
#
#   reports/make_claims.sh [AGVBENCH_BINARY]          # default build/agvbench
#   REUSE=1 reports/make_claims.sh                    # reuse reports/out/paper-*.json(l) if present
#   THREADS=2 reports/make_claims.sh                  # passed to agvbench run --threads
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bin=${1:-build/agvbench}
inputs=()
for name in paper-000 paper-002 paper-003 paper-004 paper-004-nodes \
            paper-000-random paper-002-random paper-003-random paper-004-random; do
  cfg=configs/$name.json
  if [ ! -f "$cfg" ]; then
    echo "make_claims.sh: $cfg not found: the claims of that set-up will read 'not comparable'" >&2
    continue
  fi
  rep=reports/out/$name.json
  runs=reports/out/$name.jsonl
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
    "$bin" run "$cfg" --out "$rep" --runs-out "$runs" --quiet ${THREADS:+--threads "$THREADS"}
  fi
  inputs+=("$rep" "$runs")
done
if [ ${#inputs[@]} -eq 0 ]; then
  echo "make_claims.sh: no configs/paper-*.json: nothing to check" >&2
  exit 2
fi
/usr/bin/python3 reports/check_claims.py "${inputs[@]}" --out reports/CLAIMS.md
echo "wrote reports/CLAIMS.md"
