"""A claim graded on each of its two set-ups: the reports of the set-up chosen, its comparison
(or an ordering's every step) measured and given its verdict.
"""

import json

from agvreports.claims.claims_file import SETUPS
from agvreports.claims.measure import measure
from agvreports.claims.show import DASH, show_interval, show_range
from agvreports.claims.verdict import CONTRADICTED, NA, NOT_SIGNIFICANT, REPRODUCED, verdict


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
