"""summary.md of plot.py: one overview table (planners x success, path length and planning
time, pooled over every cell), then per world (generator, size) a results table and a paired
table with Wilcoxon p-values. Times in microseconds, named in every header (the JSON keeps
nanoseconds in the fields named *_ns). Standard library only.
"""

import math
import os
import statistics

from agvreports.grouping import density_text
from agvreports.markdown_text import code, plain
from agvreports.metrics import TIME, metric_title, metric_unit
from agvreports.numeric import finite
from agvreports.stats import Moments, moments_from_summary, wilson

DASH = "\u2013"
# Columns of the per-world tables when --metrics does not choose them (the rest: the JSON,
# the pictures and the HTML report).
RESULT_METRICS = ["path_length", "optimality_ratio", "turns", "min_clearance"]
PAIRED_METRICS = ["path_length", "waypoints", "turns", "motion_time_s", TIME]


def fmt(v, digits=3):
    """Fixed decimals by magnitude, so a column reads evenly (28.14, 6.830, 0.896, 502.0)."""
    if not finite(v):
        return DASH
    a = abs(v)
    if a == 0:
        return "0"
    if a >= 1e6 or a < 1e-3:
        return f"{v:.{digits}g}"
    if a >= 1000:
        return f"{v:.0f}"
    if a >= 100:
        return f"{v:.1f}"
    if a >= 10:
        return f"{v:.2f}"
    if a >= 1:
        return f"{v:.3f}"
    return f"{v:.{digits}g}"


def fmt_p(p):
    if not finite(p):
        return "p " + DASH
    if p < 0.001:
        return "p<0.001"
    return f"p={p:.2g}" if p < 0.01 else f"p={p:.3f}".rstrip("0").rstrip(".") if p < 1 else "p=1"


def header(cols):
    return ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]


def row(cells):
    return "| " + " | ".join(cells) + " |"


def success_text(successes, runs, ci=None):
    if not runs:
        return DASH
    text = f"{100.0 * successes / runs:.1f}"
    lo, hi = ci if ci else wilson(successes, runs)
    if finite(lo) and finite(hi):
        text += f" [{lo * 100:.1f}, {hi * 100:.1f}]"
    return text


def log_moments(comp):
    """Moments of a COMPARISON's per-map log ratios (plain ratios only), or None."""
    if not isinstance(comp, dict) or comp.get("ratio", "plain") != "plain":
        return None
    n = int(comp.get("pairs") or 0) - int(comp.get("ratios_excluded") or 0)
    gm = comp.get("geo_mean_ratio")
    if n <= 0 or not finite(gm) or gm <= 0:
        return None
    ci = comp.get("ci95") or [None, None]
    lci = [math.log(c) if finite(c) and c > 0 else None for c in ci]
    return moments_from_summary(n, math.log(gm), lci)


def pooled_ratio_text(moments):
    if moments.n == 0:
        return DASH
    text = f"{math.exp(moments.mean):.3f}"
    lo, hi = moments.interval()
    if lo is not None:
        text += f" [{math.exp(lo):.3f}, {math.exp(hi):.3f}]"
    return text


def overview(rep):
    """Planners x (success, path length, planning time), pooled over every cell."""
    base = rep.baseline
    out = ["## Overview\n",
           f"Pooled over all {len(rep.doc['cells'])} cells. Success: all runs, Wilson 95% interval. "
           f"Ratios to {code(base)}: geometric mean of the per-map ratios over every pair of every cell "
           "(path length: maps where both succeeded; planning time: maps both ran) with its 95% "
           "interval; *p<0.05*: cells whose Wilcoxon signed-rank test (two-sided) gives p < 0.05, "
           "of the cells compared. Plan time: the median of the cells' medians and their range.\n"]
    cols = ["planner", "runs", "success % [95%]", f"path length / {plain(base)} [95%]", "p<0.05",
            "plan time median \u00b5s (cells' range)", f"plan time / {plain(base)} [95%]", "p<0.05"]
    out += header(cols)
    for label in rep.labels:
        runs = succ = 0
        lm, tm = Moments(), Moments()
        lsig = lcells = tsig = tcells = 0
        medians = []
        for cell in rep.doc["cells"]:
            p = rep.planner(cell, label)
            if p is None:
                continue
            runs += int(p.get("runs") or 0)
            succ += int(p.get("successes") or 0)
            t = rep.summary_of(p, TIME)
            if t and finite(t.get("median")):
                medians.append(t["median"] / 1e3)
            c = rep.paired(cell, label)
            if c is None:
                continue
            for name, acc in (("path_length", lm), (TIME, tm)):
                comp = rep.comparison_of(c, name)
                m = log_moments(comp)
                if m is not None:
                    acc.merge(m)
                if comp and int(comp.get("pairs") or 0) > 0:
                    sig = finite(comp.get("wilcoxon_p")) and comp["wilcoxon_p"] < 0.05
                    if name == TIME:
                        tcells += 1; tsig += sig
                    else:
                        lcells += 1; lsig += sig
        is_base = label == base
        name = code(label, in_table=True) + (" (baseline)" if is_base else "")
        med = (f"{fmt(statistics.median(medians))} ({fmt(min(medians))}{DASH}{fmt(max(medians))})"
               if medians else DASH)
        out.append(row([name, str(runs), success_text(succ, runs),
                        "1" if is_base else pooled_ratio_text(lm),
                        DASH if is_base else f"{lsig}/{lcells}", med,
                        "1" if is_base else pooled_ratio_text(tm),
                        DASH if is_base else f"{tsig}/{tcells}"]))
    out.append("")
    return out


def column_title(m):
    """'path length (cells)'; a ratio or a count named by its title alone."""
    unit, title = metric_unit(m), metric_title(m)
    if not unit or "/" in unit or unit in ("ratio", title) or title.endswith(")"):
        return title
    return f"{title} ({unit})"


def world_tables(rep, key):
    cells = rep.worlds[key]
    out = [f"## {plain(rep.world_title(key))}\n"]
    avail = rep.metric_names()
    metrics = avail if rep.metric_filter else [m for m in RESULT_METRICS if m in avail]
    show_time = rep.has_time() and rep.wanted(TIME)
    cols = ["density", "planner", "success % [95%]"]
    cols += [column_title(m) for m in metrics]
    if show_time:
        cols.append("plan time \u00b5s median (p5\u2013p95)")
    out.append("Means over successful runs (95% intervals: report.json and the pictures).\n")
    out += header(cols)
    for d in sorted(cells):
        for label in rep.labels:
            p = rep.planner(cells[d], label)
            if p is None:
                continue
            succ = success_text(p["successes"], p.get("runs") or 0, p.get("success_ci95"))
            fails = p.get("failures") or {}
            if fails:
                succ += " (" + ", ".join(f"{plain(k)} {v}" for k, v in fails.items()) + ")"
            r = [density_text(d), code(label, in_table=True), succ]
            r += [fmt((p["metrics"].get(m) or {}).get("mean")) for m in metrics]
            if show_time:
                t = rep.summary_of(p, TIME)
                if t and finite(t.get("median")):
                    lo, hi = t.get("p5"), t.get("p95")
                    r.append(f"{fmt(t['median'] / 1e3)} ({fmt(lo / 1e3 if finite(lo) else None)}\u2013"
                             f"{fmt(hi / 1e3 if finite(hi) else None)})")
                else:
                    r.append(DASH)
            out.append(row(r))
    out.append("")
    names = rep.paired_names()
    if not rep.metric_filter:
        names = [n for n in PAIRED_METRICS if n in names]
    others = rep.paired_planners(cells)
    if names and others:
        out.append(f"Paired against {code(rep.baseline)} on the same maps: geometric mean of planner / "
                   f"{code(rep.baseline)} (below 1: smaller) and the Wilcoxon signed-rank p-value; "
                   "pairs = maps where both succeeded.\n")
        cols = ["density", "planner", "pairs"] + [metric_title(n) for n in names]
        out += header(cols)
        for d in sorted(cells):
            for label in others:
                c = rep.paired(cells[d], label)
                if c is None:
                    continue
                first = rep.comparison_of(c, names[0]) or {}
                pairs = next((str(rep.comparison_of(c, n).get("pairs")) for n in names
                              if n != TIME and rep.comparison_of(c, n)), str(first.get("pairs", DASH)))
                r = [density_text(d), code(label, in_table=True), pairs]
                for n in names:
                    comp = rep.comparison_of(c, n)
                    if not comp or not finite(comp.get("geo_mean_ratio")):
                        r.append(DASH)
                    else:
                        r.append(f"{comp['geo_mean_ratio']:.3f} ({fmt_p(comp.get('wilcoxon_p'))})")
                out.append(row(r))
        out.append("")
    return out


def write_summary(rep, outdir, pictures):
    doc, cfg = rep.doc, rep.config
    env = doc.get("environment", {}) if isinstance(doc.get("environment"), dict) else {}
    timing = doc.get("timing", {}) if isinstance(doc.get("timing"), dict) else {}
    totals = doc.get("totals", {}) if isinstance(doc.get("totals"), dict) else {}
    out = [f"# Sweep summary: {plain(cfg.get('name', '(unnamed)'))}\n"]
    if doc.get("complete") is False:
        out.append("> **Incomplete report**: the sweep was interrupted; cells hold fewer runs "
                   "than configured.\n")
    out += overview(rep)
    out.append("## The sweep\n")
    out.append(f"- seed {cfg.get('seed', '?')}, {cfg.get('maps_per_cell', '?')} maps per cell, "
               f"{totals.get('cells', len(doc['cells']))} cells, {totals.get('maps', '?')} maps, "
               f"{totals.get('runs', '?')} runs")
    out.append(f"- planners: {', '.join(plain(l) for l in rep.labels)}; baseline {code(rep.baseline)}")
    if env:
        extra = ""
        if env.get("date_utc") or env.get("date"):
            extra += f"; run {env.get('date_utc') or env.get('date')}"
        out.append(f"- machine: {env.get('cpu_model', '?')}, {env.get('threads', '?')} threads; "
                   f"build {env.get('build', '?')}, {env.get('compiler', '?')}, revision "
                   f"{env.get('git_revision', '?')}{extra}")
    if finite(timing.get("wall_s")):
        out.append(f"- wall time {timing['wall_s']:.2f} s ({fmt(timing.get('runs_per_s'))} runs/s)")
    out.append("- units: lengths and clearances in cells, angles in rad, times in \u00b5s here "
               "(report.json: `plan_time_ns` in ns)")
    if pictures:
        out.append("- pictures: " + ", ".join(f"[{p}]({p})" for p in pictures))
    out.append("")
    for key in rep.ordered_worlds():
        out += world_tables(rep, key)
    path = os.path.join(outdir, "summary.md")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out).rstrip() + "\n")
    return path
