"""An `agvbench plan --json-out` document (one map, each planner's run on it) read and checked:
every field plot_paths.py draws is validated and normalised, a bad one named.
"""

import json

from agvreports.numeric import finite
from agvreports.report_io import ReportError

BLOCKED = set("@OTW#")  # MovingAI blocked terrain; the engine writes '@'
FREE = set(".GS")


def _points(value, where):
    if not isinstance(value, list):
        raise ReportError(f"{where}: expected a list of [x, y] points, got {type(value).__name__}")
    out = []
    for i, p in enumerate(value):
        if not (isinstance(p, list) and len(p) == 2 and finite(p[0]) and finite(p[1])):
            raise ReportError(f"{where}[{i}]: expected [x, y] with two finite numbers, got {json.dumps(p)[:60]}")
        out.append((float(p[0]), float(p[1])))
    return out


def _cell(value, where, w, h):
    if not (isinstance(value, list) and len(value) == 2 and all(isinstance(v, int) and not isinstance(v, bool) for v in value)):
        raise ReportError(f"{where}: expected [x, y] integer cell, got {json.dumps(value)[:60]}")
    x, y = value
    if not (0 <= x < w and 0 <= y < h):
        raise ReportError(f"{where}: ({x}, {y}) is outside the {w}x{h} grid")
    return x, y


def check_plan(doc):
    """Validate and normalise a plan document; raise ReportError naming the bad field."""
    if not isinstance(doc, dict):
        raise ReportError(f"expected a JSON object (an `agvbench plan --json` document), got {type(doc).__name__}")
    if "schema_version" in doc and "cells" in doc:
        raise ReportError("this is a sweep report, not a plan document (plot it with reports/plot.py)")
    for key in ("map", "runs"):
        if key not in doc:
            raise ReportError(f"missing key '{key}': not an `agvbench plan --json` document")
    m = doc["map"]
    if not isinstance(m, dict):
        raise ReportError("map: expected an object")
    for key in ("width", "height", "rows", "start", "goal"):
        if key not in m:
            raise ReportError(f"map: missing key '{key}'")
    w, h = m["width"], m["height"]
    if not (isinstance(w, int) and isinstance(h, int) and w > 0 and h > 0):
        raise ReportError(f"map: width and height must be positive integers, got {w!r} x {h!r}")
    rows = m["rows"]
    if not isinstance(rows, list) or len(rows) != h:
        raise ReportError(f"map.rows: expected {h} strings (one per row), got "
                          f"{len(rows) if isinstance(rows, list) else type(rows).__name__}")
    grid = []
    for y, r in enumerate(rows):
        if not isinstance(r, str) or len(r) != w:
            raise ReportError(f"map.rows[{y}]: expected a string of {w} characters")
        bad = set(r) - BLOCKED - FREE
        if bad:
            raise ReportError(f"map.rows[{y}]: unknown cell character(s) {''.join(sorted(bad))!r} "
                              "(expected '.' free or '@' obstacle)")
        grid.append([c in BLOCKED for c in r])
    start = _cell(m["start"], "map.start", w, h)
    goal = _cell(m["goal"], "map.goal", w, h)
    runs = doc["runs"]
    if not isinstance(runs, list):
        raise ReportError("runs: expected a list")
    out = []
    for i, run in enumerate(runs):
        where = f"runs[{i}]"
        if not isinstance(run, dict):
            raise ReportError(f"{where}: expected an object")
        if not isinstance(run.get("planner"), str):
            raise ReportError(f"{where}: missing or non-string 'planner'")
        item = {"planner": run["planner"], "outcome": str(run.get("outcome", "unknown")),
                "message": run.get("message") or "",
                "metrics": run.get("metrics") if isinstance(run.get("metrics"), dict) else {},
                "path": _points(run.get("path", []), f"{where}.path"),
                "trajectory": None, "obstacles": [], "unknown": []}
        if run.get("trajectory") is not None:
            item["trajectory"] = _points(run["trajectory"], f"{where}.trajectory")
        obstacles = run.get("obstacles")
        if obstacles is not None:
            if not isinstance(obstacles, list):
                raise ReportError(f"{where}.obstacles: expected a list of {{track, radius}}")
            for j, ob in enumerate(obstacles):
                if not isinstance(ob, dict) or "track" not in ob:
                    raise ReportError(f"{where}.obstacles[{j}]: expected an object with 'track'")
                radius = ob.get("radius", 0.5)
                if not finite(radius) or radius < 0:
                    raise ReportError(f"{where}.obstacles[{j}].radius: expected a non-negative number")
                item["obstacles"].append({"track": _points(ob["track"], f"{where}.obstacles[{j}].track"),
                                          "radius": float(radius)})
        for key in ("unknown_cells", "unknown_obstacles"):
            if run.get(key) is not None:
                item["unknown"] += _points(run[key], f"{where}.{key}")
        out.append(item)
    return {"w": w, "h": h, "grid": grid, "start": start, "goal": goal, "runs": out, "map": m}
