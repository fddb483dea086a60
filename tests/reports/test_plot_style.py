#!/usr/bin/python3
"""Checks of the pictures' style and layout (reports/agvreports: style, log_axes, layout; run by
tests/reports/test_plot.sh):
  - the palette: the first 24 planners differ in colour and in marker, no two of 120 alike;
  - log axes: limits on labelled ticks just outside the data, on many random ranges, and the
    paired plots' ratio ticks never closer than their spacing;
  - the layout check finds a legend over a panel and a note over a legend (so its silence on
    the real pictures means something), and finds nothing on a side legend;
  - every planner of a 24-planner report in the legend of each picture plot.py draws.

    /usr/bin/python3 tests/reports/test_plot_style.py REPO_ROOT MANY_REPORT.json
"""

import math
import os
import random
import sys

sys.dont_write_bytecode = True
root = sys.argv[1]
sys.path.append(os.path.join(root, "reports"))
from agvreports import figures, layout, log_axes, paired, plots, style  # noqa: E402

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL", what)


# Palette.
labels = ["base"] + [f"p{i}" for i in range(1, 121)]
st = style.Style(labels, "base")
first = labels[1:25]
check(len({st.colour[l] for l in first}) == 24, "24 planners: 24 colours")
check(len({(st.marker[l], st.fill[l]) for l in labels[:30]}) == 30, "30 planners: 30 markers")
check(len({(st.colour[l], st.marker[l], st.fill[l]) for l in labels}) == len(labels),
      "120 planners: no two alike")
check(all(st.colour[l] != st.colour["base"] for l in labels[1:]), "only the baseline is black")

# Log ticks at both ends.
rng = random.Random(7)
for _ in range(2000):
    lo = 10 ** rng.uniform(-4, 6)
    hi = lo * 10 ** rng.uniform(0.01, 7)
    a, b, ticks = log_axes.log_ladder_ticks(lo, hi)
    ok = a <= lo * (1 + 1e-9) and b >= hi * (1 - 1e-9) and ticks[0] == a and ticks[-1] == b \
        and len(ticks) <= 9 and b / a <= hi / lo * 25
    if not ok:
        check(False, f"log ticks for [{lo:g}, {hi:g}]: {a:g} {b:g} {ticks}")
        break
for _ in range(500):
    lo = 10 ** rng.uniform(-2.5, 0)
    hi = 10 ** rng.uniform(0, 3)
    a = max([t for t in paired.RATIO_LADDER if t <= lo] or [lo])
    b = min([t for t in paired.RATIO_LADDER if t >= hi] or [hi])
    ticks = log_axes.spaced_ticks([t for t in paired.RATIO_LADDER if a <= t <= b], a, b, keep=1.0)
    gap = math.log(b / a) / 7
    close = [(x, y) for x, y in zip(ticks, ticks[1:]) if math.log(y / x) < gap * 0.999
             and not (1.0 in (x, y))]
    if a not in ticks or b not in ticks or close:
        check(False, f"ratio ticks [{a}, {b}]: {ticks}")
        break

# The layout check.
plt = figures.setup_matplotlib("test_plot_style.py")
fig, axes = plt.subplots(1, 2, figsize=(6, 3))
for ax in axes:
    ax.plot([0, 1], [0, 1], label="x")
fig.legend(handles=[st.handle("p1")], loc="center")  # over the panels
check(any("legend overlaps panel" in p for p in layout.layout_problems(fig)),
      "a legend over a panel is found")
plt.close(fig)
fig, axes = plt.subplots(1, 2, figsize=(6, 3))
fig.tight_layout()
leg = layout.side_legend(fig, st, labels[:25])
fig.text(0.99, 0.9, "a note over the legend")
probs = layout.layout_problems(fig)
check(any("legend overlaps note" in p for p in probs), f"a note over the legend is found ({probs})")
plt.close(fig)
fig, axes = plt.subplots(2, 2, figsize=(6, 5))
for ax in axes.flat:
    log_axes.log_ticks_both_ends(ax, "y", [0.37, 913.0])
    ax.plot([0, 1], [0.37, 913.0])
fig.tight_layout()
leg = layout.side_legend(fig, st, labels[:25])
layout.note_below_legend(fig, leg, "a note\nunder the legend")
probs = layout.layout_problems(fig)
check(not probs, f"side legend and note: {probs}")
check(len(layout.legend_entries(fig)) == 25, "25 legend entries")
lo, hi = axes[0][0].get_ylim()
ticks = axes[0][0].get_yticks()
check(abs(lo - 0.2) < 1e-12 and abs(hi - 1000) < 1e-9 and ticks[0] == lo and ticks[-1] == hi,
      f"log axis [0.37, 913] labelled 0.2..1000, got {lo} {hi} {list(ticks)}")
plt.close(fig)

# Every planner in each legend of the real pictures (a saver that only records).
if len(sys.argv) > 2:
    from agvreports import dist, report_io
    from agvreports.grouping import Report

    class Recorder(figures.Saver):
        def save(self, fig, stem):
            self.problems += [(stem, p) for p in layout.layout_problems(fig)]
            self.entries[stem] = layout.legend_entries(fig)
            plt.close(fig)

    rep = Report(report_io.load_report(sys.argv[2]), metrics=["path_length", "plan_time_ns"])
    rec = Recorder(plt, "/nonexistent", 72, False)
    key = rep.ordered_worlds()[0]
    plots.plot_metrics(plt, rec, rep, key)
    paired.plot_paired(plt, rec, rep, key)
    dist.plot_distributions(plt, rec, rep, key, None)
    plots.plot_success(plt, rec, rep)
    plots.plot_time(plt, rec, rep)
    for stem, entries in rec.entries.items():
        want = [l for l in rep.labels if not stem.startswith("paired") or l != rep.baseline]
        names = [e.replace(" (baseline)", "") for e in entries]
        check(names == want, f"{stem}: legend {len(names)} entries, want {len(want)}")
    check(not rec.problems, f"layout problems: {rec.problems}")
    check(len(rec.entries) == 5, f"5 pictures recorded, got {sorted(rec.entries)}")

print("test_plot_style.py:", "ok" if not failures else f"{len(failures)} failures")
sys.exit(1 if failures else 0)
