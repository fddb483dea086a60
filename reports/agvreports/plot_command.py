"""plot.py's command line: read and check the report (and its journal), then draw every
picture and write summary.md. Bad input is refused (exit 2) before matplotlib is imported.
"""

import argparse
import os
import sys

from agvreports.dist import plot_distributions, plot_ecdf
from agvreports.figures import Saver, setup_matplotlib
from agvreports.grouping import Report, split_list
from agvreports.output_guard import check_output_folder
from agvreports.paired import plot_paired
from agvreports.plots import plot_metrics, plot_success, plot_time
from agvreports.report_io import BAD_INPUT, ReportError, load_report
from agvreports.runs import load_runs
from agvreports.summary import write_summary

FORMATS = ("png", "pdf", "svg")


def _may_write(name):
    """Every name plot.py may write into its folder: a picture in any format, summary.md."""
    return name == "summary.md" or name.endswith(tuple("." + f for f in FORMATS))


def main(doc, argv=None):
    """plot.py's command line; `doc` is its usage text (reports/plot.py's docstring)."""
    ap = argparse.ArgumentParser(
        description="Plot an agvbench sweep report (schema_version 2); the files it writes "
                    "are listed below. The report alone gives every picture but the ECDF; the "
                    "distribution pictures (dist_*) then show the report's summaries (box "
                    "p5..p95, whiskers min..max). --runs gives true box / violin plots and the "
                    "ECDF of planning time.",
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=doc.split("\n\n", 1)[1])
    ap.add_argument("report", help="report JSON written by `agvbench run`")
    ap.add_argument("outdir", help="folder for the pictures and summary.md (created)")
    ap.add_argument("--runs", metavar="RUNS.jsonl",
                    help="the sweep's per-run journal (`run --runs-out`): needed for the ECDF, "
                         "true box plots and violins")
    ap.add_argument("--format", choices=FORMATS, default="png", help="picture format (default png)")
    ap.add_argument("--planners", action="append", metavar="A,B",
                    help="only these planners (labels; comma-separated or repeated)")
    ap.add_argument("--metrics", action="append", metavar="M,N",
                    help="only these metrics (report names, e.g. path_length, plan_time_ns)")
    ap.add_argument("--dist", choices=("box", "violin"), default="box",
                    help="distribution pictures as box plots (default) or violins (needs --runs)")
    ap.add_argument("--dpi", type=int, default=100, help="PNG resolution (default 100)")
    ap.add_argument("--small", action="store_true",
                    help="write palette PNGs (about a third of the size; for committed samples)")
    args = ap.parse_args(argv)
    if args.dpi <= 0:
        sys.stderr.write(f"plot.py: --dpi {args.dpi}: expected a positive number\n")
        return BAD_INPUT
    if args.dist == "violin" and not args.runs:
        sys.stderr.write("plot.py: --dist violin needs --runs RUNS.jsonl (a violin is drawn from "
                         "every run; the report holds summaries only)\n")
        return BAD_INPUT
    try:
        check_output_folder("outdir", args.outdir, _may_write,
                            [("report", args.report)] + ([("--runs", args.runs)] if args.runs else []))
    except ReportError as e:
        sys.stderr.write(f"plot.py: {e}\n")
        return BAD_INPUT
    try:
        doc = load_report(args.report)
        if not doc["cells"]:
            raise ReportError("the report has no cells (nothing was swept)")
    except ReportError as e:
        sys.stderr.write(f"plot.py: {args.report}: {e}\n")
        return BAD_INPUT
    try:
        rep = Report(doc, split_list(args.planners), split_list(args.metrics))
    except ReportError as e:
        sys.stderr.write(f"plot.py: {e}\n")
        return BAD_INPUT
    runs = None
    if args.runs:
        try:
            runs = load_runs(args.runs, doc)
        except ReportError as e:
            sys.stderr.write(f"plot.py: {args.runs}: {e}\n")
            return BAD_INPUT
    if doc.get("complete") is False:
        sys.stderr.write(f"plot.py: warning: {args.report} is an incomplete (interrupted) sweep\n")
    try:
        os.makedirs(args.outdir, exist_ok=True)
    except OSError as e:
        sys.stderr.write(f"plot.py: cannot create {args.outdir}: {e.strerror}\n")
        return 1
    plt = setup_matplotlib()
    saver = Saver(plt, args.outdir, args.dpi, args.small, args.format)
    try:
        for key in rep.ordered_worlds():
            plot_metrics(plt, saver, rep, key)
        for key in rep.ordered_worlds():
            plot_distributions(plt, saver, rep, key, runs, args.dist)
        for key in rep.ordered_worlds():
            plot_paired(plt, saver, rep, key)
        plot_success(plt, saver, rep)
        plot_time(plt, saver, rep)
        if runs is not None:
            plot_ecdf(plt, saver, rep, runs)
        summary = write_summary(rep, args.outdir, saver.written)
    except OSError as e:
        sys.stderr.write(f"plot.py: cannot write into {args.outdir}: {e.strerror}\n")
        return 1
    for name, problem in saver.problems:
        sys.stderr.write(f"plot.py: layout: {name}: {problem}\n")
    if runs is None:
        sys.stderr.write("plot.py: note: no --runs: ecdf_plan_time not drawn, dist_* drawn from "
                         "the report's summaries\n")
    for name in saver.written:
        print(os.path.join(args.outdir, name))
    print(summary)
    return 0

