"""Lookups in one cell of a report (reports/SCHEMA.md CELL): its key, a planner's entry, its
comparison with the baseline, and a metric's SUMMARY or COMPARISON (planning time is kept under
`timing`, the other metrics under `metrics`).
"""

from agvreports.metrics import TIME


def cell_key(cell):
    """The cell's name as the journal's records give it (`uniform/40x40/0.3`)."""
    if isinstance(cell.get("cell"), str):
        return cell["cell"]
    return f"{cell['generator']}/{int(cell['width'])}x{int(cell['height'])}/{float(cell['density']):g}"


def planner_of(cell, label):
    for p in cell["planners"]:
        if p["planner"] == label:
            return p
    return None


def paired_of(cell, label):
    for c in cell["paired"]:
        if c["planner"] == label:
            return c
    return None


def summary_of(p, name):
    """A planner cell's SUMMARY of a metric, or of planning time."""
    if name == TIME:
        t = (p.get("timing") or {}).get(TIME)
        return t if isinstance(t, dict) else None
    s = p["metrics"].get(name)
    return s if isinstance(s, dict) else None


def comparison_of(c, name):
    if name == TIME:
        comp = (c.get("timing") or {}).get(TIME)
    else:
        comp = c["metrics"].get(name)
    return comp if isinstance(comp, dict) else None
