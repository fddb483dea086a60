#!/usr/bin/python3
"""Check the papers' headline claims (reports/claims.json) against agvbench sweep reports.

    /usr/bin/python3 reports/check_claims.py REPORT.json [RUNS.jsonl] [REPORT2.json [RUNS2.jsonl]] ...
        [--claims reports/claims.json] [--out reports/CLAIMS.md] [--json RESULTS.json] [--all-as random]

A RUNS.jsonl (the sweep's `--runs-out` per-run records) placed right after a report belongs to
that report; it is needed only for comparisons the report does not pair itself (a baseline other
than the report's, or a metric outside the paired list).

For each claim: the planners are found in each report's config (by label, or by registry name
and parameters), the cells are filtered (generator, size, density range), and the measured
figure is pooled over every matching cell of every report:

  ratio, paired in the report (candidate vs the report's baseline): each cell's COMPARISON gives
      the count, mean and (through its t interval) the spread of the per-map log ratios; they are
      merged exactly, so the pooled figure is the geometric mean over all pairs of all matching
      cells (= per-cell geometric means combined with weights = pairs) and its interval is the
      95% t interval over all those pairs, the same as recomputing from the runs;
  ratio from RUNS.jsonl: the same, computed from the per-run records;
  ratio, indirect (neither of the above; both planners paired against the report's baseline
      B0): ratio = GM(candidate/B0) / GM(baseline/B0), interval [lo_c/hi_b, hi_c/lo_b] from the
      two pooled intervals: conservative, and marked as indirect (the two pair sets may differ);
  difference (e.g. clearance): paired differences from RUNS.jsonl if given, else candidate mean
      minus baseline mean from the cell summaries with a Welch interval (unpaired: conservative).

Set-ups: each claim names two sweep configs (claims.json "setup"): "paper", its paper's own
set-up (configs/paper-00N.json), and "random", our random-map protocol (configs/paper-00N-random.json).
A report belongs to a set-up by its config's name (--all-as SETUP: every report stands for that
set-up, as for a sample sweep); each claim is graded on each set-up separately
(compare.paper_cells, where given, replaces compare.cells on the paper's set-up; "cells" may be a
list of filters, any of which a cell may match). compare.offset is added to every per-run value
before the ratio (paper 004's turns = key points - 2); it forces the per-run route.

Verdicts, five levels:
  'reproduced'      the 95% interval lies on the claimed side of no-effect (1 for ratios, 0 for
                    differences) AND the paper's figure lies inside our per-map 5-95% range of the
                    same quantity: each map's candidate/baseline ratio (or difference) from the
                    per-run records, pooled over the matching cells. A paper's figure is one map's
                    (or a few maps' mean): it is compared with what one map of ours gives, not
                    with the interval of a thousands-of-maps mean, which no single map need lie in.
                    A claim with no figure (the paper states a direction only) is reproduced by a
                    significant effect in that direction; an ordering by every step significant.
  'direction only'  significant in the claimed direction, but the paper's figure lies outside that
                    range (the reason says on which side and by how much); also when the reports
                    came without per-run records, so that the range cannot be computed.
  'contradicted'    the 95% interval lies entirely on the opposite side.
  'not significant' the 95% interval contains no-effect. A level of its own rather than folded into
                    another: with thousands of maps it means the effect is absent or negligible,
                    which neither supports the claim ('direction only' would say it did) nor
                    shows its opposite ('contradicted' would).
  'not comparable'  the claim is marked "not_comparable" in claims.json with the reason (e.g. the
                    paper's MATLAB wall seconds against our CPU nanoseconds: our figure is shown
                    for context only), or nothing to measure: no report of the set-up, a planner
                    or metric missing, no matching cells, fewer than min_pairs pairs.
An ordering's level is its worst step's (not comparable, then contradicted, then not significant).

Exit codes: 0 done (whatever the verdicts), 2 bad report / runs / claims file.
"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from agvreports.claims import command  # noqa: E402

if __name__ == "__main__":
    sys.exit(command.main())
