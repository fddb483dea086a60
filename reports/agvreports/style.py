"""One look per planner, shared by every picture and the HTML page: a colour, a marker, its
fill and a dash. Imports matplotlib only inside functions, so a bad report is rejected without it.
"""

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
