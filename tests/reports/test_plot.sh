#!/usr/bin/env bash
# The report scripts (reports/README.md):
#  1. check_claims.py verdicts on synthetic reports (tests/reports/test_claims.py): always runs,
#     it needs no matplotlib;
#  2. plot.py on tests/reports/tiny_report.json and plot_paths.py on tests/reports/tiny_plan.json:
#     every picture and summary.md written and non-empty; bad and old-schema input exits 2 with
#     a message. Skipped (exit 77, ctest SKIP_RETURN_CODE) only when Debian's /usr/bin/python3
#     cannot import matplotlib (CI installs python3-matplotlib, so it never skips there).
# Usage: test_plot.sh REPO_ROOT
set -u
root=${1:?usage: test_plot.sh REPO_ROOT}
py=${AGV_PYTHON:-/usr/bin/python3}  # override only to test the skip path
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0
fail=0
ok() { echo "ok   $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1"; fail=$((fail + 1)); }

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
n=$(ls "$out"/*.png 2>/dev/null | wc -l)
[ "$n" -eq 10 ] && ok "10 pictures for 2 generators x 2 sizes" || bad "expected 10 PNGs, got $n"
if [ -s "$out/summary.md" ] && grep -q '^| density | planner | success' "$out/summary.md" \
   && grep -q 'Paired against `astar`' "$out/summary.md"; then
  ok "summary.md has the per-cell and paired tables"
else
  bad "summary.md missing or without its tables"
fi
if [ -s "$out/summary.md" ] && [ "$(grep -c '^## ' "$out/summary.md")" -eq 4 ]; then
  ok "summary.md has one section per generator and size"
else
  bad "summary.md sections"
fi

if "$py" "$paths" "$root/tests/reports/tiny_plan.json" "$work/plan.png" >/dev/null 2>"$work/paths.err" && is_png "$work/plan.png"; then
  ok "plot_paths.py on tiny_plan.json (paths, failure, trajectory, moving obstacle, unknown cells)"
else
  bad "plot_paths.py on tiny_plan.json: $(cat "$work/paths.err")"
fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
