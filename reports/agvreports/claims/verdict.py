"""The five levels of a verdict and the rule that grades one measured comparison (the rules:
reports/check_claims.py's docstring).
"""

from agvreports.claims.show import show, show_range

REPRODUCED, DIRECTION, CONTRADICTED, NOT_SIGNIFICANT, NA = (
    "reproduced", "direction only", "contradicted", "not significant", "not comparable")
LEVELS = (REPRODUCED, DIRECTION, CONTRADICTED, NOT_SIGNIFICANT, NA)


def verdict(res, comp, paper_value):
    """(level, reason) for one measured comparison (the levels: reports/check_claims.py's docstring)."""
    direction = comp.get("direction", "smaller")
    statistic = res["statistic"]
    neutral = 1.0 if statistic == "ratio" else 0.0
    if res["estimate"] is None or res["n"] == 0:
        return NA, "; ".join(res["why"]) or "no pairs where both planners succeeded"
    if res["n"] < res["min_pairs"]:
        return NA, f"too few pairs ({res['n']} < {res['min_pairs']})"
    lo, hi = res["lo"], res["hi"]
    if lo is None or hi is None:
        return NA, "no interval (fewer than two pairs)"
    better_side = (hi < neutral) if direction == "smaller" else (lo > neutral)
    worse_side = (lo > neutral) if direction == "smaller" else (hi < neutral)
    claimed = "smaller" if direction == "smaller" else "larger"
    if worse_side:
        return CONTRADICTED, (f"the opposite: the candidate is significantly "
                              f"{'larger' if direction == 'smaller' else 'smaller'}")
    if not better_side:
        return NOT_SIGNIFICANT, f"no significant difference (the 95% interval contains {neutral:g})"
    if paper_value is None:
        return REPRODUCED, f"significantly {claimed}; the paper gives no figure: its claim is the direction"
    p5, p95 = res.get("p5"), res.get("p95")
    if p5 is None or p95 is None or res.get("range_missing"):
        return DIRECTION, (f"significantly {claimed}; the paper's figure is not graded: no per-run "
                           f"records for {', '.join(res.get('range_missing') or ['these reports'])}")
    rng = f"our per-map 5-95% range {show_range(res)}"
    if p5 - 1e-12 <= paper_value <= p95 + 1e-12:
        return REPRODUCED, f"significantly {claimed}; the paper's {show(paper_value, statistic)} lies inside {rng}"
    edge = p5 if paper_value < p5 else p95
    side = "below" if paper_value < p5 else "above"
    if statistic == "ratio":
        by = (f"by {(max(edge, paper_value) / min(edge, paper_value) - 1) * 100:.1f}% of the ratio"
              if paper_value > 0 and edge > 0 else f"by {abs(edge - paper_value):.3f}")
    else:
        by = f"by {abs(edge - paper_value):.3f}"
    return DIRECTION, (f"significantly {claimed}, but the paper's {show(paper_value, statistic)} lies {side} "
                       f"{rng}, {by} beyond its {'5%' if side == 'below' else '95%'} point")
