#!/usr/bin/python3
"""Pictures and a Markdown summary of an `agvbench run` report (reports/SCHEMA.md, version 2).

    /usr/bin/python3 reports/plot.py REPORT.json OUTDIR [--runs RUNS.jsonl] [--format png|pdf|svg]
        [--planners A,B,...] [--metrics M,N,...] [--dist box|violin] [--dpi N] [--small]

Writes into OUTDIR (FMT = --format, default png):
  metrics_<generator>_<WxH>.FMT  every metric's mean vs obstacle density, one panel per metric,
                                 one line per planner, 95% interval band of the mean, plus the
                                 success rate with its Wilson bars                [report]
  dist_<generator>_<WxH>.FMT     distribution of each metric and of planning time per planner,
                                 one panel per metric, boxes grouped by density.  With --runs:
                                 box = quartiles, whiskers 1.5 IQR, dots = outliers, diamond =
                                 mean (or violins, --dist violin). Without: the report's
                                 summaries, box = p5..p95, whiskers min..max      [report; --runs]
  paired_<generator>_<WxH>.FMT   each planner / baseline on the same maps: geometric-mean ratio
                                 per density with its 95% interval and the 1.0 line  [report]
  success.FMT                    success rate vs density (Wilson 95% bars), panel per world
  plan_time.FMT                  planning time vs grid size, every size of the sweep, log-log,
                                 median with p5-p95 band, panel per generator and density
  ecdf_plan_time.FMT             ECDF of planning time per planner (every run, failures
                                 included), panel per world                      [needs --runs]
  summary.md                     overview table, then tables per world with p-values
Legends sit beside the panels; times are shown in microseconds (the JSON keeps nanoseconds).

Exit codes: 0 done, 1 could not write / matplotlib missing, 2 bad input (report, journal, an
unknown planner or metric in --planners / --metrics, --dist violin without --runs).
Runs with Debian's /usr/bin/python3 and python3-matplotlib; no other third-party package.
"""

import argparse
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
# reports/ holds html.py, which would hide the standard library's `html` package (matplotlib
# imports html.entities): the folder goes last on the path, after the standard library.
_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != _here] + [_here]
import agvreport  # noqa: E402
import agvruns  # noqa: E402
from agvreport import ReportError, density_text  # noqa: E402
from plot_report import (METRIC_LABELS, TIME, Report, finite, metric_title, nan_or,  # noqa: E402
                         split_list)
from plot_style import (Saver, log_ticks_both_ends, note_below_legend, panel_grid, setup_matplotlib,  # noqa: E402
                        side_legend, spaced_ticks)

FORMATS = ("png", "pdf", "svg")


def draw_series(ax, rep, label, xs, ys, los, his, band=True, dodge=0.0):
    """Mean line with its interval: a shaded band, or (band=False, or a single point) error bars
    shifted sideways by `dodge` so that planners with equal values stay visible."""
    import numpy as np
    kw = rep.style.line_kw(label)
    colour = kw["color"]
    x = np.array(xs, dtype=float) + (dodge if (len(xs) == 1 or not band) else 0.0)
    y = np.array([nan_or(v) for v in ys])
    lo = np.array([nan_or(v) for v in los])
    hi = np.array([nan_or(v) for v in his])
    lw = 1.8 if label == rep.baseline else 1.4
    if len(x) == 1 or not band:
        yerr = np.vstack([np.where(np.isfinite(lo), y - lo, 0), np.where(np.isfinite(hi), hi - y, 0)])
        yerr = np.maximum(np.nan_to_num(yerr, nan=0.0), 0.0)  # rounding can put p a hair outside
        ax.errorbar(x, y, yerr=yerr, lw=lw, ms=4.5, capsize=2.5, elinewidth=1.0, label=label, **kw)
        return
    ax.plot(x, y, lw=lw, ms=4.5, label=label, **kw)
    ok = np.isfinite(lo) & np.isfinite(hi)
    if ok.any():
        ax.fill_between(x, np.where(ok, lo, y), np.where(ok, hi, y), where=ok, color=colour,
                        alpha=0.14, lw=0, interpolate=False)
    # A point with no finite neighbour gets no band: show its interval as an error bar.
    fin = np.isfinite(y)
    for i in range(len(x)):
        alone = fin[i] and not (i > 0 and fin[i - 1]) and not (i + 1 < len(x) and fin[i + 1])
        if alone and ok[i]:
            ax.errorbar([x[i]], [y[i]], yerr=[[max(0.0, y[i] - lo[i])], [max(0.0, hi[i] - y[i])]],
                        color=colour, capsize=2.5, elinewidth=1.0, lw=0)


def dodge_of(labels, label, densities):
    """Sideways shift for error bars of planner `label` (a few % of the smallest density step)."""
    if label not in labels:
        return 0.0
    steps = [b - a for a, b in zip(densities, densities[1:]) if b > a]
    step = min(steps) if steps else 0.1
    k, n = labels.index(label), len(labels)
    return (k - (n - 1) / 2.0) * min(0.06, 0.5 / max(1, n)) * step


def density_axis(ax, densities):
    ax.set_xticks(densities)
    ax.set_xticklabels([density_text(d) for d in densities])
    if len(densities) > 1:
        span = densities[-1] - densities[0]
        ax.set_xlim(densities[0] - 0.1 * span, densities[-1] + 0.1 * span)
    elif densities:
        ax.set_xlim(densities[0] - 0.05, densities[0] + 0.05)


def log_if_spread(ax, values, ratio=30.0):
    vals = [v for v in values if finite(v)]
    pos = [v for v in vals if v > 0]
    if pos and len(pos) == len(vals) and max(pos) / min(pos) > ratio:
        log_ticks_both_ends(ax, "y", pos)


def success_ylim(ax, lows):
    lo = min([v for v in lows if finite(v)], default=100.0)
    ax.set_ylim(max(0, math.floor((lo - 3) / 10) * 10), 101.5)


def finish(fig, rep, labels, title, stem, saver, note=None, line=True):
    """Title, tight panels, the legend beside them (and a note under it), save."""
    fig.suptitle(title, fontsize=11, fontweight="bold", x=0.0, ha="left")
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    legend = side_legend(fig, rep.style, labels, line=line)
    if note:
        note_below_legend(fig, legend, note)
    saver.save(fig, stem)


def plot_metrics(plt, saver, rep, key):
    cells = rep.worlds[key]
    ds = sorted(cells)
    panels = ["success_rate"] + rep.metric_names()
    labels = rep.present(cells.values())
    if not labels:
        return
    ncol = min(4, len(panels))
    nrow = math.ceil(len(panels) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.5 * ncol, 2.7 * nrow + 0.5), squeeze=False)
    flat = [a for row in axes for a in row]
    for ax, name in zip(flat, panels):
        allv = []
        for label in labels:
            xs, ys, los, his = [], [], [], []
            for d in ds:
                p = rep.planner(cells[d], label)
                if p is None:
                    continue
                if name == "success_rate":
                    runs = p.get("runs") or 0
                    v = p["successes"] / runs if runs else float("nan")
                    ci = p.get("success_ci95") or [None, None]
                    xs.append(d); ys.append(nan_or(v) * 100)
                    los.append(nan_or(ci[0]) * 100); his.append(nan_or(ci[1]) * 100)
                else:
                    s = p["metrics"].get(name)
                    if not isinstance(s, dict):
                        continue
                    ci = s.get("ci95") or [None, None]
                    xs.append(d); ys.append(s.get("mean")); los.append(ci[0]); his.append(ci[1])
            if xs and any(finite(v) for v in ys):
                if name == "success_rate":
                    draw_series(ax, rep, label, xs, ys, los, his, band=False,
                                dodge=dodge_of(labels, label, ds))
                    allv += [v for v in los if finite(v)]
                else:
                    draw_series(ax, rep, label, xs, ys, los, his)
                    allv += [v for v in los + his if finite(v)]
                allv += [v for v in ys if finite(v)]
        if name == "success_rate":
            ax.set_title("success rate")
            ax.set_ylabel("% of runs (bar: Wilson 95%)")
            success_ylim(ax, allv)
        else:
            unit, title = METRIC_LABELS.get(name, ("", name.replace("_", " ")))
            ax.set_title(title)
            ax.set_ylabel(unit)
            log_if_spread(ax, allv)
        density_axis(ax, ds)
        ax.set_xlabel("obstacle density")
    for ax in flat[len(panels):]:
        fig.delaxes(ax)
    maps = max((c.get("maps", 0) for c in cells.values()), default=0)
    finish(fig, rep, labels, f"{rep.world_title(key)}: mean per metric vs obstacle density "
           f"(successful runs; band = 95% CI of the mean; {maps} maps per density)",
           f"metrics_{rep.world_file(key)}", saver)


RATIO_LADDER = [0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8,
                0.9, 1.0, 1.25, 1.5, 2.0, 3.0, 4.0, 5.0, 7.0, 10.0, 20.0, 50.0, 100.0, 200.0,
                500.0, 1000.0, 2000.0, 5000.0, 10000.0]


def _pct(v):
    p = (v - 1.0) * 100.0
    if abs(p) < 0.05:
        return "\u00b10%"
    if abs(p) >= 10 and (round(p) != -100 or v == 0):  # 0.001 is -99.9%, not -100%
        return f"{p:+.0f}%"
    return f"{p:+.0f}%" if abs(p - round(p)) < 0.05 else f"{p:+.1f}%"


def ratio_ticks(ax, values):
    """Ratio axis: log scale when the spread is large, with labelled ticks at both ends (the
    ladder values just outside the data) and at 1; tick labels carry the % change."""
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter, NullLocator
    vals = [v for v in values if finite(v) and v > 0] + [1.0]
    lo, hi = min(vals), max(vals)
    if hi / lo > 2.5:
        ax.set_yscale("log")
        a = max([t for t in RATIO_LADDER if t <= lo] or [lo])
        b = min([t for t in RATIO_LADDER if t >= hi] or [hi])
        # An end close to 1 would print its label over 1's: move it a ladder step outward.
        gap = math.log(b / a) / 7
        while a < 1.0 and math.log(1.0 / a) < 0.8 * gap and a > RATIO_LADDER[0]:
            a = max(t for t in RATIO_LADDER if t < a)
        while b > 1.0 and math.log(b) < 0.8 * gap and b < RATIO_LADDER[-1]:
            b = min(t for t in RATIO_LADDER if t > b)
        ticks = spaced_ticks([t for t in RATIO_LADDER if a <= t <= b], a, b, keep=1.0)
        ax.set_ylim(a / 1.06, b * 1.06)
        ax.yaxis.set_major_locator(FixedLocator(ticks))
        ax.yaxis.set_minor_locator(NullLocator())
        ax.yaxis.set_minor_formatter(NullFormatter())
    else:
        pad = max(0.01, 0.08 * (hi - lo))
        ax.set_ylim(lo - pad, hi + pad)
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g} ({_pct(v)})"))


def plot_paired(plt, saver, rep, key):
    import numpy as np
    cells = rep.worlds[key]
    ds = sorted(cells)
    names = rep.paired_names()
    others = [l for l in rep.labels if l != rep.baseline
              and any(rep.paired(c, l) for c in cells.values())]
    if not names or not others:
        return
    ncol = min(4, len(names))
    nrow = math.ceil(len(names) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.6 * ncol, 2.8 * nrow + 0.5), squeeze=False)
    flat = [a for row in axes for a in row]
    width = 0.8
    step = width / max(1, len(others))
    for ax, name in zip(flat, names):
        allv = []
        for k, label in enumerate(others):
            xs, ys, lo, hi = [], [], [], []
            for i, d in enumerate(ds):
                c = rep.paired(cells[d], label)
                comp = rep.comparison_of(c, name) if c else None
                if comp is None or not finite(comp.get("geo_mean_ratio")):
                    continue
                r = comp["geo_mean_ratio"]
                ci = comp.get("ci95") or [None, None]
                xs.append(i - width / 2 + step * (k + 0.5))
                ys.append(r)
                lo.append(max(0.0, r - ci[0]) if finite(ci[0]) else 0.0)
                hi.append(max(0.0, ci[1] - r) if finite(ci[1]) else 0.0)
                allv += [r, ci[0] if finite(ci[0]) else r, ci[1] if finite(ci[1]) else r]
            if xs:
                kw = rep.style.line_kw(label)
                kw["linestyle"] = "none"
                ax.errorbar(xs, ys, yerr=np.vstack([lo, hi]), ms=4.5, capsize=2, lw=1.2,
                            label=label, **kw)
        ax.axhline(1.0, color="#333333", lw=1.2, ls="--", zorder=1)
        ax.set_xticks(range(len(ds)))
        ax.set_xticklabels([density_text(d) for d in ds])
        ax.set_xlim(-0.6, len(ds) - 0.4)
        ax.set_xlabel("obstacle density")
        ax.set_title(metric_title(name))
        ax.set_ylabel(f"ratio to {rep.baseline}")
        ax.grid(axis="x", visible=False)
        ratio_ticks(ax, allv)
    for ax in flat[len(names):]:
        fig.delaxes(ax)
    note = (f"Per map: planner / {rep.baseline},\nover maps where both succeeded\n"
            "(planning time: every map both ran).\nMarker: geometric mean;\nbar: 95% t-interval.\n"
            "Below 1: smaller than\nthe baseline.")
    finish(fig, rep, others, f"{rep.world_title(key)}: paired ratio to {rep.baseline} on the same "
           "maps, per density (the shape of paper 000 Table XII)",
           f"paired_{rep.world_file(key)}", saver, note=note, line=False)


def plot_success(plt, saver, rep):
    gens, sizes = rep.generators, rep.sizes
    present = [(gi, si) for gi, g in enumerate(gens) for si, (w, h) in enumerate(sizes)
               if rep.worlds.get((g, w, h))]
    fig, panels = panel_grid(plt, len(gens), len(sizes), present, 3.4, 3.0, sharey=True)
    lows = []
    for gi, si, ax, left, _ in panels:
        g, (w, h) = gens[gi], sizes[si]
        cells = rep.worlds[(g, w, h)]
        ax.set_title(f"{g} {w}\u00d7{h}")
        ds = sorted(cells)
        labels = rep.present(cells.values())
        for label in labels:
            xs, ys, los, his = [], [], [], []
            for d in ds:
                p = rep.planner(cells[d], label)
                if p is None or not p.get("runs"):
                    continue
                ci = p.get("success_ci95") or [None, None]
                xs.append(d); ys.append(100.0 * p["successes"] / p["runs"])
                los.append(nan_or(ci[0]) * 100); his.append(nan_or(ci[1]) * 100)
            if xs:
                draw_series(ax, rep, label, xs, ys, los, his, band=False,
                            dodge=dodge_of(labels, label, ds))
                lows += los
        density_axis(ax, ds)
        ax.set_xlabel("obstacle density")
        if left:
            ax.set_ylabel("success %")
    for _, _, ax, _, _ in panels:
        success_ylim(ax, lows)
    finish(fig, rep, rep.labels, "success rate vs obstacle density (bars: Wilson 95% interval)",
           "success", saver)


def plot_time(plt, saver, rep):
    if not rep.has_time() or not rep.wanted(TIME):
        return
    gens, ds = rep.generators, rep.densities
    present = [(gi, di) for gi, g in enumerate(gens) for di, d in enumerate(ds)
               if any(d in rep.worlds.get((g, w, h), {}) for (w, h) in rep.sizes)]
    if not present:
        return
    fig, panels = panel_grid(plt, len(gens), len(ds), present, 3.1, 3.0, extra_w=0.5,
                             sharex=True, sharey=True)
    xticks = [w * h for (w, h) in rep.sizes]
    allv = []
    for gi, di, ax, left, bottom in panels:
        g, d = gens[gi], ds[di]
        sep = "\n" if "/" in g else ", "  # a map file's name is long: its density below it
        ax.set_title(f"{g}{sep}density {density_text(d)}")
        for label in rep.labels:
            xs, ys, los, his = [], [], [], []
            for (w, h) in rep.sizes:
                cell = rep.worlds.get((g, w, h), {}).get(d)
                p = rep.planner(cell, label) if cell else None
                t = (p.get("timing") or {}).get(TIME) if p else None
                if not isinstance(t, dict) or not finite(t.get("median")):
                    continue
                xs.append(w * h); ys.append(t["median"] / 1e3)
                los.append(nan_or(t.get("p5")) / 1e3); his.append(nan_or(t.get("p95")) / 1e3)
            if xs:
                draw_series(ax, rep, label, xs, ys, los, his)
                allv += [v for v in ys + los + his if finite(v) and v > 0]
        ax.set_xscale("log")
        if bottom:  # its own tick labels: sharex shows them on the grid's last row only
            ax.set_xlabel("grid cells (w\u00d7h)")
            ax.xaxis.set_tick_params(labelbottom=True)
        if left:
            ax.set_ylabel("plan time (\u00b5s)")
    from matplotlib.ticker import FixedLocator, NullLocator
    size_names = [f"{w}\u00b2" if w == h else f"{w}\u00d7{h}" for (w, h) in rep.sizes]
    for _, _, ax, _, _ in panels:
        log_ticks_both_ends(ax, "y", allv)
        ax.xaxis.set_major_locator(FixedLocator(xticks))
        ax.xaxis.set_minor_locator(NullLocator())
        ax.set_xticklabels(size_names)
        lo, hi = min(xticks), max(xticks)
        pad = (hi / lo) ** 0.08 if hi > lo else 1.5
        ax.set_xlim(lo / pad, hi * pad)
    cpu = rep.doc.get("environment", {}).get("cpu_model", "unknown CPU") if isinstance(rep.doc.get("environment"), dict) else "unknown CPU"
    finish(fig, rep, rep.labels, "planning time vs grid size (log-log): median, band p5\u2013p95, "
           f"every run [{cpu}]", "plan_time", saver)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Plot an agvbench sweep report (schema_version 2); the files it writes "
                    "are listed below. The report alone gives every picture but the ECDF; the "
                    "distribution pictures (dist_*) then show the report's summaries (box "
                    "p5..p95, whiskers min..max). --runs gives true box / violin plots and the "
                    "ECDF of planning time.",
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("report", help="report JSON written by `agvbench run`")
    ap.add_argument("outdir", help="folder for the pictures and summary.md (created)")
    ap.add_argument("--runs", metavar="RUNS.jsonl",
                    help="the sweep's per-run journal (`run --runs-out`): needed for the ECDF, "
                         "true box plots and violins")
    ap.add_argument("--format", choices=FORMATS, default="png", help="picture format (default png)")
    ap.add_argument("--planners", action="append", metavar="A,B",
                    help="only these planners (labels; comma-separated or repeated)")
    ap.add_argument("--metrics", action="append", metavar="M,N",
                    help="only these metrics (report names, e.g. path_length, plan_time_ns)")
    ap.add_argument("--dist", choices=("box", "violin"), default="box",
                    help="distribution pictures as box plots (default) or violins (needs --runs)")
    ap.add_argument("--dpi", type=int, default=100, help="PNG resolution (default 100)")
    ap.add_argument("--small", action="store_true",
                    help="write palette PNGs (about a third of the size; for committed samples)")
    args = ap.parse_args(argv)
    if args.dpi <= 0:
        sys.stderr.write(f"plot.py: --dpi {args.dpi}: expected a positive number\n")
        return agvreport.BAD_INPUT
    if args.dist == "violin" and not args.runs:
        sys.stderr.write("plot.py: --dist violin needs --runs RUNS.jsonl (a violin is drawn from "
                         "every run; the report holds summaries only)\n")
        return agvreport.BAD_INPUT
    try:
        doc = agvreport.load_report(args.report)
        if not doc["cells"]:
            raise ReportError("the report has no cells (nothing was swept)")
    except ReportError as e:
        sys.stderr.write(f"plot.py: {args.report}: {e}\n")
        return agvreport.BAD_INPUT
    try:
        rep = Report(doc, split_list(args.planners), split_list(args.metrics))
    except ReportError as e:
        sys.stderr.write(f"plot.py: {e}\n")
        return agvreport.BAD_INPUT
    runs = None
    if args.runs:
        try:
            runs = agvruns.load_runs(args.runs, doc)
        except ReportError as e:
            sys.stderr.write(f"plot.py: {args.runs}: {e}\n")
            return agvreport.BAD_INPUT
    if doc.get("complete") is False:
        sys.stderr.write(f"plot.py: warning: {args.report} is an incomplete (interrupted) sweep\n")
    try:
        os.makedirs(args.outdir, exist_ok=True)
    except OSError as e:
        sys.stderr.write(f"plot.py: cannot create {args.outdir}: {e.strerror}\n")
        return 1
    plt = setup_matplotlib()
    import plot_dist
    import summary_md
    saver = Saver(plt, args.outdir, args.dpi, args.small, args.format)
    try:
        for key in rep.ordered_worlds():
            plot_metrics(plt, saver, rep, key)
        for key in rep.ordered_worlds():
            plot_dist.plot_distributions(plt, saver, rep, key, runs, args.dist)
        for key in rep.ordered_worlds():
            plot_paired(plt, saver, rep, key)
        plot_success(plt, saver, rep)
        plot_time(plt, saver, rep)
        if runs is not None:
            plot_dist.plot_ecdf(plt, saver, rep, runs)
        summary = summary_md.write_summary(rep, args.outdir, saver.written)
    except OSError as e:
        sys.stderr.write(f"plot.py: cannot write into {args.outdir}: {e.strerror}\n")
        return 1
    for name, problem in saver.problems:
        sys.stderr.write(f"plot.py: layout: {name}: {problem}\n")
    if runs is None:
        sys.stderr.write("plot.py: note: no --runs: ecdf_plan_time not drawn, dist_* drawn from "
                         "the report's summaries\n")
    for name in saver.written:
        print(os.path.join(args.outdir, name))
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
