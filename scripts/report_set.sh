#!/usr/bin/env bash
# Runs the refactoring check set into OUTDIR: configs/quick.json as it is, configs/default.json at
# 20 maps per cell and each paper config at 50, so that two builds' reports can be compared field
# by field with slurm/same_report.py (scripts/report_set.sh compare A B; where they differ,
# scripts/report_diff.py says where, the config-as-run taken apart).
# Usage: scripts/report_set.sh run BINARY OUTDIR | scripts/report_set.sh compare DIR_A DIR_B
set -euo pipefail
cd "$(dirname "$0")/.."
py=/usr/bin/python3
case ${1:-} in
  run)
    bin=$2 out=$3
    mkdir -p "$out"
    for cfg in configs/quick.json configs/default.json configs/paper-00{0,2,3,4}.json; do
      name=$(basename "$cfg" .json)
      case $name in quick) maps= ;; default) maps=20 ;; *) maps=50 ;; esac
      $py - "$cfg" "$out/$name.config.json" "$maps" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
if sys.argv[3]:
    c["maps_per_cell"] = int(sys.argv[3])
c.pop("report", None)
c.pop("runs", None)
json.dump(c, open(sys.argv[2], "w"), indent=1)
PY
      start=$(date +%s)
      "$bin" run "$out/$name.config.json" --threads "$(nproc)" --quiet --out "$out/$name.json"
      echo "report_set: $name took $(( $(date +%s) - start )) s"
    done
    ;;
  compare)
    rc=0
    for a in "$2"/*.json; do
      case $a in *.config.json) continue ;; esac
      b="$3/$(basename "$a")"
      if $py slurm/same_report.py "$a" "$b" >/dev/null; then
        echo "same: $(basename "$a")"
      else
        # Not equal: say where, with the config-as-run taken apart (renamed parameters).
        $py scripts/report_diff.py "$a" "$b" || true
        rc=1
      fi
    done
    exit $rc
    ;;
  *) echo "usage: $0 run BINARY OUTDIR | compare DIR_A DIR_B" >&2; exit 2 ;;
esac
