#!/usr/bin/python3
"""Verdicts of reports/check_claims.py on synthetic reports (tests/reports/synth_report.py):
each level (reproduced, direction only, contradicted, not significant, not comparable) made to
happen by the synthetic effect, the per-map 5-95% range against its own recomputation, the two
set-ups side by side, paper 002's per-size cells, paper 004's turn count (key points - 2),
differences, orderings, and bad input (exit 2).

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
sys.path.append(os.path.join(ROOT, "reports"))
import synth_report  # noqa: E402
from agvreports import stats  # noqa: E402

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


def verdict_is(results, cid, expected, why_contains=None, setup="paper_setup"):
    """Checks a claim's level on one set-up (the paper's by default); returns the claim's result."""
    r = results.get(cid) if results else None
    x = r[setup] if r else None
    got = x["verdict"] if x else None
    cond = got == expected and (why_contains is None or why_contains in x["why"])
    ok(cond, f"{cid}: {expected}" + (f" ({why_contains})" if why_contains else ""),
       f"got {got}: {x['why'] if x else 'no result'}")
    return r


def by_map(runs_path):
    with open(runs_path) as f:
        recs = [json.loads(line) for line in f]
    out = {}
    for rec in recs:
        out.setdefault((rec["cell"], rec["map_index"]), {})[rec["planner"]] = rec
    return out


def quantile(values, q):
    v = sorted(values)
    pos = q * (len(v) - 1)
    i = int(math.floor(pos))
    return v[-1] if i + 1 >= len(v) else v[i] + (pos - i) * (v[i + 1] - v[i])


P0, R0 = "paper-000", "paper-000-random"

# 1. reproduced: HMA* 12% shorter than A*, maps spread +-7%: the paper's 0.879 inside our per-map
#    5-95% range. The pooled figure equals the one recomputed from the runs, and so does the range.
p1, r1 = make(P0, spec(name=P0, planners=[P("hma_star", length=0.88, nodes=0.25, turns=0.3),
                                          P("ma_star", length=0.95, expanded=0.4, time=0.7)]), runs=True)
res = check([p1, r1])
r = verdict_is(res, "000-XII-hma-vs-astar-length", "reproduced", "inside our per-map 5-95% range")
x = r["paper_setup"]
pairs = [v for v in by_map(r1).values() if v["hma_star"]["outcome"] == "success" and v["astar"]["outcome"] == "success"]
ratios = [v["hma_star"]["metrics"]["path_length"] / v["astar"]["metrics"]["path_length"] for v in pairs]
m = stats.Moments.of([math.log(q) for q in ratios])
lo, hi = m.interval()
ok(abs(x["estimate"] - math.exp(m.mean)) < 1e-9 and abs(x["lo"] - math.exp(lo)) < 1e-9
   and abs(x["hi"] - math.exp(hi)) < 1e-9 and x["pairs"] == len(ratios),
   "the pooled ratio and interval equal a recomputation over all pairs")
ok(abs(x["p5"] - quantile(ratios, 0.05)) < 1e-12 and abs(x["p95"] - quantile(ratios, 0.95)) < 1e-12
   and x["p5"] < 0.8792 < x["p95"], "the per-map 5-95% range is the runs' own quantiles",
   f"{x['p5']} {x['p95']} vs {quantile(ratios, 0.05)} {quantile(ratios, 0.95)}")
verdict_is(res, "000-XII-hma-vs-prm-length", "not comparable", "planner 'prm' not in report")
ok(r["random_setup"]["verdict"] == "not comparable" and "no report of the set-up 'paper-000-random'" in r["random_setup"]["why"],
   "a set-up without a report is not comparable", r["random_setup"]["why"])
# A claim the paper measured otherwise (MATLAB seconds) is not comparable whatever we measure.
verdict_is(res, "000-II-mastar-vs-astar-time", "not comparable", "MATLAB")
# Without the per-run records the magnitude cannot be graded: direction only, saying why.
verdict_is(check([p1]), "000-XII-hma-vs-astar-length", "direction only", "no per-run records")

# A sample sweep of any name stands for one set-up with --all-as.
ps, rs = make("sample", spec(name="sample", planners=[P("hma_star", length=0.88)]), runs=True)
verdict_is(check([ps, rs, "--all-as", "random"]), "000-XII-hma-vs-astar-length", "reproduced", setup="random_setup")
verdict_is(check([ps, rs]), "000-XII-hma-vs-astar-length", "not comparable", "no report of the set-up",
           setup="random_setup")

# 2. direction only, both ways: an effect smaller than the paper's (3% against 12%, tight maps)
#    and one larger than the paper's (HMA* 25% shorter than RRT, the paper says 7.8%).
p2, r2 = make(P0 + "s", spec(name=P0, planners=[P("hma_star", length=0.97, sigma=0.01)]), runs=True)
r = verdict_is(check([p2, r2]), "000-XII-hma-vs-astar-length", "direction only", "lies below our per-map")
ok(r is not None and r["paper_setup"]["p5"] > 0.8792, "the paper's figure is below the 5% point")
p2b, r2b = make(P0 + "l", spec(name=P0, planners=[P("rrt", sigma=0.01), P("hma_star", length=0.75, sigma=0.01)]),
                runs=True)
verdict_is(check([p2b, r2b]), "000-XII-hma-vs-rrt-length", "direction only", "lies above our per-map")

# 3. contradicted (significantly longer) and not significant (no effect, wide spread).
p3, r3 = make(P0 + "o", spec(name=P0, planners=[P("hma_star", length=1.04)]), runs=True)
verdict_is(check([p3, r3]), "000-XII-hma-vs-astar-length", "contradicted", "the opposite")
p3b, r3b = make(P0 + "n", spec(name=P0, planners=[P("hma_star", length=1.0, sigma=0.05)]), runs=True)
verdict_is(check([p3b, r3b]), "000-XII-hma-vs-astar-length", "not significant", "contains 1")

# 4. Too few pairs; no matching cells.
res = check([make("few", spec(name=P0, maps_per_cell=5, planners=[P("hma_star", length=0.88)]), runs=True)[0]])
verdict_is(res, "000-XII-hma-vs-astar-length", "not comparable", "too few pairs")
res = check([make("nocells", spec(name=P0, sizes=[[32, 32]], planners=[P("hma_star", length=0.88)]))[0]])
verdict_is(res, "000-XII-hma-vs-astar-length", "not comparable", "no cells match")

# 5. Both set-ups side by side: the paper's set-up reproduces, our random maps contradict.
pr, rr = make(R0, spec(name=R0, seed=5, planners=[P("hma_star", length=1.05)]), runs=True)
res = check([p1, r1, pr, rr])
r = verdict_is(res, "000-XII-hma-vs-astar-length", "reproduced")
ok(r is not None and r["random_setup"]["verdict"] == "contradicted" and r["random_setup"]["config"] == R0
   and r["paper_setup"]["pairs"] == x["pairs"], "each set-up is graded on its own reports only",
   r and str(r["random_setup"]))
md_text = open(os.path.join(work, "CLAIMS.md")).read()
ok("| reproduced | " in md_text and "| contradicted | " in md_text and "our random maps" in md_text,
   "CLAIMS.md counts each level for both set-ups")

# 6. Paper 002: the paper's set-up compares each size at its own obstacle share (paper_cells);
#    the random set-up pools every cell. A baseline other than the report's goes through the runs.
P2 = "paper-002"
sp = spec(name=P2, sizes=[[20, 20], [30, 30], [40, 40]], densities=[0.135, 0.151, 0.242], maps_per_cell=60,
          planners=[P("improved_astar_internal", turns=0.6, expanded=0.8, time=0.9),
                    P("improved_astar", length=0.89, turns=0.3)])
p6, r6 = make(P2, sp, runs=True)
sp_r = dict(sp, name=P2 + "-random", seed=6)
p6r, r6r = make(P2 + "-random", sp_r, runs=True)
res = check([p6, r6, p6r, r6r])
r = verdict_is(res, "002-T5-full-vs-internal-length", "reproduced")
ok(r is not None and r["paper_setup"]["pairs"] == 3 * 60 and r["random_setup"]["pairs"] == 9 * 60,
   "paper_cells: three of the nine cells on the paper's set-up, all nine on the random one",
   r and f"{r['paper_setup']['pairs']} / {r['random_setup']['pairs']}")
ok(r is not None and "impossible" in (r.get("note") or "") and "26.87" in r["note"],
   "002-T5 carries the arithmetic of the paper's impossible lengths")
verdict_is(res, "002-S6-internal-vs-astar-turns", "reproduced", "no figure")
r = verdict_is(res, "002-S53-full-vs-astar-motion", "direction only")
ok(r is not None and r["paper_setup"]["pairs"] == 60, "a 20x20-only claim on the paper's set-up uses the 20x20 cell at 13.5%")

# 7. Differences (clearance), paired from the runs: reproduced when +0.5 is typical of a map,
#    contradicted when the alternative A* keeps less clearance.
p7, r7 = make("paper-003", spec(name="paper-003", planners=[P("alt_astar", clearance_add=0.5, length=0.96)]), runs=True)
r = verdict_is(check([p7, r7]), "003-T1-alt-vs-astar-clearance", "reproduced")
ok(r is not None and "per-run" in (r["paper_setup"]["method"] or ""), "clearance difference paired from the runs")
p7b, r7b = make("paper-003b", spec(name="paper-003", planners=[P("alt_astar", clearance_add=-0.2)]), runs=True)
verdict_is(check([p7b, r7b]), "003-T1-alt-vs-astar-clearance", "contradicted", "the opposite")
dwa = [P("dwa_classic", "dwa", {"score": "classic"}), P("dwa_improved", "dwa", {"score": "improved_003"}, length=0.85)]
p7c, r7c = make("paper-003c", spec(name="paper-003", planners=dwa), runs=True)
verdict_is(check([p7c, r7c]), "003-S3-improved-dwa-vs-dwa-length", "reproduced")

# 8. Orderings: every step significant -> reproduced; one step reversed -> contradicted.
order = [P("prm", length=0.97), P("rrt", length=0.95), P("birrt", length=0.93), P("hma_star", length=0.88)]
verdict_is(check(list(make("order", spec(name=P0, planners=order), runs=True))), "000-XI-length-ordering", "reproduced")
swapped = [P("prm", length=0.97), P("rrt", length=1.01), P("birrt", length=0.93), P("hma_star", length=0.88)]
verdict_is(check(list(make("order2", spec(name=P0, planners=swapped), runs=True))), "000-XI-length-ordering",
           "contradicted", "rrt vs prm")

# 9. Paper 004's turns: the global path's key points minus start and goal (compare.offset -2),
#    per map, from the runs (the report cannot pair a shifted count).
P4 = "paper-004"
sp4 = spec(name=P4, sizes=[[21, 21]], densities=[0.1, 0.2], maps_per_cell=80,
           planners=[P("fusion_astar_dwa"), P("fusion_kin_dwa", turns=0.75, sigma_turns=0.0)])
recs = synth_report.simulate(sp4)
for rec in recs:
    t = rec["metrics"]["turns"]
    rec["metrics"]["key_points"] = None if t is None else t + 2
p9, r9 = os.path.join(work, "p4.json"), os.path.join(work, "p4.jsonl")
report9 = synth_report.aggregate(sp4, recs)
for rec in recs:  # the journal of this report: check_claims.py matches its config hash
    rec["config_hash"] = synth_report.config_hash(report9["config"])
with open(p9, "w") as f:
    json.dump(report9, f)
with open(r9, "w") as f:
    f.write("".join(json.dumps(rec) + "\n" for rec in recs))
r = check([p9, r9])["004-T2-fusion-vs-astar-dwa-turns"]
pairs = [v for v in by_map(r9).values()
         if v["fusion_kin_dwa"]["outcome"] == "success" and v["fusion_astar_dwa"]["outcome"] == "success"]
logs = []
for v in pairs:
    c, b = v["fusion_kin_dwa"]["metrics"]["turns"], v["fusion_astar_dwa"]["metrics"]["turns"]
    if c > 0 and b > 0:
        logs.append(math.log(c / b))
    elif c == 0 and b == 0:
        logs.append(0.0)
est = math.exp(sum(logs) / len(logs))
ok(abs(r["paper_setup"]["estimate"] - est) < 1e-9 and r["paper_setup"]["verdict"] in ("reproduced", "direction only"),
   "key_points - 2 gives the turn-count ratio per map", f"{r['paper_setup']} vs {est}")

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
    f.write('{"tool": "agvbench", "journal_version": 1, "planner": "astar"}\n')
bad("not JSON", [notjson], "not valid JSON")
bad("old schema", [old], "schema_version is 0")
bad("no schema_version", [nokey], "schema_version")
bad("missing file", [os.path.join(work, "nope.json")], "no such file")
bad("claims file", [p1], "missing key", claims=badclaims)
nosetup = os.path.join(work, "nosetup.json")
with open(CLAIMS) as f:
    doc = json.load(f)
doc["claims"][0]["setup"] = {"paper": "paper-000"}
with open(nosetup, "w") as f:
    json.dump(doc, f)
bad("claim without a random set-up", [p1], "setup", claims=nosetup)
bad("runs first", [r1], "must follow the report")
bad("bad runs", [p1, badruns], "key 'cell'")
foreign = os.path.join(work, "foreign.jsonl")
with open(foreign, "w") as f:
    f.write('{"tool": "agvbench", "journal_version": 0, "planner": "astar", "cell": "c", '
            '"map_index": 0, "outcome": "success", "metrics": {}}\n')
bad("foreign journal version", [p1, foreign], "journal_version 0; this script reads")
# Another report's journal (another config): refused by its config hash (issue 49, class 5).
bad("another config's journal", [p1, r9], "not of the report's (hash")

print(f"{passes} passed, {failures} failed")
sys.exit(1 if failures else 0)
