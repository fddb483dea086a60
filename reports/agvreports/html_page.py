"""The page of html_report.py: the report's numbers as one JSON object, and the self-contained
HTML file around them (the page's script and style from reports/html_report.js and .css, and
plotly.js from Debian's python3-plotly, all inline: the page loads nothing).
"""

import base64
import gzip
import json
import os

from agvreports.metrics import TIME, metric_title, metric_unit, scale_of
from agvreports.numeric import finite

ASSETS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # reports/: the page's .js, .css
# The mark of a page this script wrote (under its former name html.py, which the mark keeps):
# only such a file is overwritten.
MARK = "<!-- agvbench html.py report -->"
PLOTLY_JS = "/usr/share/python3-plotly/plotly.js"  # Debian python3-plotly


def plotly_js():
    """plotly.js source from the installed python3-plotly (no download)."""
    try:
        from plotly.offline import get_plotlyjs
        return get_plotlyjs()
    except ImportError:
        pass
    try:
        with open(PLOTLY_JS, encoding="utf-8") as f:
            return f.read()
    except OSError:
        return None


def rounded(v, digits=5):
    """Fewer digits for the embedded numbers (the page shows 3-4): a smaller file."""
    if not finite(v):
        return None
    if v == 0:
        return 0
    return float(f"{v:.{digits}g}")


def summary(s, scale=1.0):
    if not isinstance(s, dict):
        return None
    out = {k: rounded(s.get(k) * scale) if finite(s.get(k)) else None
           for k in ("count", "mean", "stddev", "min", "p5", "median", "p95", "max")}
    ci = s.get("ci95") or [None, None]
    out["ci95"] = [rounded(c * scale) if finite(c) else None for c in ci]
    return out


def comparison(c):
    if not isinstance(c, dict):
        return None
    out = {k: c.get(k) for k in ("pairs", "better", "wins", "ties", "losses", "ratio",
                                 "ratios_excluded", "wilcoxon_exact")}
    out["gm"] = rounded(c.get("geo_mean_ratio"))
    out["ci95"] = [rounded(v) for v in (c.get("ci95") or [None, None])]
    out["p"] = rounded(c.get("wilcoxon_p"), 3)
    return out


def page_data(rep, runs):
    """Everything the page draws, as one JSON object."""
    metrics = rep.metrics_with_time()
    labels = {m: [metric_unit(m), metric_title(m)] for m in metrics}
    labels[TIME] = [metric_unit(TIME), metric_title(TIME)]
    planners = [{"label": l, "colour": rep.style.colour[l], "marker": rep.style.marker[l],
                 "open": rep.style.fill[l] == "none"} for l in rep.labels]
    worlds = []
    for key in rep.ordered_worlds():
        cells = rep.worlds[key]
        wc = []
        for d in sorted(cells):
            cell = cells[d]
            ps, pr, rv = {}, {}, {}
            for label in rep.labels:
                p = rep.planner(cell, label)
                if p is None:
                    continue
                ps[label] = {
                    "runs": p.get("runs"), "successes": p.get("successes"),
                    "ci": [rounded(v) for v in (p.get("success_ci95") or [None, None])],
                    "failures": p.get("failures") or {},
                    "m": {m: summary(rep.summary_of(p, m), scale_of(m)) for m in metrics},
                }
                c = rep.paired(cell, label)
                if c is not None:
                    pr[label] = {m: comparison(rep.comparison_of(c, m)) for m in metrics
                                 if rep.comparison_of(c, m)}
                if runs is not None:
                    ck = rep.cell_key(cell)
                    rv[label] = {m: [rounded(v * scale_of(m), 4)
                                     for v in runs.values(ck, label, m)] for m in metrics}
            wc.append({"density": d, "cell": rep.cell_key(cell), "maps": cell.get("maps"),
                       "planners": ps, "paired": pr, "runs": rv if runs is not None else None})
        worlds.append({"title": rep.world_title(key), "cells": wc})
    cfg = rep.config
    env = rep.doc.get("environment") if isinstance(rep.doc.get("environment"), dict) else {}
    return {"name": cfg.get("name", "(unnamed)"), "seed": cfg.get("seed"),
            "maps_per_cell": cfg.get("maps_per_cell"), "baseline": rep.baseline,
            "complete": rep.doc.get("complete", True), "planners": planners, "metrics": metrics,
            "metric_labels": labels, "worlds": worlds, "has_runs": runs is not None,
            "environment": {k: env.get(k) for k in ("cpu_model", "threads", "git_revision",
                                                   "compiler", "build", "date_utc")
                            if env.get(k) is not None}}


def plotly_and_app(js_plotly, js_app, compress):
    """The script elements: plotly.js and the page's script after it. Compressed: plotly.js as
    gzip in base64 (2.5 MB instead of Debian's unminified 8.7 MB), unpacked by the browser's
    DecompressionStream into an inline script (no request), then the page's script runs."""
    if not compress:
        return ["<script>", js_plotly, "</script>", "<script>", js_app, "</script>"]
    packed = base64.b64encode(gzip.compress(js_plotly.encode("utf-8"), 9, mtime=0)).decode("ascii")
    loader = (
        "(async function () {\n"
        "  if (typeof DecompressionStream === 'undefined') {\n"
        "    throw new Error('this browser cannot unpack the embedded plotly.js (no DecompressionStream): "
        "write the page with html_report.py --uncompressed');\n"
        "  }\n"
        "  const b64 = document.getElementById('plotly-gz').textContent;\n"
        "  const bin = atob(b64), bytes = new Uint8Array(bin.length);\n"
        "  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);\n"
        "  const text = await new Response(new Blob([bytes]).stream()"
        ".pipeThrough(new DecompressionStream('gzip'))).text();\n"
        "  const s = document.createElement('script');\n"
        "  s.textContent = text;\n"
        "  document.head.appendChild(s);\n"
        + js_app +
        "\n})().catch(function (e) { console.error('loading the page failed: ' + e); });\n")
    return [f"<script id=\"plotly-gz\" type=\"application/octet-stream\">{packed}</script>",
            "<script>", loader, "</script>"]


def script_json(data):
    """`data` as JSON to embed in a <script> element whatever its strings hold (a planner label
    may be "</script>" or "<!--<script>", which would end the element early or keep it from
    ending): no '<', '>' or '&' in the text, each written as a JSON escape instead."""
    text = json.dumps(data, separators=(",", ":"), allow_nan=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def build_page(data, js_app, js_plotly, title, compress=True):
    esc = lambda s: (s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;"))
    blob = script_json(data)
    with open(os.path.join(ASSETS, "html_report.css"), encoding="utf-8") as f:
        css = f.read()
    return "\n".join([
        "<!DOCTYPE html>", MARK, "<html lang=\"en\"><head><meta charset=\"utf-8\">",
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">",
        f"<title>{esc(title)}</title>",
        # First of all: every error or console.error of the page is kept and shown (the test
        # reads #page-errors in the rendered DOM).
        "<script>window.__pageErrors=[];(function(){function keep(m){window.__pageErrors.push(String(m));"
        "var e=document.getElementById('page-errors');if(e){e.textContent=window.__pageErrors.join('\\n');e.hidden=false;}}"
        "window.addEventListener('error',function(ev){keep('error: '+ev.message+' at '+ev.filename+':'+ev.lineno);});"
        "window.addEventListener('unhandledrejection',function(ev){keep('unhandled rejection: '+ev.reason);});"
        "var ce=console.error;console.error=function(){keep('console.error: '+Array.prototype.join.call(arguments,' '));ce.apply(console,arguments);};"
        "})();</script>",
        f"<style>{css}</style>", "</head><body>",
        "<pre id=\"page-errors\" hidden></pre>",
        "<header><h1 id=\"title\"></h1><p id=\"meta\"></p></header>",
        "<section id=\"controls\"></section>",
        "<section class=\"chart\"><h2 id=\"box-title\">Distribution</h2><div id=\"box-chart\"></div><p class=\"note\" id=\"box-note\"></p></section>",
        "<section class=\"chart\"><h2>Success rate</h2><div id=\"success-chart\"></div><p class=\"note\">Share of runs that succeeded; bars: Wilson 95% interval.</p></section>",
        "<section class=\"chart\"><h2 id=\"paired-title\">Paired ratio to the baseline</h2><div id=\"paired-chart\"></div><p class=\"note\" id=\"paired-note\"></p></section>",
        "<section class=\"chart\"><h2 id=\"table-title\">Table</h2><div id=\"table\"></div></section>",
        f"<script id=\"report-data\" type=\"application/json\">{blob}</script>",
    ] + plotly_and_app(js_plotly, js_app, compress) + [

        "</body></html>", ""])
