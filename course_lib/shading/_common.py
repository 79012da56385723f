"""Shared input checks and constants of :mod:`course_lib.shading`."""

import numpy as np

from .._linalg import dot as _dot  # noqa: F401 (the package's files use it)
from .._validate import as_array, as_points


# ---------------------------------------------------------------------------------------------
# Small vector helpers and input checks
# ---------------------------------------------------------------------------------------------

def _unit(value, name):
    """`value` as an array of 3D vectors (..., 3), each normalized; zero vectors are rejected."""
    v = as_points(value, name, dims=3)
    length = np.sqrt(_dot(v, v))
    if np.any(length == 0):
        index = np.unravel_index(np.argmin(length), length.shape) if length.ndim else ()
        where = f" (at index {tuple(int(i) for i in index)})" if length.ndim else ""
        raise ValueError(f"{name} must not contain zero vectors{where}: a zero vector has no "
                         "direction")
    return v / length[..., None]


def _shininess(value):
    n = as_array(value, "shininess")
    if np.any(n <= 0):
        raise ValueError(f"shininess must be positive (the specular exponent n), got "
                         f"{float(n[n <= 0].flat[0]):g}")
    return n
