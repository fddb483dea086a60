#!/usr/bin/python3
"""Synthetic agvbench sweep reports (reports/SCHEMA.md, schema_version 2) for testing the report
scripts without the engine.

Each planner gets a simple per-map model relative to the baseline (multiplicative factors with
log-normal noise), runs are drawn from a seeded RNG, and the per-run records are aggregated the
way engine/outputs/report.cpp does it (summaries over successful runs, Wilson intervals, paired
geometric-mean ratios with t intervals on the log ratios). So a test can set "HMA* is 12% shorter
than A*" and check what the claims checker makes of it, and can also write the per-run JSON
Lines file the report was built from.

    /usr/bin/python3 tests/reports/synth_report.py OUT.json [RUNS.jsonl]   # the default spec
"""

import json
import math
import os
import random
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "reports"))
from agvreports import stats  # noqa: E402
from agvreports.runs import config_hash  # noqa: E402

METRICS = ["path_length", "path_length_m", "waypoints", "turns", "turn_angle_rad",
           "smoothness_mean", "smoothness_max", "min_clearance", "motion_time_s",
           "search_expansions", "optimality_ratio"]
PAIRED = ["path_length", "waypoints", "turns", "turn_angle_rad", "search_expansions",
          "motion_time_s"]

# factor: multiplicative effect vs the baseline; sigma: log-normal spread per map.
DEFAULT_SPEC = {
    "name": "synthetic",
    "seed": 11,
    "generators": ["uniform", "blocks"],
    "sizes": [[16, 16], [32, 32], [64, 64]],
    "densities": [0.1, 0.2, 0.3, 0.4],
    "maps_per_cell": 30,
    "baseline": "astar",
    "planners": [
        {"label": "astar", "name": "astar", "params": {"corner_rule": "allow"}, "model": {}},
        {"label": "dijkstra", "name": "dijkstra", "params": {"corner_rule": "allow"},
         "model": {"length": 1.0, "sigma_length": 0.0, "expanded": 3.0, "time": 2.5}},
        {"label": "ma_star", "name": "ma_star", "params": {"g_mode": "euclid_from_start"},
         "model": {"length": 0.95, "nodes": 0.35, "turns": 0.6, "expanded": 0.5, "time": 0.8}},
        {"label": "hma_star", "name": "hma_star", "params": {"inertia": "stochastic"},
         "model": {"length": 0.9, "nodes": 0.3, "turns": 0.4, "expanded": 0.5, "time": 6.0,
                   "success": 0.97}},
    ],
}


def _summary(values):
    values = [v for v in values if v is not None and math.isfinite(v)]
    n = len(values)
    out = {"count": n, "mean": None, "stddev": None, "min": None, "p5": None, "median": None,
           "p95": None, "max": None, "ci95": [None, None]}
    if n == 0:
        return out
    m = stats.Moments.of(values)
    s = sorted(values)

    def q(p):
        h = (n - 1) * p
        lo = int(math.floor(h))
        if lo + 1 >= n:
            return s[-1]
        return s[lo] + (h - lo) * (s[lo + 1] - s[lo])

    lo, hi = m.interval()
    out.update({"mean": m.mean, "stddev": m.sd, "min": s[0], "p5": q(0.05), "median": q(0.5),
                "p95": q(0.95), "max": s[-1], "ci95": [lo, hi]})
    return out


def _paired(cand, base, tol=1e-9):
    pairs = wins = ties = losses = excluded = 0
    logs = []
    for c, b in zip(cand, base):
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
        if c > 0 and b > 0:
            logs.append(math.log(c / b))
        elif c == 0 and b == 0:
            logs.append(0.0)
        else:
            excluded += 1
    gm, ci = None, [None, None]
    if logs:
        m = stats.Moments.of(logs)
        gm = math.exp(m.mean)
        lo, hi = m.interval()
        if lo is not None:
            ci = [math.exp(lo), math.exp(hi)]
    # Wilcoxon is not needed by the scripts; a normal-approximation stand-in keeps the shape.
    return {"pairs": pairs, "geo_mean_ratio": gm, "ci95": ci, "ratios_excluded": excluded,
            "wins": wins, "ties": ties, "losses": losses,
            "wilcoxon_p": None if pairs == 0 else (1.0 if wins == losses else 0.01)}


def simulate(spec):
    """Per-run records (SCHEMA.md 'Per-run records') for the spec, in task order."""
    rng = random.Random(spec["seed"])
    records = []
    for gen in spec["generators"]:
        for (w, h) in spec["sizes"]:
            for d in spec["densities"]:
                cell = f"{gen}/{w}x{h}/{d:g}"
                for m in range(spec["maps_per_cell"]):
                    straight = math.hypot(w - 1, h - 1)
                    optimum = straight * (1.02 + 0.35 * d) * math.exp(rng.gauss(0, 0.03))
                    base = {
                        "path_length": optimum * math.exp(abs(rng.gauss(0, 0.01))),
                        "waypoints": max(2.0, round((w + h) * 0.55 * math.exp(rng.gauss(0, 0.1)))),
                        "turns": max(1.0, round((2 + 12 * d) * (w / 16) ** 0.5 * math.exp(rng.gauss(0, 0.25)))),
                        "search_expansions": round(w * h * (0.15 + 0.8 * d) * math.exp(rng.gauss(0, 0.2))),
                        "min_clearance": max(0.0, 0.5 - 0.6 * d + rng.gauss(0, 0.1)),
                        "time": 40.0 * w * h * (0.2 + d) * math.exp(rng.gauss(0, 0.15)),
                    }
                    for p in spec["planners"]:
                        mod = p.get("model", {})
                        prng = random.Random(f"{spec['seed']}/{cell}/{m}/{p['label']}")
                        ok = prng.random() < mod.get("success", 1.0)
                        rec = {
                            "tool": "agvbench", "journal_version": 1,
                            "task_id": f"synthetic/{cell}/{m}/{p['label']}",
                            "config_hash": "0000000000000000", "planner": p["label"],
                            "planner_name": p["name"], "generator": gen, "size": [w, h],
                            "density": d, "cell": cell, "map_index": m, "seed": spec["seed"],
                            "map": {"rejections": 0, "obstacle_fraction": d},
                            "outcome": "success" if ok else "no_path",
                            "message": "" if ok else "synthetic failure",
                        }
                        metrics = {k: None for k in METRICS}
                        sig = mod.get("sigma", 0.03)

                        def f(key, default=1.0, sigma=None):
                            s = mod.get("sigma_" + key, sig if sigma is None else sigma)
                            return mod.get(key, default) * math.exp(prng.gauss(0, s) if s > 0 else 0.0)

                        if ok:
                            length = base["path_length"] * f("length")
                            nodes = max(2.0, round(base["waypoints"] * f("nodes", sigma=0.1)))
                            turns = max(0.0, round(base["turns"] * f("turns", sigma=0.15)))
                            angle = turns * 0.785 * math.exp(prng.gauss(0, 0.1))
                            metrics.update({
                                "path_length": length, "path_length_m": length,
                                "waypoints": nodes, "turns": turns, "turn_angle_rad": angle,
                                "smoothness_mean": angle / length, "smoothness_max": 0.785 if turns else 0.0,
                                "min_clearance": base["min_clearance"] + mod.get("clearance_add", 0.0),
                                "motion_time_s": length / 1.0 + nodes * 0.1 + angle / math.pi,
                                "search_expansions": max(1.0, round(base["search_expansions"] * f("expanded", sigma=0.1))),
                                "optimality_ratio": length / optimum,
                            })
                        rec["metrics"] = metrics
                        t = base["time"] * f("time", sigma=0.2)
                        rec["timing"] = {"plan_time_ns": int(t), "phases": {"search": int(t * 0.9)}}
                        records.append(rec)
    return records


def aggregate(spec, records):
    by = {}
    for r in records:
        by.setdefault(r["cell"], {}).setdefault(r["planner"], []).append(r)
    cells = []
    labels = [p["label"] for p in spec["planners"]]
    base = spec["baseline"]
    for gen in spec["generators"]:
        for (w, h) in spec["sizes"]:
            for d in spec["densities"]:
                key = f"{gen}/{w}x{h}/{d:g}"
                runs = by[key]
                planners = []
                for p in spec["planners"]:
                    rs = sorted(runs[p["label"]], key=lambda r: r["map_index"])
                    succ = [r for r in rs if r["outcome"] == "success"]
                    fails = {}
                    for r in rs:
                        if r["outcome"] != "success":
                            fails[r["outcome"]] = fails.get(r["outcome"], 0) + 1
                    lo, hi = stats.wilson(len(succ), len(rs))
                    planners.append({
                        "planner": p["label"], "name": p["name"], "runs": len(rs),
                        "successes": len(succ), "success_rate": len(succ) / len(rs),
                        "success_ci95": [lo, hi], "failures": fails,
                        "metrics": {k: _summary([r["metrics"][k] for r in succ]) for k in METRICS},
                        "timing": {"plan_time_ns": _summary([float(r["timing"]["plan_time_ns"]) for r in rs]),
                                   "phases": {"search": _summary([float(r["timing"]["phases"]["search"]) for r in rs])}},
                    })
                paired = []
                bruns = {r["map_index"]: r for r in runs[base]}
                for label in labels:
                    if label == base:
                        continue
                    cruns = {r["map_index"]: r for r in runs[label]}
                    both = [m for m in sorted(cruns) if cruns[m]["outcome"] == "success"
                            and bruns[m]["outcome"] == "success"]
                    metrics = {k: _paired([cruns[m]["metrics"][k] for m in both],
                                          [bruns[m]["metrics"][k] for m in both]) for k in PAIRED}
                    timing = _paired([float(cruns[m]["timing"]["plan_time_ns"]) for m in both],
                                     [float(bruns[m]["timing"]["plan_time_ns"]) for m in both])
                    paired.append({"planner": label, "baseline": base, "metrics": metrics,
                                   "timing": {"plan_time_ns": timing}})
                cells.append({
                    "cell": key, "generator": gen, "width": w, "height": h, "density": d,
                    "maps": spec["maps_per_cell"], "rejections": 0,
                    "obstacle_fraction": _summary([d] * spec["maps_per_cell"]),
                    "planners": planners, "paired": paired,
                })
    n_runs = len(records)
    return {
        "schema_version": 2,
        "tool": "agvbench",
        "config": {
            "name": spec["name"], "seed": spec["seed"], "generators": spec["generators"],
            "sizes": spec["sizes"], "densities": spec["densities"],
            "maps_per_cell": spec["maps_per_cell"],
            "map": {"endpoints": "corners", "require_solvable": True, "solvable_rule": "no_corner_cut",
                    "cell_edge": 1.0},
            "planners": [{"label": p["label"], "name": p["name"], "params": p.get("params", {})}
                         for p in spec["planners"]],
            "baseline": base, "time_limit_s": 10,
            "motion": {"line_speed_mps": 1.0, "node_time_s": 0.1, "turn_speed_radps": math.pi},
        },
        "complete": True,
        "totals": {"cells": len(cells), "maps": len(cells) * spec["maps_per_cell"], "runs": n_runs},
        "cells": cells,
        "environment": {"compiler": "synthetic", "build": "none", "git_revision": "none",
                        "cpu_model": "synthetic", "hardware_threads": 1, "threads": 1,
                        "host": "synthetic"},
        "timing": {"wall_s": 1.0, "runs_per_s": float(n_runs)},
    }


def make(spec, report_path, runs_path=None):
    records = simulate(spec)
    report = aggregate(spec, records)
    # The records carry their report's config hash, as the engine's do: the scripts check it.
    digest = config_hash(report["config"])
    for r in records:
        r["config_hash"] = digest
    with open(report_path, "w", encoding="utf-8") as f:
        json.dump(report, f, indent=1)
        f.write("\n")
    if runs_path:
        with open(runs_path, "w", encoding="utf-8") as f:
            for r in records:
                f.write(json.dumps(r) + "\n")
    return report


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    make(DEFAULT_SPEC, sys.argv[1], sys.argv[2] if len(sys.argv) == 3 else None)
