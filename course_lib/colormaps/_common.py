"""Shared input checks and constants of :mod:`course_lib.colormaps`."""

import numpy as np

from .._validate import as_array, as_vector


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _data_allowing_nan(value, name):
    """Like ``as_array`` but NaN is allowed (it marks missing data); infinity is not."""
    if isinstance(value, (str, bytes)) or value is None or value is Ellipsis:
        as_array(value, name)                       # raises the standard TypeError
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        as_array(value, name)
        raise
    if np.isinf(arr).any():
        raise ValueError(f"{name} must not contain infinite values (NaN is allowed and marks "
                         "missing data)")
    return arr


def _range(value, name, ordered):
    r = as_vector(value, name, 2)
    if ordered and r[0] > r[1]:
        raise ValueError(f"{name} must be (low, high) with low <= high, got ({r[0]:g}, {r[1]:g})")
    return r


def _data_range(data, in_range):
    if in_range is not None:
        return _range(in_range, "in_range", ordered=True)
    finite = data[~np.isnan(data)]
    if finite.size == 0:
        raise ValueError("data has no values to take the range from (it is empty or all NaN): "
                         "pass in_range=(low, high)")
    return np.array([finite.min(), finite.max()])


def _unit_interval(arr, name, what):
    bad = (arr < 0) | (arr > 1)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        raise ValueError(f"{name} must lie in [0, 1] ({what}), got {arr[index]:g} at index "
                         f"{index if len(index) > 1 else index[0]}")
    return arr
