"""Shared input checks and constants of :mod:`course_lib.texturing`."""

import numpy as np

from .._linalg import dot as _dot  # noqa: F401 (the package's files use it)
from .._validate import as_array

__all__ = ["WRAP_MODES"]


WRAP_MODES = ("repeat", "clamp", "mirror")


# ---------------------------------------------------------------------------------------------
# Input checks
# ---------------------------------------------------------------------------------------------

def _texture(texture, name="texture"):
    t = as_array(texture, name)
    if t.ndim not in (2, 3):
        raise ValueError(f"{name} must be a 2D array (H, W) of grey values or a 3D array "
                         f"(H, W, channels), got shape {t.shape}")
    if t.shape[0] == 0 or t.shape[1] == 0 or (t.ndim == 3 and t.shape[2] == 0):
        raise ValueError(f"{name} must not be empty, got shape {t.shape}")
    return t


def _uv(u, v):
    u = as_array(u, "u")
    v = as_array(v, "v")
    try:
        return np.broadcast_arrays(u, v)
    except ValueError:
        raise ValueError(f"u and v must have the same shape (or broadcast), got {u.shape} and "
                         f"{v.shape}") from None


def _wrap(index, n, wrap):
    """Integer texel indices wrapped into [0, n) by the wrap mode."""
    if wrap == "repeat":
        return index & (n - 1) if n & (n - 1) == 0 else np.mod(index, n)   # power of two: mask
    if wrap == "clamp":
        return np.clip(index, 0, n - 1)
    m = np.mod(index, 2 * n)
    return np.where(m < n, m, 2 * n - 1 - m)
