"""The paired pictures of plot.py (paired_*, the shape of paper 000's Table XII): each planner /
baseline on the same maps, geometric mean per density with its 95% interval, on a ratio axis
whose tick labels carry the % change.
"""

import math

from agvreports.figures import finish
from agvreports.grouping import density_text
from agvreports.log_axes import spaced_ticks
from agvreports.metrics import metric_title
from agvreports.numeric import finite


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
    others = rep.paired_planners(cells)
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
