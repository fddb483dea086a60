"""Look and layout shared by the report pictures (plot.py, plot_dist.py): one colour and one
marker per planner, legends beside the panels (never over data), log axes labelled at both
ends, the output format, and a check that legends and notes overlap nothing.

Imports matplotlib only inside functions, so plot.py can reject a bad report without it.
"""

import math
import os

# 24 colours of high mutual contrast (Kelly's 22 without white and black, plus two), ordered so
# that the first ten are the most distinct; black is the baseline's.
PALETTE = ["#0067a5", "#be0032", "#008856", "#f38400", "#875692", "#882d17", "#e68fac",
           "#a1caf1", "#8db600", "#848482", "#f3c300", "#604e97", "#2b3d26", "#f99379",
           "#00a5a5", "#b3446c", "#654522", "#dcd300", "#e25822", "#c2b280", "#3c5aa8",
           "#5c0f3c", "#7fd3a4", "#b8860b"]
BASELINE_COLOUR = "#000000"
# 15 filled markers; planners past the 15th get the same shapes hollow: 30 distinct marks
# (the baseline's included).
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*", "<", ">", "h", "p", "d", "H", "8"]
DASHES = ["-", "--", "-.", ":"]
LOG_LADDER = [1, 2, 5]  # labelled ticks of a log axis: 1, 2, 5 x 10^k


class Style:
    """Colour, marker, fill and dash of every planner. The baseline is black circles; the
    others walk the palette and the markers together, so no two planners share both (unique up
    to lcm(24, 30) = 120 planners, and the first 24 differ in colour and marker alike)."""

    def __init__(self, labels, baseline):
        self.baseline = baseline
        self.colour, self.marker, self.fill, self.dash = {}, {}, {}, {}
        i = 0
        for label in labels:
            if label == baseline:
                self.colour[label], self.marker[label] = BASELINE_COLOUR, "o"
                self.fill[label], self.dash[label] = "full", "-"
                continue
            k = i + 1  # the baseline owns marker 0 ("o" filled)
            self.colour[label] = PALETTE[i % len(PALETTE)]
            self.marker[label] = MARKERS[k % len(MARKERS)]
            self.fill[label] = "full" if (k // len(MARKERS)) % 2 == 0 else "none"
            self.dash[label] = DASHES[(i // len(PALETTE)) % len(DASHES)]
            i += 1

    def line_kw(self, label):
        """Keyword arguments of plot()/errorbar() for the planner's line and marker."""
        return {"color": self.colour[label], "marker": self.marker[label],
                "fillstyle": self.fill[label], "linestyle": self.dash[label],
                "markerfacecolor": self.colour[label] if self.fill[label] == "full" else "none",
                "markeredgecolor": self.colour[label]}

    def handle(self, label, name=None, line=True):
        from matplotlib.lines import Line2D
        kw = self.line_kw(label)
        if not line:
            kw["linestyle"] = "none"
        return Line2D([0], [0], lw=1.6, ms=6, label=name or label, **kw)


# ---------------------------------------------------------------------------------------------
# Legends and notes beside the panels


def panel_grid(plt, rows, cols, present, panel_w, panel_h, extra_w=0.4, **subplot_kw):
    """The axes of a rows x cols grid of panels of which `present` ((row, col) pairs, in row
    order) have data. Every panel present: the grid as it is. Otherwise (a sweep of map files,
    each file a row with one panel of its own) the present panels wrap four to a row, so no page
    of empty rows. Returns (fig, [(row, col, ax, left, bottom)]): left = first of its row,
    bottom = nothing under it; the unused axes are hidden."""
    full = len(present) == rows * cols
    ncols = cols if full else max(1, min(4, len(present)))
    nrows = rows if full else -(-len(present) // ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(panel_w * ncols + extra_w, panel_h * nrows + 0.6),
                             squeeze=False, **subplot_kw)
    flat = [ax for row in axes for ax in row]
    for ax in flat[len(present):]:  # the wrapped layout's last row, past the last panel
        ax.set_visible(False)
    out = []
    for i, (r, c) in enumerate(present):
        k = r * cols + c if full else i
        out.append((r, c, flat[k], k % ncols == 0, k + ncols >= len(present)))
    return fig, out


def side_legend(fig, style, labels, title=None, line=True, names=None):
    """The planners' legend in a column right of every panel (outside the axes; the saved
    picture is cropped to include it, savefig bbox_inches="tight"). Call after tight_layout.
    Returns the legend."""
    handles = [style.handle(l, (names or {}).get(l) or (f"{l} (baseline)" if l == style.baseline else l), line)
               for l in labels]
    ncol = 1 if len(handles) <= 26 else 2
    # Right of everything the panels draw (a tick label can stick out past the last axes).
    renderer = fig.canvas.get_renderer()
    to_fig = fig.transFigure.inverted()
    shown = [ax for ax in fig.axes if ax.get_visible()]
    right = max(ax.get_tightbbox(renderer).transformed(to_fig).x1 for ax in shown)
    top = max(ax.get_position().y1 for ax in shown)
    return fig.legend(handles=handles, loc="upper left", bbox_to_anchor=(right + 0.01, top),
                      bbox_transform=fig.transFigure, ncol=ncol, frameon=False, title=title,
                      borderaxespad=0.0, handlelength=2.6)


def note_below_legend(fig, legend, text):
    """A note in the legend's column, under the legend (placed after measuring it)."""
    renderer = fig.canvas.get_renderer()
    box = legend.get_window_extent(renderer).transformed(fig.transFigure.inverted())
    return fig.text(box.x0, box.y0 - 0.03, text, ha="left", va="top", fontsize=8.5,
                    color="#444444")


def reserve_right(fig, inches):
    """Widen the figure by `inches` on the right and keep the panels where they were, so the
    legend column has room without squeezing the panels."""
    w = fig.get_figwidth()
    fig.set_figwidth(w + inches)
    fig.subplots_adjust(right=(w * fig.subplotpars.right) / (w + inches))


# ---------------------------------------------------------------------------------------------
# Log axes


def spaced_ticks(candidates, a, b, keep=None, most=7):
    """Ticks of a log axis from `candidates`: both ends and `keep` always, then the others (in
    order of roundness: 1 x 10^k, then 2 and 5, then the rest) wherever they are at least 1/most
    of the axis away (in log) from every tick already chosen, so labels never collide."""
    gap = math.log(b / a) / most if b > a else 1.0
    chosen = [a, b] + ([keep] if keep is not None and a <= keep <= b else [])

    def roundness(t):
        m = t / 10 ** math.floor(math.log10(t) + 1e-9)
        return 0 if abs(m - 1) < 1e-9 else 1 if min(abs(m - 2), abs(m - 5)) < 1e-9 else 2
    for t in sorted(candidates, key=lambda t: (roundness(t), abs(math.log(t)))):
        if all(abs(math.log(t / c)) >= gap * 0.999 for c in chosen):
            chosen.append(t)
    return sorted(set(chosen))


def log_ladder_ticks(lo, hi, most=8):
    """(a, b, ticks) for a log axis over [lo, hi] (both > 0): a and b are the 1-2-5 ladder
    values just outside the data, so the smallest and the largest value both sit under a
    labelled tick; more than `most` ticks are thinned (spaced_ticks: ends kept, then the
    roundest values that keep the labels apart)."""
    k_lo, k_hi = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
    ladder = [m * 10.0 ** k for k in range(k_lo - 1, k_hi + 1) for m in LOG_LADDER]
    below = [t for t in ladder if t <= lo * (1 + 1e-12)]
    above = [t for t in ladder if t >= hi * (1 - 1e-12)]
    a, b = (below[-1] if below else lo), (above[0] if above else hi)
    if a == b:
        a, b = a / 2, b * 2
    ticks = [t for t in ladder if a * (1 - 1e-9) <= t <= b * (1 + 1e-9)]
    if len(ticks) > most:
        ticks = spaced_ticks(ticks, a, b, most=most - 1)
    return a, b, ticks


def log_ticks_both_ends(ax, axis="y", values=None, fmt=None):
    """A log axis whose limits are ticks of the 1-2-5 ladder just outside the data, labelled
    at both ends (log_ladder_ticks)."""
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator
    vals = [v for v in (values or []) if isinstance(v, (int, float)) and math.isfinite(v) and v > 0]
    if not vals:
        return
    a, b, ticks = log_ladder_ticks(min(vals), max(vals))
    side = ax.yaxis if axis == "y" else ax.xaxis
    if axis == "y":
        ax.set_yscale("log")
        ax.set_ylim(a, b)
    else:
        ax.set_xscale("log")
        ax.set_xlim(a, b)
    side.set_major_locator(FixedLocator(ticks))
    side.set_minor_locator(NullLocator())
    side.set_major_formatter(FuncFormatter(fmt or (lambda v, _: f"{v:g}")))


# ---------------------------------------------------------------------------------------------
# Layout check and saving


def layout_problems(fig):
    """What overlaps in the drawn figure: a legend over an axes (its panel area, ticks, labels
    and title included) or over a note or the title, a note over an axes, or two legends.
    Empty when clean."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    axes = [a for a in fig.axes if a.get_visible() and a.axison]
    legends = list(fig.legends) + [a.get_legend() for a in fig.axes if a.get_legend()]
    notes = [t for t in fig.texts if t.get_visible() and t.get_text().strip()]
    boxes = {}
    for a in axes:
        boxes[id(a)] = a.get_tightbbox(renderer)
    for a in legends + notes:
        boxes[id(a)] = a.get_window_extent(renderer)

    def overlap(a, b):
        a, b = boxes[id(a)], boxes[id(b)]
        return a.x0 < b.x1 - 0.5 and b.x0 < a.x1 - 0.5 and a.y0 < b.y1 - 0.5 and b.y0 < a.y1 - 0.5

    def axes_name(ax):
        return f"panel '{ax.get_title()}'"

    def note_name(t):
        return f"note '{t.get_text()[:40]}'"

    problems = []
    for i, lg in enumerate(legends):
        for ax in axes:
            if ax.get_legend() is not lg and overlap(lg, ax):
                problems.append(f"legend overlaps {axes_name(ax)}")
        for t in notes:
            if overlap(lg, t):
                problems.append(f"legend overlaps {note_name(t)}")
        for other in legends[i + 1:]:
            if overlap(lg, other):
                problems.append("two legends overlap")
    for i, t in enumerate(notes):
        for ax in axes:
            if overlap(t, ax):
                problems.append(f"{note_name(t)} overlaps {axes_name(ax)}")
        for other in notes[i + 1:]:
            if overlap(t, other):
                problems.append(f"{note_name(t)} overlaps {note_name(other)}")
    return problems


def legend_entries(fig):
    """Labels of every legend in the figure (a test checks that none is missing)."""
    out = []
    for lg in list(fig.legends) + [a.get_legend() for a in fig.axes if a.get_legend()]:
        out += [t.get_text() for t in lg.get_texts()]
    return out


class Saver:
    """Writes figures as OUTDIR/NAME.FORMAT, cropped to everything drawn (legends beside the
    panels included), with reproducible files: no date in PDF or SVG metadata."""

    def __init__(self, plt, outdir, dpi, small, fmt="png", check_layout=True):
        self.plt, self.outdir, self.dpi, self.small, self.fmt = plt, outdir, dpi, small, fmt
        self.check_layout = check_layout
        self.written = []
        self.problems = []  # (file, problem)
        self.entries = {}   # file -> legend labels

    def save(self, fig, stem):
        name = f"{stem}.{self.fmt}"
        path = os.path.join(self.outdir, name)
        if self.check_layout:
            self.problems += [(name, p) for p in layout_problems(fig)]
        self.entries[name] = legend_entries(fig)
        meta = {"png": {"Software": None}, "pdf": {"CreationDate": None, "Producer": None},
                "svg": {"Date": None}}[self.fmt]
        fig.savefig(path, dpi=self.dpi, format=self.fmt, bbox_inches="tight", pad_inches=0.12,
                    metadata=meta)
        self.plt.close(fig)
        if self.small and self.fmt == "png":
            try:  # palette PNG: a third of the bytes, no visible loss on flat-colour charts
                from PIL import Image
                with Image.open(path) as im:
                    q = im.convert("RGB").quantize(colors=128, method=Image.Quantize.MEDIANCUT)
                q.save(path, optimize=True)
            except Exception:  # noqa: BLE001 - keep the full-colour PNG
                pass
        self.written.append(name)
        return path


def setup_matplotlib(prog="plot.py"):
    import sys
    try:
        import matplotlib
    except ImportError:
        sys.stderr.write(f"{prog}: matplotlib is not importable by this interpreter "
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
        "svg.fonttype": "none", "pdf.fonttype": 42, "svg.hashsalt": "agvbench",
    })
    return plt
