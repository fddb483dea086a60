#!/usr/bin/python3
"""What a sweep would do on more threads than this machine has: its map tasks replayed on P
simulated threads the way the engine runs them, from the times a journal recorded.

    perf/scaling_model.py --report R.json --journal J.jsonl --engine-us 121 --locked-us 11.6 \\
        --serial-s 0.05 --threads 1,2,16,64

The engine (engine/sweep/sweep_runner.cpp) has each thread take the next map task in plan order
(cells in report order, maps in index order) from one counter, run it (the planners, and the
engine's own work on each run: map, references, judge), then hand its runs to the sinks under one
lock (journal lines, and when the task completes its cell, the cell's statistics). The model
replays that: a task costs the sum of its runs' `plan_time_ns` plus `--engine-us` per run outside
the lock, then holds the lock for `--locked-us` per run, first come first served; `--serial-s`
is added once (set-up and the report's last writes, on one thread). It prints each thread
count's predicted wall time, speed-up over one thread, the lock's busy share, and the ceiling
the lock sets whatever the threads (1 / locked-us runs per second). With --busy-at P, it also
gives P threads' efficiency on the same config at fewer and more maps per cell (each cell's first
maps, or its measured maps again in turn), for the size of sweep that keeps P cores busy.

Left out, so the figures are upper bounds: memory bandwidth and caches shared by the cores, a
CPU clock that drops when all cores run, and the time a thread waits to be woken for the lock.
Standard library and reports/agvreports only; /usr/bin/python3.
"""

import argparse
import heapq
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "reports"))
from agvreports import runs as runs_io  # noqa: E402


def task_costs(report_path, journal_path):
    """[(seconds of planner time, runs)] per map task, in plan order, and the maps per cell."""
    with open(report_path, encoding="utf-8") as f:
        order = [c["cell"] for c in json.load(f)["cells"]]
    rank = {cell: i for i, cell in enumerate(order)}
    tasks = {}
    for _, r in runs_io.journal_records(journal_path):
        key = (rank[r["cell"]], r["map_index"])
        ns, n = tasks.get(key, (0, 0))
        tasks[key] = (ns + r["timing"]["plan_time_ns"], n + 1)
    keys = sorted(tasks)
    return [(tasks[k][0] * 1e-9, tasks[k][1], k) for k in keys]


def simulate(tasks, threads, engine_us, locked_us):
    """Wall seconds of the runs on `threads` threads, and the lock's busy seconds."""
    ready = [(0.0, t) for t in range(threads)]  # (time the thread is free, thread)
    heapq.heapify(ready)
    lock_free = 0.0
    lock_busy = 0.0
    pending = []  # (time the task's compute ends, thread, locked seconds)
    end = 0.0

    def settle():
        nonlocal lock_free, lock_busy, end
        done, th, hold = heapq.heappop(pending)
        lock_free = max(done, lock_free) + hold
        lock_busy += hold
        heapq.heappush(ready, (lock_free, th))
        end = max(end, lock_free)

    for plan_s, n, _ in tasks:
        # A thread is free again once its task's lock hold is over; the holds go in the order
        # the computes end (first come first served). Every task whose compute ends before the
        # next free thread's time takes the lock first.
        while pending and (not ready or pending[0][0] <= ready[0][0]):
            settle()
        free_at, t = heapq.heappop(ready)
        heapq.heappush(pending, (free_at + plan_s + n * engine_us * 1e-6, t, n * locked_us * 1e-6))
    while pending:
        settle()
    return end, lock_busy


def with_maps(tasks, maps):
    """The sweep with `maps` maps per cell: each cell's first maps, or its measured maps again
    in turn beyond those (a larger sweep of the same config costs about as much a map)."""
    by_cell = {}
    for t in tasks:
        by_cell.setdefault(t[2][0], []).append(t)
    return [by_cell[c][m % len(by_cell[c])] for c in sorted(by_cell) for m in range(maps)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--report", required=True, help="the sweep's report (its cells' order)")
    ap.add_argument("--journal", required=True, help="its journal (--runs-out), one thread best")
    ap.add_argument("--engine-us", type=float, required=True,
                    help="engine CPU per run outside the lock (bench_sweep: map + reference + judge)")
    ap.add_argument("--locked-us", type=float, required=True,
                    help="CPU per run under the sinks' lock (journal, cell statistics)")
    ap.add_argument("--serial-s", type=float, default=0.0, help="set-up and end, one thread")
    ap.add_argument("--threads", default="1,2,16,64")
    ap.add_argument("--busy-at", type=int, default=0, help="P threads' efficiency by sweep size")
    args = ap.parse_args()
    tasks = task_costs(args.report, args.journal)
    runs = sum(t[1] for t in tasks)

    def wall(ts, p):
        w, busy = simulate(ts, p, args.engine_us, args.locked_us)
        return w + args.serial_s, busy

    one, _ = wall(tasks, 1)
    print(f"{len(tasks)} map tasks, {runs} runs; one thread {one:.1f} s; the lock's ceiling "
          f"{1e6 / args.locked_us:,.0f} runs/s")
    print("threads  wall s  speed-up  efficiency  lock busy  runs/s")
    for p in (int(x) for x in args.threads.split(",")):
        w, busy = wall(tasks, p)
        print(f"{p:7d} {w:7.2f} {one / w:9.2f} {one / w / p:11.3f} {busy / w:10.3f} "
              f"{runs / w:7.0f}")
    if args.busy_at:
        p = args.busy_at
        maps = max(t[2][1] for t in tasks) + 1
        for m in sorted({max(1, maps * k // 8) for k in range(1, 8)} | {maps * k for k in
                                                                          (1, 2, 4, 8, 16)}):
            sub = with_maps(tasks, m)
            w1, _ = wall(sub, 1)
            wp, _ = wall(sub, p)
            print(f"{m:5d} maps per cell: {sum(t[1] for t in sub):8d} runs, {p} threads "
                  f"{wp:7.2f} s, efficiency {w1 / wp / p:.3f}")

if __name__ == "__main__":
    main()
