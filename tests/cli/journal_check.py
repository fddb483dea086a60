"""The runs of an agvbench journal (version 1 or 2, reports/SCHEMA.md "Per-run records"), for the
CLI test scripts: decoded by reports/agvreports/runs.py, counted, and checked for repeats.

    journal_check.py JOURNAL [EXPECTED_RUNS]   # "N runs, D duplicates"; exit 0 when D is 0
                                               # (and N is EXPECTED_RUNS when given)
    journal_check.py --count JOURNAL           # prints N
    journal_check.py --dump JOURNAL            # one decoded run a line (JSON), file order
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "reports"))
from agvreports.runs import journal_records  # noqa: E402


def runs(path):
    return [r for _, r in journal_records(path)]


def main(argv):
    if len(argv) == 3 and argv[1] == "--count":
        print(len(runs(argv[2])))
        return 0
    if len(argv) == 3 and argv[1] == "--dump":
        for r in runs(argv[2]):
            print(json.dumps(r, sort_keys=True))
        return 0
    rs = runs(argv[1])
    keys = [(r["cell"], r["map_index"], r["planner"]) for r in rs]
    dup = len(keys) - len(set(keys))
    print(f"{len(keys)} runs, {dup} duplicates")
    return 0 if dup == 0 and (len(argv) < 3 or len(keys) == int(argv[2])) else 1


sys.exit(main(sys.argv))
