"""Shared input checks and constants of :mod:`course_lib.visibility`."""

import numpy as np

from .._validate import as_array, as_matrix


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _triangles(value, name, dim=3):
    t = as_array(value, name)
    if t.shape == (3, dim):
        t = t[None]
    if t.ndim != 3 or t.shape[1:] != (3, dim):
        raise ValueError(f"{name} must be an array of triangles of shape (m, 3, {dim}) "
                         f"(m triangles, 3 vertices, {dim} coordinates), got shape {t.shape}")
    if len(t) == 0:
        raise ValueError(f"{name} must contain at least one triangle, got an empty array")
    return t


def _camera(view, projection):
    return as_matrix(view, "view", 4), as_matrix(projection, "projection", 4)
