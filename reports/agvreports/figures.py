"""matplotlib set up for the pictures (headless, one look), and the saving of a figure:
cropped to everything drawn, reproducible (no date in the file), checked for overlaps.
"""

import os
import sys

from agvreports.layout import layout_problems, legend_entries, note_below_legend, side_legend


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
        # Labels are the user's text, shown as written: "$\alpha$" or "x_1^2" is no mathtext.
        "text.parse_math": False,
    })
    return plt


def finish(fig, rep, labels, title, stem, saver, note=None, line=True):
    """Title, tight panels, the legend beside them (and a note under it), save."""
    fig.suptitle(title, fontsize=11, fontweight="bold", x=0.0, ha="left")
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    legend = side_legend(fig, rep.style, labels, line=line)
    if note:
        note_below_legend(fig, legend, note)
    saver.save(fig, stem)
