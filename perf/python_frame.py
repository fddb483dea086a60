#!/usr/bin/python3
"""How soon a sweep's DataFrame is ready (issue 48, perf/README.md "Python: the runs'
DataFrame"): a sweep of RUNS cheap runs (A* and Dijkstra on 16x16 uniform maps) through
agvbench.run, ROUNDS rounds, each timing keep_runs=True and keep_runs=False in turn. Per call:
from the sweep's end (the last progress call, made as the engine's threads finish) to run()'s
return (the report's assembly and, with keep_runs, the table's columns copied into numpy
arrays), then the DataFrame built from them as agvbench.run builds it. Prints the medians and
the DataFrame's own cost per run.

Usage: PYTHONPATH=build/python /usr/bin/python3 perf/python_frame.py [--runs N] [--rounds R]
"""

import argparse
import statistics
import time

from agvbench import _core
from agvbench.sweeps import runs_frame


def config(runs):
    return {"name": "frame-cost", "seed": 1, "generators": ["uniform"], "sizes": [16],
            "densities": [0.1], "maps_per_cell": runs // 2, "planners": ["astar", "dijkstra"],
            "baseline": "astar", "references": {"any_angle": False}}


def after_end(cfg, keep_runs, threads):
    """Seconds from the sweep's end to the engine's return (report built; with keep_runs the
    table's columns copied into numpy arrays), then to the DataFrame built (runs_frame, as
    agvbench.run does), and the rows."""
    last = [0.0]

    def progress(done, total):
        if done == total:
            last[0] = time.perf_counter()

    got = _core.run(cfg, "", threads, "", "", None, keep_runs, progress)
    returned = time.perf_counter()
    rows = len(runs_frame(got["runs"])) if keep_runs else 0
    built = time.perf_counter()
    return returned - last[0], built - returned, rows


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=100_000)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args()
    cfg = config(args.runs)
    core, frame, bare = [], [], []
    rows = 0
    for _ in range(args.rounds):
        c, f, rows = after_end(cfg, True, args.threads)
        core.append(c)
        frame.append(f)
        bare.append(after_end(cfg, False, args.threads)[0])
    med = statistics.median
    total = med(core) + med(frame) - med(bare)
    print(f"{rows} runs, {args.rounds} rounds, medians, seconds after the sweep's end")
    print(f"engine returns, keep_runs=False (the report):      {med(bare):.3f}")
    print(f"engine returns, keep_runs=True (+ numpy columns):   {med(core):.3f}")
    print(f"DataFrame built from the columns (pandas):          {med(frame):.3f}")
    print(f"ready after the sweep's end: {med(core) + med(frame):.3f} s; the DataFrame's own cost "
          f"{total:.3f} s, {total / rows * 1e9:.0f} ns a run")


if __name__ == "__main__":
    main()
