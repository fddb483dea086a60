"""How a measured figure is written: the estimate with its interval and % change, the per-map
range, and a paper's figure.
"""

DASH = "\u2013"


def show_range(res):
    if res.get("p5") is None:
        return DASH
    if res["statistic"] == "ratio":
        return f"[{res['p5']:.3f}, {res['p95']:.3f}]"
    return f"[{res['p5']:+.3f}, {res['p95']:+.3f}]"


def show(v, statistic):
    if v is None:
        return "\u2013"
    if statistic == "ratio":
        return f"{v:.3f} ({(v - 1) * 100:+.1f}%)"
    return f"{v:+.3f}"


def show_interval(res):
    if res["estimate"] is None:
        return "\u2013"
    st = res["statistic"]
    text = f"{res['estimate']:.3f}" if st == "ratio" else f"{res['estimate']:+.3f}"
    if res["lo"] is not None and res["hi"] is not None:
        text += f" [{res['lo']:.3f}, {res['hi']:.3f}]" if st == "ratio" else f" [{res['lo']:+.3f}, {res['hi']:+.3f}]"
    if st == "ratio":
        text += f" ({(res['estimate'] - 1) * 100:+.1f}%)"
    return text
