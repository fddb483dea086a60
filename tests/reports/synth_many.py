#!/usr/bin/python3
"""A small synthetic sweep with many planners (for the palette, legend and filter tests of the
report scripts): tests/reports/synth_report.py's model, N planners (default 24) on one generator,
three sizes and two densities.

    /usr/bin/python3 tests/reports/synth_many.py OUT.json RUNS.jsonl [N]
"""

import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import synth_report  # noqa: E402


def spec(n):
    planners = [{"label": "astar", "name": "astar", "params": {}, "model": {}}]
    for i in range(1, n):
        # Spread effects so that the planners differ visibly (lengths 0.85..1.3, times 0.3..30).
        planners.append({"label": f"planner_{i:02d}_variant", "name": "astar", "params": {"k": i},
                         "model": {"length": 0.85 + 0.45 * i / n, "time": 0.3 * 100 ** (i / n),
                                   "turns": 0.5 + i / n, "expanded": 0.2 + 2 * i / n,
                                   "success": 1.0 if i % 3 else 0.9}})
    return {"name": f"synthetic {n} planners", "seed": 5, "generators": ["uniform"],
            "sizes": [[16, 16], [24, 24], [32, 32]], "densities": [0.1, 0.3], "maps_per_cell": 8,
            "baseline": "astar", "planners": planners}


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    synth_report.make(spec(int(sys.argv[3]) if len(sys.argv) == 4 else 24), sys.argv[1], sys.argv[2])
