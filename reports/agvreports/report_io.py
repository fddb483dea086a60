"""Loading and checking an `agvbench run` report against reports/SCHEMA.md (schema_version 2),
and the report-wide facts every script reads: the planners in order and the baseline.

Standard library only: this module never imports matplotlib, so a bad report is rejected with
exit code 2 even on a machine without it.
"""

import json

SCHEMA_VERSION = 2
BAD_INPUT = 2  # exit code for bad or old-schema input, as the engine uses


class ReportError(Exception):
    """A file that is not a readable schema-2 agvbench report (message names the field)."""


def _need(obj, key, where, types=None):
    if not isinstance(obj, dict):
        raise ReportError(f"{where}: expected an object, got {type(obj).__name__}")
    if key not in obj:
        raise ReportError(f"{where}: missing key '{key}'")
    value = obj[key]
    if types is not None and not isinstance(value, types):
        names = types.__name__ if isinstance(types, type) else "/".join(t.__name__ for t in types)
        raise ReportError(f"{where}.{key}: expected {names}, got {type(value).__name__}")
    return value


def _check_timing(entry, where):
    """An optional "timing" is an object of objects (SUMMARY or COMPARISON per time): a damaged
    report is refused here, naming the field, not by an AttributeError while drawing."""
    if "timing" not in entry or entry["timing"] is None:
        return
    if not isinstance(entry["timing"], dict):
        raise ReportError(f"{where}.timing: expected an object, got {json.dumps(entry['timing'])}")
    for name, v in entry["timing"].items():
        if not isinstance(v, dict):
            raise ReportError(f"{where}.timing.{name}: expected an object, got {json.dumps(v)}")


def _is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def load_json(path):
    try:
        with open(path, "r", encoding="utf-8") as f:
            return json.load(f)
    except FileNotFoundError:
        raise ReportError("no such file") from None
    except IsADirectoryError:
        raise ReportError("is a directory, expected a JSON file") from None
    except UnicodeDecodeError as e:
        raise ReportError(f"not UTF-8 text ({e.reason})") from None
    except json.JSONDecodeError as e:
        raise ReportError(f"not valid JSON: {e.msg} at line {e.lineno} column {e.colno}") from None
    except OSError as e:
        raise ReportError(f"cannot read: {e.strerror}") from None


def check_report(doc):
    """Raise ReportError unless doc has the schema-2 shape the scripts rely on."""
    if not isinstance(doc, dict):
        raise ReportError(f"expected a JSON object (an agvbench report), got {type(doc).__name__}")
    if "schema_version" not in doc:
        if "runs" in doc and "map" in doc:
            raise ReportError("this is an `agvbench plan` document, not a sweep report "
                              "(draw it with reports/plot_paths.py)")
        raise ReportError("missing key 'schema_version': not an agvbench report, or one older "
                          "than schema version 1")
    version = doc["schema_version"]
    if version != SCHEMA_VERSION:
        raise ReportError(f"schema_version is {json.dumps(version)}, these scripts read version "
                          f"{SCHEMA_VERSION} (regenerate the report with the current agvbench)")
    _need(doc, "config", "report", dict)
    cells = _need(doc, "cells", "report", list)
    for i, cell in enumerate(cells):
        w = f"cells[{i}]"
        for key in ("generator",):
            _need(cell, key, w, str)
        for key in ("width", "height", "density"):
            v = _need(cell, key, w)
            if not _is_number(v):
                raise ReportError(f"{w}.{key}: expected a number, got {json.dumps(v)}")
        planners = _need(cell, "planners", w, list)
        for j, p in enumerate(planners):
            pw = f"{w}.planners[{j}]"
            _need(p, "planner", pw, str)
            _need(p, "runs", pw)
            _need(p, "successes", pw)
            _need(p, "success_ci95", pw, list)
            metrics = _need(p, "metrics", pw, dict)
            for name, s in metrics.items():
                if not isinstance(s, dict) or "mean" not in s or "ci95" not in s:
                    raise ReportError(f"{pw}.metrics.{name}: expected a SUMMARY object with "
                                      "'mean' and 'ci95'")
            _check_timing(p, pw)
        paired = _need(cell, "paired", w, list)
        for j, c in enumerate(paired):
            cw = f"{w}.paired[{j}]"
            _need(c, "planner", cw, str)
            _need(c, "baseline", cw, str)
            metrics = _need(c, "metrics", cw, dict)
            _check_timing(c, cw)
            for name, comp in metrics.items():
                if not isinstance(comp, dict) or "geo_mean_ratio" not in comp or "pairs" not in comp:
                    raise ReportError(f"{cw}.metrics.{name}: expected a COMPARISON object with "
                                      "'pairs' and 'geo_mean_ratio'")
    return doc


def load_report(path):
    return check_report(load_json(path))


def planner_order(report):
    """Planner labels in config order (falling back to the order they appear in cells)."""
    labels = []
    for p in report.get("config", {}).get("planners", []) or []:
        if isinstance(p, dict) and isinstance(p.get("label"), str):
            labels.append(p["label"])
        elif isinstance(p, str):
            labels.append(p)
    for cell in report["cells"]:
        for p in cell["planners"]:
            if p["planner"] not in labels:
                labels.append(p["planner"])
    return labels


def baseline_label(report):
    b = report.get("config", {}).get("baseline")
    if isinstance(b, str):
        return b
    for cell in report["cells"]:
        for c in cell["paired"]:
            return c["baseline"]
    return None
