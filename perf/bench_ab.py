#!/usr/bin/python3
"""Two or more builds of one Google Benchmark binary side by side: each round runs every binary
once (alternating, so a slow spell of a shared machine falls on all of them), and the medians of
the CPU time per iteration over the rounds are printed per benchmark with their ratio to the
first binary.

    perf/bench_ab.py --filter 'aco/' --rounds 5 OLD/bench_baselines NEW/bench_baselines

Standard library only.
"""

import argparse
import collections
import json
import statistics
import subprocess
import sys


def run_once(binary, flt, min_time):
    out = subprocess.run([binary, f"--benchmark_filter={flt}", f"--benchmark_min_time={min_time}",
                          "--benchmark_format=json"], capture_output=True, text=True, check=True)
    doc = json.loads(out.stdout)
    return {b["name"]: b["cpu_time"] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
            for b in doc["benchmarks"] if b.get("run_type", "iteration") == "iteration"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("binaries", nargs="+", help="the builds' binaries; the first is the reference")
    ap.add_argument("--filter", required=True, help="--benchmark_filter")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--min-time", default="0.5", help="--benchmark_min_time per run")
    args = ap.parse_args()
    times = collections.defaultdict(lambda: collections.defaultdict(list))
    for _ in range(args.rounds):
        for i, b in enumerate(args.binaries):  # by position: one binary may be given twice
            for name, ms in run_once(b, args.filter, args.min_time).items():
                times[name][i].append(ms)
    print(f"medians of {args.rounds} rounds, CPU ms per iteration; ratio to {args.binaries[0]}")
    for name, by in times.items():
        ref = statistics.median(by[0])
        cells = [f"{statistics.median(by[i]):.3f} ({statistics.median(by[i]) / ref:.3f})"
                 for i in range(len(args.binaries))]
        print(f"{name}: " + "  ".join(cells))
    return 0


if __name__ == "__main__":
    sys.exit(main())
