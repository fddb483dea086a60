#!/usr/bin/python3
"""Compares the deterministic parts of two agvbench reports: each report with every `timing`
and `environment` key removed at any depth (as engine/outputs/report.h's deterministic_part does).
Exit 0 when they are equal, 1 with the first difference otherwise.
Usage: same_report.py A.json B.json"""
import json
import sys

DROP = {"timing", "environment"}


def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k not in DROP}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v


def first_difference(a, b, where="$"):
    if type(a) is not type(b):
        return f"{where}: {type(a).__name__} vs {type(b).__name__}"
    if isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                return f"{where}.{k}: only in {'second' if k not in a else 'first'}"
            d = first_difference(a[k], b[k], f"{where}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{where}: {len(a)} vs {len(b)} items"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{where}[{i}]")
            if d:
                return d
        return None
    return None if a == b else f"{where}: {json.dumps(a)[:200]} vs {json.dumps(b)[:200]}"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = (strip(json.load(open(p))) for p in sys.argv[1:])
    d = first_difference(a, b)
    if d:
        print(f"same_report: {sys.argv[1]} and {sys.argv[2]} differ at {d}")
        sys.exit(1)
    print(f"same_report: {sys.argv[1]} and {sys.argv[2]} agree (timing and environment aside)")


if __name__ == "__main__":
    main()
