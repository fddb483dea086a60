"""The reports a claim is checked on: each report with its optional per-run records, its
planners found by label or by registry name and parameters, and the cells a claim's filter
selects.
"""

import json
import os

from agvreports.numeric import finite
from agvreports.report_io import ReportError, baseline_label
from agvreports.runs import matched_records


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
        self.baseline = baseline_label(doc)
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
        for _, r in matched_records(path, self.doc):
            # Keep only what the comparisons read (paper sweeps have many records).
            records.append({"planner": r["planner"], "cell": r["cell"], "map_index": r["map_index"],
                            "outcome": r["outcome"], "metrics": r["metrics"],
                            "timing": {"plan_time_ns": (r.get("timing") or {}).get("plan_time_ns")}})
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
