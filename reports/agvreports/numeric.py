"""Tests on the numbers of a report: JSON gives ints, floats, bools and nulls alike."""

import math


def finite(v):
    """A finite number (a bool is not one, though Python counts it as an int)."""
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def nan_or(v):
    return float(v) if finite(v) else float("nan")
