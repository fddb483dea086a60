#!/usr/bin/python3
"""Check the papers' headline claims (reports/claims.json) against agvbench sweep reports.

    /usr/bin/python3 reports/check_claims.py REPORT.json [RUNS.jsonl] [REPORT2.json [RUNS2.jsonl]] ...
        [--claims reports/claims.json] [--out reports/CLAIMS.md] [--json RESULTS.json] [--all-as random]

A RUNS.jsonl (the sweep's `--runs-out` per-run records) placed right after a report belongs to
that report; it is needed only for comparisons the report does not pair itself (a baseline other
than the report's, or a metric outside the paired list).

For each claim: the planners are found in each report's config (by label, or by registry name
and parameters), the cells are filtered (generator, size, density range), and the measured
figure is pooled over every matching cell of every report:

  ratio, paired in the report (candidate vs the report's baseline): each cell's COMPARISON gives
      the count, mean and (through its t interval) the spread of the per-map log ratios; they are
      merged exactly, so the pooled figure is the geometric mean over all pairs of all matching
      cells (= per-cell geometric means combined with weights = pairs) and its interval is the
      95% t interval over all those pairs, the same as recomputing from the runs;
  ratio from RUNS.jsonl: the same, computed from the per-run records;
  ratio, indirect (neither of the above; both planners paired against the report's baseline
      B0): ratio = GM(candidate/B0) / GM(baseline/B0), interval [lo_c/hi_b, hi_c/lo_b] from the
      two pooled intervals: conservative, and marked as indirect (the two pair sets may differ);
  difference (e.g. clearance): paired differences from RUNS.jsonl if given, else candidate mean
      minus baseline mean from the cell summaries with a Welch interval (unpaired: conservative).

Set-ups: each claim names two sweep configs (claims.json "setup"): "paper", its paper's own
set-up (configs/paper-00N.json), and "random", our random-map protocol (configs/paper-00N-random.json).
A report belongs to a set-up by its config's name (--all-as SETUP: every report stands for that
set-up, as for a sample sweep); each claim is graded on each set-up separately
(compare.paper_cells, where given, replaces compare.cells on the paper's set-up; "cells" may be a
list of filters, any of which a cell may match). compare.offset is added to every per-run value
before the ratio (paper 004's turns = key points - 2); it forces the per-run route.

Verdicts, five levels:
  'reproduced'      the 95% interval lies on the claimed side of no-effect (1 for ratios, 0 for
                    differences) AND the paper's figure lies inside our per-map 5-95% range of the
                    same quantity: each map's candidate/baseline ratio (or difference) from the
                    per-run records, pooled over the matching cells. A paper's figure is one map's
                    (or a few maps' mean): it is compared with what one map of ours gives, not
                    with the interval of a thousands-of-maps mean, which no single map need lie in.
                    A claim with no figure (the paper states a direction only) is reproduced by a
                    significant effect in that direction; an ordering by every step significant.
  'direction only'  significant in the claimed direction, but the paper's figure lies outside that
                    range (the reason says on which side and by how much); also when the reports
                    came without per-run records, so that the range cannot be computed.
  'contradicted'    the 95% interval lies entirely on the opposite side.
  'not significant' the 95% interval contains no-effect. A level of its own rather than folded into
                    another: with thousands of maps it means the effect is absent or negligible,
                    which neither supports the claim ('direction only' would say it did) nor
                    shows its opposite ('contradicted' would).
  'not comparable'  the claim is marked "not_comparable" in claims.json with the reason (e.g. the
                    paper's MATLAB wall seconds against our CPU nanoseconds: our figure is shown
                    for context only), or nothing to measure: no report of the set-up, a planner
                    or metric missing, no matching cells, fewer than min_pairs pairs.
An ordering's level is its worst step's (not comparable, then contradicted, then not significant).

Exit codes: 0 done (whatever the verdicts), 2 bad report / runs / claims file.
"""

import argparse
import json
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
# reports/ holds html.py, which would hide the standard library's `html` package (matplotlib
# imports html.entities): the folder goes last on the path, after the standard library.
_here = os.path.dirname(os.path.abspath(__file__))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != _here] + [_here]
import agvreport  # noqa: E402
import agvruns  # noqa: E402
from agvreport import Moments, ReportError, moments_from_summary  # noqa: E402

DASH = "\u2013"
# The per-run record format agvbench writes (engine/run_record.h kJournalVersion).
REPRODUCED, DIRECTION, CONTRADICTED, NOT_SIGNIFICANT, NA = (
    "reproduced", "direction only", "contradicted", "not significant", "not comparable")
LEVELS = (REPRODUCED, DIRECTION, CONTRADICTED, NOT_SIGNIFICANT, NA)
SETUPS = (("paper", "the paper's set-up"), ("random", "our random maps"))
DEFAULT_CLAIMS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "claims.json")


def finite(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


# ---------------------------------------------------------------------------------------------
# Inputs


class Source:
    """One report (and its optional per-run records)."""

    def __init__(self, path, doc):
        self.path = path
        self.doc = doc
        self.runs_path = None
        self.runs = None  # list of records
        self.as_setup = None  # --all-as: stands for this set-up of every claim, whatever its name
        cfg = doc.get("config", {})
        self.name = cfg.get("name", os.path.basename(path)) if isinstance(cfg, dict) else os.path.basename(path)
        self.baseline = agvreport.baseline_label(doc)
        self.planners = []  # [{label, name, params}]
        for p in (cfg.get("planners") or []) if isinstance(cfg, dict) else []:
            if isinstance(p, dict) and isinstance(p.get("label"), str):
                self.planners.append({"label": p["label"], "name": p.get("name", p["label"]),
                                      "params": p.get("params") if isinstance(p.get("params"), dict) else {}})
            elif isinstance(p, str):
                self.planners.append({"label": p, "name": p, "params": {}})
        known = {p["label"] for p in self.planners}
        for cell in doc["cells"]:
            for p in cell["planners"]:
                if p["planner"] not in known:
                    known.add(p["planner"])
                    self.planners.append({"label": p["planner"], "name": p.get("name", p["planner"]), "params": {}})

    def attach_runs(self, path):
        records = []
        try:
            for _, r in agvruns.journal_records(path):
                # Keep only what the comparisons read (paper sweeps have many records).
                records.append({"planner": r["planner"], "cell": r["cell"], "map_index": r["map_index"],
                                "outcome": r["outcome"], "metrics": r["metrics"],
                                "timing": {"plan_time_ns": (r.get("timing") or {}).get("plan_time_ns")}})
        except OSError as e:
            raise ReportError(f"cannot read: {e.strerror}") from None
        self.runs_path = path
        self.runs = records
        self._by_cell = {}
        for r in records:
            self._by_cell.setdefault(r["cell"], {}).setdefault(r["map_index"], {})[r["planner"]] = r

    def runs_of_cell(self, key):
        return self._by_cell.get(key, {}) if self.runs is not None else {}


def _loose_equal(a, b):
    if finite(a) and finite(b):
        return abs(float(a) - float(b)) <= 1e-12 * max(1.0, abs(a), abs(b))
    return a == b


def resolve(selector, src):
    """Label of the report's planner the selector names, or (None, why)."""
    if isinstance(selector, str):
        selector = {"label": selector}
    label, name, params = selector.get("label"), selector.get("name"), selector.get("params") or {}
    if label is not None:
        for p in src.planners:
            if p["label"] == label and (name is None or p["name"] == name) and \
                    all(k in p["params"] and _loose_equal(p["params"][k], v) for k, v in params.items()):
                return p["label"], None
    if name is not None:
        hits = [p for p in src.planners if p["name"] == name and
                all(k in p["params"] and _loose_equal(p["params"][k], v) for k, v in params.items())]
        if hits:
            for p in hits:
                if p["label"] == name:
                    return p["label"], None
            return hits[0]["label"], None
    what = f"label '{label}'" if label and not name else f"'{name or label}'"
    if params:
        what += " with " + ", ".join(f"{k}={json.dumps(v)}" for k, v in params.items())
    return None, f"planner {what} not in report"


def cell_matches(cell, filt):
    if not filt:
        return True
    if isinstance(filt, list):  # a union of filters (paper 002: each size at its own density)
        return any(cell_matches(cell, f) for f in filt)
    gens = filt.get("generators")
    if gens and cell["generator"] not in gens:
        return False
    sizes = filt.get("sizes")
    if sizes:
        ok = False
        for s in sizes:
            w, h = (s, s) if isinstance(s, (int, float)) else (s[0], s[1])
            if int(cell["width"]) == int(w) and int(cell["height"]) == int(h):
                ok = True
        if not ok:
            return False
    dr = filt.get("density")
    if dr:
        lo, hi = dr
        d = float(cell["density"])
        if (lo is not None and d < lo - 1e-9) or (hi is not None and d > hi + 1e-9):
            return False
    return True


def describe_filter(filt):
    if not filt:
        return "all cells"
    if isinstance(filt, list):
        return " or ".join(f"({describe_filter(f)})" for f in filt)
    parts = []
    if filt.get("generators"):
        parts.append("generator " + "/".join(filt["generators"]))
    if filt.get("sizes"):
        parts.append("size " + "/".join(f"{s[0]}x{s[1]}" if isinstance(s, list) else f"{s}x{s}" for s in filt["sizes"]))
    if filt.get("density"):
        lo, hi = filt["density"]
        parts.append(f"density {lo:g}-{hi:g}")
    return ", ".join(parts) or "all cells"


# ---------------------------------------------------------------------------------------------
# Per-cell statistics


def _comparison(paired_entry, metric):
    if metric == "plan_time_ns":
        return (paired_entry.get("timing") or {}).get("plan_time_ns")
    return paired_entry["metrics"].get(metric)


def _paired_entry(cell, cand, base):
    for c in cell["paired"]:
        if c["planner"] == cand and c["baseline"] == base:
            return c
    return None


def paired_metrics_of(src):
    names = set()
    for cell in src.doc["cells"]:
        for c in cell["paired"]:
            names.update(c["metrics"].keys())
            if isinstance((c.get("timing") or {}).get("plan_time_ns"), dict):
                names.add("plan_time_ns")
    return names


def report_metrics_of(src):
    names = set()
    for cell in src.doc["cells"]:
        for p in cell["planners"]:
            names.update(p["metrics"].keys())
    names.add("plan_time_ns")
    return names


def run_metrics_of(src):
    names = {"plan_time_ns"}
    for r in (src.runs or [])[:2000]:
        if isinstance(r.get("metrics"), dict):
            names.update(r["metrics"].keys())
    return names


class Acc:
    """Accumulated evidence for one comparison (over cells and reports)."""

    def __init__(self):
        self.m = Moments()
        self.pairs = self.wins = self.ties = self.losses = self.excluded = 0
        self.maps = 0
        self.cells = []
        self.sources = []


def cell_ratio_from_report(cell, cand, base, metric):
    entry = _paired_entry(cell, cand, base)
    if entry is None:
        return None
    comp = _comparison(entry, metric)
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
    if metric == "plan_time_ns":
        s = (planner_cell.get("timing") or {}).get("plan_time_ns")
    else:
        s = planner_cell["metrics"].get(metric)
    if not isinstance(s, dict):
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


def _planner_cell(cell, label):
    for p in cell["planners"]:
        if p["planner"] == label:
            return p
    return None


# ---------------------------------------------------------------------------------------------
# One comparison over all sources


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
    indirect = {"c": Acc(), "b": Acc(), "via": set(), "cells": [], "sources": []}
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
        cells = [c for c in cells if _planner_cell(c, cand) and _planner_cell(c, base)]
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
            indirect.setdefault("maps", 0)
            indirect["maps"] = indirect.get("maps", 0) + maps_here
        elif statistic == "difference":
            ok = True
            for c in cells:
                mc = summary_moments(_planner_cell(c, cand), metric)
                mb = summary_moments(_planner_cell(c, base), metric)
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
                   maps=indirect.get("maps", 0), cells=indirect["cells"], sources=indirect["sources"],
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
                t = agvreport.t_quantile(0.975, df)
                lo, hi = est - t * se, est + t * se
        res.update(estimate=est, lo=lo, hi=hi, n=min(mc.n, mb.n), pairs=min(mc.n, mb.n),
                   maps=unpaired["maps"], cells=unpaired["cells"], sources=unpaired["sources"],
                   method="unpaired difference of means from the cell summaries (Welch; conservative)")
    res["min_pairs"] = min_pairs
    return res


def verdict(res, comp, paper_value):
    """(level, reason) for one measured comparison (the levels: module docstring)."""
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


# ---------------------------------------------------------------------------------------------
# Claims


def check_claims_file(doc):
    if not isinstance(doc, dict) or not isinstance(doc.get("claims"), list):
        raise ReportError("expected an object with a 'claims' list")
    ids = set()
    for i, c in enumerate(doc["claims"]):
        w = f"claims[{i}]"
        for key in ("id", "paper", "where", "claim", "paper_figure", "compare"):
            if key not in c:
                raise ReportError(f"{w}: missing key '{key}'")
        if c["id"] in ids:
            raise ReportError(f"{w}: duplicate id '{c['id']}'")
        ids.add(c["id"])
        comp = c["compare"]
        if comp.get("type") == "ordering":
            if not isinstance(comp.get("planners"), list) or len(comp["planners"]) < 2:
                raise ReportError(f"{w}.compare.planners: expected at least two planner selectors")
            if comp.get("direction", "decreasing") not in ("decreasing", "increasing"):
                raise ReportError(f"{w}.compare.direction: expected 'decreasing' or 'increasing'")
        else:
            for key in ("candidate", "baseline", "metric"):
                if key not in comp:
                    raise ReportError(f"{w}.compare: missing key '{key}'")
            if comp.get("direction", "smaller") not in ("smaller", "larger"):
                raise ReportError(f"{w}.compare.direction: expected 'smaller' or 'larger'")
            if comp.get("statistic", "ratio") not in ("ratio", "difference"):
                raise ReportError(f"{w}.compare.statistic: expected 'ratio' or 'difference'")
    return doc


def sel_text(sel):
    if isinstance(sel, str):
        return sel
    t = sel.get("label") or sel.get("name")
    if sel.get("params"):
        t += "(" + ", ".join(f"{k}={json.dumps(v)}" for k, v in sel["params"].items()) + ")"
    return t


def check_claims_file(doc):
    if not isinstance(doc, dict) or not isinstance(doc.get("claims"), list):
        raise ReportError("expected an object with a 'claims' list")
    ids = set()
    for i, c in enumerate(doc["claims"]):
        w = f"claims[{i}]"
        for key in ("id", "paper", "where", "claim", "paper_figure", "compare", "setup"):
            if key not in c:
                raise ReportError(f"{w}: missing key '{key}'")
        if c["id"] in ids:
            raise ReportError(f"{w}: duplicate id '{c['id']}'")
        ids.add(c["id"])
        setup = c["setup"]
        if not isinstance(setup, dict) or not all(isinstance(setup.get(k), str) for k, _ in SETUPS):
            raise ReportError(f"{w}.setup: expected {{\"paper\": CONFIG NAME, \"random\": CONFIG NAME}}")
        if "not_comparable" in c and not isinstance(c["not_comparable"], str):
            raise ReportError(f"{w}.not_comparable: expected the reason as a string")
        comp = c["compare"]
        if comp.get("type") == "ordering":
            if not isinstance(comp.get("planners"), list) or len(comp["planners"]) < 2:
                raise ReportError(f"{w}.compare.planners: expected at least two planner selectors")
            if comp.get("direction", "decreasing") not in ("decreasing", "increasing"):
                raise ReportError(f"{w}.compare.direction: expected 'decreasing' or 'increasing'")
        else:
            for key in ("candidate", "baseline", "metric"):
                if key not in comp:
                    raise ReportError(f"{w}.compare: missing key '{key}'")
            if comp.get("direction", "smaller") not in ("smaller", "larger"):
                raise ReportError(f"{w}.compare.direction: expected 'smaller' or 'larger'")
            if comp.get("statistic", "ratio") not in ("ratio", "difference"):
                raise ReportError(f"{w}.compare.statistic: expected 'ratio' or 'difference'")
            if "offset" in comp and not finite(comp["offset"]):
                raise ReportError(f"{w}.compare.offset: expected a number")
    return doc


def sel_text(sel):
    if isinstance(sel, str):
        return sel
    t = sel.get("label") or sel.get("name")
    if sel.get("params"):
        t += "(" + ", ".join(f"{k}={json.dumps(v)}" for k, v in sel["params"].items()) + ")"
    return t


def evaluate_setup(claim, comp, sources, min_pairs, setup_key):
    """One claim against the reports of one set-up (config name claim.setup[setup_key])."""
    config = claim["setup"][setup_key]
    srcs = [s for s in sources if (s.as_setup == setup_key if s.as_setup else s.name == config)]
    out = {"config": config}
    cells = comp.get("paper_cells", comp.get("cells")) if setup_key == "paper" else comp.get("cells")
    if not srcs:
        out.update(verdict=NA, why=f"no report of the set-up '{config}' given", measured=DASH,
                   range=DASH, pairs=0, maps=0, result=None)
        return out
    if comp.get("type") == "ordering":
        sels = comp["planners"]
        steps = []
        for a, b in zip(sels, sels[1:]):
            sub = {"candidate": b, "baseline": a, "metric": comp["metric"], "cells": cells,
                   "direction": "smaller" if comp.get("direction", "decreasing") == "decreasing" else "larger",
                   "statistic": "ratio"}
            res = measure(srcs, sub, min_pairs)
            v, why = verdict(res, sub, None)
            steps.append({"step": f"{sel_text(b)} vs {sel_text(a)}", "verdict": v, "why": why, "result": res})
        verdicts = [st["verdict"] for st in steps]
        for level in (NA, CONTRADICTED, NOT_SIGNIFICANT):
            if level in verdicts:
                v = level
                why = "; ".join(f"{st['step']}: {st['why']}" for st in steps if st["verdict"] == level)
                break
        else:
            v, why = REPRODUCED, "every step significant in the claimed direction (the paper gives no per-step figure)"
        out.update(verdict=v, why=why, steps=steps, result=None,
                   measured="; ".join(f"{st['step']}: {show_interval(st['result'])}" for st in steps
                                      if st["result"]["estimate"] is not None) or DASH,
                   range="; ".join(f"{st['step']}: {show_range(st['result'])}" for st in steps
                                   if st["result"].get("p5") is not None) or DASH,
                   pairs=min((st["result"]["pairs"] for st in steps if st["result"]["pairs"]), default=0),
                   maps=max((st["result"]["maps"] for st in steps), default=0))
        return out
    sub = dict(comp, cells=cells)
    res = measure(srcs, sub, min_pairs)
    v, why = verdict(res, sub, comp.get("paper_value"))
    out.update(verdict=v, why=why, result=res, measured=show_interval(res), range=show_range(res),
               pairs=res["pairs"], maps=res["maps"])
    return out


def evaluate(claim, sources, defaults):
    comp = claim["compare"]
    min_pairs = int(comp.get("min_pairs", claim.get("min_pairs", defaults.get("min_pairs", 30))))
    out = {"id": claim["id"], "paper": claim["paper"], "where": claim["where"], "claim": claim["claim"],
           "paper_figure": claim["paper_figure"], "paper_value": comp.get("paper_value"),
           "measures": claim.get("measures", ""), "note": claim.get("note"),
           "setup": claim["setup"]}
    if comp.get("type") == "ordering":
        out["comparison"] = f"{comp['metric']}: " + " > ".join(sel_text(s) for s in comp["planners"])
    else:
        metric = comp["metric"] if isinstance(comp["metric"], str) else " / ".join(comp["metric"])
        if comp.get("offset"):
            metric += f" {comp['offset']:+g}"
        op = "/" if comp.get("statistic", "ratio") == "ratio" else "-"
        out["comparison"] = (f"{metric} {comp.get('statistic', 'ratio')}: {sel_text(comp['candidate'])} {op} "
                             f"{sel_text(comp['baseline'])}")
    for key, _ in SETUPS:
        r = evaluate_setup(claim, comp, sources, min_pairs, key)
        if claim.get("not_comparable"):
            r["verdict"], r["why"] = NA, claim["not_comparable"] + " (our figure shown for context)"
        out[key + "_setup"] = r
    return out


def md(text):
    """Escape what Markdown would read as emphasis or table syntax (A* is common here)."""
    return str(text).replace("\\", "\\\\").replace("*", "\\*").replace("_", "\\_").replace("|", "\\|")


def compact_cells(cells):
    groups = {}
    for c in cells:
        parts = c.split("/")
        if len(parts) == 3:
            groups.setdefault("/".join(parts[:2]), []).append(parts[2])
        else:
            groups.setdefault(c, [])
    return ", ".join(f"{k}/{{{','.join(v)}}}" if v else k for k, v in groups.items())


def markdown(results, sources, claims_doc, claims_path):
    out = ["# The papers' headline claims against our sweeps", ""]
    out.append(f"Generated by `reports/check_claims.py` from `{os.path.relpath(claims_path)}`. Each claim is "
               "checked twice: on its paper's own set-up (`configs/paper-00N.json`: the paper's grid, cell "
               "edge, obstacle shares, endpoint rule and collision model, each value with its `sources`) and "
               "on our random-map protocol (`configs/paper-00N-random.json`: corner to corner on uniform "
               "maps, except paper 002's blocks). Reports:")
    out.append("")
    for s in sources:
        cfg = s.doc.get("config", {})
        totals = s.doc.get("totals", {})
        mp = cfg.get("map", {}) if isinstance(cfg.get("map"), dict) else {}
        ends = mp.get("endpoints", "?")
        if ends == "fixed":
            ends += f" {mp.get('start')} -> {mp.get('goal')}"
        elif ends == "random":
            ends += f" (min_distance {mp.get('min_distance', 0):g})"
        gens = ", ".join(g.get("name", "?") if isinstance(g, dict) else str(g) for g in cfg.get("generators", []))
        line = (f"- `{s.path}`: sweep `{s.name}`, seed {cfg.get('seed', '?')}, {gens}, "
                f"{cfg.get('maps_per_cell', '?')} maps per cell, {totals.get('cells', len(s.doc['cells']))} cells, "
                f"cell edge {mp.get('cell_edge', 1):g} m, endpoints {ends}, "
                f"planners {', '.join(p['label'] for p in s.planners)}; baseline `{s.baseline}`")
        if s.runs is not None:
            line += f"; per-run records `{s.runs_path}`"
        if s.doc.get("complete") is False:
            line += " **(incomplete sweep)**"
        out.append(line)
    out += ["", f"Verdicts of the {len(results)} claims:", "",
            "| level | " + " | ".join(title for _, title in SETUPS) + " |", "|---|---:|---:|"]
    for level in LEVELS:
        out.append(f"| {level} | " + " | ".join(str(sum(1 for r in results if r[k + '_setup']['verdict'] == level))
                                                for k, _ in SETUPS) + " |")
    out += ["", "Levels: **reproduced** = the claimed direction, significant (95% interval), and the paper's "
            "figure inside our per-map 5-95% range of the same quantity (each map's candidate/baseline ratio or "
            "difference, from the per-run records); **direction only** = the direction significant, the "
            "paper's figure outside that range (by how much is given); **contradicted** = the opposite "
            "direction, significant; **not significant** = the 95% interval contains no-effect; **not "
            "comparable** = not measured the same way, or not measured (the reason is given). Measured: "
            "candidate / baseline geometric-mean ratio over the maps where both succeeded, pooled over the "
            "matching cells, with its 95% interval and % change (differences for clearance). Rules: "
            "`reports/check_claims.py` docstring and `reports/README.md`.", ""]
    head = "| claim | the paper says | measured quantity | paper's figure |"
    rule = "|---|---|---|---|"
    for _, title in SETUPS:
        head += f" {title}: measured (95% CI); per-map 5-95% | verdict |"
        rule += "---|---|"
    out += [head, rule]
    for r in results:
        row = (f"| `{r['id']}` ({r['paper']}, {md(r['where'])}) | {md(r['claim'])} | {md(r['comparison'])}"
               + (f"; {md(r['measures'])}" if r.get("measures") else "") + f" | {md(r['paper_figure'])}"
               + (f" **Note:** {md(r['note'])}" if r.get("note") else "") + " |")
        for k, _ in SETUPS:
            x = r[k + "_setup"]
            row += f" `{x['config']}`: {x['measured']}; {x['range']} | **{x['verdict']}**: {md(x['why'])} |"
        out.append(row.replace("\n", " "))
    out += ["", "## Details", ""]
    for r in results:
        out.append(f"### `{r['id']}`: {r['paper_setup']['verdict']} on the paper's set-up, "
                   f"{r['random_setup']['verdict']} on random maps")
        out.append("")
        out.append(f"- comparison: {md(r['comparison'])}")
        if r.get("measures"):
            out.append(f"- what the paper measured: {md(r['measures'])}")
        out.append(f"- paper's figure: {md(r['paper_figure'])}"
                   + (f" (as a number: {r['paper_value']:g})" if r.get("paper_value") is not None else ""))
        if r.get("note"):
            out.append(f"- note: {md(r['note'])}")
        for k, title in SETUPS:
            x = r[k + "_setup"]
            out.append(f"- {title} (`{x['config']}`): **{x['verdict']}**: {md(x['why'])}")
            if x.get("steps"):
                for st in x["steps"]:
                    res = st["result"]
                    out.append(f"  - step {st['step']}: {show_interval(res)}, per-map 5-95% {show_range(res)}, "
                               f"{res['pairs']} pairs, {st['verdict']}; method: {res['method'] or DASH}")
            elif x.get("result") is not None and x["result"]["estimate"] is not None:
                res = x["result"]
                out.append(f"  - measured {show_interval(res)} over {res['pairs']} pairs ({res['n']} used"
                           + (f", {res.get('excluded', 0)} without a ratio" if res.get("excluded") else "")
                           + f") from {res['maps']} maps; per-map 5-95% {show_range(res)} over {res['range_n']} maps")
                if res["wins"] is not None:
                    out.append(f"  - wins / ties / losses (candidate smaller = win): {res['wins']} / {res['ties']} / {res['losses']}")
                out.append(f"  - method: {res['method'] or DASH}; cells: {compact_cells(res['cells'])}")
        out.append("")
    return "\n".join(out).rstrip() + "\n"


def result_json(r):
    """A claim's results without the bulky internals (the --json output)."""
    out = {k: v for k, v in r.items() if k not in SETUPS_KEYS}
    for k in SETUPS_KEYS:
        x = r[k]
        res = x.get("result") or {}
        out[k] = {"config": x["config"], "verdict": x["verdict"], "why": x["why"], "measured": x["measured"],
                  "pairs": x["pairs"], "maps": x["maps"], "estimate": res.get("estimate"), "lo": res.get("lo"),
                  "hi": res.get("hi"), "n": res.get("n"), "p5": res.get("p5"), "p95": res.get("p95"),
                  "method": res.get("method"),
                  "steps": [{"step": st["step"], "verdict": st["verdict"], "why": st["why"],
                             "estimate": st["result"]["estimate"]} for st in x.get("steps", [])]}
    return out


SETUPS_KEYS = tuple(k + "_setup" for k, _ in SETUPS)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Check the papers' claims against agvbench sweep reports.")
    ap.add_argument("inputs", nargs="+", help="REPORT.json, each optionally followed by its RUNS.jsonl")
    ap.add_argument("--claims", default=DEFAULT_CLAIMS, help="claims file (default: reports/claims.json)")
    ap.add_argument("--out", default=None, help="Markdown to write (default: print to stdout)")
    ap.add_argument("--json", default=None, help="also write the results as JSON here")
    ap.add_argument("--all-as", choices=[k for k, _ in SETUPS], default=None,
                    help="every report stands for this set-up of every claim, whatever its config name "
                         "(a sample sweep)")
    args = ap.parse_args(argv)
    try:
        claims_doc = check_claims_file(agvreport.load_json(args.claims))
    except ReportError as e:
        sys.stderr.write(f"check_claims.py: {args.claims}: {e}\n")
        return agvreport.BAD_INPUT
    sources = []
    for path in args.inputs:
        try:
            if path.endswith(".jsonl"):
                if not sources:
                    raise ReportError("a per-run JSONL must follow the report it belongs to")
                if sources[-1].runs is not None:
                    raise ReportError(f"the report {sources[-1].path} already has per-run records")
                sources[-1].attach_runs(path)
            else:
                sources.append(Source(path, agvreport.load_report(path)))
        except ReportError as e:
            sys.stderr.write(f"check_claims.py: {path}: {e}\n")
            return agvreport.BAD_INPUT
    for src in sources:
        src.as_setup = args.all_as
    defaults = claims_doc.get("defaults", {})
    results = [evaluate(c, sources, defaults) for c in claims_doc["claims"]]
    text = markdown(results, sources, claims_doc, args.claims)
    if args.out:
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump([result_json(r) for r in results], f, indent=1)
    width = max((len(r["id"]) for r in results), default=10)
    for r in results:
        line = (f"{r['id']:<{width}}  paper set-up: {r['paper_setup']['verdict']:<16} "
                f"random maps: {r['random_setup']['verdict']}")
        print(line, file=sys.stdout if args.out else sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
