"""agvbench from Python: maps, single plans and sweeps of the agvbench engine (docs/PYTHON.md).

Import it with Debian's interpreter from the build tree (``PYTHONPATH=build/python
/usr/bin/python3``) or after ``cmake --install``. Bad input raises ValueError naming the argument.
"""

from agvbench._core import __version__
from agvbench.catalogue import generators, map_sources, planners
from agvbench.maps import Map, load_map, make_map
from agvbench.plans import PlanResult, plan
from agvbench.sweeps import SweepResult, merge, read_runs, run

__all__ = [
    "__version__",
    "Map",
    "PlanResult",
    "SweepResult",
    "generators",
    "load_map",
    "make_map",
    "map_sources",
    "merge",
    "plan",
    "planners",
    "read_runs",
    "run",
]
