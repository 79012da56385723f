"""Shared input checks and constants of :mod:`course_lib.mesh`."""

import numbers

import numpy as np

from .._validate import as_points


# The 3x3 block A of a quadric counts as singular when det(A) <= _SINGULAR * trace(A)**3. For a
# positive semi-definite A with eigenvalues l1 <= l2 <= l3 this is l1 l2 l3 <= 1e-10 (l1+l2+l3)^3,
# i.e. roughly l1 l2 / l3^2 below 3e-9: a flat (l1, l2 ~ 0) or cylindrical (l1 ~ 0) patch.
_SINGULAR = 1e-10


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _vertices(vertices):
    v = as_points(vertices, "vertices", dims=3)
    if v.ndim != 2:
        raise ValueError(f"vertices must be an (n, 3) array of points, got shape {v.shape}")
    return v


def _is_int_array(a):
    return np.issubdtype(a.dtype, np.integer) and not np.issubdtype(a.dtype, np.bool_)


def _face_table(faces):
    """Flatten a face list: (corners, starts) with face f = corners[starts[f]:starts[f + 1]].

    Accepts an (m, k) integer array (all faces with k vertices) or a sequence of integer
    sequences of any lengths (polygons).
    """
    if isinstance(faces, (str, bytes)) or faces is None or faces is Ellipsis:
        raise TypeError("faces must be a list of faces, each a list of vertex indices, got "
                        f"{'None' if faces is None else 'a ' + type(faces).__name__}")
    arr = None
    if isinstance(faces, np.ndarray):
        arr = faces
    else:
        try:
            arr = np.asarray(faces)
        except (TypeError, ValueError):        # ragged: polygons of different sizes
            arr = None
        if arr is not None and arr.dtype == object:
            arr = None
    if arr is not None and arr.ndim == 2 and arr.size:
        if not _is_int_array(arr):
            raise TypeError(f"faces must hold integer vertex indices, got an array of {arr.dtype}")
        m, k = arr.shape
        return arr.astype(np.int64).ravel(), np.arange(m + 1, dtype=np.int64) * k
    if arr is not None and arr.size == 0:
        raise ValueError("faces must contain at least one face, got none")
    if arr is not None and arr.ndim == 1 and _is_int_array(arr):
        raise ValueError(f"faces must be a list of faces, got one flat list of indices "
                         f"{arr.tolist()[:8]}{'...' if arr.size > 8 else ''}; for a single face "
                         "write [[a, b, c]]")
    if arr is not None and arr.ndim > 2:
        raise ValueError(f"faces must be an (m, k) array or a list of vertex-index lists, "
                         f"got shape {arr.shape}")
    try:
        items = list(faces)
    except TypeError:
        raise TypeError(f"faces must be a list of faces, got a {type(faces).__name__}") from None
    rows = []
    for i, f in enumerate(items):
        a = np.asarray(f) if not isinstance(f, (str, bytes)) else np.asarray([])
        if a.ndim != 1 or (a.size and not _is_int_array(a)):
            raise TypeError(f"face {i} must be a list of integer vertex indices, got {f!r}")
        rows.append(a.astype(np.int64))
    if not rows:
        raise ValueError("faces must contain at least one face, got none")
    sizes = np.array([len(r) for r in rows], dtype=np.int64)
    return np.concatenate(rows), np.concatenate([[0], np.cumsum(sizes)])


def _index(value, count, name, what):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer {what} index, got {value!r}")
    value = int(value)
    if not 0 <= value < count:
        raise ValueError(f"{name} must be a {what} index from 0 to {count - 1}, got {value}")
    return value


def _compact(vertices, faces):
    used = np.zeros(len(vertices), dtype=bool)
    used[faces] = True
    new_index = np.cumsum(used) - 1
    return vertices[used], new_index[faces].astype(np.int64)
