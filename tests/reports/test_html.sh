#!/usr/bin/env bash
# reports/html_report.py (reports/README.md "Interactive HTML report"):
#  1. bad input exits 2 with a message and writes nothing (an existing file that html_report.py
#     did not write is never overwritten);
#  2. the page of a 24-planner synthetic sweep with its journal, and of tests/reports/tiny_report.json
#     without one, is drawn by headless Chromium with the network cut off: every chart drawn
#     (plotly's SVG in the DOM after the script ran, one trace per chosen planner), no error and
#     no console message, no http(s) resource in the file.
# Needs Debian's chromium and python3-plotly: installed here when missing (scripts/apt_need.sh);
# skipped (exit 77) only when they cannot be installed.
# Usage: test_html.sh REPO_ROOT
set -u
root=${1:?usage: test_html.sh REPO_ROOT}
py=/usr/bin/python3
source "$(dirname "$0")/lib.sh"

if ! command -v chromium >/dev/null || ! "$py" -c 'import plotly' 2>/dev/null; then
  "$root/scripts/apt_need.sh" chromium python3-plotly >/dev/null 2>&1 || true
fi
if ! command -v chromium >/dev/null || ! "$py" -c 'import plotly' 2>/dev/null; then
  echo "SKIP: chromium or python3-plotly missing and not installable (apt-get install chromium python3-plotly)"
  exit 77
fi
html="$root/reports/html_report.py"

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

tiny="$root/tests/reports/tiny_report.json"
printf '{ not json' >"$work/notjson.json"
echo "my notes" >"$work/notes.html"
expect2 "html_report.py not JSON" "not valid JSON" "$py" "$html" "$work/notjson.json" "$work/a.html"
expect2 "html_report.py unknown planner" "no planner 'nope'" "$py" "$html" "$tiny" "$work/a.html" --planners astar,nope
"$py" -c 'import json, sys; d = json.load(open(sys.argv[1])); d["cells"][0]["planners"][0]["timing"] = 5; json.dump(d, open(sys.argv[2], "w"))' "$tiny" "$work/badtiming.json"
expect2 "html_report.py damaged timing" "cells\[0\].planners\[0\].timing: expected an object, got 5" "$py" "$html" "$work/badtiming.json" "$work/a.html"
expect2 "html_report.py missing journal" "no such file" "$py" "$html" "$tiny" "$work/a.html" --runs "$work/missing.jsonl"
[ -e "$work/a.html" ] && bad "html_report.py wrote a page for bad input" || ok "no page for bad input"
expect2 "html_report.py will not overwrite a user's file" "refusing to overwrite" "$py" "$html" "$tiny" "$work/notes.html"
[ "$(cat "$work/notes.html")" = "my notes" ] && ok "the user's file is untouched" || bad "notes.html changed"

# Pages.
"$py" "$root/tests/reports/synth_many.py" "$work/many.json" "$work/many.jsonl" 24 || bad "synth_many.py"
"$py" "$root/tests/reports/synth_many.py" "$work/other.json" "$work/other.jsonl" 3 || bad "synth_many.py 3"
expect2 "html_report.py journal of another sweep" "a record of config '[0-9a-f]{16}', not of the report's" \
  "$py" "$html" "$tiny" "$work/a.html" --runs "$work/other.jsonl"
# The same config name, cells and planners, another seed: still another sweep (issue 28, class 9).
"$py" -c 'import json, sys; d = json.load(open(sys.argv[1])); d["config"]["seed"] += 1; json.dump(d, open(sys.argv[2], "w"))' \
  "$work/many.json" "$work/many_seed.json"
expect2 "html_report.py journal of the same config name, another seed" "a record of config '[0-9a-f]{16}', not of the report's" \
  "$py" "$html" "$work/many_seed.json" "$work/a.html" --runs "$work/many.jsonl"
if "$py" "$html" "$work/many.json" "$work/many.html" --runs "$work/many.jsonl" >"$work/out.txt" 2>"$work/err.txt"; then
  ok "html_report.py with --runs: $(cat "$work/out.txt")"
else
  bad "html_report.py with --runs: $(cat "$work/err.txt")"
fi
if "$py" "$html" "$tiny" "$work/tiny.html" --uncompressed >"$work/out.txt" 2>"$work/err.txt" \
   && "$py" "$html" "$tiny" "$work/tiny.html" >/dev/null 2>&1; then
  ok "html_report.py without --runs, --uncompressed (and over its own page): $(cat "$work/out.txt")"
else
  bad "html_report.py without --runs: $(cat "$work/err.txt")"
fi
for f in many tiny; do
  # Outside the embedded scripts (plotly.js quotes web addresses in its documentation strings):
  # no element that loads anything (src=, <link>, CSS url()), so nothing can be fetched.
  refs=$("$py" - "$work/$f.html" <<'PY'
import re, sys
page = open(sys.argv[1], encoding="utf-8").read()
outside = re.sub(r"(<script[^>]*>).*?(</script>)", r"\1\2", page, flags=re.S)
hits = re.findall(r'<script[^>]*\bsrc=|<link\b|<img\b|<iframe\b|\bsrc="|url\(|@import', outside, flags=re.I)
print(len(hits), " ".join(hits[:5]))
PY
)
  if [ "${refs%% *}" = "0" ]; then
    ok "$f.html: nothing outside its scripts loads a resource"
  else
    bad "$f.html loads resources: $refs"
  fi
done

# Headless Chromium, network cut off (every request goes to a closed local port, every host
# name fails), on a copy in its own folder. DOM after the scripts ran; the console log.
render() {  # FILE HASH NAME -> $work/NAME.dom, $work/NAME.log
  local file=$1 hash=$2 name=$3
  timeout 240 chromium --headless --disable-gpu --no-sandbox --no-first-run --disable-extensions \
    --user-data-dir="$work/profile-$name" --proxy-server=127.0.0.1:9 \
    --host-resolver-rules="MAP * ~NOTFOUND" --enable-logging=stderr --v=0 \
    --virtual-time-budget=20000 --window-size=1400,1800 --dump-dom "file://$file#$hash" \
    >"$work/$name.dom" 2>"$work/$name.log"
}
check_page() {  # NAME TRACES: every chart drawn with TRACES traces (box and success)
  local name=$1 traces=$2
  local dom="$work/$name.dom" log="$work/$name.log"
  if [ ! -s "$dom" ]; then bad "$name: chromium wrote no DOM ($(tail -3 "$log"))"; return; fi
  grep -q 'data-ready="1"' "$dom" && ok "$name: the page's script ran to the end" || bad "$name: no data-ready"
  local n
  n=$(grep -o 'id="page-errors" hidden=""></pre>' "$dom" | wc -l)
  [ "$n" -eq 1 ] && ok "$name: no JavaScript error" || bad "$name: errors: $(grep -o 'id="page-errors"[^<]*' "$dom" | head -c 600)"
  if grep -q 'CONSOLE' "$log"; then
    bad "$name: console messages: $(grep 'CONSOLE' "$log" | head -5)"
  else
    ok "$name: nothing on the console"
  fi
  for chart in box-chart success-chart paired-chart; do
    # The chart's div, up to the next section: plotly's <svg class="main-svg"> and its traces.
    local part
    part=$("$py" - "$dom" "$chart" <<'PY'
import re, sys
dom = open(sys.argv[1], encoding="utf-8").read()
m = re.search(r'<div id="%s"[^>]*>' % re.escape(sys.argv[2]), dom)
if not m:
    print("missing"); sys.exit()
tag = m.group(0)
rest = dom[m.end():dom.find("</section>", m.end())]
drawn = re.search(r'data-drawn="(\d+)"', tag)
traces = re.search(r'data-traces="(\d+)"', tag)
print(drawn.group(1) if drawn else 0, traces.group(1) if traces else -1, rest.count('class="main-svg"'),
      len(re.findall(r'class="trace (?:boxes|bars|scatter)', rest)) + len(re.findall(r'class="points"', rest)) * 0)
PY
)
    read -r drawn ntr svgs _ <<<"$part"
    if [ "$part" = "missing" ] || [ "${drawn:-0}" -lt 1 ] || [ "${svgs:-0}" -lt 1 ]; then
      bad "$name: $chart not drawn ($part)"
    elif [ "$chart" != paired-chart ] && [ "$ntr" != "$traces" ]; then
      bad "$name: $chart has $ntr traces, expected $traces"
    else
      ok "$name: $chart drawn (plotly SVG, $ntr traces)"
    fi
  done
  grep -q '<table class="values" id="values-table">' "$dom" && ok "$name: the table" || bad "$name: no table"
  if grep -qiE '<(img|iframe|link|script)[^>]*(src|href)="https?:' "$dom"; then
    bad "$name: the drawn page references a web resource"
  else
    ok "$name: the drawn page references no web resource"
  fi
}

mkdir -p "$work/site"
cp "$work/many.html" "$work/site/many.html"
cp "$work/tiny.html" "$work/site/tiny.html"
# The three pages at once: each Chromium spends much of its 8-11 s waiting, not computing.
render "$work/site/many.html" "" many &
p_many=$!
render "$work/site/many.html" "metric=plan_time_ns&density=0.3&planners=astar,planner_05_variant,planner_23_variant" many-subset &
p_subset=$!
render "$work/site/tiny.html" "world=blocks%2032%C3%9732&metric=turns" tiny &
p_tiny=$!
rendered() {  # PID NAME TRACES: checks the page NAME once its Chromium (PID) has ended
  if wait "$1"; then check_page "$2" "$3"; else bad "$2: chromium failed ($(tail -3 "$work/$2.log"))"; fi
}
rendered $p_many many 24
rendered $p_subset many-subset 3
rendered $p_tiny tiny 3
grep -q '<option value="1" selected="">blocks 16×16\|<option value="3" selected="">blocks 32×32' "$work/tiny.dom" \
  && ok "tiny: the URL's cell group chosen" || bad "tiny: the URL's cell group was not chosen"

finish
