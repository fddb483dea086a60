#!/usr/bin/env bash
# Planner labels of any text through every report script (issue 28, class 10): a synthetic sweep
# and its journal (tests/reports/synth_report.py) whose planners are labelled with Markdown,
# TeX, HTML and JavaScript syntax (`a|b`, `$\alpha$`, `<script>alert(1)</script>`, a line break,
# a label starting with '_', `__proto__`, ...) and whose baseline is `a|b`:
#  1. plot.py --runs: exit 0, every picture written, every label in every legend as written (the
#     SVG keeps text as text: no mathtext, none left out), no layout problem;
#  2. summary.md: every table row has its header's cells, and its planner cells, the headers
#     naming the baseline and the list of planners read back (GFM's rules: a row splits at a pipe
#     not after a backslash, code spans, backslash escapes) as exactly the labels, with nothing
#     left unescaped that Markdown would read as markup, and no tag but <br> and <code> in the
#     file (a label's HTML as entities, code spans included);
#  3. html_report.py --runs: the embedded JSON holds no '<' (no label can end its <script> or
#     keep it open) and reads back as the labels; no label with HTML syntax anywhere in the page
#     as it is; the page's title escaped; with Debian's chromium (optional, one render): the page
#     drawn without error from a URL naming all planners but one, the legends, the planner list
#     and the table showing the labels as written, nothing injected;
#  4. check_claims.py with claims naming such planners: exit 0, its tables' rows whole, the
#     labels read back;
#  5. plot_paths.py on a plan whose runs carry such labels: exit 0, no warning, every label in
#     the legend as written.
# Skipped (exit 77) only when Debian's /usr/bin/python3 cannot import matplotlib; without
# python3-plotly the page is not checked, without chromium it is not drawn.
# Usage: test_odd_labels.sh REPO_ROOT
set -u
root=${1:?usage: test_odd_labels.sh REPO_ROOT}
py=/usr/bin/python3
source "$(dirname "$0")/lib.sh"

if [ ! -x "$py" ] || ! "$py" -c 'import matplotlib' 2>/dev/null; then
  echo "SKIP: $py cannot import matplotlib (apt-get install python3-matplotlib)"
  exit 77
fi

# The sweep, its journal, the labels (JSON, for the checks), a claims file and a plan document.
"$py" - "$root" "$work" <<'PY' || { echo "FAIL building the synthetic sweep"; exit 1; }
import json, os, sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
root, work = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(root, "tests", "reports"))
import synth_report
# "$\frac{1$" is TeX that matplotlib's mathtext cannot parse: drawn as mathtext, it stopped plot.py.
labels = ["a|b", "x_1^2", "$\\alpha$", "$\\frac{1$", "50%", "`tick`", "<script>alert(1)</script>",
          "a&b", "\"quoted\"", "back\\slash", "*star*", "[link](x)", "two\nlines", "\u00c4*",
          "_hidden", "</script><!--<script>", "%{y} c,d", "__proto__"]
planners = [{"label": l, "name": "astar", "params": {"k": i},
             "model": {"length": 1 + 0.02 * i, "time": 1 + 0.1 * i}} for i, l in enumerate(labels)]
spec = {"name": "odd <i>labels</i> & *more*", "seed": 3, "generators": ["uniform"],
        "sizes": [[16, 16]], "densities": [0.1, 0.3], "maps_per_cell": 6, "baseline": labels[0],
        "planners": planners}
synth_report.make(spec, f"{work}/odd.json", f"{work}/odd.jsonl")
json.dump({"labels": labels, "name": spec["name"]}, open(f"{work}/labels.json", "w"))
setup = {"paper": "none", "random": "none"}
claims = {"claims": [
    {"id": "odd-ratio", "paper": "000", "where": "test", "claim": "odd labels", "paper_figure": "-",
     "setup": setup, "compare": {"candidate": labels[6], "baseline": labels[0],
                                 "metric": "path_length", "min_pairs": 2}},
    {"id": "odd-order", "paper": "000", "where": "test", "claim": "odd labels", "paper_figure": "-",
     "setup": setup, "compare": {"type": "ordering", "planners": [labels[0], labels[5], labels[12]],
                                 "metric": "path_length", "direction": "increasing",
                                 "min_pairs": 2}}]}
json.dump(claims, open(f"{work}/claims.json", "w"))
plan = json.load(open(os.path.join(root, "tests", "reports", "tiny_plan.json")))
for run, label in zip(plan["runs"], ["_hidden", "$\\frac{1$", "two\nlines", "<b>a|b</b>"]):
    run["planner"] = label
json.dump(plan, open(f"{work}/plan.json", "w"))
PY

# Checks of the outputs, by the rules their readers apply (run as: checks.py WHAT FILE...).
cat >"$work/checks.py" <<'PY'
import json, re, sys
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

results = []


def check(cond, what):
    results.append(cond)
    print(("ok   " if cond else "FAIL ") + what)


PUNCT = "!\"#$%&'()*+,-./:;<=>?@[\\]^_`{|}~"


def cells(line):
    """A GFM table row's cells: split at each pipe not right after a backslash (cmark-gfm's
    longest match), each cell's escaped pipes then unescaped."""
    body = line.strip()
    body = body[1:] if body.startswith("|") else body
    body = body[:-1] if body.endswith("|") and not body.endswith("\\|") else body
    return [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", body)]


def inline(text):
    """What a Markdown reader shows for text made of code spans, <code> elements, backslash
    escapes, the entities &lt; &gt; &amp;, <br> and plain characters; raises ValueError at
    anything it would read as markup instead."""
    out, i = [], 0
    while i < len(text):
        c = text[i]
        if c == "`":
            fence = re.match(r"`+", text[i:]).group(0)
            end = text.find(fence, i + len(fence))
            while end >= 0 and text[end + len(fence):end + len(fence) + 1] == "`":
                end = text.find(fence, end + len(fence) + 1)
            if end < 0:
                raise ValueError(f"unclosed code span at {i}: {text!r}")
            body = text[i + len(fence):end]
            if body.startswith(" ") and body.endswith(" ") and body.strip(" "):
                body = body[1:-1]
            out.append(body)
            i = end + len(fence)
        elif text.startswith("<br>", i):
            out.append("\n")
            i += 4
        elif text.startswith("<code>", i):
            end = text.find("</code>", i)
            if end < 0:
                raise ValueError(f"unclosed <code> at {i}: {text!r}")
            out.append(inline(text[i + 6:end]))
            i = end + 7
        elif m := re.match(r"&(lt|gt|amp);", text[i:]):
            out.append({"lt": "<", "gt": ">", "amp": "&"}[m.group(1)])
            i += m.end()
        elif c == "\\" and i + 1 < len(text) and text[i + 1] in PUNCT:
            out.append(text[i + 1])
            i += 2
        elif c in "*~$&#\\" or (c == "<" and re.match(r"</?[A-Za-z!?]", text[i:])) \
                or text.startswith("](", i):
            raise ValueError(f"markup {c!r} at {i}: {text!r}")
        elif c == "_" and not (0 < i < len(text) - 1 and text[i - 1].isalnum() and text[i + 1].isalnum()):
            raise ValueError(f"emphasis '_' at {i}: {text!r}")
        else:
            out.append(c)
            i += 1
    return "".join(out)


def shown(text):
    try:
        return inline(text)
    except ValueError as e:
        return f"<unreadable: {e}>"


def tables(md):
    """[(header cells, [row cells], [rows as written])] of every table (a header row, then
    its |---| rule)."""
    lines, out = md.split("\n"), []
    for k in range(len(lines) - 1):
        if lines[k].startswith("|") and re.fullmatch(r"\|(?:-+:?\|)+|\|(?:---:?\|)+", lines[k + 1]):
            rows, j = [], k + 2
            while j < len(lines) and lines[j].startswith("|"):
                rows.append(lines[j])
                j += 1
            out.append((cells(lines[k]), [cells(r) for r in rows], rows))
    return out


def no_raw_html(md, what):
    """No tag but <br> and <code>, no entity but &lt; &gt; &amp; anywhere in the file, code
    spans included: not every renderer honours a backslash escape or a code span."""
    tags = set(re.findall(r"</?[A-Za-z!?][^\s>]*", md)) - {"<br", "<code", "</code"}
    ents = set(re.findall(r"&[#A-Za-z0-9]+;", md)) - {"&lt;", "&gt;", "&amp;"}
    check(not tags and not ents, f"{what}: no label's HTML as it is (not: {sorted(tags | ents)[:4]})")


def summary(path, labels, name):
    md = open(path, encoding="utf-8").read()
    no_raw_html(md, "summary.md")
    base = labels[0]
    found = tables(md)
    check(len(found) == 3, f"summary.md: 3 tables (got {len(found)})")
    for head, rows, raw in found:
        wrong = [r for r, c in zip(raw, rows) if len(c) != len(head)]
        check(not wrong, f"summary.md: every row of the '{head[0]} | {head[1]}' table has "
              f"{len(head)} cells" + (f" (not: {wrong[0][:120]})" if wrong else ""))
        col = head.index("planner")
        got = [shown(c[col]) for c in rows]
        got = [g[:-len(" (baseline)")] if g.endswith(" (baseline)") else g for g in got]
        # The overview: once each; the world's tables: once per density (2), the paired one
        # without the baseline.
        want = labels if head[0] == "planner" else (labels[1:] if "pairs" in head else labels) * 2
        check(got == want, f"summary.md: the '{head[0]} | {head[1]}' table's planners read back "
              f"as the labels" + ("" if got == want else f": {[g for g in got if g not in want][:3]}"))
    over = found[0][0] if found else []
    check(f"path length / {base} [95%]" in [shown(h) for h in over],
          "summary.md: the overview's header names the baseline as written")
    line = next((l for l in md.split("\n") if l.startswith("- planners: ")), "")
    listed = line[len("- planners: "):line.rfind("; baseline ")]
    check(shown(listed) == ", ".join(labels), "summary.md: the list of planners reads back as the labels")
    check(shown(line[line.rfind("; baseline ") + 11:]) == base, "summary.md: the baseline in a code span")
    check(shown(md.split("\n")[0][len("# Sweep summary: "):]) == name, "summary.md: the sweep's name as written")


def claims(path, labels):
    md = open(path, encoding="utf-8").read()
    no_raw_html(md, "CLAIMS.md")
    found = tables(md)
    check(len(found) == 2 and all(len(c) == len(h) for h, rows, _ in found for c in rows),
          "CLAIMS.md: every row of its 2 tables has its header's cells")
    rows = {shown(c[0]).split(" (")[0]: c for h, rs, _ in found[1:] for c in rs}
    ratio, order = rows.get("odd-ratio"), rows.get("odd-order")
    check(ratio is not None and shown(ratio[2]) == f"path_length ratio: {labels[6]} / {labels[0]}",
          "CLAIMS.md: the ratio's planners read back as the labels")
    check(order is not None and shown(order[2]) == f"path_length: {labels[0]} > {labels[5]} > {labels[12]}",
          "CLAIMS.md: the ordering's planners read back as the labels")
    line = next((l for l in md.split("\n") if l.startswith("- `")), "")
    listed = line[line.find(", planners ") + 11:line.rfind("; baseline ")]
    check(shown(listed) == ", ".join(labels), "CLAIMS.md: the report's planners read back as the labels")


def svg_text(path):
    root = ET.parse(path).getroot()
    return "\n".join("".join(t.itertext()) for t in root.iter("{http://www.w3.org/2000/svg}text"))


def svg(path, labels, *extra):
    try:
        text = svg_text(path)
    except (OSError, ET.ParseError) as e:
        return check(False, f"{path.rsplit('/', 1)[-1]}: not written or not SVG ({e})")
    miss = [l for l in labels + list(extra) if l not in text]
    check(not miss, f"{path.rsplit('/', 1)[-1]}: every label as written" + (f" (not: {miss})" if miss else ""))


def pictures(folder, labels):
    """plot.py's pictures: every label in each legend; the paired one names the others, and
    the baseline on its axis."""
    for stem in ("metrics_uniform_16x16", "dist_uniform_16x16", "success", "plan_time", "ecdf_plan_time"):
        svg(f"{folder}/{stem}.svg", labels)
    svg(f"{folder}/paired_uniform_16x16.svg", labels[1:], f"ratio to {labels[0]}")


def page(path, labels, name):
    html = open(path, encoding="utf-8").read()
    m = re.search(r'<script id="report-data" type="application/json">', html)
    blob = html[m.end():html.find("</script", m.end())] if m else ""
    check(m is not None and "<" not in blob, "page: the embedded JSON holds no '<'")
    try:
        data = json.loads(blob)
    except ValueError:
        data = {"planners": [], "worlds": []}
    check([p["label"] for p in data["planners"]] == labels and data["name"] == name,
          "page: the embedded JSON reads back as the labels and the name")
    check(all(list(c["planners"]) == labels for w in data["worlds"] for c in w["cells"]),
          "page: every cell's planners under their labels")
    raw = [l for l in labels + [name] if re.search(r"[<>&]", l) and l in html]
    check(not raw, "page: no label with HTML syntax as it is" + (f" ({raw})" if raw else ""))
    esc = name.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    check(f"<title>agvbench: {esc}</title>" in html, "page: the title escaped")


class Dom(HTMLParser):
    """Texts of the drawn page: each chart's legend entries, the planner list, the table's
    first column; and the elements a label could have injected (<i>, a script of its own)."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.found, self.open, self.column = [], {}, None, 0
        self.injected = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.stack.append((tag, a.get("id") or ""))
        if tag == "i":
            self.injected.append("<i>")
        if tag == "script":
            self.open = ("script", tag, [])
        ids = [i for _, i in self.stack]
        chart = next((i for i in ids if i.endswith("-chart")), None)
        self.column = 0 if tag == "tr" else self.column + (tag in ("td", "th"))
        if chart and "legendtext" in (a.get("class") or "").split():
            self.open = (chart, tag, [])
        elif tag == "label" and "planner-box" in ids[:-1]:
            self.open = ("planner-box", tag, [])
        elif tag == "td" and "values-table" in ids and self.column == 1:
            self.open = ("table", tag, [])

    def handle_endtag(self, tag):
        while self.stack and self.stack.pop()[0] != tag:
            pass
        if self.open and self.open[1] == tag:
            text = "".join(self.open[2])
            if self.open[0] == "script" and text.strip() == "alert(1)":
                self.injected.append("<script>alert(1)</script>")
            self.found.setdefault(self.open[0], []).append(text)
            self.open = None

    def handle_data(self, data):
        if self.open:
            self.open[2].append(data)


def dom(path, labels, left_out):
    html = open(path, encoding="utf-8").read()
    check('data-ready="1"' in html, "drawn page: its script ran to the end")
    check('id="page-errors" hidden=""></pre>' in html, "drawn page: no JavaScript error")
    chosen = [l for l in labels if l != left_out]
    m = re.search(r'<div id="box-chart"[^>]*data-traces="(\d+)"', html)
    check(m is not None and int(m.group(1)) == len(chosen),
          f"drawn page: the URL's {len(chosen)} planners chosen ({m.group(1) if m else 'no'} traces)")
    p = Dom()
    p.feed(html)
    check(not p.injected, "drawn page: no element from a label" + (f" ({p.injected})" if p.injected else ""))
    flat = [l.replace("\n", "") for l in chosen]  # plotly draws a <br> as a line of its own
    for chart, want in (("box-chart", flat), ("success-chart", flat), ("paired-chart", flat[1:])):
        got = p.found.get(chart, [])
        check(got == want, f"drawn page: {chart}'s legend shows the labels as written"
              + ("" if got == want else f" (got {got[:4]}...)"))
    suffix = lambda l: l + (" (baseline)" if l == labels[0] else "")
    check(p.found.get("planner-box") == [suffix(l) for l in labels],
          "drawn page: the planner list shows the labels as written")
    check(p.found.get("table") == [suffix(l) for l in chosen],
          "drawn page: the table shows the labels as written")


if __name__ == "__main__":
    what, path, meta = sys.argv[1], sys.argv[2], json.load(open(sys.argv[3]))
    labels, name = meta["labels"], meta["name"]
    if what == "summary":
        summary(path, labels, name)
    elif what == "claims":
        claims(path, labels)
    elif what == "pictures":
        pictures(path, labels)
    elif what == "plan":
        svg(path, [], *sys.argv[4:])
    elif what == "page":
        page(path, labels, name)
    elif what == "dom":
        dom(path, labels, sys.argv[4])
    sys.exit(0 if all(results) else 1)
PY
checks() {  # WHAT FILE [ARGS]: the checks' lines, counted
  local out
  out=$("$py" -B "$work/checks.py" "$1" "$2" "$work/labels.json" "${@:3}" 2>&1)
  echo "$out"
  pass=$((pass + $(grep -c '^ok ' <<<"$out")))
  fail=$((fail + $(grep -c '^FAIL' <<<"$out")))
  grep -q 'Traceback' <<<"$out" && bad "checks.py $1 failed" || true
}

# 3. The page first: Chromium draws it while the pictures are made.
html="$root/reports/html_report.py"
chromium_pid=
if ! "$py" -c 'import plotly' 2>/dev/null; then
  echo "note: no python3-plotly: html_report.py not checked (apt-get install python3-plotly)"
else
  if "$py" "$html" "$work/odd.json" "$work/odd.html" --runs "$work/odd.jsonl" >/dev/null 2>"$work/html.err"; then
    ok "html_report.py --runs on odd labels"
  else
    bad "html_report.py --runs on odd labels: $(cat "$work/html.err")"
  fi
  [ -s "$work/odd.html" ] && checks page "$work/odd.html"
  if command -v chromium >/dev/null; then
    # The URL names every planner but "50%", each label encoded, so its commas, '%' and '&'
    # must come back whole.
    mkdir -p "$work/site"
    cp "$work/odd.html" "$work/site/odd.html"
    hash=$("$py" -c 'import json, sys, urllib.parse as u
labels = json.load(open(sys.argv[1]))["labels"]
print(u.urlencode({"planners": ",".join(u.quote(l, safe="") for l in labels if l != "50%")}))' "$work/labels.json")
    timeout 240 chromium --headless --disable-gpu --no-sandbox --no-first-run --disable-extensions \
      --user-data-dir="$work/profile" --proxy-server=127.0.0.1:9 --host-resolver-rules="MAP * ~NOTFOUND" \
      --enable-logging=stderr --v=0 --virtual-time-budget=20000 --window-size=1400,1800 \
      --dump-dom "file://$work/site/odd.html#$hash" >"$work/odd.dom" 2>"$work/chromium.log" &
    chromium_pid=$!
  else
    echo "note: no chromium: the page is not drawn (apt-get install chromium)"
  fi
fi

# 1. The pictures, from every run; SVG keeps their text as text.
plot="$root/reports/plot.py"
out="$work/plots"
if "$py" "$plot" "$work/odd.json" "$out" --runs "$work/odd.jsonl" --format svg \
     --metrics path_length,plan_time_ns >/dev/null 2>"$work/plot.err"; then
  ok "plot.py --runs on odd labels"
else
  bad "plot.py --runs on odd labels: $(tail -5 "$work/plot.err")"
fi
grep -q "layout:" "$work/plot.err" && bad "layout problems: $(grep layout: "$work/plot.err")" || ok "no layout problem reported"
checks pictures "$out"

# 2. summary.md.
[ -s "$out/summary.md" ] && checks summary "$out/summary.md" || bad "summary.md not written"

# 4. The claims checker, with claims naming the odd planners.
if "$py" "$root/reports/check_claims.py" "$work/odd.json" "$work/odd.jsonl" --all-as random \
     --claims "$work/claims.json" --out "$work/CLAIMS.md" >/dev/null 2>"$work/claims.err"; then
  ok "check_claims.py on odd labels"
  checks claims "$work/CLAIMS.md"
else
  bad "check_claims.py on odd labels: $(tail -5 "$work/claims.err")"
fi

# 5. plot_paths.py, its text kept as text in the SVG (a matplotlibrc of this test's own).
printf 'svg.fonttype: none\n' >"$work/matplotlibrc"
if MATPLOTLIBRC="$work/matplotlibrc" "$py" "$root/reports/plot_paths.py" "$work/plan.json" "$work/plan.svg" \
     >/dev/null 2>"$work/paths.err" && ! grep -q 'Warning\|Traceback' "$work/paths.err"; then
  ok "plot_paths.py on odd labels, no warning"
else
  bad "plot_paths.py on odd labels: $(tail -5 "$work/paths.err")"
fi
[ -s "$work/plan.svg" ] && checks plan "$work/plan.svg" "_hidden: " "\$\\frac{1\$: " "two
lines: " "<b>a|b</b>: "

if [ -n "$chromium_pid" ]; then
  if wait "$chromium_pid" && [ -s "$work/odd.dom" ]; then
    checks dom "$work/odd.dom" "50%"
    grep -q CONSOLE "$work/chromium.log" && bad "drawn page: console messages: $(grep CONSOLE "$work/chromium.log" | head -3)" \
      || ok "drawn page: nothing on the console"
  else
    bad "chromium failed: $(tail -3 "$work/chromium.log")"
  fi
fi

finish
