"""One pairwise comparison measured over every matching cell of every report of a set-up: by
the report's own pairing, from the per-run records, indirectly through the report's baseline, or
as an unpaired difference of means (the routes: reports/check_claims.py's docstring).
"""

import math
import os

from agvreports.cells import planner_of
from agvreports.claims.cell_stats import cell_from_runs, cell_ratio_from_report, percentile, summary_moments
from agvreports.claims.sources import (cell_matches, describe_filter, paired_metrics_of, report_metrics_of,
                                       resolve, run_metrics_of)
from agvreports.stats import Moments, t_quantile


class Acc:
    """Accumulated evidence for one comparison (over cells and reports)."""

    def __init__(self):
        self.m = Moments()
        self.pairs = self.wins = self.ties = self.losses = self.excluded = 0
        self.maps = 0
        self.cells = []
        self.sources = []


def measure(sources, comp, min_pairs):
    """Evaluate one pairwise comparison. Returns a result dict (see verdict())."""
    cand_sel, base_sel = comp["candidate"], comp["baseline"]
    statistic = comp.get("statistic", "ratio")
    metrics = comp["metric"] if isinstance(comp["metric"], list) else [comp["metric"]]
    filt = comp.get("cells") or {}
    offset = float(comp.get("offset", 0.0))
    values = []  # per-map ratios (or differences), from the per-run records
    values_missing = []  # sources without per-run records
    exact = {"acc": Acc(), "method": set()}
    indirect = {"c": Acc(), "b": Acc(), "via": set(), "cells": [], "sources": [], "maps": 0}
    unpaired = {"c": Moments(), "b": Moments(), "cells": [], "sources": [], "maps": 0}
    why = []
    used_metric = None
    for src in sources:
        cand, w1 = resolve(cand_sel, src)
        base, w2 = resolve(base_sel, src)
        if cand is None or base is None:
            why.append(f"{src.name}: " + "; ".join(w for w in (w1, w2) if w))
            continue
        if cand == base:
            why.append(f"{src.name}: candidate and baseline resolve to the same planner '{cand}'")
            continue
        cells = [c for c in src.doc["cells"] if cell_matches(c, filt)]
        cells = [c for c in cells if planner_of(c, cand) and planner_of(c, base)]
        if not cells:
            why.append(f"{src.name}: no cells match ({describe_filter(filt)})")
            continue
        available = report_metrics_of(src) | (run_metrics_of(src) if src.runs is not None else set())
        metric = next((m for m in metrics if m in available), None)
        if metric is None:
            why.append(f"{src.name}: metric {' / '.join(metrics)} not in report")
            continue
        used_metric = used_metric or metric
        paired_here = metric in paired_metrics_of(src) and offset == 0.0
        if src.runs is not None:
            for c in cells:
                cell_from_runs(src, c, cand, base, metric, statistic, offset=offset, values=values)
        else:
            values_missing.append(src.name)
        maps_here = sum(int(c.get("maps") or 0) for c in cells)
        if statistic == "ratio" and paired_here and base == src.baseline and \
                all(cell_ratio_from_report(c, cand, base, metric) for c in cells):
            acc = exact["acc"]
            for c in cells:
                m, pairs, w, t, l, ex = cell_ratio_from_report(c, cand, base, metric)
                acc.m.merge(m)
                acc.pairs += pairs; acc.wins += w; acc.ties += t; acc.losses += l; acc.excluded += ex
                acc.cells.append(c["cell"])
            acc.maps += maps_here
            acc.sources.append(src.name)
            exact["method"].add("paired in the report")
        elif src.runs is not None:
            acc = exact["acc"]
            for c in cells:
                m, pairs, w, t, l, ex = cell_from_runs(src, c, cand, base, metric, statistic, offset=offset)
                acc.m.merge(m)
                acc.pairs += pairs; acc.wins += w; acc.ties += t; acc.losses += l; acc.excluded += ex
                acc.cells.append(c["cell"])
            acc.maps += maps_here
            acc.sources.append(src.name + " + " + os.path.basename(src.runs_path))
            exact["method"].add("paired from the per-run records")
        elif statistic == "ratio" and paired_here and src.baseline not in (cand, base):
            ok = True
            part = {"c": Acc(), "b": Acc()}
            for c in cells:
                rc = cell_ratio_from_report(c, cand, src.baseline, metric)
                rb = cell_ratio_from_report(c, base, src.baseline, metric)
                if rc is None or rb is None:
                    ok = False
                    break
                for key, r in (("c", rc), ("b", rb)):
                    part[key].m.merge(r[0])
                    part[key].pairs += r[1]
            if not ok:
                why.append(f"{src.name}: {cand} and {base} are not both paired against {src.baseline}")
                continue
            indirect["c"].m.merge(part["c"].m); indirect["c"].pairs += part["c"].pairs
            indirect["b"].m.merge(part["b"].m); indirect["b"].pairs += part["b"].pairs
            indirect["via"].add(src.baseline)
            indirect["cells"] += [c["cell"] for c in cells]
            indirect["sources"].append(src.name)
            indirect["maps"] += maps_here
        elif statistic == "difference":
            ok = True
            for c in cells:
                mc = summary_moments(planner_of(c, cand), metric)
                mb = summary_moments(planner_of(c, base), metric)
                if mc is None or mb is None:
                    ok = False
                    break
                unpaired["c"].merge(mc)
                unpaired["b"].merge(mb)
            if not ok:
                why.append(f"{src.name}: no {metric} summaries for {cand} / {base}")
                continue
            unpaired["cells"] += [c["cell"] for c in cells]
            unpaired["sources"].append(src.name)
            unpaired["maps"] += maps_here
        else:
            if not paired_here:
                why.append(f"{src.name}: {metric} is not among the report's paired metrics "
                           "(give the sweep's --runs-out JSONL after the report)")
            else:
                why.append(f"{src.name}: the report pairs planners only against '{src.baseline}' "
                           f"(give the sweep's --runs-out JSONL after the report)")

    values.sort()
    res = {"statistic": statistic, "metric": used_metric or metrics[0], "why": why,
           "estimate": None, "lo": None, "hi": None, "n": 0, "pairs": 0, "maps": 0, "cells": [],
           "sources": [], "method": None, "wins": None, "ties": None, "losses": None,
           "p5": percentile(values, 0.05), "p95": percentile(values, 0.95), "range_n": len(values),
           "range_missing": values_missing}
    acc = exact["acc"]
    if acc.m.n > 0 or acc.pairs > 0:
        m = acc.m
        lo, hi = m.interval()
        if statistic == "ratio":
            res.update(estimate=math.exp(m.mean) if m.n else None,
                       lo=math.exp(lo) if lo is not None else None, hi=math.exp(hi) if hi is not None else None)
        else:
            res.update(estimate=m.mean if m.n else None, lo=lo, hi=hi)
        res.update(n=m.n, pairs=acc.pairs, maps=acc.maps, cells=acc.cells, sources=acc.sources,
                   method=" and ".join(sorted(exact["method"])), wins=acc.wins, ties=acc.ties,
                   losses=acc.losses, excluded=acc.excluded)
    elif indirect["c"].m.n > 0 and indirect["b"].m.n > 0:
        mc, mb = indirect["c"].m, indirect["b"].m
        lc, hc = mc.interval()
        lb, hb = mb.interval()
        res.update(estimate=math.exp(mc.mean - mb.mean),
                   lo=math.exp(lc - hb) if lc is not None and hb is not None else None,
                   hi=math.exp(hc - lb) if hc is not None and lb is not None else None,
                   n=min(mc.n, mb.n), pairs=min(indirect["c"].pairs, indirect["b"].pairs),
                   maps=indirect["maps"], cells=indirect["cells"], sources=indirect["sources"],
                   method=f"indirect via {'/'.join(sorted(indirect['via']))} (conservative interval)")
    elif unpaired["c"].n > 0 and unpaired["b"].n > 0:
        mc, mb = unpaired["c"], unpaired["b"]
        est = mc.mean - mb.mean
        lo = hi = None
        if mc.n >= 2 and mb.n >= 2:
            vc, vb = (mc.sd ** 2) / mc.n, (mb.sd ** 2) / mb.n
            se = math.sqrt(vc + vb)
            if se == 0:
                lo = hi = est
            else:
                df = (vc + vb) ** 2 / ((vc * vc) / (mc.n - 1) + (vb * vb) / (mb.n - 1))
                t = t_quantile(0.975, df)
                lo, hi = est - t * se, est + t * se
        res.update(estimate=est, lo=lo, hi=hi, n=min(mc.n, mb.n), pairs=min(mc.n, mb.n),
                   maps=unpaired["maps"], cells=unpaired["cells"], sources=unpaired["sources"],
                   method="unpaired difference of means from the cell summaries (Welch; conservative)")
    res["min_pairs"] = min_pairs
    return res
