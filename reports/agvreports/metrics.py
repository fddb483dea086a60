"""The metrics' names as the pictures, summary.md and the HTML page show them: unit, short
title, panel order, and planning time (the JSON keeps nanoseconds, the outputs microseconds).
"""

# Metric names -> (unit, short title). Order = panel order. Times are shown in microseconds
# (the JSON keeps nanoseconds in the fields named *_ns).
METRIC_LABELS = {
    "path_length": ("cells", "path length"),
    "path_length_m": ("m", "path length (m)"),
    "optimality_ratio": ("length / optimum", "optimality ratio"),
    "waypoints": ("waypoints", "waypoints"),
    "max_turn_rad": ("rad", "largest turn"),
    "any_angle_ratio": ("ratio", "length / any-angle optimum"),
    "scen_ratio": ("ratio", "length / MovingAI scenario optimum"),
    "turns": ("turns", "turns"),
    "turn_angle_rad": ("rad", "turn angle sum"),
    "smoothness_mean": ("rad / cell", "mean curvature proxy"),
    "smoothness_max": ("rad / cell", "max curvature proxy"),
    "min_clearance": ("cells", "min clearance"),
    "min_clearance_m": ("m", "min clearance (m)"),
    "motion_time_s": ("s", "motion time (eq. 5.2e)"),
    "search_expansions": ("nodes", "search expansions"),
    "collision_checks": ("checks", "collision checks"),
}
TIME = "plan_time_ns"
TIME_LABEL = ("\u00b5s", "planning time")
PAIRED_ORDER = ["path_length", "motion_time_s", "waypoints", "turns", "turn_angle_rad",
                "collision_checks"]


def metric_title(name):
    if name == TIME:
        return TIME_LABEL[1]
    return METRIC_LABELS.get(name, ("", name.replace("_", " ")))[1]


def metric_unit(name):
    if name == TIME:
        return TIME_LABEL[0]
    return METRIC_LABELS.get(name, ("", ""))[0]


def scale_of(name):
    """Factor from the JSON's unit to the shown one: ns -> µs for planning time."""
    return 1e-3 if name == TIME else 1.0
