#!/usr/bin/python3
"""Line-of-sight ratios from bench_los JSON (perf/README.md "Line of sight").

Usage: los_table.py LABEL=FILE.json[,FILE.json...] ... --columns LABEL:VARIANT ... [--base LABEL:VARIANT]

Each LABEL names one build's bench_los output (several files: rounds of the same build, pooled).
A column LABEL:VARIANT is that build's variant (reference, fast, batched, batched-LEVEL) divided,
per case, by the base (default: the first label's reference); each figure is the best of every
repetition (the fastest, as the machine's noise only ever slows a run down). --base
native:batched --columns portable:batched compares two builds' batched checks. Prints the per-case table and, per
mode and column, the judged figures of issue 47: the geometric mean over density 0 and 0.1 at
8-128 cells, the worst case, and the free 32- and 128-cell cases.
"""
import argparse
import json
import math
import re
import sys
from collections import defaultdict

NAME = re.compile(r"^(?P<variant>[^/]+)/(?P<mode>[^/]+)/d(?P<density>[0-9.]+)/len(?P<length>[0-9]+)")


def best_rates(files):
    """{(variant, mode, density, length): (best segments/s, free fraction)}"""
    best = {}
    for path in files:
        with open(path) as f:
            doc = json.load(f)
        for b in doc["benchmarks"]:
            if b.get("run_type") != "iteration":
                continue
            m = NAME.match(b["run_name"] if "run_name" in b else b["name"])
            if not m:
                continue
            key = (m["variant"], m["mode"], float(m["density"]), int(m["length"]))
            rate = b["segments_per_s"]
            if key not in best or rate > best[key][0]:
                best[key] = (rate, b["free"])
    return best


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("builds", nargs="+", help="LABEL=FILE.json[,FILE.json...]")
    ap.add_argument("--columns", nargs="+", required=True, help="LABEL:VARIANT")
    ap.add_argument("--base", help="LABEL:VARIANT the columns are divided by")
    args = ap.parse_args()
    builds = {}
    for spec in args.builds:
        label, _, files = spec.partition("=")
        if not files:
            sys.exit(f"los_table: {spec}: expected LABEL=FILE.json")
        builds[label] = best_rates(files.split(","))
    first = next(iter(builds))
    base_label, base_variant = first, "reference"
    if args.base:
        base_label, _, base_variant = args.base.partition(":")
        if base_label not in builds or not base_variant:
            sys.exit(f"los_table: --base {args.base}: expected LABEL:VARIANT of a given build")
    columns = []
    for spec in args.columns:
        label, _, variant = spec.partition(":")
        if label not in builds or not variant:
            sys.exit(f"los_table: column {spec}: expected LABEL:VARIANT of a given build")
        columns.append((spec, builds[label], variant))
    cases = sorted({k[1:] for k in builds[first] if k[0] == "reference"})
    base_name = "reference" if not args.base else args.base
    print(f"| mode | density | length | free | {base_name} | " + " | ".join(c[0] for c in columns) + " |")
    print("| --- | ---: | ---: | ---: | ---: |" + " ---: |" * len(columns))
    ratios = defaultdict(list)
    for mode, density, length in cases:
        ref, free = builds[base_label][(base_variant, mode, density, length)]
        cells = []
        for spec, rates, variant in columns:
            r = rates.get((variant, mode, density, length))
            if r is None:
                cells.append("-")
                continue
            ratio = r[0] / ref
            ratios[(mode, spec)].append((density, length, ratio))
            cells.append(f"{ratio:.2f}x")
        print(f"| {mode} | {density:.1f} | {length} | {free:.2f} | {ref / 1e6:.1f} M | " + " | ".join(cells) + " |")
    print()
    print("| mode | column | geometric mean | worst case | free 32 | free 128 |")
    print("| --- | --- | ---: | ---: | ---: | ---: |")
    for (mode, spec), rows in ratios.items():
        judged = [r for d, n, r in rows if d in (0.0, 0.1) and n >= 8]
        geo = math.exp(sum(map(math.log, judged)) / len(judged)) if judged else float("nan")
        free = {n: r for d, n, r in rows if d == 0.0}
        print(f"| {mode} | {spec} | {geo:.2f} | {min(r for _, _, r in rows):.2f} | "
              f"{free.get(32, float('nan')):.2f} | {free.get(128, float('nan')):.2f} |")


if __name__ == "__main__":
    main()
