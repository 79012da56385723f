"""Shared input checks and constants of :mod:`course_lib.scivis`."""

import numpy as np

from .._validate import as_array, as_vector


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _grid(value, name, ndim):
    """A finite float array with `ndim` axes of at least 2 samples each (NaN rejected)."""
    what = {2: "a 2D field, shape (ny, nx)", 3: "a 3D volume, shape (nz, ny, nx)"}[ndim]
    arr = np.asarray(value) if isinstance(value, np.ndarray) else None
    if arr is not None and arr.dtype.kind == "f" and np.isnan(arr).any():
        raise ValueError(f"{name} contains NaN (missing data): fill or mask it first, e.g. "
                         f"np.nan_to_num({name}, nan=value)")
    arr = as_array(value, name)
    if arr.ndim != ndim:
        raise ValueError(f"{name} must be {what}, got {arr.ndim} axes (shape {arr.shape})")
    if min(arr.shape) < 2:
        raise ValueError(f"{name} must have at least 2 samples along every axis, got shape "
                         f"{arr.shape}")
    return arr


def _spacing(value, dim, name="spacing"):
    s = as_vector(value, name, dim)
    if (s <= 0).any():
        raise ValueError(f"{name} must be positive along every axis (the distance between "
                         f"neighbouring samples), got {tuple(float(v) for v in s)}")
    return s
