#!/usr/bin/python3
"""Pictures and a Markdown summary of an `agvbench run` report (reports/SCHEMA.md, version 2).

    /usr/bin/python3 reports/plot.py REPORT.json OUTDIR [--runs RUNS.jsonl] [--format png|pdf|svg]
        [--planners A,B,...] [--metrics M,N,...] [--dist box|violin] [--dpi N] [--small]

Writes into OUTDIR (FMT = --format, default png):
  metrics_<generator>_<WxH>.FMT  every metric's mean vs obstacle density, one panel per metric,
                                 one line per planner, 95% interval band of the mean, plus the
                                 success rate with its Wilson bars                [report]
  dist_<generator>_<WxH>.FMT     distribution of each metric and of planning time per planner,
                                 one panel per metric, boxes grouped by density.  With --runs:
                                 box = quartiles, whiskers 1.5 IQR, dots = outliers, diamond =
                                 mean (or violins, --dist violin). Without: the report's
                                 summaries, box = p5..p95, whiskers min..max      [report; --runs]
  paired_<generator>_<WxH>.FMT   each planner / baseline on the same maps: geometric-mean ratio
                                 per density with its 95% interval and the 1.0 line  [report]
  success.FMT                    success rate vs density (Wilson 95% bars), panel per world
  plan_time.FMT                  planning time vs grid size, every size of the sweep, log-log,
                                 median with p5-p95 band, panel per generator and density
  ecdf_plan_time.FMT             ECDF of planning time per planner (every run, failures
                                 included), panel per world                      [needs --runs]
  summary.md                     overview table, then tables per world with p-values
Legends sit beside the panels; times are shown in microseconds (the JSON keeps nanoseconds).

Exit codes: 0 done, 1 could not write / matplotlib missing, 2 bad input (report, journal, an
unknown planner or metric in --planners / --metrics, --dist violin without --runs).
Runs with Debian's /usr/bin/python3 and python3-matplotlib; no other third-party package.
"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from agvreports import plot_command  # noqa: E402

if __name__ == "__main__":
    sys.exit(plot_command.main(__doc__))
