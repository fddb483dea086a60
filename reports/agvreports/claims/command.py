"""check_claims.py's command line: the claims file and the reports (each with its optional
per-run records) read and checked, every claim graded, CLAIMS.md and the --json results written.
"""

import argparse
import json
import os
import sys

from agvreports.claims.claims_file import DEFAULT_CLAIMS, SETUPS, check_claims_file
from agvreports.claims.evaluate import evaluate
from agvreports.claims.markdown import markdown, result_json
from agvreports.claims.sources import Source
from agvreports.output_guard import check_outputs
from agvreports.report_io import BAD_INPUT, ReportError, load_json, load_report


def main(argv=None):
    """check_claims.py's command line."""
    ap = argparse.ArgumentParser(description="Check the papers' claims against agvbench sweep reports.")
    ap.add_argument("inputs", nargs="+", help="REPORT.json, each optionally followed by its RUNS.jsonl")
    ap.add_argument("--claims", default=DEFAULT_CLAIMS, help="claims file (default: reports/claims.json)")
    ap.add_argument("--out", default=None, help="Markdown to write (default: print to stdout)")
    ap.add_argument("--json", default=None, help="also write the results as JSON here")
    ap.add_argument("--all-as", choices=[k for k, _ in SETUPS], default=None,
                    help="every report stands for this set-up of every claim, whatever its config name "
                         "(a sample sweep)")
    args = ap.parse_args(argv)
    inputs = [("--claims", args.claims)] + \
        [("journal" if p.endswith(".jsonl") else "report", p) for p in args.inputs]
    outputs = [(opt, path) for opt, path in (("--out", args.out), ("--json", args.json)) if path]
    try:
        check_outputs(outputs, inputs)
    except ReportError as e:
        sys.stderr.write(f"check_claims.py: {e}\n")
        return BAD_INPUT
    try:
        claims_doc = check_claims_file(load_json(args.claims))
    except ReportError as e:
        sys.stderr.write(f"check_claims.py: {args.claims}: {e}\n")
        return BAD_INPUT
    sources = []
    for path in args.inputs:
        try:
            if path.endswith(".jsonl"):
                if not sources:
                    raise ReportError("a per-run JSONL must follow the report it belongs to")
                if sources[-1].runs is not None:
                    raise ReportError(f"the report {sources[-1].path} already has per-run records")
                sources[-1].attach_runs(path)
            else:
                sources.append(Source(path, load_report(path)))
        except ReportError as e:
            sys.stderr.write(f"check_claims.py: {path}: {e}\n")
            return BAD_INPUT
    for src in sources:
        src.as_setup = args.all_as
    defaults = claims_doc.get("defaults", {})
    results = [evaluate(c, sources, defaults) for c in claims_doc["claims"]]
    text = markdown(results, sources, args.claims)
    if args.out:
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump([result_json(r) for r in results], f, indent=1)
    width = max((len(r["id"]) for r in results), default=10)
    for r in results:
        line = (f"{r['id']:<{width}}  paper set-up: {r['paper_setup']['verdict']:<16} "
                f"random maps: {r['random_setup']['verdict']}")
        print(line, file=sys.stdout if args.out else sys.stderr)
    return 0
