"""One planner on one map, validated and measured as a sweep's run."""

from dataclasses import dataclass

import numpy

from agvbench import _core
from agvbench.maps import CellGrid, Map
from agvbench.plain import plain


@dataclass(frozen=True)
class PlanResult:
    """A run: outcome (str, as the reports' outcomes), path (N x 2 float array of (x, y) cell
    coordinates), metrics (dict; None where undefined), phases (dict of ns), plan_time_ns, the
    corner rule the planner moved under, the planner's parameters with their defaults, and the
    judge's message."""

    outcome: str
    path: numpy.ndarray
    metrics: dict
    phases: dict
    plan_time_ns: int
    rule: str
    params: dict
    message: str


def plan(grid, start=None, goal=None, planner="astar", *, collision=None, time_limit_s=None,
         seed=None, cell=None, map_index=None, cell_edge=None, **params):
    """Runs `planner` from `start` to `goal` on `grid` and judges the path as a sweep does.

    grid is a Map (make_map, load_map: its start and goal are the defaults), a Map's .grid (it
    remembers the cell, map_index, seed and cell_edge that name the run's random stream: the
    defaults) or a 2-D numpy bool array (True = obstacle; its runs keyed by the cell "grid");
    start and goal are (x, y) = (column, row) cells; collision a config's "collision" object
    ({"corner_rule": ..., "clearance": ...}); time_limit_s a deadline (default none, as
    `agvbench plan`); params the planner's parameters. The run's random stream is the sweep's for
    (seed, cell, map_index, planner). Raises ValueError naming a bad argument.
    """
    if isinstance(grid, Map):
        start = grid.start if start is None else start
        goal = grid.goal if goal is None else goal
        grid = grid.grid
    if isinstance(grid, CellGrid) and grid.stream is not None:
        stream = grid.stream
        seed = stream["seed"] if seed is None else seed
        cell = stream["cell"] if cell is None else cell
        map_index = stream["map_index"] if map_index is None else map_index
        cell_edge = stream["cell_edge"] if cell_edge is None else cell_edge
    if start is None or goal is None:
        raise ValueError(("start" if start is None else "goal") + ": missing (an (x, y) cell)")
    if not isinstance(planner, str):
        raise ValueError("planner: expected a planner name, got " + repr(planner))
    out = _core.plan(grid, start, goal, planner, plain(params), plain(collision),
                     plain(time_limit_s), plain(0 if seed is None else seed),
                     "grid" if cell is None else str(cell),
                     int(0 if map_index is None else map_index),
                     float(1.0 if cell_edge is None else cell_edge))
    return PlanResult(**out)
