"""Log axes labelled at both ends: limits on the 1-2-5 ladder just outside the data, so the
smallest and the largest value sit under a labelled tick, and ticks thinned so labels never
collide.
"""

import math

LOG_LADDER = [1, 2, 5]  # labelled ticks of a log axis: 1, 2, 5 x 10^k


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
