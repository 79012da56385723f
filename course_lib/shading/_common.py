"""Shared input checks and constants of :mod:`course_lib.shading`."""

import numpy as np

from .._validate import as_array, as_points


# ---------------------------------------------------------------------------------------------
# Small vector helpers and input checks
# ---------------------------------------------------------------------------------------------

def _dot(a, b):
    return np.einsum("...i,...i->...", a, b)


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


def _rgb(value, name, low=0.0, high=None):
    """A colour: a number (grey), an RGB triple, or per-point colours (..., 3) or (..., 1)."""
    c = as_array(value, name)
    if c.ndim == 0:
        c = np.full(3, float(c))
    elif c.shape[-1] not in (1, 3):
        raise ValueError(f"{name} must be a number (grey) or RGB triples (shape (3,) or "
                         f"(..., 3)), got shape {c.shape}")
    if np.any(c < low) or (high is not None and np.any(c > high)):
        bad = c[(c < low) | ((c > high) if high is not None else False)].flat[0]
        rng = f"[{low:g}, {high:g}]" if high is not None else f">= {low:g}"
        raise ValueError(f"{name} must lie in {rng}, got {bad:g}")
    return c


def _shininess(value):
    n = as_array(value, "shininess")
    if np.any(n <= 0):
        raise ValueError(f"shininess must be positive (the specular exponent n), got "
                         f"{float(n[n <= 0].flat[0]):g}")
    return n
