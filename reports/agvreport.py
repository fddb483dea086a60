"""Shared helpers for the report scripts (plot.py, check_claims.py): loading and checking an
`agvbench run` report against reports/SCHEMA.md (schema_version 2), and the few statistics
the scripts need (Student t quantiles, pooling of per-cell summaries).

Standard library only: this module never imports matplotlib, so a bad report is rejected with
exit code 2 even on a machine without it.
"""

import json
import math
from statistics import NormalDist

SCHEMA_VERSION = 2
BAD_INPUT = 2  # exit code for bad or old-schema input, as the engine uses


class ReportError(Exception):
    """A file that is not a readable schema-2 agvbench report (message names the field)."""


# ---------------------------------------------------------------------------------------------
# Loading and checking


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
        paired = _need(cell, "paired", w, list)
        for j, c in enumerate(paired):
            cw = f"{w}.paired[{j}]"
            _need(c, "planner", cw, str)
            _need(c, "baseline", cw, str)
            metrics = _need(c, "metrics", cw, dict)
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


def size_text(w, h):
    return f"{int(w)}x{int(h)}"


def density_text(d):
    return f"{d:g}"


# ---------------------------------------------------------------------------------------------
# Statistics (no scipy): Student t via the regularized incomplete beta function.


def _betacf(a, b, x):
    # Continued fraction for the incomplete beta function (modified Lentz).
    tiny = 1e-300
    qab, qap, qam = a + b, a + 1.0, a - 1.0
    c, d = 1.0, 1.0 - qab * x / qap
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 400):
        m2 = 2 * m
        aa = m * (b - m) * x / ((qam + m2) * (a + m2))
        d = 1.0 + aa * d
        d = 1.0 / (d if abs(d) > tiny else tiny)
        c = 1.0 + aa / c
        c = c if abs(c) > tiny else tiny
        h *= d * c
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2))
        d = 1.0 + aa * d
        d = 1.0 / (d if abs(d) > tiny else tiny)
        c = 1.0 + aa / c
        c = c if abs(c) > tiny else tiny
        delta = d * c
        h *= delta
        if abs(delta - 1.0) < 1e-15:
            break
    return h


def betainc(a, b, x):
    """Regularized incomplete beta I_x(a, b)."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    lbt = math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log1p(-x)
    if x < (a + 1.0) / (a + b + 2.0):
        return math.exp(lbt) * _betacf(a, b, x) / a
    return 1.0 - math.exp(lbt) * _betacf(b, a, 1.0 - x) / b


def t_cdf(t, df):
    x = df / (df + t * t)
    tail = 0.5 * betainc(df / 2.0, 0.5, x)
    return 1.0 - tail if t > 0 else tail


def t_quantile(p, df):
    """Quantile of Student's t with df degrees of freedom (df >= 1)."""
    if df <= 0:
        return float("nan")
    if df > 1e7:
        return NormalDist().inv_cdf(p)
    if p == 0.5:
        return 0.0
    if p < 0.5:
        return -t_quantile(1.0 - p, df)
    lo, hi = 0.0, 1.0
    while t_cdf(hi, df) < p:
        hi *= 2.0
        if hi > 1e12:
            return float("inf")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if t_cdf(mid, df) < p:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-13 * max(1.0, hi):
            break
    return 0.5 * (lo + hi)


def t_interval(mean, sd, n, confidence=0.95):
    """Interval of the mean, or (None, None) for fewer than two values."""
    if n < 2 or sd is None or not math.isfinite(sd):
        return (None, None)
    half = t_quantile(1.0 - (1.0 - confidence) / 2.0, n - 1) * sd / math.sqrt(n)
    return (mean - half, mean + half)


class Moments:
    """Count, mean and sum of squared deviations; merges exactly (Chan et al.)."""

    __slots__ = ("n", "mean", "m2")

    def __init__(self, n=0, mean=0.0, m2=0.0):
        self.n, self.mean, self.m2 = n, mean, m2

    @classmethod
    def of(cls, values):
        m = cls()
        for v in values:
            m.add(v)
        return m

    def add(self, x):
        self.n += 1
        d = x - self.mean
        self.mean += d / self.n
        self.m2 += d * (x - self.mean)

    def merge(self, other):
        if other.n == 0:
            return self
        if self.n == 0:
            self.n, self.mean, self.m2 = other.n, other.mean, other.m2
            return self
        n = self.n + other.n
        d = other.mean - self.mean
        self.mean += d * other.n / n
        self.m2 += other.m2 + d * d * self.n * other.n / n
        self.n = n
        return self

    @property
    def sd(self):
        return math.sqrt(self.m2 / (self.n - 1)) if self.n >= 2 else None

    def interval(self, confidence=0.95):
        return t_interval(self.mean, self.sd, self.n, confidence)


def moments_from_summary(n, mean, ci, confidence=0.95):
    """Rebuild (n, mean, M2) of a sample from its mean and its two-sided t interval of the mean
    (the engine's SUMMARY / COMPARISON ci95). Exact up to rounding: sd = half * sqrt(n) / t."""
    if n <= 0 or mean is None:
        return Moments()
    if n == 1:
        return Moments(1, mean, 0.0)
    if not ci or ci[0] is None or ci[1] is None:
        return None
    half = (ci[1] - ci[0]) / 2.0
    t = t_quantile(1.0 - (1.0 - confidence) / 2.0, n - 1)
    sd = half * math.sqrt(n) / t
    return Moments(n, mean, sd * sd * (n - 1))


def wilson(successes, n, confidence=0.95):
    if n <= 0:
        return (None, None)
    z = NormalDist().inv_cdf(1.0 - (1.0 - confidence) / 2.0)
    p = successes / n
    z2n = z * z / n
    centre = (p + z2n / 2.0) / (1.0 + z2n)
    half = z / (1.0 + z2n) * math.sqrt(p * (1.0 - p) / n + z2n / (4.0 * n))
    return (max(0.0, centre - half), min(1.0, centre + half))
