"""Distribution pictures of plot.py: box or violin plots per planner for each metric
(dist_<world>.FMT) and the ECDF of planning time (ecdf_plan_time.FMT).

What each needs: the ECDF and the violins are drawn from every run, so they need the journal
(--runs); box plots are true box plots (quartiles, 1.5 IQR whiskers, outliers) with the journal
and, from the report alone, boxes of the summaries it holds (p5..p95, median, whiskers min..max,
mean). Metrics are over successful runs, planning time over every run (reports/SCHEMA.md).
"""

import math

from agvreports.figures import finish
from agvreports.grouping import density_text
from agvreports.layout import panel_grid
from agvreports.log_axes import log_ladder_ticks, log_ticks_both_ends
from agvreports.metrics import TIME, metric_title, metric_unit, scale_of
from agvreports.numeric import finite, nan_or

BOX_GROUP = 0.8  # share of a density's slot the planners' boxes take


def _box_from_summary(s, scale):
    keys = ("median", "p5", "p95", "min", "max")
    if not isinstance(s, dict) or not all(finite(s.get(k)) for k in keys):
        return None
    return {"med": s["median"] * scale, "q1": s["p5"] * scale, "q3": s["p95"] * scale,
            "whislo": s["min"] * scale, "whishi": s["max"] * scale,
            "mean": nan_or(s.get("mean")) * scale, "fliers": []}


def _box_from_values(values):
    from matplotlib import cbook
    if not values:
        return None
    return cbook.boxplot_stats(values, whis=1.5)[0]


def _panel_data(rep, key, name, runs, labels):
    """[(density index, planner index, label, box stats or None, values or None)]."""
    cells = rep.worlds[key]
    out = []
    scale = scale_of(name)
    for i, d in enumerate(sorted(cells)):
        cell = cells[d]
        for k, label in enumerate(labels):
            p = rep.planner(cell, label)
            if p is None:
                continue
            if runs is not None:
                vals = [v * scale for v in runs.values(rep.cell_key(cell), label, name)]
                out.append((i, k, label, _box_from_values(vals), vals))
            else:
                out.append((i, k, label, _box_from_summary(rep.summary_of(p, name), scale), None))
    return out


def _draw_violin(ax, pos, width, vals, colour, logged):
    import numpy as np
    data = np.log10(vals) if logged else np.asarray(vals, dtype=float)
    if len(data) < 2 or np.ptp(data) <= 1e-12 * max(1.0, abs(float(np.mean(data)))):
        ax.plot([pos - width / 2, pos + width / 2], [data[0]] * 2, color=colour, lw=2)
        return float(np.median(data))
    parts = ax.violinplot([data], positions=[pos], widths=width, showextrema=False)
    for body in parts["bodies"]:
        body.set_facecolor(colour)
        body.set_edgecolor(colour)
        body.set_alpha(0.45)
    q1, med, q3 = np.percentile(data, [25, 50, 75])
    ax.plot([pos, pos], [q1, q3], color=colour, lw=2.2, solid_capstyle="butt")
    return float(med)


def plot_distributions(plt, saver, rep, key, runs, kind="box"):
    cells = rep.worlds[key]
    ds = sorted(cells)
    labels = rep.present(cells.values())
    names = rep.metrics_with_time()
    if not labels or not names:
        return
    n = len(labels)
    slot = BOX_GROUP / n
    panel_w = max(3.6, 0.16 * n * len(ds) + 1.2)
    ncol = max(1, min(4, len(names), int(15.0 // panel_w)))
    nrow = math.ceil(len(names) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(panel_w * ncol, 2.8 * nrow + 0.5), squeeze=False)
    flat = [a for row in axes for a in row]
    for ax, name in zip(flat, names):
        data = _panel_data(rep, key, name, runs, labels)
        allv = []
        for (_, _, _, st, vals) in data:
            if vals:
                allv += vals
            elif st:
                allv += [st["whislo"], st["whishi"]]
        pos_vals = [v for v in allv if finite(v)]
        # Log scale when the boxes' whiskers (not a few outliers) span more than 30x.
        spans = [v for (_, _, _, st, _) in data if st for v in (st["whislo"], st["whishi"]) if finite(v)]
        logged = bool(pos_vals) and min(pos_vals) > 0 and bool(spans) and min(spans) > 0 \
            and max(spans) / min(spans) > 30
        for (i, k, label, st, vals) in data:
            if st is None:
                continue
            kw = rep.style.line_kw(label)
            colour = kw["color"]
            pos = i - BOX_GROUP / 2 + slot * (k + 0.5)
            if kind == "violin" and vals:
                med = _draw_violin(ax, pos, slot * 0.9, vals, colour, logged)
                mark_y = med
            else:
                bp = ax.bxp([st], positions=[pos], widths=slot * 0.75, showmeans=False,
                            showfliers=True, patch_artist=True, manage_ticks=False)
                for b in bp["boxes"]:
                    b.set_facecolor(colour); b.set_alpha(0.35); b.set_edgecolor(colour)
                for part in ("whiskers", "caps"):
                    for l in bp[part]:
                        l.set_color(colour); l.set_linewidth(1.0)
                for l in bp["medians"]:
                    l.set_color(colour); l.set_linewidth(1.8)
                for f in bp["fliers"]:
                    f.set_marker("."); f.set_markersize(2.5); f.set_markeredgecolor(colour)
                    f.set_alpha(0.6)
                mark_y = st["mean"]
            if finite(mark_y):  # the planner's own marker: at the mean (box) or median (violin)
                ax.plot([pos], [mark_y], ms=4.5, zorder=4, **{**kw, "linestyle": "none"})
        ax.set_xticks(range(len(ds)))
        ax.set_xticklabels([density_text(d) for d in ds])
        ax.set_xlim(-0.55, len(ds) - 0.45)
        for i in range(1, len(ds)):
            ax.axvline(i - 0.5, color="#cccccc", lw=0.8, zorder=0)
        ax.grid(axis="x", visible=False)
        ax.set_xlabel("obstacle density")
        ax.set_title(metric_title(name))
        ax.set_ylabel(metric_unit(name))
        if logged:
            if kind == "violin" and runs is not None:
                a, b, ticks = log_ladder_ticks(min(pos_vals), max(pos_vals))
                ax.set_ylim(math.log10(a), math.log10(b))
                ax.set_yticks([math.log10(t) for t in ticks])
                ax.set_yticklabels([f"{t:g}" for t in ticks])
                ax.set_ylabel(f"{metric_unit(name)} (log scale)")
            else:
                log_ticks_both_ends(ax, "y", pos_vals)
    for ax in flat[len(names):]:
        fig.delaxes(ax)
    if runs is not None and kind == "violin":
        how = "violins of every run (bar: quartiles; marker: median)"
    elif runs is not None:
        how = "box: quartiles, whiskers 1.5 IQR, dots beyond; marker: mean"
    else:
        how = "from the report's summaries: box p5\u2013p95, line median, whiskers min\u2013max; marker: mean"
    finish(fig, rep, labels, f"{rep.world_title(key)}: distribution per planner and density ({how})",
           f"dist_{rep.world_file(key)}", saver,
           note="Metrics: successful runs.\nPlanning time: every run,\nfailures included (\u00b5s).",
           line=False)


def plot_ecdf(plt, saver, rep, runs):
    """ECDF of planning time per planner, one panel per world, all its densities pooled."""
    import numpy as np
    if not rep.wanted(TIME):
        return
    gens, sizes = rep.generators, rep.sizes
    fig, panels = panel_grid(plt, len(gens), len(sizes), rep.world_grid(), 3.6, 3.0, sharey=True)
    drawn = []
    for gi, si, ax, left, _ in panels:
        g, (w, h) = gens[gi], sizes[si]
        cells = rep.worlds[(g, w, h)]
        ax.set_title(f"{g} {w}\u00d7{h}")
        allv = []
        for label in rep.present(cells.values()):
            vals = []
            for cell in cells.values():
                vals += runs.values(rep.cell_key(cell), label, TIME)
            if not vals:
                continue
            x = np.sort(np.asarray(vals) / 1e3)
            y = np.arange(1, len(x) + 1) / len(x)
            kw = rep.style.line_kw(label)
            ax.step(x, y, where="post", color=kw["color"], linestyle=kw["linestyle"], lw=1.3)
            med = x[(len(x) - 1) // 2]
            ax.plot([med], [0.5], ms=5, zorder=4, **{**kw, "linestyle": "none"})
            allv += [float(v) for v in x if v > 0]
            if label not in drawn:
                drawn.append(label)
        if allv:
            log_ticks_both_ends(ax, "x", allv)
        ax.set_ylim(0, 1.02)
        ax.set_xlabel("plan time (\u00b5s, log scale)")
        if left:
            ax.set_ylabel("share of runs \u2264 x")
    if not drawn:
        plt.close(fig)
        return
    finish(fig, rep, [l for l in rep.labels if l in drawn], "ECDF of planning time per planner "
           "(every run, failures included; the world's densities pooled; marker at the median)",
           "ecdf_plan_time", saver)
