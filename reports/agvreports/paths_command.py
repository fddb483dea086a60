"""plot_paths.py's command line: read and check the plan document, then draw it."""

import argparse
import sys

from agvreports.output_guard import check_outputs
from agvreports.paths import draw
from agvreports.plan_doc import check_plan
from agvreports.report_io import BAD_INPUT, ReportError, load_json


def main(argv=None):
    """plot_paths.py's command line."""
    ap = argparse.ArgumentParser(description="Draw an `agvbench plan --json-out` document.")
    ap.add_argument("plan", help="JSON written by `agvbench plan --json-out FILE` (or --json)")
    ap.add_argument("out", help="PNG to write")
    ap.add_argument("--dpi", type=int, default=100)
    ap.add_argument("--title", default=None, help="title (default: the map's cell, seed and index)")
    ap.add_argument("--small", action="store_true", help="write a palette PNG (for committed samples)")
    args = ap.parse_args(argv)
    try:
        check_outputs([("out", args.out)], [("plan", args.plan)])
    except ReportError as e:
        sys.stderr.write(f"plot_paths.py: {e}\n")
        return BAD_INPUT
    try:
        plan = check_plan(load_json(args.plan))
    except ReportError as e:
        sys.stderr.write(f"plot_paths.py: {args.plan}: {e}\n")
        return BAD_INPUT
    return draw(plan, args.out, args.dpi, args.title, args.small)

