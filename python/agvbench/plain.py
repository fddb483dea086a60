"""Python values as the engine reads them (JSON's types): numpy scalars become Python numbers."""

import numbers


def plain(value):
    """`value` with numpy scalars (in dicts, lists and tuples too) turned into Python ones."""
    if isinstance(value, dict):
        return {key: plain(v) for key, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, (bool, int, float, str)) or value is None:
        return value
    if isinstance(value, numbers.Number) and hasattr(value, "item"):
        return value.item()  # numpy.int64, numpy.float32, numpy.bool_ ...
    return value
