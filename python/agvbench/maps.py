"""Maps: a sweep cell's generated map, or a map file, as a numpy bool grid with its endpoints."""

from dataclasses import dataclass, field
from typing import Optional, Tuple

import numpy

from agvbench import _core
from agvbench.plain import plain


class CellGrid(numpy.ndarray):
    """A map's grid that remembers what names its runs' random streams (cell, map_index, seed,
    cell_edge in `stream`), so that plan(m.grid, m.start, m.goal, planner) draws what the
    sweep's run draws, as plan(m, ...) does. A slice or copy is another grid and forgets it."""

    stream = None


@dataclass(frozen=True)
class Map:
    """A grid (rows x columns, True = obstacle) and what names its runs' random streams.

    start and goal are (x, y) = (column, row) cells, None for a map file (it has no query).
    cell is the sweep cell's key ("uniform/32x32/0.2") or the file's path; plan() uses it with
    map_index and seed so that a stochastic planner draws what the sweep's run draws.
    """

    grid: numpy.ndarray
    start: Optional[Tuple[int, int]] = None
    goal: Optional[Tuple[int, int]] = None
    cell: str = "grid"
    map_index: int = 0
    seed: int = 0
    cell_edge: float = 1.0
    params: dict = field(default_factory=dict)

    def __post_init__(self):
        grid = self.grid.view(CellGrid)
        grid.stream = {"cell": self.cell, "map_index": self.map_index, "seed": self.seed,
                       "cell_edge": self.cell_edge}
        object.__setattr__(self, "grid", grid)


def make_map(generator, size, density, seed, map_index=0, *, map=None, **params):
    """Map `map_index` of the sweep cell (generator, size, density) under `seed`.

    Exactly the map of that cell in a sweep with this seed (and of `agvbench plan --generator`):
    `size` is a side or (width, height); `map` a config's "map" object (endpoints, min_distance,
    start and goal, require_solvable, solvable_rule, max_attempts, cell_edge); `params` the
    generator's shape parameters. Raises ValueError naming a bad argument, RuntimeError when no
    solvable map was found in max_attempts draws.
    """
    made = _core.make_map(plain(generator), plain(size), plain(density), plain(seed),
                          plain(map_index), plain(map), plain(params))
    return Map(**made)


def load_map(path):
    """A MovingAI .map, or a ROS map_server .yaml / .pgm / .png occupancy image, read as a
    map-file sweep reads it (unknown and occupied pixels are obstacles)."""
    return Map(**_core.load_map(str(path)))
