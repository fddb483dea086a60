#!/usr/bin/env bash
# The report scripts (reports/README.md):
#  1. check_claims.py verdicts on synthetic reports (tests/reports/test_claims.py): always runs,
#     it needs no matplotlib;
#  2. plot.py on tests/reports/tiny_report.json and plot_paths.py on tests/reports/tiny_plan.json:
#     every picture and summary.md written and non-empty; bad and old-schema input exits 2 with
#     a message; --planners / --metrics filters (an unknown name exits 2 naming it), --format
#     pdf and svg, --runs (ECDF, box and violin plots from every run) on a synthetic 24-planner
#     sweep (tests/reports/synth_many.py): every planner in every legend, no legend or note over
#     a panel or another note (agvreports/layout.py layout_problems, itself checked on a figure made to
#     overlap), distinct colour and marker per planner, log axes labelled at both ends. Skipped (exit 77, ctest SKIP_RETURN_CODE) only when Debian's /usr/bin/python3
#     cannot import matplotlib (CI installs python3-matplotlib, so it never skips there).
# Usage: test_plot.sh REPO_ROOT
set -u
root=${1:?usage: test_plot.sh REPO_ROOT}
py=${AGV_PYTHON:-/usr/bin/python3}  # override only to test the skip path
source "$(dirname "$0")/lib.sh"

if [ ! -x "$py" ]; then
  echo "SKIP: $py not found (the report scripts run with Debian's python3)"
  exit 77
fi

# 1. Claims checker (standard library only).
if "$py" "$root/tests/reports/test_claims.py" "$root"; then
  ok "check_claims verdicts (test_claims.py)"
else
  bad "check_claims verdicts (test_claims.py)"
fi

# Bad input for a script: exit 2 and a message on stderr matching a pattern.
expect2() {  # NAME PATTERN COMMAND...
  local name=$1 pattern=$2
  shift 2
  "$@" >"$work/out.txt" 2>"$work/err.txt"
  local code=$?
  if [ $code -ne 2 ]; then
    bad "$name: exit $code, expected 2 ($(head -c 300 "$work/err.txt"))"
  elif ! grep -qE -- "$pattern" "$work/err.txt"; then
    bad "$name: message does not match /$pattern/: $(head -c 300 "$work/err.txt")"
  else
    ok "$name: $(head -c 160 "$work/err.txt")"
  fi
}

# Bad reports are rejected before matplotlib is imported: these run everywhere.
printf '{ not json' >"$work/notjson.json"
printf '[1, 2, 3]' >"$work/array.json"
printf '{"config": {}, "cells": []}' >"$work/noversion.json"
printf '{"schema_version": 1, "config": {}, "cells": []}' >"$work/old.json"
printf '{"schema_version": 3, "config": {}, "cells": []}' >"$work/new.json"
printf '{"schema_version": 2, "config": {}}' >"$work/nocells.json"
printf '{"schema_version": 2, "config": {}, "cells": [{"generator": "uniform", "width": 8, "height": 8, "density": 0.1, "paired": []}]}' >"$work/noplanners.json"
printf '{"schema_version": 2, "config": {}, "cells": []}' >"$work/empty.json"
plot="$root/reports/plot.py"
expect2 "plot.py not JSON" "not valid JSON" "$py" "$plot" "$work/notjson.json" "$work/o1"
expect2 "plot.py JSON array" "expected a JSON object" "$py" "$plot" "$work/array.json" "$work/o1"
expect2 "plot.py no schema_version" "schema_version" "$py" "$plot" "$work/noversion.json" "$work/o1"
expect2 "plot.py schema-1 report" "schema_version is 1" "$py" "$plot" "$work/old.json" "$work/o1"
expect2 "plot.py newer schema" "schema_version is 3" "$py" "$plot" "$work/new.json" "$work/o1"
expect2 "plot.py missing cells" "missing key 'cells'" "$py" "$plot" "$work/nocells.json" "$work/o1"
expect2 "plot.py cell without planners" "cells\[0\]: missing key 'planners'" "$py" "$plot" "$work/noplanners.json" "$work/o1"
expect2 "plot.py no cells" "no cells" "$py" "$plot" "$work/empty.json" "$work/o1"
expect2 "plot.py missing file" "no such file" "$py" "$plot" "$work/nothere.json" "$work/o1"
expect2 "plot.py plan document" "plot_paths.py" "$py" "$plot" "$root/tests/reports/tiny_plan.json" "$work/o1"
tiny="$root/tests/reports/tiny_report.json"
expect2 "plot.py unknown planner" "--planners: no planner 'nope'" "$py" "$plot" "$tiny" "$work/o1" --planners astar,nope
expect2 "plot.py unknown metric" "--metrics: no metric 'path_lenght'" "$py" "$plot" "$tiny" "$work/o1" --metrics path_lenght
expect2 "plot.py unknown format" "invalid choice: 'gif'" "$py" "$plot" "$tiny" "$work/o1" --format gif
expect2 "plot.py violin without runs" "--dist violin needs --runs" "$py" "$plot" "$tiny" "$work/o1" --dist violin
expect2 "plot.py missing journal" "nothere.jsonl: no such file" "$py" "$plot" "$tiny" "$work/o1" --runs "$work/nothere.jsonl"
printf '{"tool": "agvbench", "journal_version": 1, "planner": "astar", "cell": "uniform/99x99/0.5", "map_index": 0, "outcome": "success", "metrics": {}}\n' >"$work/other.jsonl"
expect2 "plot.py journal of another sweep" "line 1: a record of config None, not of the report's" "$py" "$plot" "$tiny" "$work/o1" --runs "$work/other.jsonl"
printf '{"tool": "agvbench", "journal_version": 9}\n' >"$work/v9.jsonl"
expect2 "plot.py journal of another version" "journal_version 9" "$py" "$plot" "$tiny" "$work/o1" --runs "$work/v9.jsonl"
[ -e "$work/o1" ] && bad "plot.py created OUTDIR for a bad report" || ok "no OUTDIR for bad reports"

paths="$root/reports/plot_paths.py"
"$py" - "$root/tests/reports/tiny_plan.json" "$work" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
d = json.loads(json.dumps(doc)); d["map"]["rows"][2] = "..."
json.dump(d, open(sys.argv[2] + "/shortrow.json", "w"))
d = json.loads(json.dumps(doc)); d["runs"][0]["path"][1] = [1.0]
json.dump(d, open(sys.argv[2] + "/badpoint.json", "w"))
d = json.loads(json.dumps(doc)); d["map"]["goal"] = [99, 0]
json.dump(d, open(sys.argv[2] + "/badgoal.json", "w"))
d = json.loads(json.dumps(doc)); d["runs"][3]["obstacles"][0]["radius"] = "big"
json.dump(d, open(sys.argv[2] + "/badradius.json", "w"))
d = json.loads(json.dumps(doc)); del d["map"]["rows"]
json.dump(d, open(sys.argv[2] + "/norows.json", "w"))
PY
expect2 "plot_paths.py not JSON" "not valid JSON" "$py" "$paths" "$work/notjson.json" "$work/p.png"
expect2 "plot_paths.py sweep report" "sweep report" "$py" "$paths" "$root/tests/reports/tiny_report.json" "$work/p.png"
expect2 "plot_paths.py short row" "map.rows\[2\]" "$py" "$paths" "$work/shortrow.json" "$work/p.png"
expect2 "plot_paths.py bad point" "runs\[0\].path\[1\]" "$py" "$paths" "$work/badpoint.json" "$work/p.png"
expect2 "plot_paths.py goal outside" "map.goal" "$py" "$paths" "$work/badgoal.json" "$work/p.png"
expect2 "plot_paths.py bad radius" "obstacles\[0\].radius" "$py" "$paths" "$work/badradius.json" "$work/p.png"
expect2 "plot_paths.py no rows" "missing key 'rows'" "$py" "$paths" "$work/norows.json" "$work/p.png"

# 2. Pictures: need matplotlib.
if ! "$py" -c 'import matplotlib' 2>/dev/null; then
  echo "$pass passed, $fail failed"
  [ $fail -ne 0 ] && exit 1
  echo "SKIP: $py cannot import matplotlib (apt-get install python3-matplotlib); the plotting checks did not run"
  exit 77
fi

is_png() { [ -s "$1" ] && [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; }

out="$work/plots"
if "$py" "$plot" "$root/tests/reports/tiny_report.json" "$out" >"$work/plot.out" 2>"$work/plot.err"; then
  ok "plot.py on tiny_report.json"
else
  bad "plot.py on tiny_report.json: $(cat "$work/plot.err")"
fi
for f in success.png plan_time.png metrics_uniform_16x16.png metrics_blocks_32x32.png \
         paired_uniform_16x16.png paired_blocks_32x32.png; do
  if is_png "$out/$f"; then ok "$f written"; else bad "$f missing, empty or not a PNG"; fi
done
for f in dist_uniform_16x16.png dist_blocks_32x32.png; do
  if is_png "$out/$f"; then ok "$f written"; else bad "$f missing, empty or not a PNG"; fi
done
n=$(ls "$out"/*.png 2>/dev/null | wc -l)
[ "$n" -eq 14 ] && ok "14 pictures for 2 generators x 2 sizes" || bad "expected 14 PNGs, got $n"
[ -e "$out/ecdf_plan_time.png" ] && bad "an ECDF without --runs" || ok "no ECDF without --runs"
grep -q "layout:" "$work/plot.err" && bad "layout problems: $(grep layout: "$work/plot.err")" || ok "no layout problem reported"
sum="$out/summary.md"
if [ -s "$sum" ] && grep -q '^| density | planner | success' "$sum" \
   && grep -q 'Paired against `astar`' "$sum"; then
  ok "summary.md has the per-cell and paired tables"
else
  bad "summary.md missing or without its tables"
fi
# Overview first: the first section, planners x success, length and time, then one section per world.
if [ "$(grep '^## ' "$sum" | head -1)" = "## Overview" ] \
   && grep -q '^| planner | runs | success % \[95%\] | path length / astar \[95%\] | p<0.05 | plan time median µs' "$sum" \
   && [ "$(grep -c '^| `\(astar\|dijkstra\|rrt\)`' "$sum")" -ge 3 ]; then
  ok "summary.md opens with the overview table"
else
  bad "summary.md overview: $(grep -A3 '^## Overview' "$sum" | head -5)"
fi
[ "$(grep -c '^## ' "$sum")" -eq 6 ] && ok "summary.md: overview, the sweep, one section per generator and size" \
  || bad "summary.md sections: $(grep '^## ' "$sum" | tr '\n' ';')"
# p-values of the paired tables, and every time header in µs (none in ns).
grep -qE '\((p=|p<)[0-9.]+\)' "$sum" && ok "summary.md gives Wilcoxon p-values" || bad "summary.md has no p-value"
if grep -E '^\| (density|planner) ' "$sum" | grep -E 'plan time' | grep -vq 'µs'; then
  bad "a plan time header without µs"
else
  ok "every plan time header names µs"
fi
# The widest table row stays readable (the old summary's rows ran past 400 characters).
wide=$(awk '/^\|/ { if (length($0) > m) m = length($0) } END { print m + 0 }' "$sum")
[ "$wide" -le 260 ] && ok "summary.md rows at most 260 characters (widest $wide)" || bad "summary.md row of $wide characters"

# A sweep of map files (a map source's cells, named by the file): each file a world of its own
# (its pictures named by it), never points of one curve over the files' obstacle shares; the
# grid pictures hold one panel per file, wrapped, with no empty panel.
"$py" - "$tiny" "$work/files.json" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
doc["config"]["generators"] = [{"name": "movingai", "params": {"files": ["maps/*.map"]},
                                "map_files": []}]
cells = doc["cells"][:5]
for k, cell in enumerate(cells):
    name = f"room{k}.map"
    cell["cell"] = f"movingai/{name}"
    cell["generator"] = "movingai"
    cell["density"] = 0.1 + 0.037 * k  # measured shares: no two alike
    doc["config"]["generators"][0]["map_files"].append({"name": name, "content_hash": "0"})
doc["cells"] = cells
json.dump(doc, open(sys.argv[2], "w"))
PY
fo="$work/files"
# Two metrics: the pictures' naming and panels are what is checked here (every metric's panels
# are drawn for the tiny report above).
if "$py" "$plot" "$work/files.json" "$fo" --metrics path_length,plan_time_ns >/dev/null 2>"$work/files.err"; then
  ok "plot.py on a sweep of five map files"
else
  bad "plot.py on map files: $(cat "$work/files.err")"
fi
nm=$(ls "$fo"/metrics_movingai_room*.map_*.png 2>/dev/null | wc -l)
[ "$nm" -eq 5 ] && ok "one metrics picture per map file" || bad "metrics pictures per file: $nm"
grep -q "layout:" "$work/files.err" && bad "map files: $(grep layout: "$work/files.err")" || ok "map files: no layout problem reported"
"$py" - "$root" "$work/files.json" <<'PY' && ok "map files: five panels in the grid pictures, none empty" || bad "map files: panel layout"
import json, sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.append(sys.argv[1] + "/reports")
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from agvreports import plots
from agvreports.grouping import Report
rep = Report(json.load(open(sys.argv[2])))
assert len(rep.worlds) == 5, rep.worlds.keys()
assert all(len(cells) == 1 for cells in rep.worlds.values())
captured = []
class Saver:
    def save(self, fig, stem):
        captured.append((stem, [ax for ax in fig.axes if ax.get_visible() and ax.get_title()]))
for draw in (plots.plot_success, plots.plot_time):
    draw(plt, Saver(), rep)
for stem, axes in captured:
    assert len(axes) == 5, (stem, len(axes))
    assert all(ax.has_data() for ax in axes), stem
PY

# Filters and formats: PDF of two planners and two metrics.
fo="$work/filtered"
if "$py" "$plot" "$tiny" "$fo" --format pdf --planners astar,rrt --metrics path_length,plan_time_ns >/dev/null 2>"$work/f.err"; then
  ok "plot.py --format pdf --planners --metrics"
else
  bad "plot.py filtered: $(cat "$work/f.err")"
fi
npdf=$(ls "$fo"/*.pdf 2>/dev/null | wc -l)
nother=$(ls "$fo" | grep -vc '\.pdf$\|^summary.md$')
[ "$npdf" -eq 14 ] && [ "$nother" -eq 0 ] && ok "14 PDFs, nothing else" || bad "filtered: $npdf PDFs, $nother other files"
[ "$(head -c 5 "$fo/success.pdf")" = "%PDF-" ] && ok "success.pdf is a PDF" || bad "success.pdf is not a PDF"
# Reproducible files: the same command writes the same bytes (no date in the PDF).
"$py" "$plot" "$tiny" "$work/filtered2" --format pdf --planners astar,rrt --metrics path_length,plan_time_ns >/dev/null 2>&1
same=1
for f in "$fo"/*.pdf; do cmp -s "$f" "$work/filtered2/$(basename "$f")" || same=0; done
[ $same -eq 1 ] && ok "PDFs byte-identical when drawn again" || bad "PDFs differ when drawn again"
if grep -q 'dijkstra' "$fo/summary.md" || ! grep -q 'path length' "$fo/summary.md" || grep -q 'turns' "$fo/summary.md"; then
  bad "--planners/--metrics not applied to summary.md"
else
  ok "summary.md holds only the chosen planners and metrics"
fi

# 24 planners with their journal: SVG, violins, the ECDF; the layout, legends and palette.
"$py" "$root/tests/reports/synth_many.py" "$work/many.json" "$work/many.jsonl" 24
mo="$work/many"
if "$py" "$plot" "$work/many.json" "$mo" --runs "$work/many.jsonl" --format svg --dist violin \
     --metrics path_length,turns,plan_time_ns >"$work/m.out" 2>"$work/m.err"; then
  ok "plot.py --runs --format svg --dist violin on 24 planners"
else
  bad "plot.py on 24 planners: $(cat "$work/m.err")"
fi
grep -q "layout:" "$work/m.err" && bad "24 planners: $(grep layout: "$work/m.err")" || ok "24 planners: no legend or note over a panel or a note"
for f in ecdf_plan_time.svg dist_uniform_24x24.svg plan_time.svg success.svg paired_uniform_32x32.svg metrics_uniform_16x16.svg; do
  if [ -s "$mo/$f" ] && head -c 300 "$mo/$f" | grep -q '<svg\|<?xml'; then ok "$f written (SVG)"; else bad "$f missing or not SVG"; fi
done
# Every planner named in each legend (the SVG keeps text as text).
for f in ecdf_plan_time.svg dist_uniform_24x24.svg plan_time.svg success.svg metrics_uniform_16x16.svg; do
  miss=$("$py" - "$work/many.json" "$mo/$f" <<'PY'
import json, sys
labels = [p["label"] for p in json.load(open(sys.argv[1]))["config"]["planners"]]
svg = open(sys.argv[2], encoding="utf-8").read()
print(" ".join(l for l in labels if l not in svg))
PY
)
  [ -z "$miss" ] && ok "$f names all 24 planners" || bad "$f misses planners: $miss"
done
# Every size of the sweep on the time axis.
grep -q '16²' "$mo/plan_time.svg" && grep -q '24²' "$mo/plan_time.svg" && grep -q '32²' "$mo/plan_time.svg" \
  && ok "plan_time.svg: every size (16², 24², 32²)" || bad "plan_time.svg lacks a size"
if "$py" "$root/tests/reports/test_plot_style.py" "$root" "$work/many.json"; then
  ok "palette, log ticks and the layout check (test_plot_style.py)"
else
  bad "test_plot_style.py"
fi

if "$py" "$paths" "$root/tests/reports/tiny_plan.json" "$work/plan.png" >/dev/null 2>"$work/paths.err" && is_png "$work/plan.png"; then
  ok "plot_paths.py on tiny_plan.json (paths, failure, trajectory, moving obstacle, unknown cells)"
else
  bad "plot_paths.py on tiny_plan.json: $(cat "$work/paths.err")"
fi

finish
