#!/usr/bin/python3
"""An interactive, self-contained HTML report of an `agvbench run` report.

    /usr/bin/python3 reports/html_report.py REPORT.json OUT.html [--runs RUNS.jsonl] [--planners A,B]

One file that loads nothing from the network: the report's numbers, the page's script
(reports/html_report.js) and plotly.js (Debian's python3-plotly ships it; embedded whole,
gzip-compressed unless --uncompressed) are all inside it. Open it in any browser, offline.
On the page: choose the cell group (generator and size), the density (or all), the metric
and the planners; it draws
  - box plots per planner and density: from every run with --runs (quartiles, 1.5 IQR
    whiskers, points beyond), else from the report's summaries (box p5..p95, whiskers min..max);
  - success rates with their Wilson 95% intervals;
  - paired ratios to the baseline on the same maps (geometric mean, 95% interval, Wilcoxon p,
    wins/ties/losses) for the chosen metric;
  - a table of the chosen metric per planner and density.
Planning time is shown in microseconds (the JSON keeps nanoseconds).

Exit codes: 0 written, 1 cannot write or plotly missing, 2 bad input (report, journal, unknown
planner, OUT.html an existing file that is not an earlier page of this script).
"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from agvreports import html_command  # noqa: E402

if __name__ == "__main__":
    sys.exit(html_command.main(__doc__))
