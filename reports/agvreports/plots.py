"""The pictures of plot.py drawn from the report's means: every metric vs obstacle density per
world (metrics_*), the success rate per world (success) and planning time vs grid size
(plan_time), with the series drawing they share (a line with its interval band, or error bars
shifted sideways so that equal values stay visible).
"""

import math

from agvreports.figures import finish
from agvreports.grouping import density_text
from agvreports.layout import panel_grid
from agvreports.log_axes import log_ticks_both_ends
from agvreports.metrics import METRIC_LABELS, TIME
from agvreports.numeric import finite, nan_or


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


def plot_success(plt, saver, rep):
    gens, sizes = rep.generators, rep.sizes
    fig, panels = panel_grid(plt, len(gens), len(sizes), rep.world_grid(), 3.4, 3.0, sharey=True)
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
