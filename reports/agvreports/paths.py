"""The picture of plot_paths.py: the grid, start and goal, each planner's path in its own colour
(equal paths as nested stripes), and a fusion run's trajectory, moving obstacles and unknown
cells when present.
"""

import math
import os
import sys

from agvreports.layout import literal_legend
from agvreports.numeric import finite

PALETTE = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf",
           "#7f7f7f", "#393b79", "#637939"]


def describe(run):
    mt = run["metrics"]
    parts = [run["outcome"]]
    if run["outcome"] == "success":
        if finite(mt.get("travelled_length")):
            parts.append(f"travelled {mt['travelled_length']:.1f}")
        if finite(mt.get("path_length")):
            parts.append(f"length {mt['path_length']:.2f}")
        if finite(mt.get("turns")):
            parts.append(f"{int(mt['turns'])} turns")
        if finite(mt.get("collision_checks")):
            parts.append(f"{int(mt['collision_checks'])} checks")
    elif run["message"]:
        parts.append(run["message"][:50])
    return ", ".join(parts)


def draw(plan, out_path, dpi, title, small=False):
    try:
        import matplotlib
    except ImportError:
        sys.stderr.write("plot_paths.py: matplotlib is not importable by this interpreter "
                         f"({sys.executable}); run with /usr/bin/python3 after "
                         "`apt-get install python3-matplotlib`\n")
        return 1
    matplotlib.use("Agg")
    # Planner labels and messages are the user's text, shown as written, not read as mathtext.
    matplotlib.rcParams["text.parse_math"] = False
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Rectangle

    w, h = plan["w"], plan["h"]
    side = 7.5
    scale = side / max(w, h)
    fig_w, fig_h = w * scale + 1.0, h * scale + 1.0
    fig, ax = plt.subplots(figsize=(fig_w, fig_h))
    occ = [[1 if b else 0 for b in row] for row in plan["grid"]]
    ax.imshow(occ, cmap=ListedColormap(["#ffffff", "#3b3b3b"]), vmin=0, vmax=1,
              extent=(0, w, h, 0), interpolation="nearest", zorder=0)
    if max(w, h) <= 80:
        for x in range(w + 1):
            ax.axvline(x, color="#d8d8d8", lw=0.4, zorder=0.5)
        for y in range(h + 1):
            ax.axhline(y, color="#d8d8d8", lw=0.4, zorder=0.5)
    ax.add_patch(Rectangle((0, 0), w, h, fill=False, ec="#3b3b3b", lw=1.2, zorder=1))

    handles = []
    runs = plan["runs"]
    drawn = [r for r in runs if len(r["path"]) >= 2]
    n = max(1, len(drawn))
    seen = {}
    k = 0
    for run in runs:
        name = run["planner"]
        seen[name] = seen.get(name, 0) + 1
        label = name if seen[name] == 1 else f"{name} #{seen[name]}"
        colour = PALETTE[runs.index(run) % len(PALETTE)]
        text = f"{label}: {describe(run)}"
        if len(run["path"]) >= 2:
            # Wider lines first, so equal paths show as nested stripes instead of hiding each other.
            cell_pt = scale * 72.0
            lw_max = max(2.0, min(10.0, 0.6 * cell_pt))
            lw_min = max(1.2, min(2.4, lw_max / 3.0))
            lw = lw_min + (lw_max - lw_min) * (n - 1 - k) / (n - 1) if n > 1 else max(lw_min, min(3.0, lw_max))
            k += 1
            xs = [p[0] for p in run["path"]]
            ys = [p[1] for p in run["path"]]
            many = len(xs) > 150
            ax.plot(xs, ys, color=colour, lw=lw, solid_capstyle="round",
                    solid_joinstyle="round", zorder=3 + k * 0.01)
            if not many:
                ax.plot(xs, ys, linestyle="none", marker="o", ms=max(2.5, min(4.5, lw * 0.8)), mfc="white",
                        mec=colour, mew=1.1, zorder=3.5 + k * 0.01)
            handles.append(Line2D([0], [0], color=colour, lw=2.6, marker=None if many else "o",
                                  mfc="white", mec=colour, label=text))
        else:
            handles.append(Line2D([0], [0], color="#999999", lw=0, marker="x", ms=7, label=text))
        if run["trajectory"] and len(run["trajectory"]) >= 2:
            xs = [p[0] for p in run["trajectory"]]
            ys = [p[1] for p in run["trajectory"]]
            ax.plot(xs, ys, color=colour, lw=1.6, ls=(0, (4, 2)), zorder=4)
            handles.append(Line2D([0], [0], color=colour, lw=1.6, ls=(0, (4, 2)), label=f"{label}: executed trajectory"))
        for cx, cy in run["unknown"]:
            ax.add_patch(Rectangle((math.floor(cx), math.floor(cy)), 1, 1, fc="#bbbbbb", ec="#555555",
                                   hatch="////", lw=0.6, zorder=1.5))
        if run["unknown"]:
            handles.append(Rectangle((0, 0), 1, 1, fc="#bbbbbb", ec="#555555", hatch="////",
                                     label=f"{label}: unknown static cells"))
        for j, ob in enumerate(run["obstacles"]):
            tr = ob["track"]
            if not tr:
                continue
            xs = [p[0] for p in tr]
            ys = [p[1] for p in tr]
            ax.plot(xs, ys, color="#e6a100", lw=1.2, ls=":", zorder=2.5)
            ax.add_patch(Circle(tr[0], ob["radius"], fc="none", ec="#e6a100", lw=1.0, ls="--", zorder=2.6))
            ax.add_patch(Circle(tr[-1], ob["radius"], fc="#ffd34d", ec="#b37d00", lw=1.0, alpha=0.9, zorder=2.6))
            if len(tr) >= 2:
                ax.annotate("", xy=tr[-1], xytext=tr[max(0, len(tr) - 3)],
                            arrowprops=dict(arrowstyle="->", color="#b37d00", lw=1.0), zorder=2.7)
        if run["obstacles"]:
            handles.append(Line2D([0], [0], color="#e6a100", lw=1.2, ls=":", marker="o", mfc="#ffd34d",
                                  mec="#b37d00", label=f"{label}: moving obstacles (track, last position)"))

    sx, sy = plan["start"]
    gx, gy = plan["goal"]
    ms = max(7.0, min(16.0, scale * 72 * 0.7))
    ax.plot(sx + 0.5, sy + 0.5, marker="o", ms=ms, mfc="#2ca02c", mec="black", mew=1.0, zorder=6)
    ax.plot(gx + 0.5, gy + 0.5, marker="*", ms=ms * 1.4, mfc="#d62728", mec="black", mew=1.0, zorder=6)
    handles.append(Line2D([0], [0], lw=0, marker="o", ms=8, mfc="#2ca02c", mec="black", label=f"start ({sx}, {sy})"))
    handles.append(Line2D([0], [0], lw=0, marker="*", ms=11, mfc="#d62728", mec="black", label=f"goal ({gx}, {gy})"))
    handles.append(Rectangle((0, 0), 1, 1, fc="#3b3b3b", label="obstacle cell"))

    ax.set_xlim(0, w)
    ax.set_ylim(h, 0)
    ax.set_aspect("equal")
    ax.set_xlabel("x (cells)")
    ax.set_ylabel("y (cells, 0 = top row)")
    ax.tick_params(labelsize=8)
    from matplotlib.ticker import MaxNLocator
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.yaxis.set_major_locator(MaxNLocator(integer=True))
    m = plan["map"]
    if title is None:
        if "cell" in m:
            title = f"{m['cell']}  seed {m.get('seed', '?')}, map {m.get('map_index', '?')}"
        elif "file" in m:
            title = os.path.basename(str(m["file"]))
        else:
            title = f"{w}\u00d7{h} map"
        density = sum(sum(r) for r in occ) / (w * h)
        title += f"  ({density * 100:.0f}% obstacles)"
    ax.set_title(title, fontsize=11, fontweight="bold")
    literal_legend(ax, handles, loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False, fontsize=8.5,
                   borderaxespad=0.0)
    parent = os.path.dirname(os.path.abspath(out_path))
    try:
        os.makedirs(parent, exist_ok=True)
        fig.savefig(out_path, dpi=dpi, bbox_inches="tight", pad_inches=0.15)
    except OSError as e:
        sys.stderr.write(f"plot_paths.py: cannot write {out_path}: {e.strerror}\n")
        return 1
    plt.close(fig)
    if small:
        try:  # palette PNG, as plot.py --small
            from PIL import Image
            with Image.open(out_path) as im:
                q = im.convert("RGB").quantize(colors=128, method=Image.Quantize.MEDIANCUT)
            q.save(out_path, optimize=True)
        except Exception:  # noqa: BLE001 - keep the full-colour PNG
            pass
    print(out_path)
    return 0
