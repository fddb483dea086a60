"""The claims file (reports/claims.json): where it is, its two set-ups, and its check."""

import os

from agvreports.numeric import finite
from agvreports.report_io import ReportError

SETUPS = (("paper", "the paper's set-up"), ("random", "our random maps"))
SETUPS_KEYS = tuple(k + "_setup" for k, _ in SETUPS)
REPORTS = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_CLAIMS = os.path.join(REPORTS, "claims.json")


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
