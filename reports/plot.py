#!/usr/bin/python3
"""Pictures and a Markdown summary of an `agvbench run` report (reports/SCHEMA.md, version 1).

    /usr/bin/python3 reports/plot.py REPORT.json OUTDIR [--dpi N] [--small]

Writes into OUTDIR:
  metrics_<generator>_<WxH>.png  every metric's mean vs obstacle density, one panel per metric,
                                 one line per planner, 95% interval band of the mean (plus the
                                 success rate with its Wilson band)
  paired_<generator>_<WxH>.png   each planner / baseline on the same maps: geometric-mean ratio
                                 per density with its 95% interval and the 1.0 line (the shape of
                                 paper 000's Table XII), one panel per paired metric
  success.png                    success rate vs density (Wilson 95% band), panel per world
  plan_time.png                  planning time vs grid size, log-log, median with p5-p95 band
  summary.md                     the same numbers as tables, with links to the pictures

Exit codes: 0 done, 1 could not write / matplotlib missing, 2 bad or old-schema report.
Runs with Debian's /usr/bin/python3 and python3-matplotlib; no other third-party package.
"""

import argparse
import math
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import agvreport  # noqa: E402
from agvreport import ReportError, density_text, size_text  # noqa: E402

# Metric names -> (axis label, short title). Order = panel order.
METRIC_LABELS = {
    "path_length": ("cells", "path length"),
    "path_length_m": ("m", "path length (m)"),
    "optimality_ratio": ("length / optimum", "optimality ratio"),
    "waypoints": ("waypoints", "waypoints"),
    "max_turn_rad": ("rad", "largest turn"),
    "any_angle_ratio": ("ratio", "length / any-angle optimum"),
    "scen_ratio": ("ratio", "length / MovingAI scenario optimum"),
    "turns": ("turns", "turns"),
    "turn_angle_rad": ("rad", "turn angle sum"),
    "smoothness_mean": ("rad / cell", "mean curvature proxy"),
    "smoothness_max": ("rad / cell", "max curvature proxy"),
    "min_clearance": ("cells", "min clearance"),
    "min_clearance_m": ("m", "min clearance (m)"),
    "motion_time_s": ("s", "motion time (eq. 5.2e)"),
    "search_expansions": ("nodes", "search expansions"),
    "collision_checks": ("checks", "collision checks"),
}
PAIRED_ORDER = ["path_length", "motion_time_s", "waypoints", "turns", "turn_angle_rad",
                "collision_checks"]
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*", "<", ">", "h", "p"]
DASHES = ["-", "--", "-.", ":"]


def safe_name(text):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text).strip("_") or "x"


def finite(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def nan_or(v):
    return float(v) if finite(v) else float("nan")


class Report:
    """The report regrouped for plotting: worlds (generator, size) -> density -> cell."""

    def __init__(self, doc):
        self.doc = doc
        self.config = doc.get("config", {})
        self.labels = agvreport.planner_order(doc)
        self.baseline = agvreport.baseline_label(doc)
        self.worlds = {}  # (gen, w, h) -> {density: cell}
        for cell in doc["cells"]:
            key = (cell["generator"], int(cell["width"]), int(cell["height"]))
            self.worlds.setdefault(key, {})[float(cell["density"])] = cell
        self.generators = []
        self.sizes = []
        self.densities = sorted({d for cells in self.worlds.values() for d in cells})
        for (g, w, h) in self.worlds:
            if g not in self.generators:
                self.generators.append(g)
            if (w, h) not in self.sizes:
                self.sizes.append((w, h))
        self.sizes.sort(key=lambda s: (s[0] * s[1], s))
        edge = self.config.get("map", {}).get("cell_edge", 1.0) if isinstance(self.config.get("map"), dict) else 1.0
        self.cell_edge = edge if finite(edge) else 1.0
        nonbase = [l for l in self.labels if l != self.baseline]
        palette = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2",
                   "#17becf", "#bcbd22", "#7f7f7f", "#393b79", "#ad494a", "#e6550d", "#31a354",
                   "#756bb1", "#843c39", "#3182bd", "#8ca252", "#d6616b", "#636363"]
        self.colour = {}
        self.style = {}
        for i, label in enumerate(nonbase):
            self.colour[label] = palette[i % len(palette)]
            self.style[label] = (MARKERS[(i + 1) % len(MARKERS)], DASHES[(i // len(palette)) % len(DASHES)])
        if self.baseline is not None:
            self.colour[self.baseline] = "#000000"
            self.style[self.baseline] = (MARKERS[0], "-")

    def world_title(self, key):
        g, w, h = key
        return f"{g} {w}\u00d7{h}"

    def planner(self, cell, label):
        for p in cell["planners"]:
            if p["planner"] == label:
                return p
        return None

    def paired(self, cell, label):
        for c in cell["paired"]:
            if c["planner"] == label:
                return c
        return None

    def metric_names(self):
        seen = []
        for cells in self.worlds.values():
            for cell in cells.values():
                for p in cell["planners"]:
                    for name, s in p["metrics"].items():
                        if name not in seen and finite(s.get("mean")):
                            seen.append(name)
        known = [m for m in METRIC_LABELS if m in seen]
        if abs(self.cell_edge - 1.0) < 1e-12:  # metres = cells when the cell edge is 1 m
            known = [m for m in known if m not in ("path_length_m", "min_clearance_m")]
        extras = sorted(m for m in seen if m not in METRIC_LABELS)
        return known + extras

    def paired_names(self):
        seen = []
        for cells in self.worlds.values():
            for cell in cells.values():
                for c in cell["paired"]:
                    for name, comp in c["metrics"].items():
                        if name not in seen and finite(comp.get("geo_mean_ratio")):
                            seen.append(name)
        names = [m for m in PAIRED_ORDER if m in seen] + sorted(m for m in seen if m not in PAIRED_ORDER)
        for cells in self.worlds.values():
            for cell in cells.values():
                for c in cell["paired"]:
                    t = (c.get("timing") or {}).get("plan_time_ns")
                    if isinstance(t, dict) and finite(t.get("geo_mean_ratio")):
                        return names + ["plan_time_ns"]
        return names


# ---------------------------------------------------------------------------------------------
# Drawing


def setup_matplotlib():
    try:
        import matplotlib
    except ImportError:
        sys.stderr.write("plot.py: matplotlib is not importable by this interpreter "
                         f"({sys.executable}); run with /usr/bin/python3 after "
                         "`apt-get install python3-matplotlib`\n")
        sys.exit(1)
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    plt.rcParams.update({
        "font.size": 9, "axes.titlesize": 10, "axes.titleweight": "bold", "axes.labelsize": 9,
        "legend.fontsize": 9, "xtick.labelsize": 8, "ytick.labelsize": 8,
        "axes.grid": True, "grid.color": "#dddddd", "grid.linewidth": 0.6,
        "axes.spines.top": False, "axes.spines.right": False, "axes.axisbelow": True,
        "figure.facecolor": "white", "savefig.facecolor": "white",
    })
    return plt


class Saver:
    def __init__(self, plt, outdir, dpi, small):
        self.plt, self.outdir, self.dpi, self.small = plt, outdir, dpi, small
        self.written = []

    def save(self, fig, name):
        path = os.path.join(self.outdir, name)
        fig.savefig(path, dpi=self.dpi)
        self.plt.close(fig)
        if self.small:
            try:  # palette PNG: a third of the bytes, no visible loss on flat-colour charts
                from PIL import Image
                with Image.open(path) as im:
                    q = im.convert("RGB").quantize(colors=128, method=Image.Quantize.MEDIANCUT)
                q.save(path, optimize=True)
            except Exception:  # noqa: BLE001 - keep the full-colour PNG
                pass
        self.written.append(name)
        return path


def _log_if_spread(ax, values, ratio=30.0):
    vals = [v for v in values if finite(v) and v > 0]
    if vals and all(finite(v) and v > 0 for v in values if finite(v)) and max(vals) / min(vals) > ratio:
        ax.set_yscale("log")


def draw_series(ax, rep, label, xs, ys, los, his, band=True, dodge=0.0):
    """Mean line with its interval: a shaded band, or (band=False, or a single point) error bars
    shifted sideways by `dodge` so that planners with equal values stay visible."""
    import numpy as np
    marker, dash = rep.style[label]
    colour = rep.colour[label]
    x = np.array(xs, dtype=float) + (dodge if (len(xs) == 1 or not band) else 0.0)
    y = np.array([nan_or(v) for v in ys])
    lo = np.array([nan_or(v) for v in los])
    hi = np.array([nan_or(v) for v in his])
    lw = 1.8 if label == rep.baseline else 1.4
    if len(x) == 1 or not band:
        yerr = np.vstack([np.where(np.isfinite(lo), y - lo, 0), np.where(np.isfinite(hi), hi - y, 0)])
        yerr = np.maximum(np.nan_to_num(yerr, nan=0.0), 0.0)  # rounding can put p a hair outside
        ax.errorbar(x, y, yerr=yerr, color=colour, marker=marker, linestyle=dash, lw=lw, ms=4.5,
                    capsize=2.5, elinewidth=1.0, label=label)
        return
    ax.plot(x, y, color=colour, marker=marker, linestyle=dash, lw=lw, ms=4.5, label=label)
    ok = np.isfinite(lo) & np.isfinite(hi)
    if ok.any():
        ax.fill_between(x, np.where(ok, lo, y), np.where(ok, hi, y), where=ok, color=colour,
                        alpha=0.16, lw=0, interpolate=False)
    # A point with no finite neighbour gets no band: show its interval as an error bar.
    fin = np.isfinite(y)
    for i in range(len(x)):
        alone = fin[i] and not (i > 0 and fin[i - 1]) and not (i + 1 < len(x) and fin[i + 1])
        if alone and ok[i]:
            ax.errorbar([x[i]], [y[i]], yerr=[[max(0.0, y[i] - lo[i])], [max(0.0, hi[i] - y[i])]],
                        color=colour, capsize=2.5, elinewidth=1.0, lw=0)


def dodge_of(rep, labels, label, densities):
    """Sideways shift for error bars of planner `label` (a few % of the smallest density step)."""
    if label not in labels:
        return 0.0
    steps = [b - a for a, b in zip(densities, densities[1:]) if b > a]
    step = min(steps) if steps else 0.1
    k, n = labels.index(label), len(labels)
    return (k - (n - 1) / 2.0) * min(0.06, 0.25 / max(1, n)) * step


def density_axis(ax, densities):
    ax.set_xticks(densities)
    ax.set_xticklabels([density_text(d) for d in densities])
    if len(densities) > 1:
        span = densities[-1] - densities[0]
        ax.set_xlim(densities[0] - 0.08 * span, densities[-1] + 0.08 * span)
    elif densities:
        ax.set_xlim(densities[0] - 0.05, densities[0] + 0.05)


def figure_legend(fig, ax_or_fig, rep, labels, loc="upper center", ncol=None, anchor=None):
    from matplotlib.lines import Line2D
    handles = []
    for l in labels:
        marker, dash = rep.style[l]
        name = f"{l} (baseline)" if l == rep.baseline else l
        handles.append(Line2D([0], [0], color=rep.colour[l], marker=marker, linestyle=dash, lw=1.6, label=name))
    kw = {"frameon": False}
    if anchor is not None:
        kw["bbox_to_anchor"] = anchor
    ax_or_fig.legend(handles=handles, loc=loc, ncol=ncol or min(len(handles), 6), **kw)


LEGEND_ENTRY_IN = 2.2   # width of one legend entry (handle + the longest planner labels), inches
LEGEND_ROW_IN = 0.24    # height of one legend row at legend.fontsize 9
TITLE_IN = 0.45         # the suptitle's band


def top_legend(fig, rep, labels):
    """A legend above the panels, wrapped to the figure's width in as many rows as the labels
    need; grows the figure by the legend's height and returns the top of the panels' area (a
    figure fraction) for tight_layout."""
    ncol = max(1, min(len(labels), int(fig.get_figwidth() // LEGEND_ENTRY_IN)))
    legend_in = LEGEND_ROW_IN * math.ceil(len(labels) / ncol) + 0.1
    fig.set_figheight(fig.get_figheight() + legend_in)
    height = fig.get_figheight()
    figure_legend(fig, fig, rep, labels, loc="upper center", ncol=ncol,
                  anchor=(0.5, 1.0 - TITLE_IN / height))
    return 1.0 - (TITLE_IN + legend_in) / height


def plot_metrics(plt, saver, rep, key):
    cells = rep.worlds[key]
    ds = sorted(cells)
    metrics = rep.metric_names()
    panels = ["success_rate"] + metrics
    ncol = 4
    labels_present = [l for l in rep.labels if any(rep.planner(c, l) for c in cells.values())]
    # The legend takes a spare panel when there is one and one column of it fits there; else
    # it goes on top.
    spare_slot = len(panels) % ncol != 0 and len(labels_present) * LEGEND_ROW_IN <= 2.4
    nrow = math.ceil(len(panels) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.5 * ncol, 2.6 * nrow + (0.9 if spare_slot else 0.6)),
                             squeeze=False)
    flat = [a for row in axes for a in row]
    for ax, name in zip(flat, panels):
        allv = []
        for label in labels_present:
            xs, ys, los, his = [], [], [], []
            for d in ds:
                p = rep.planner(cells[d], label)
                if p is None:
                    continue
                if name == "success_rate":
                    runs = p.get("runs") or 0
                    v = p.get("success_rate")
                    if not finite(v) and runs:
                        v = p["successes"] / runs
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
                                dodge=dodge_of(rep, labels_present, label, ds))
                    allv += [v for v in los if finite(v)]
                else:
                    draw_series(ax, rep, label, xs, ys, los, his)
                allv += [v for v in ys if finite(v)]
        if name == "success_rate":
            ax.set_title("success rate")
            ax.set_ylabel("% of runs (bar: Wilson 95%)")
            lo = min(allv) if allv else 100
            ax.set_ylim(max(0, math.floor((lo - 3) / 10) * 10), 101.5)
        else:
            unit, title = METRIC_LABELS.get(name, ("", name.replace("_", " ")))
            ax.set_title(title)
            ax.set_ylabel(unit)
            _log_if_spread(ax, allv)
        density_axis(ax, ds)
        ax.set_xlabel("obstacle density")
    for ax in flat[len(panels):]:
        ax.axis("off")
    top = 0.96
    if spare_slot:
        figure_legend(fig, flat[len(panels)], rep, labels_present, loc="center", ncol=1)
    else:
        top = top_legend(fig, rep, labels_present)
    maps = max((c.get("maps", 0) for c in cells.values()), default=0)
    fig.suptitle(f"{rep.world_title(key)}: mean per metric vs obstacle density "
                 f"(successful runs; band = 95% CI of the mean; {maps} maps per density)",
                 fontsize=11, fontweight="bold")
    fig.tight_layout(rect=(0, 0, 1, top))
    g, w, h = key
    saver.save(fig, f"metrics_{safe_name(g)}_{w}x{h}.png")


RATIO_LADDER = [0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8,
                0.9, 1.0, 1.25, 1.5, 2.0, 3.0, 4.0, 5.0, 7.0, 10.0, 20.0, 50.0, 100.0, 200.0,
                500.0, 1000.0]


def _pct(v):
    p = (v - 1.0) * 100.0
    if abs(p) < 0.05:
        return "\u00b10%"
    return f"{p:+.0f}%" if abs(p) >= 10 or abs(p - round(p)) < 0.05 else f"{p:+.1f}%"


def _ratio_ticks(ax, values):
    """Ratio axis: log scale when the spread is large; tick labels carry the % change."""
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter, NullLocator
    vals = [v for v in values if finite(v) and v > 0] + [1.0]
    lo, hi = min(vals), max(vals)
    if hi / lo > 2.5:
        ax.set_yscale("log")
        ax.set_ylim(lo / 1.15, hi * 1.15)
        ticks = [t for t in RATIO_LADDER if lo / 1.15 <= t <= hi * 1.15]
        while len(ticks) > 7:  # thin out, keeping 1
            i1 = ticks.index(1.0) if 1.0 in ticks else 0
            ticks = [t for i, t in enumerate(ticks) if (i - i1) % 2 == 0]
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
    ncol = 4 if len(names) > 3 else len(names) + 1
    nrow = math.ceil((len(names) + 1) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.6 * ncol, 2.8 * nrow + 1.0), squeeze=False)
    flat = [a for row in axes for a in row]
    width = 0.7
    step = width / max(1, len(others))
    for ax, name in zip(flat, names):
        allv = []
        for k, label in enumerate(others):
            xs, ys, lo, hi = [], [], [], []
            for i, d in enumerate(ds):
                c = rep.paired(cells[d], label)
                if c is None:
                    continue
                comp = (c.get("timing") or {}).get("plan_time_ns") if name == "plan_time_ns" else c["metrics"].get(name)
                if not isinstance(comp, dict) or not finite(comp.get("geo_mean_ratio")):
                    continue
                r = comp["geo_mean_ratio"]
                ci = comp.get("ci95") or [None, None]
                xs.append(i - width / 2 + step * (k + 0.5))
                ys.append(r)
                lo.append(max(0.0, r - ci[0]) if finite(ci[0]) else 0.0)
                hi.append(max(0.0, ci[1] - r) if finite(ci[1]) else 0.0)
                allv += [r, ci[0] if finite(ci[0]) else r, ci[1] if finite(ci[1]) else r]
            if xs:
                marker, _ = rep.style[label]
                ax.errorbar(xs, ys, yerr=np.vstack([lo, hi]), fmt=marker, color=rep.colour[label],
                            ms=5, capsize=3, lw=1.3, label=label)
        ax.axhline(1.0, color="#333333", lw=1.2, ls="--", zorder=1)
        ax.set_xticks(range(len(ds)))
        ax.set_xticklabels([density_text(d) for d in ds])
        ax.set_xlim(-0.6, len(ds) - 0.4)
        ax.set_xlabel("obstacle density")
        title = "planning time" if name == "plan_time_ns" else METRIC_LABELS.get(name, ("", name))[1]
        ax.set_title(title)
        ax.set_ylabel(f"ratio to {rep.baseline}")
        ax.grid(axis="x", visible=False)
        _ratio_ticks(ax, allv)
    for ax in flat[len(names):]:
        ax.axis("off")
    spare = flat[len(names)]
    figure_legend(fig, spare, rep, others, loc="upper center", ncol=1)
    spare.text(0.5, 0.02,
               f"Per map: planner / {rep.baseline},\nover maps where both succeeded.\n"
               "Marker: geometric mean;\nbar: 95% t-interval.\n"
               "Below 1: smaller (better)\nthan the baseline.",
               ha="center", va="bottom", fontsize=8.5, color="#444444", transform=spare.transAxes)
    fig.suptitle(f"{rep.world_title(key)}: paired ratio to {rep.baseline} on the same maps, "
                 "per density (the shape of paper 000 Table XII)", fontsize=11, fontweight="bold")
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    g, w, h = key
    saver.save(fig, f"paired_{safe_name(g)}_{w}x{h}.png")


def plot_success(plt, saver, rep):
    gens, sizes = rep.generators, rep.sizes
    fig, axes = plt.subplots(len(gens), len(sizes), figsize=(3.3 * len(sizes) + 0.4, 2.5 * len(gens) + 0.5),
                             squeeze=False, sharey=True)
    ymin = 100.0
    for gi, g in enumerate(gens):
        for si, (w, h) in enumerate(sizes):
            ax = axes[gi][si]
            cells = rep.worlds.get((g, w, h))
            ax.set_title(f"{g} {w}\u00d7{h}")
            if not cells:
                ax.axis("off")
                continue
            ds = sorted(cells)
            for label in rep.labels:
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
                                dodge=dodge_of(rep, rep.labels, label, ds))
                    ymin = min([ymin] + [v for v in los if finite(v)])
            density_axis(ax, ds)
            if gi == len(gens) - 1:
                ax.set_xlabel("obstacle density")
            if si == 0:
                ax.set_ylabel("success %")
    for row in axes:
        for ax in row:
            ax.set_ylim(max(0, math.floor((ymin - 3) / 10) * 10), 101.5)
    top = top_legend(fig, rep, rep.labels)
    fig.suptitle("success rate vs obstacle density (bars: Wilson 95% interval)",
                 fontsize=11, fontweight="bold")
    fig.tight_layout(rect=(0, 0, 1, top))
    saver.save(fig, "success.png")


def plot_time(plt, saver, rep):
    have = any(isinstance((p.get("timing") or {}).get("plan_time_ns"), dict)
               for cells in rep.worlds.values() for c in cells.values() for p in c["planners"])
    if not have:
        return
    gens, ds = rep.generators, rep.densities
    fig, axes = plt.subplots(len(gens), len(ds), figsize=(3.0 * len(ds) + 0.5, 2.6 * len(gens) + 0.5),
                             squeeze=False, sharex=True, sharey=True)
    xticks = [w * h for (w, h) in rep.sizes]
    for gi, g in enumerate(gens):
        for di, d in enumerate(ds):
            ax = axes[gi][di]
            ax.set_title(f"{g}, density {density_text(d)}")
            for label in rep.labels:
                xs, ys, los, his = [], [], [], []
                for (w, h) in rep.sizes:
                    cell = rep.worlds.get((g, w, h), {}).get(d)
                    p = rep.planner(cell, label) if cell else None
                    t = (p.get("timing") or {}).get("plan_time_ns") if p else None
                    if not isinstance(t, dict) or not finite(t.get("median")):
                        continue
                    xs.append(w * h); ys.append(t["median"] / 1e3)
                    los.append(nan_or(t.get("p5")) / 1e3); his.append(nan_or(t.get("p95")) / 1e3)
                if xs:
                    draw_series(ax, rep, label, xs, ys, los, his)
            ax.set_xscale("log")
            ax.set_yscale("log")
            if gi == len(gens) - 1:
                ax.set_xlabel("grid cells (w\u00d7h)")
            if di == 0:
                ax.set_ylabel("plan time (\u00b5s)")
    from matplotlib.ticker import FixedLocator, NullLocator
    for row in axes:
        for ax in row:
            ax.xaxis.set_major_locator(FixedLocator(xticks))
            ax.xaxis.set_minor_locator(NullLocator())
            ax.set_xticklabels([f"{w}\u00b2" if w == h else f"{w}\u00d7{h}" for (w, h) in rep.sizes])
    top = top_legend(fig, rep, rep.labels)
    fig.suptitle("planning time vs grid size (log-log): median, band p5\u2013p95 "
                 f"[{rep.doc.get('environment', {}).get('cpu_model', 'unknown CPU')}]",
                 fontsize=11, fontweight="bold")
    fig.tight_layout(rect=(0, 0, 1, top))
    saver.save(fig, "plan_time.png")


# ---------------------------------------------------------------------------------------------
# Markdown summary


def fmt(v, digits=3):
    """Fixed decimals by magnitude, so a column reads evenly (28.14, 6.830, 0.896, 502.0)."""
    if not finite(v):
        return "\u2013"
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


def fmt_ci(s, digits=3):
    if not isinstance(s, dict):
        return "\u2013"
    ci = s.get("ci95") or [None, None]
    text = fmt(s.get("mean"), digits)
    if finite(ci[0]) and finite(ci[1]):
        text += f" [{fmt(ci[0], digits)}, {fmt(ci[1], digits)}]"
    return text


def fmt_ratio(comp):
    if not isinstance(comp, dict) or not finite(comp.get("geo_mean_ratio")):
        return "\u2013"
    r = comp["geo_mean_ratio"]
    ci = comp.get("ci95") or [None, None]
    text = f"{r:.3f}"
    if finite(ci[0]) and finite(ci[1]):
        text += f" [{ci[0]:.3f}, {ci[1]:.3f}]"
    return text + f" ({(r - 1) * 100:+.1f}%, n={comp.get('pairs', 0)})"


def write_summary(rep, outdir, pictures):
    doc, cfg = rep.doc, rep.config
    env = doc.get("environment", {}) if isinstance(doc.get("environment"), dict) else {}
    timing = doc.get("timing", {}) if isinstance(doc.get("timing"), dict) else {}
    totals = doc.get("totals", {}) if isinstance(doc.get("totals"), dict) else {}
    out = []
    out.append(f"# Sweep summary: {cfg.get('name', '(unnamed)')}\n")
    if doc.get("complete") is False:
        out.append("> **Incomplete report**: the sweep was interrupted; cells hold fewer runs "
                   "than configured.\n")
    out.append(f"- seed {cfg.get('seed', '?')}, {cfg.get('maps_per_cell', '?')} maps per cell, "
               f"{totals.get('cells', len(doc['cells']))} cells, {totals.get('maps', '?')} maps, "
               f"{totals.get('runs', '?')} runs")
    out.append(f"- planners: {', '.join(rep.labels)}; baseline `{rep.baseline}`")
    if env:
        out.append(f"- machine: {env.get('cpu_model', '?')}, {env.get('threads', '?')} threads; "
                   f"build {env.get('build', '?')}, {env.get('compiler', '?')}, revision "
                   f"{env.get('git_revision', '?')}")
    if finite(timing.get("wall_s")):
        out.append(f"- wall time {timing['wall_s']:.2f} s ({fmt(timing.get('runs_per_s'))} runs/s)")
    out.append("")
    out.append("Means over successful runs with 95% t-intervals; success with its Wilson interval; "
               "plan time median (p5\u2013p95). Paired columns: geometric mean of planner / "
               f"`{rep.baseline}` on the maps where both succeeded, 95% interval, % change, pairs.\n")
    if pictures:
        out.append("Pictures: " + ", ".join(f"[{p}]({p})" for p in pictures) + "\n")
    cols = [m for m in ["path_length", "optimality_ratio", "any_angle_ratio", "waypoints", "turns",
                        "turn_angle_rad", "min_clearance", "collision_checks"] if m in rep.metric_names()]
    for key in sorted(rep.worlds, key=lambda k: (rep.generators.index(k[0]), k[1] * k[2])):
        cells = rep.worlds[key]
        out.append(f"## {rep.world_title(key)}\n")
        head = ["density", "planner", "success"] + [METRIC_LABELS[m][1] for m in cols] + ["plan time \u00b5s"]
        out.append("| " + " | ".join(head) + " |")
        out.append("|" + "---|" * len(head))
        for d in sorted(cells):
            cell = cells[d]
            for label in rep.labels:
                p = rep.planner(cell, label)
                if p is None:
                    continue
                ci = p.get("success_ci95") or [None, None]
                runs = p.get("runs") or 0
                rate = p["successes"] / runs if runs else float("nan")
                succ = f"{rate * 100:.1f}%" if finite(rate) else "\u2013"
                if finite(ci[0]) and finite(ci[1]):
                    succ += f" [{ci[0] * 100:.1f}, {ci[1] * 100:.1f}]"
                fails = p.get("failures") or {}
                if fails:
                    succ += " (" + ", ".join(f"{k} {v}" for k, v in fails.items()) + ")"
                row = [density_text(d), f"`{label}`", succ]
                row += [fmt_ci(p["metrics"].get(m)) for m in cols]
                t = (p.get("timing") or {}).get("plan_time_ns")
                if isinstance(t, dict) and finite(t.get("median")):
                    row.append(f"{t['median'] / 1e3:.3g} ({nan_or(t.get('p5')) / 1e3:.3g}\u2013"
                               f"{nan_or(t.get('p95')) / 1e3:.3g})")
                else:
                    row.append("\u2013")
                out.append("| " + " | ".join(row) + " |")
        out.append("")
        names = rep.paired_names()
        others = [l for l in rep.labels if l != rep.baseline]
        if names and others:
            out.append(f"Paired against `{rep.baseline}`:\n")
            head = ["density", "planner"] + [("plan time" if n == "plan_time_ns" else METRIC_LABELS.get(n, ("", n))[1])
                                             for n in names]
            out.append("| " + " | ".join(head) + " |")
            out.append("|" + "---|" * len(head))
            for d in sorted(cells):
                for label in others:
                    c = rep.paired(cells[d], label)
                    if c is None:
                        continue
                    row = [density_text(d), f"`{label}`"]
                    for n in names:
                        comp = (c.get("timing") or {}).get("plan_time_ns") if n == "plan_time_ns" else c["metrics"].get(n)
                        row.append(fmt_ratio(comp))
                    out.append("| " + " | ".join(row) + " |")
            out.append("")
    path = os.path.join(outdir, "summary.md")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out).rstrip() + "\n")
    return path


def main(argv=None):
    ap = argparse.ArgumentParser(description="Plot an agvbench sweep report (schema_version 2).")
    ap.add_argument("report", help="report JSON written by `agvbench run`")
    ap.add_argument("outdir", help="folder for the PNGs and summary.md (created)")
    ap.add_argument("--dpi", type=int, default=100, help="PNG resolution (default 100)")
    ap.add_argument("--small", action="store_true",
                    help="write palette PNGs (about a third of the size; for committed samples)")
    args = ap.parse_args(argv)
    try:
        doc = agvreport.load_report(args.report)
        if not doc["cells"]:
            raise ReportError("the report has no cells (nothing was swept)")
        rep = Report(doc)
    except ReportError as e:
        sys.stderr.write(f"plot.py: {args.report}: {e}\n")
        return agvreport.BAD_INPUT
    if doc.get("complete") is False:
        sys.stderr.write(f"plot.py: warning: {args.report} is an incomplete (interrupted) sweep\n")
    try:
        os.makedirs(args.outdir, exist_ok=True)
    except OSError as e:
        sys.stderr.write(f"plot.py: cannot create {args.outdir}: {e.strerror}\n")
        return 1
    plt = setup_matplotlib()
    saver = Saver(plt, args.outdir, args.dpi, args.small)
    worlds = sorted(rep.worlds, key=lambda k: (rep.generators.index(k[0]), k[1] * k[2]))
    for key in worlds:
        plot_metrics(plt, saver, rep, key)
    for key in worlds:
        plot_paired(plt, saver, rep, key)
    plot_success(plt, saver, rep)
    plot_time(plt, saver, rep)
    summary = write_summary(rep, args.outdir, saver.written)
    for name in saver.written:
        print(os.path.join(args.outdir, name))
    print(summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())
