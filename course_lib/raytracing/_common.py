"""Shared input checks and constants of :mod:`course_lib.raytracing`."""

import numpy as np

from .._linalg import dot as _dot  # noqa: F401 (the package's files use it)
from .._validate import as_array, as_points


DEFAULT_EPSILON = 1e-4


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _where(index, lead):
    """' (at index ...)' for a flat index into arrays of leading shape `lead`."""
    if not lead:
        return ""
    return f" (at index {tuple(int(i) for i in np.unravel_index(index, lead))})"


def _nonzero_vectors(v, name, lead):
    zero = ~np.any(v != 0, axis=-1)
    if zero.any():
        raise ValueError(f"{name} must not contain the zero vector"
                         f"{_where(int(np.argmax(zero.ravel())), lead)}: a ray needs a direction")


def _indices(value, name):
    """Refractive indices: positive numbers (arrays allowed)."""
    eta = as_array(value, name)
    if np.any(eta <= 0):
        raise ValueError(f"{name} must be positive (a refractive index; 1 for vacuum or air, "
                         f"about 1.5 for glass), got {float(eta[eta <= 0].flat[0]):g}")
    return eta


def _unit_vectors(value, name):
    v = as_points(value, name, dims=3)
    length = np.sqrt(_dot(v, v))
    if np.any(length == 0):
        raise ValueError(f"{name} must not contain the zero vector"
                         f"{_where(int(np.argmin(length.ravel())), length.shape)}: it has no "
                         "direction")
    return v / length[..., None]


