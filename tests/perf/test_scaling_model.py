#!/usr/bin/python3
"""Checks of perf/scaling_model.py's replay of a sweep on P threads, on task lists whose wall
time is known by hand: even tasks split evenly; a long first task sets the wall while the others
share the second thread; a lock held longer than the tasks compute makes the threads queue at
it (the ceiling); first come first served at the lock; more maps per cell cycle the measured ones.

    /usr/bin/python3 tests/perf/test_scaling_model.py REPO_ROOT
"""

import importlib.util
import os
import sys

sys.dont_write_bytecode = True
root = sys.argv[1]
spec = importlib.util.spec_from_file_location("scaling_model",
                                              os.path.join(root, "perf", "scaling_model.py"))
model = importlib.util.module_from_spec(spec)
spec.loader.exec_module(model)

failures = []


def near(got, want, what):
    if abs(got - want) > 1e-9:
        failures.append(f"{what}: {got} != {want}")
        print("FAIL", what, got, want)


def tasks(*seconds, runs=1, cell=0):
    return [(s, runs, (cell, i)) for i, s in enumerate(seconds)]


# Four one-second tasks: 4 s on one thread, 2 on two, 1 on four or more.
even = tasks(1.0, 1.0, 1.0, 1.0)
for p, want in ((1, 4.0), (2, 2.0), (4, 1.0), (8, 1.0)):
    near(model.simulate(even, p, 0.0, 0.0)[0], want, f"even tasks on {p} threads")
# In plan order: the 3 s task on thread 0, the three 1 s tasks one after another on thread 1.
near(model.simulate(tasks(3.0, 1.0, 1.0, 1.0), 2, 0.0, 0.0)[0], 3.0, "a long first task")
# The engine's per-run time adds to every task: 2 runs x 0.5 s.
near(model.simulate(tasks(1.0, 1.0, runs=2), 1, 0.5e6, 0.0)[0], 4.0, "engine time per run")
# Ten tasks of no compute, each holding the lock 1 s: 10 s on any number of threads, lock busy
# all of it.
lock_bound = tasks(*([0.0] * 10))
for p in (1, 2, 16):
    wall, busy = model.simulate(lock_bound, p, 0.0, 1e6)
    near(wall, 10.0, f"lock-bound on {p} threads")
    near(busy, 10.0, f"lock busy on {p} threads")
# Two threads, tasks of 1 s compute and 1 s under the lock: thread 0 locks 1-2, thread 1 waits
# for it and locks 2-3; thread 0 computes its next task 2-3, locks 3-4; thread 1 computes 3-4,
# locks 4-5: four tasks end at 5 s (one thread: 8 s).
near(model.simulate(tasks(1.0, 1.0, 1.0, 1.0), 2, 0.0, 1e6)[0], 5.0, "lock first come first served")
near(model.simulate(tasks(1.0, 1.0, 1.0, 1.0), 1, 0.0, 1e6)[0], 8.0, "lock on one thread")
# More maps than measured: each cell's maps again in turn; fewer: the first ones.
measured = tasks(1.0, 2.0, cell=0) + tasks(5.0, cell=1)
grown = model.with_maps(measured, 3)
near(sum(t[0] for t in grown), 1 + 2 + 1 + 5 * 3, "three maps per cell")
near(len(model.with_maps(measured, 1)), 2, "one map per cell")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("scaling model: all checks passed")
