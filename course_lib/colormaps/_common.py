"""Shared input checks and constants of :mod:`course_lib.colormaps`."""

import numpy as np

from .._validate import as_array, as_scalar, as_vector


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


def _rgb(value, name="rgb"):
    rgb = as_array(value, name)
    if rgb.ndim == 0 or rgb.shape[-1] != 3:
        raise ValueError(f"{name} must have 3 components (r, g, b) in the last axis, got shape "
                         f"{rgb.shape}")
    if ((rgb < -1e-9) | (rgb > 1 + 1e-9)).any():
        _unit_interval(rgb, name, "sRGB components")
    return np.clip(rgb, 0.0, 1.0)


def _count(value, name, minimum):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got a bool")
    v = as_scalar(value, name)
    if v != int(v) or v < minimum:
        raise ValueError(f"{name} must be a whole number >= {minimum}, got {value!r}")
    return int(v)
