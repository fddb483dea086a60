#!/usr/bin/python3
"""Where two agvbench reports differ, config-as-run apart: first the deterministic rest (as
slurm/same_report.py compares it), then the config key by key (planner parameters renamed or
changed, map options and generator entries). Exit 0 when the rest is equal, 1 otherwise.
Usage: report_diff.py BEFORE.json AFTER.json"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "slurm"))
import same_report  # noqa: E402


def main(a_path, b_path):
    a = same_report.strip(json.load(open(a_path)))
    b = same_report.strip(json.load(open(b_path)))
    ca, cb = a.pop("config", {}), b.pop("config", {})
    rest = same_report.first_difference(a, b)
    print(f"{os.path.basename(a_path)}: outside the config {'differs at ' + rest if rest else 'equal'}")
    for key in sorted(set(ca) | set(cb)):
        x, y = ca.get(key), cb.get(key)
        if x == y:
            continue
        if key == "planners" and isinstance(x, list) and isinstance(y, list) and len(x) == len(y):
            for i, (p, q) in enumerate(zip(x, y)):
                if p == q:
                    continue
                pp, qq = p.get("params", {}), q.get("params", {})
                changed = [k for k in pp if k in qq and pp[k] != qq[k]]
                print(f"  config.planners[{i}] ({p.get('label')}): params only before "
                      f"{sorted(set(pp) - set(qq))}, only after {sorted(set(qq) - set(pp))}, "
                      f"changed {changed}")
        elif isinstance(x, dict) and isinstance(y, dict):
            print(f"  config.{key}: only before {sorted(set(x) - set(y))}, only after "
                  f"{sorted(set(y) - set(x))}, changed {[k for k in x if k in y and x[k] != y[k]]}")
        else:
            print(f"  config.{key}: {json.dumps(x)[:100]} -> {json.dumps(y)[:160]}")
    return 1 if rest else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
