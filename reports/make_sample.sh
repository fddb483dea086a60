#!/usr/bin/env bash
# Regenerate reports/sample/: the sample sweep (reports/sample/config.json) and its journal (kept
# in a temporary folder, not committed), its pictures drawn from every run, its Markdown summary,
# an SVG and a PDF example, the interactive HTML report, one map's path picture and the claims
# table at sample scale.
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

"$bin" run "$out/config.json" --out "$out/report.json" --runs-out "$tmp/runs.jsonl" --quiet
rm -f "$out"/*.png "$out"/*.svg "$out"/*.pdf "$out/summary.md"
"$py" reports/plot.py "$out/report.json" "$out" --runs "$tmp/runs.jsonl" --small --dpi 72
# Vector examples: the ECDF as SVG, the 40x40 violins as PDF.
"$py" reports/plot.py "$out/report.json" "$tmp/svg" --runs "$tmp/runs.jsonl" --format svg >/dev/null
cp "$tmp/svg/ecdf_plan_time.svg" "$out/"
"$py" reports/plot.py "$out/report.json" "$tmp/pdf" --runs "$tmp/runs.jsonl" --format pdf --dist violin \
  --metrics path_length,turns,plan_time_ns >/dev/null
cp "$tmp/pdf/dist_uniform_40x40.pdf" "$out/violin_uniform_40x40.pdf"
"$py" reports/html_report.py "$out/report.json" "$out/report.html" --runs "$tmp/runs.jsonl"
"$bin" plan --planner astar --planner dijkstra --planner prm --planner rrt --planner birrt \
  --generator uniform --size 20 --density 0.3 --seed 2024 --map-index 0 \
  --json-out "$out/plan.json" --no-ascii >/dev/null
"$py" reports/plot_paths.py "$out/plan.json" "$out/plan.png" --small --dpi 72
"$py" reports/check_claims.py "$out/report.json" --all-as random --out "$out/CLAIMS.md" >/dev/null
du -ch "$out"/*.png | tail -1 | sed 's/total/PNG total/'
du -h "$out/report.html" "$out"/*.svg "$out"/*.pdf
ls "$out"
