#!/usr/bin/python3
"""Draw an `agvbench plan --json-out` document: the grid, its obstacles, start and goal, and
each planner's path in its own colour (with a legend giving outcome, length and turns).

    /usr/bin/python3 reports/plot_paths.py PLAN.json OUT.png [--dpi N] [--title TEXT] [--small]

Coordinates follow the engine: cell (x, y) spans [x, x+1) x [y, y+1), its centre is
(x + 0.5, y + 0.5), and y = 0 is the TOP row (image convention); paths are in these continuous
cell coordinates. Optional per-run keys, drawn when present (fusion runs): `trajectory`
[[x, y], ...] (the executed robot trajectory, dashed), `obstacles` [{"track": [[x, y], ...],
"radius": r}] (moving obstacles' tracks, with the disc at its first and last position) and
`unknown_cells` [[x, y], ...] (static cells the global planner did not see, hatched).

Exit codes: 0 done, 1 could not write / matplotlib missing, 2 bad input.
"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from agvreports import paths_command  # noqa: E402

if __name__ == "__main__":
    sys.exit(paths_command.main())
