#!/usr/bin/env bash
# Regenerate reports/sample/: the sample sweep (reports/sample/config.json), its pictures, its
# Markdown summary, one map's path picture and the claims table at sample scale.
# Builds nothing: give it the agvbench binary (default build/agvbench).
#
#   reports/make_sample.sh [AGVBENCH_BINARY]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bin=${1:-build/agvbench}
py=/usr/bin/python3
out=reports/sample
if [ ! -x "$bin" ]; then
  echo "make_sample.sh: no agvbench binary at $bin (build it first: scripts/sweep.sh or ninja -C build agvbench)" >&2
  exit 2
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" run "$out/config.json" --out "$out/report.json" --quiet
rm -f "$out"/*.png "$out/summary.md"
"$py" reports/plot.py "$out/report.json" "$out" --small --dpi 72
"$bin" plan --planner astar --planner dijkstra --planner prm --planner rrt --planner birrt \
  --generator uniform --size 20 --density 0.3 --seed 2024 --map-index 0 \
  --json-out "$out/plan.json" --no-ascii >/dev/null
"$py" reports/plot_paths.py "$out/plan.json" "$out/plan.png" --small --dpi 72
"$py" reports/check_claims.py "$out/report.json" --all-as random --out "$out/CLAIMS.md" >/dev/null
du -ch "$out"/*.png | tail -1 | sed 's/total/PNG total/'
ls "$out"
