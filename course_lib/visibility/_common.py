"""Shared input checks and constants of :mod:`course_lib.visibility`."""

import numpy as np

from .._raycore import as_triangles as _triangles  # noqa: F401 (painter, z_buffer)
from .._validate import as_matrix, as_points, as_scalar


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _pixels(value, name):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number of pixels, got a bool")
    v = as_scalar(value, name)
    if v <= 0 or v != int(v):
        raise ValueError(f"{name} must be a positive whole number of pixels, got {value!r}")
    return int(v)


def _faces(faces, n_vertices):
    f = np.asarray(faces)
    if f.ndim == 1 and f.shape == (3,):
        f = f[None]
    if f.ndim != 2 or f.shape[1] != 3 or not (np.issubdtype(f.dtype, np.integer) or f.size == 0):
        raise ValueError(f"faces must be an (m, 3) array of vertex indices (triangles only), "
                         f"got shape {f.shape} and type {f.dtype}")
    if len(f) == 0:
        raise ValueError("faces must contain at least one triangle, got an empty array")
    if f.min() < 0 or f.max() >= n_vertices:
        bad = int(f.max() if f.max() >= n_vertices else f.min())
        raise ValueError(f"faces refers to vertex {bad} but there are {n_vertices} vertices")
    return f.astype(np.intp)


def _mesh(vertices, faces):
    v = as_points(vertices, "vertices", dims=3)
    if v.ndim != 2 or len(v) == 0:
        raise ValueError(f"vertices must be an (n, 3) array with n >= 1, got shape {v.shape}")
    return v, _faces(faces, len(v))


def _camera(view, projection):
    return as_matrix(view, "view", 4), as_matrix(projection, "projection", 4)
