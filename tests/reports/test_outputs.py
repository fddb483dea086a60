#!/usr/bin/python3
"""No report script writes over what it reads (issue 49, class 4): for check_claims.py, plot.py,
plot_paths.py and html_report.py, an output that is one of the inputs (the same path, another
spelling of it, a symbolic link to it, a hard link to it) or another output is exit 2 with a
message naming both, and every input is left as it was and nothing is written; an output folder
that is a file is exit 2 too. Each refusal happens before matplotlib or plotly is imported, so
this test needs neither.

Standard library only. Usage: test_outputs.py REPO_ROOT
"""

import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(ROOT, "tests", "reports"))
import synth_report  # noqa: E402

PY = sys.executable
SCRIPTS = os.path.join(ROOT, "reports")
work = tempfile.mkdtemp(prefix="agv_outputs_")
results = []


def ok(cond, what, detail=""):
    results.append(bool(cond))
    print(("ok   " if cond else "FAIL ") + what + ("" if cond else f" {detail}"))


def snapshot(folder):
    """Every file under `folder` with its bytes (links as what they point to)."""
    out = {}
    for base, _, files in os.walk(folder):
        for f in files:
            path = os.path.join(base, f)
            try:
                with open(path, "rb") as fh:
                    out[os.path.relpath(path, folder)] = fh.read()
            except OSError:
                out[os.path.relpath(path, folder)] = None  # a dangling link
    return out


def refused(what, script, args, pattern):
    """`script args` exits 2 with `pattern` in its message and changes nothing under work/."""
    before = snapshot(work)
    p = subprocess.run([PY, os.path.join(SCRIPTS, script)] + args, cwd=work,
                       capture_output=True, text=True)
    after = snapshot(work)
    changed = sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))
    ok(p.returncode == 2 and pattern in p.stderr and not changed,
       f"{what}: exit 2, named, nothing changed",
       f"(exit {p.returncode}, stderr {p.stderr.strip()[:300]!r}, changed {changed})")


synth_report.make(dict(synth_report.DEFAULT_SPEC, generators=["uniform"], sizes=[[16, 16]],
                       densities=[0.2], maps_per_cell=4),
                  os.path.join(work, "r.json"), os.path.join(work, "r.jsonl"))
shutil.copy(os.path.join(ROOT, "tests", "reports", "tiny_plan.json"), os.path.join(work, "plan.json"))
shutil.copy(os.path.join(ROOT, "reports", "claims.json"), os.path.join(work, "claims.json"))
os.symlink("r.json", os.path.join(work, "link_to_report.json"))
os.link(os.path.join(work, "r.jsonl"), os.path.join(work, "hard_journal.md"))
os.link(os.path.join(work, "claims.json"), os.path.join(work, "hard_claims.md"))
os.symlink("plan.json", os.path.join(work, "link_to_plan.png"))
os.mkdir(os.path.join(work, "sub"))

claims = ["check_claims.py", "--claims", "claims.json", "r.json", "r.jsonl"]
refused("check_claims --out the report", claims[0], claims[1:] + ["--out", "r.json"],
        "--out r.json: is the report r.json (the same file)")
refused("check_claims --out the report spelled another way", claims[0],
        claims[1:] + ["--out", "sub/../r.json"], "is the report r.json")
refused("check_claims --json a symbolic link to the report", claims[0],
        claims[1:] + ["--json", "link_to_report.json"], "--json link_to_report.json: is the report r.json")
refused("check_claims --out a hard link to the journal", claims[0],
        claims[1:] + ["--out", "hard_journal.md"], "--out hard_journal.md: is the journal r.jsonl")
refused("check_claims --out a hard link to the claims file", claims[0],
        claims[1:] + ["--out", "hard_claims.md"], "--out hard_claims.md: is the --claims claims.json")
refused("check_claims --out and --json the same file", claims[0],
        claims[1:] + ["--out", "same.md", "--json", "./same.md"], "--json ./same.md: is the --out same.md")
refused("check_claims --out a folder", claims[0], claims[1:] + ["--out", "sub"], "--out sub: is a folder")

refused("plot_paths P P", "plot_paths.py", ["plan.json", "plan.json"], "out plan.json: is the plan plan.json")
refused("plot_paths onto a symbolic link to its plan", "plot_paths.py", ["plan.json", "link_to_plan.png"],
        "out link_to_plan.png: is the plan plan.json")

refused("html_report onto its report", "html_report.py", ["r.json", "r.json"], "out r.json: is the report r.json")
refused("html_report onto a hard link to its journal", "html_report.py",
        ["r.json", "hard_journal.md", "--runs", "r.jsonl"], "out hard_journal.md: is the --runs r.jsonl")

os.mkdir(os.path.join(work, "pics"))
os.symlink("../r.json", os.path.join(work, "pics", "summary.md"))
refused("plot.py into a folder whose summary.md links to the report", "plot.py", ["r.json", "pics"],
        "outdir pics/summary.md: is the report r.json")
os.unlink(os.path.join(work, "pics", "summary.md"))
os.link(os.path.join(work, "r.jsonl"), os.path.join(work, "pics", "success.png"))
refused("plot.py into a folder whose success.png is a hard link to the journal", "plot.py",
        ["r.json", "pics", "--runs", "r.jsonl"], "outdir pics/success.png: is the --runs r.jsonl")
refused("plot.py into a folder that is a file", "plot.py", ["r.json", "r.jsonl"],
        "outdir r.jsonl: is a file, expected a folder")

# The guard refuses only what it must: a fresh output beside the inputs is written.
p = subprocess.run([PY, os.path.join(SCRIPTS, claims[0])] + claims[1:] + ["--out", "sub/CLAIMS.md", "--json", "c.json"],
                   cwd=work, capture_output=True, text=True)
ok(p.returncode == 0 and os.path.getsize(os.path.join(work, "sub", "CLAIMS.md")) > 0 and
   os.path.getsize(os.path.join(work, "c.json")) > 0, "check_claims to fresh files: exit 0, both written",
   p.stderr[-300:])

shutil.rmtree(work)
print(f"test_outputs: {sum(results)} passed, {len(results) - sum(results)} failed")
sys.exit(0 if all(results) else 1)
