"""Per-cell evidence of one comparison: the pooled log ratios of a cell's COMPARISON in the
report, the paired values recomputed from the per-run records (and each map's own ratio or
difference), a cell summary's moments, and percentiles.
"""

import math

from agvreports.cells import comparison_of, summary_of
from agvreports.numeric import finite
from agvreports.stats import Moments, moments_from_summary


def _paired_entry(cell, cand, base):
    for c in cell["paired"]:
        if c["planner"] == cand and c["baseline"] == base:
            return c
    return None


def cell_ratio_from_report(cell, cand, base, metric):
    entry = _paired_entry(cell, cand, base)
    if entry is None:
        return None
    comp = comparison_of(entry, metric)
    if not isinstance(comp, dict):
        return None
    # Schema 2 compares counts by the shifted ratio (c + 1) / (b + 1) (reports/SCHEMA.md); a
    # paper's figure is a plain ratio, recomputed from the runs instead.
    if comp.get("ratio", "plain") != "plain":
        return None
    pairs = int(comp.get("pairs") or 0)
    excluded = int(comp.get("ratios_excluded") or 0)
    n = pairs - excluded
    gm = comp.get("geo_mean_ratio")
    if n <= 0 or not finite(gm) or gm <= 0:
        m = Moments()
    else:
        ci = comp.get("ci95") or [None, None]
        lci = [math.log(ci[0]) if finite(ci[0]) and ci[0] > 0 else None,
               math.log(ci[1]) if finite(ci[1]) and ci[1] > 0 else None]
        m = moments_from_summary(n, math.log(gm), lci)
        if m is None:
            return None
    return m, pairs, int(comp.get("wins") or 0), int(comp.get("ties") or 0), int(comp.get("losses") or 0), excluded


def _run_value(rec, metric, offset=0.0):
    if rec.get("outcome") != "success":
        return None
    if metric == "plan_time_ns":
        v = (rec.get("timing") or {}).get("plan_time_ns")
    else:
        v = (rec.get("metrics") or {}).get(metric)
    return float(v) + offset if finite(v) else None


def cell_from_runs(src, cell, cand, base, metric, statistic, tol=1e-9, offset=0.0, values=None):
    """Paired moments of one cell from the per-run records; each map's own ratio (or difference)
    is appended to `values` when given (the per-map distribution the magnitude is graded on)."""
    maps = src.runs_of_cell(cell["cell"])
    m = Moments()
    pairs = wins = ties = losses = excluded = 0
    for idx in sorted(maps):
        recs = maps[idx]
        if cand not in recs or base not in recs:
            continue
        c, b = _run_value(recs[cand], metric, offset), _run_value(recs[base], metric, offset)
        if c is None or b is None:
            continue
        pairs += 1
        tie = abs(c - b) <= tol * max(abs(c), abs(b))
        if tie:
            ties += 1
        elif c < b:
            wins += 1
        else:
            losses += 1
        if statistic == "difference":
            m.add(0.0 if tie else c - b)
            if values is not None:
                values.append(0.0 if tie else c - b)
        elif c > 0 and b > 0:
            m.add(math.log(c / b))
            if values is not None:
                values.append(c / b)
        elif c == 0 and b == 0:
            m.add(0.0)
            if values is not None:
                values.append(1.0)
        else:
            excluded += 1
    return m, pairs, wins, ties, losses, excluded


def percentile(sorted_values, q):
    """The q-quantile (0..1) by linear interpolation between order statistics (numpy's default)."""
    n = len(sorted_values)
    if n == 0:
        return None
    pos = q * (n - 1)
    i = int(math.floor(pos))
    if i + 1 >= n:
        return sorted_values[-1]
    return sorted_values[i] + (pos - i) * (sorted_values[i + 1] - sorted_values[i])


def summary_moments(planner_cell, metric):
    s = summary_of(planner_cell, metric)
    if s is None:
        return None
    n = int(s.get("count") or 0)
    if n == 0:
        return Moments()
    mean, sd = s.get("mean"), s.get("stddev")
    if not finite(mean):
        return Moments()
    if n == 1:
        return Moments(1, mean, 0.0)
    if not finite(sd):
        return None
    return Moments(n, mean, sd * sd * (n - 1))
