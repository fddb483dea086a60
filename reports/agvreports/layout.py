"""Where the parts of a picture go: panels in a grid, the planners' legend in a column right of
them and notes under it (never over data), and a check, on the drawn figure, that no legend or
note overlaps a panel or another (the tests require it silent on every picture).
"""


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
    return literal_legend(fig, handles, loc="upper left", bbox_to_anchor=(right + 0.01, top),
                          bbox_transform=fig.transFigure, ncol=ncol, frameon=False, title=title,
                          borderaxespad=0.0, handlelength=2.6)


def literal_legend(owner, handles, **kw):
    """owner.legend (a figure's or an axes') with every handle's label as it is: matplotlib
    leaves a label starting with '_' out of a legend, so such an entry is made under a stand-in
    and given its text back."""
    texts = [h.get_label() for h in handles]
    legend = owner.legend(handles=handles, labels=[" " + t if t.startswith("_") else t for t in texts],
                          **kw)
    for entry, text in zip(legend.get_texts(), texts):
        entry.set_text(text)
    return legend


def note_below_legend(fig, legend, text):
    """A note in the legend's column, under the legend (placed after measuring it)."""
    renderer = fig.canvas.get_renderer()
    box = legend.get_window_extent(renderer).transformed(fig.transFigure.inverted())
    return fig.text(box.x0, box.y0 - 0.03, text, ha="left", va="top", fontsize=8.5,
                    color="#444444")


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
