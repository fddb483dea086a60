#!/usr/bin/python3
"""Verdicts of reports/check_claims.py on synthetic reports (tests/reports/synth_report.py):
holds / does not hold / not comparable, the exactness of pooling from report summaries, the
per-run JSONL route, the indirect route, differences, orderings, and bad input (exit 2).

Standard library only (no matplotlib). Usage: test_claims.py REPO_ROOT
"""

import copy
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(ROOT, "tests", "reports"))
sys.path.append(os.path.join(ROOT, "reports"))  # after the standard library: reports/html.py
import synth_report  # noqa: E402
import agvreport  # noqa: E402

PY = sys.executable
CHECK = os.path.join(ROOT, "reports", "check_claims.py")
CLAIMS = os.path.join(ROOT, "reports", "claims.json")
work = tempfile.mkdtemp(prefix="agv_claims_")
failures = 0
passes = 0


def ok(cond, what, detail=""):
    global failures, passes
    if cond:
        passes += 1
        print(f"ok   {what}")
    else:
        failures += 1
        print(f"FAIL {what} {detail}")


def spec(**kw):
    s = copy.deepcopy(synth_report.DEFAULT_SPEC)
    s.update(name="t", generators=["uniform"], sizes=[[20, 20]], densities=[0.2, 0.3, 0.4],
             maps_per_cell=120)
    planners = kw.pop("planners", None)
    s.update(kw)
    if planners is not None:
        s["planners"] = [{"label": "astar", "name": "astar", "params": {"corner_rule": "allow"}, "model": {}}] + planners
    return s


def P(label, name=None, params=None, **model):
    return {"label": label, "name": name or label, "params": params or {}, "model": model}


def make(name, sp, runs=False):
    path = os.path.join(work, name + ".json")
    runs_path = os.path.join(work, name + ".jsonl") if runs else None
    synth_report.make(sp, path, runs_path)
    return path, runs_path


def check(args, claims=CLAIMS):
    out_json = os.path.join(work, "results.json")
    if os.path.exists(out_json):
        os.remove(out_json)
    cmd = [PY, CHECK] + args + ["--claims", claims, "--out", os.path.join(work, "CLAIMS.md"), "--json", out_json]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout, p.stderr)
        return None
    with open(out_json) as f:
        return {r["id"]: r for r in json.load(f)}


def verdict_is(results, cid, expected, why_contains=None):
    r = results.get(cid) if results else None
    got = r["verdict"] if r else None
    cond = got == expected and (why_contains is None or why_contains in r["why"])
    ok(cond, f"{cid}: {expected}" + (f" ({why_contains})" if why_contains else ""),
       f"got {got}: {r['why'] if r else 'no result'}")
    return r


# 1. Paper 000 Table XII against A*: larger effect than the paper's -> holds; missing planners ->
#    not comparable; the pooled figure equals the one recomputed from the per-run records.
p1, r1 = make("hold", spec(planners=[P("hma_star", length=0.86, nodes=0.25, turns=0.3),
                                     P("ma_star", length=0.95, expanded=0.4, time=0.7)]), runs=True)
res = check([p1])
verdict_is(res, "000-XII-hma-vs-astar-length", "holds")
verdict_is(res, "000-XII-hma-vs-prm-length", "not comparable", "planner 'prm' not in report")
verdict_is(res, "000-II-mastar-vs-astar-nodes", "holds")
verdict_is(res, "002-T4-internal-vs-astar-turn", "not comparable", "improved_astar_internal")
verdict_is(res, "004-T2-fusion-vs-astar-dwa-turns", "not comparable", "fusion_kin_dwa")
r = res["000-XII-hma-vs-astar-length"]
with open(r1) as f:
    recs = [json.loads(line) for line in f]
by = {}
for rec in recs:
    by.setdefault((rec["cell"], rec["map_index"]), {})[rec["planner"]] = rec
logs = [math.log(v["hma_star"]["metrics"]["path_length"] / v["astar"]["metrics"]["path_length"])
        for v in by.values() if v["hma_star"]["outcome"] == "success" and v["astar"]["outcome"] == "success"]
m = agvreport.Moments.of(logs)
lo, hi = m.interval()
ok(abs(r["estimate"] - math.exp(m.mean)) < 1e-9 and abs(r["lo"] - math.exp(lo)) < 1e-9
   and abs(r["hi"] - math.exp(hi)) < 1e-9 and r["pairs"] == len(logs),
   "pooling the report's per-cell summaries equals recomputing over all pairs",
   f"{r['estimate']} [{r['lo']}, {r['hi']}] vs {math.exp(m.mean)} [{math.exp(lo)}, {math.exp(hi)}] n={len(logs)}")
res_runs = check([p1, r1])
rr = res_runs["000-XII-hma-vs-astar-length"]
ok(abs(rr["estimate"] - r["estimate"]) < 1e-12, "with the runs attached the report route is used and agrees")

# 2. Effect real but smaller than the paper's -> does not hold; opposite -> does not hold;
#    no difference -> does not hold.
res = check([make("smaller", spec(planners=[P("hma_star", length=0.95)]))[0]])
verdict_is(res, "000-XII-hma-vs-astar-length", "does not hold", "larger effect than our whole interval")
res = check([make("opposite", spec(planners=[P("hma_star", length=1.04)]))[0]])
verdict_is(res, "000-XII-hma-vs-astar-length", "does not hold", "the opposite")
res = check([make("same", spec(planners=[P("hma_star", length=1.0, sigma=0.05, nodes=1.0, turns=1.0)]))[0]])
verdict_is(res, "000-XII-hma-vs-astar-length", "does not hold", "no significant difference")

# 3. Too few pairs; no matching cells.
res = check([make("few", spec(maps_per_cell=5, planners=[P("hma_star", length=0.85)]))[0]])
verdict_is(res, "000-XII-hma-vs-astar-length", "not comparable", "too few pairs")
res = check([make("nocells", spec(sizes=[[32, 32]], planners=[P("hma_star", length=0.85)]))[0]])
verdict_is(res, "000-XII-hma-vs-astar-length", "not comparable", "no cells match")

# 4. A baseline other than the report's: indirect without runs, exact with runs. Direction-only
#    claim (turns) and magnitude claim (Table 5 length).
sp = spec(sizes=[[20, 20], [30, 30], [40, 40]], densities=[0.2], maps_per_cell=150,
          planners=[P("improved_astar_internal", turns=0.6, expanded=0.8, time=0.9),
                    P("improved_astar", length=0.85, turns=0.2)])
p4, r4 = make("p002", sp, runs=True)
res = check([p4])
r = verdict_is(res, "002-T5-full-vs-internal-length", "holds")
ok(r is not None and "indirect" in (r["method"] or ""), "without runs the ratio is indirect (via the report's baseline)")
res2 = check([p4, r4])
r2 = verdict_is(res2, "002-T5-full-vs-internal-length", "holds")
ok(r2 is not None and "per-run" in (r2["method"] or ""), "with runs the ratio is paired from the per-run records")
ok(r is not None and r2 is not None and r["lo"] <= r2["lo"] and r["hi"] >= r2["hi"],
   "the indirect interval is wider than the exact one (conservative)")
verdict_is(res2, "002-S6-internal-vs-astar-turns", "holds", "direction only")

# 5. Differences (clearance): from the summaries (Welch) and from the runs (paired).
sp = spec(planners=[P("alt_astar", clearance_add=0.6, length=0.96)])
p5, r5 = make("p003", sp, runs=True)
res = check([p5])
r = verdict_is(res, "003-T1-alt-vs-astar-clearance", "holds")
ok(r is not None and "Welch" in (r["method"] or "") and abs(r["estimate"] - 0.6) < 1e-6,
   "clearance difference from the cell summaries", str(r and r["estimate"]))
res = check([p5, r5])
r = verdict_is(res, "003-T1-alt-vs-astar-clearance", "holds")
ok(r is not None and "per-run" in (r["method"] or ""), "clearance difference paired from the runs")
res = check([make("p003b", spec(planners=[P("alt_astar", clearance_add=-0.2)]))[0]])
verdict_is(res, "003-T1-alt-vs-astar-clearance", "does not hold", "the opposite")

# 6. Orderings.
order = [P("prm", length=0.97), P("rrt", length=0.95), P("birrt", length=0.93), P("hma_star", length=0.88)]
res = check([make("order", spec(planners=order), runs=True)[0]])
verdict_is(res, "000-XI-length-ordering", "holds")
verdict_is(res, "000-XII-hma-vs-birrt-length", "holds")
swapped = [P("prm", length=0.97), P("rrt", length=1.01), P("birrt", length=0.93), P("hma_star", length=0.88)]
res = check([make("order2", spec(planners=swapped))[0]])
verdict_is(res, "000-XI-length-ordering", "does not hold", "rrt vs prm")

# 7. Several reports pool: pairs add up; selectors by name + params.
a = make("multiA", spec(seed=1, planners=[P("hma_star", length=0.86)]))[0]
b = make("multiB", spec(seed=2, planners=[P("hma_star", length=0.86)]))[0]
ra = check([a])["000-XII-hma-vs-astar-length"]
rb = check([a, b])["000-XII-hma-vs-astar-length"]
ok(rb["pairs"] == 2 * ra["pairs"] or abs(rb["pairs"] - 2 * ra["pairs"]) < 0.1 * ra["pairs"],
   "two reports pool their pairs", f"{ra['pairs']} vs {rb['pairs']}")
dwa = [P("dwa_classic", "dwa", {"score": "classic"}), P("dwa_improved", "dwa", {"score": "improved_003"}, length=0.8)]
p7, r7 = make("dwa", spec(planners=dwa), runs=True)
res = check([p7, r7])
verdict_is(res, "003-S3-improved-dwa-vs-dwa-length", "holds")

# 8. Bad input: exit 2 with a message.
def bad(name, args, pattern, claims=CLAIMS):
    p = subprocess.run([PY, CHECK] + args + ["--claims", claims, "--out", os.path.join(work, "bad.md")],
                       capture_output=True, text=True)
    ok(p.returncode == 2 and pattern in p.stderr, f"bad input {name}: exit 2, '{pattern}'",
       f"exit {p.returncode}: {p.stderr.strip()[:200]}")


notjson = os.path.join(work, "notjson.json")
with open(notjson, "w") as f:
    f.write("{ this is not json")
old = os.path.join(work, "old.json")
with open(old, "w") as f:
    json.dump({"schema_version": 0, "cells": []}, f)
nokey = os.path.join(work, "nokey.json")
with open(nokey, "w") as f:
    json.dump({"config": {}, "cells": []}, f)
badclaims = os.path.join(work, "badclaims.json")
with open(badclaims, "w") as f:
    json.dump({"claims": [{"id": "x"}]}, f)
badruns = os.path.join(work, "bad.jsonl")
with open(badruns, "w") as f:
    f.write('{"planner": "astar"}\n')
bad("not JSON", [notjson], "not valid JSON")
bad("old schema", [old], "schema_version is 0")
bad("no schema_version", [nokey], "schema_version")
bad("missing file", [os.path.join(work, "nope.json")], "no such file")
bad("claims file", [p1], "missing key", claims=badclaims)
bad("runs first", [r1], "must follow the report")
bad("bad runs", [p1, badruns], "missing key 'cell'")
foreign = os.path.join(work, "foreign.jsonl")
with open(foreign, "w") as f:
    f.write('{"tool": "agvbench", "journal_version": 0, "planner": "astar", "cell": "c", '
            '"map_index": 0, "outcome": "success", "metrics": {}}\n')
bad("foreign journal version", [p1, foreign], "journal_version 0; this script reads")

print(f"{passes} passed, {failures} failed")
sys.exit(1 if failures else 0)
