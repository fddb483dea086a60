"""What this build offers: the entries `agvbench list --json` prints, as Python objects."""

from agvbench import _core


def planners():
    """Every planner: a list of dicts (name, kind, summary, source, params, ...)."""
    return _core.catalogue()["planners"]


def generators():
    """Every map generator: a list of dicts (name, summary, params)."""
    return _core.catalogue()["generators"]


def map_sources():
    """Every map source (map files as a sweep's cells): a list of dicts (name, summary, params)."""
    return _core.catalogue()["map_sources"]
