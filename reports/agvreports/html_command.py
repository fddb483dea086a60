"""html_report.py's command line: read and check the report (and its journal), refuse to
overwrite a file the script did not write, and write the page atomically.
"""

import argparse
import os
import sys
import tempfile

from agvreports.grouping import Report, split_list
from agvreports.html_page import ASSETS, MARK, build_page, page_data, plotly_js
from agvreports.output_guard import check_outputs
from agvreports.report_io import BAD_INPUT, ReportError, load_report
from agvreports.runs import load_runs


def main(doc, argv=None):
    """html_report.py's command line; `doc` is its usage text (the script's docstring)."""
    ap = argparse.ArgumentParser(description=doc.split("\n\n")[2].strip(),
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=doc.split("\n\n", 2)[2])
    ap.add_argument("report", help="report JSON written by `agvbench run`")
    ap.add_argument("out", help="the HTML file to write (an existing one only if html_report.py wrote it)")
    ap.add_argument("--runs", metavar="RUNS.jsonl",
                    help="the sweep's per-run journal (`run --runs-out`): box plots of every run")
    ap.add_argument("--planners", action="append", metavar="A,B",
                    help="only these planners (labels; comma-separated or repeated)")
    ap.add_argument("--uncompressed", action="store_true",
                    help="embed plotly.js as plain text (8.7 MB) instead of gzip + base64 (2.5 MB, "
                         "unpacked by the browser's DecompressionStream: Chromium 80+, Firefox 113+, "
                         "Safari 16.4+)")
    args = ap.parse_args(argv)
    try:
        doc = load_report(args.report)
        if not doc["cells"]:
            raise ReportError("the report has no cells (nothing was swept)")
    except ReportError as e:
        sys.stderr.write(f"html_report.py: {args.report}: {e}\n")
        return BAD_INPUT
    try:
        rep = Report(doc, split_list(args.planners))
    except ReportError as e:
        sys.stderr.write(f"html_report.py: {e}\n")
        return BAD_INPUT
    runs = None
    if args.runs:
        try:
            runs = load_runs(args.runs, doc)
        except ReportError as e:
            sys.stderr.write(f"html_report.py: {args.runs}: {e}\n")
            return BAD_INPUT
    out = args.out
    try:
        check_outputs([("out", out)], [("report", args.report)] +
                      ([("--runs", args.runs)] if args.runs else []))
    except ReportError as e:
        sys.stderr.write(f"html_report.py: {e}\n")
        return BAD_INPUT
    if os.path.isdir(out):
        sys.stderr.write(f"html_report.py: {out}: is a directory, expected the HTML file to write\n")
        return BAD_INPUT
    if os.path.exists(out):
        # Never overwrite a user's file by mistake: only a page this script wrote.
        try:
            with open(out, "r", encoding="utf-8", errors="replace") as f:
                head = f.read(200)
        except OSError as e:
            sys.stderr.write(f"html_report.py: {out}: cannot read the existing file: {e.strerror}\n")
            return BAD_INPUT
        if MARK not in head:
            sys.stderr.write(f"html_report.py: {out}: exists and is not a report html_report.py "
                             "wrote; refusing to overwrite it (delete it or choose another name)\n")
            return BAD_INPUT
    js = plotly_js()
    if js is None:
        sys.stderr.write("html_report.py: plotly.js not found: install Debian's python3-plotly "
                         "(apt-get install python3-plotly)\n")
        return 1
    with open(os.path.join(ASSETS, "html_report.js"), encoding="utf-8") as f:
        app = f.read()
    data = page_data(rep, runs)
    page = build_page(data, app, js, f"agvbench: {data['name']}", not args.uncompressed)
    folder = os.path.dirname(os.path.abspath(out))
    try:  # atomically: a temporary file beside OUT, then a rename
        fd, tmp = tempfile.mkstemp(prefix=".html-", suffix=".tmp", dir=folder)
        try:
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                f.write(page)
            os.chmod(tmp, 0o644)
            os.replace(tmp, out)
        except BaseException:
            os.unlink(tmp)
            raise
    except OSError as e:
        sys.stderr.write(f"html_report.py: cannot write {out}: {e.strerror}\n")
        return 1
    print(f"{out} ({os.path.getsize(out) / 1e6:.1f} MB, {len(rep.labels)} planners, "
          f"{len(data['worlds'])} cell groups{', per-run box plots' if runs else ''})")
    return 0

