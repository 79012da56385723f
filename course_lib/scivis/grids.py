"""Chapter 18 (lesson section 1): bilinear and trilinear interpolation on regular grids."""

import numpy as np

from .._validate import as_array, as_points, as_vector
from ._common import _spacing

__all__ = ["multilinear_interpolate"]


# ---------------------------------------------------------------------------------------------
# Interpolation on grids
# ---------------------------------------------------------------------------------------------

def _lerp_grid(flat, dims, idx):
    """Multilinear interpolation at continuous index coordinates.

    flat : the grid raveled in C order (x fastest), shape (N,) or (N, k)
    dims : samples along x, y(, z)
    idx : list of d arrays of index coordinates along x, y(, z), any values (clamped)
    """
    strides = np.cumprod([1] + list(dims[:-1]))
    base, fracs = 0, []
    for c, n in enumerate(dims):
        u = np.clip(idx[c], 0.0, n - 1)
        i0 = np.minimum(u.astype(np.intp), n - 2)
        fracs.append(u - i0)
        base = base + i0 * strides[c]
    # corner k has bit c set when it is the upper neighbour along coordinate c
    values = [flat[base + sum(strides[c] for c in range(len(dims)) if (k >> c) & 1)]
              for k in range(2 ** len(dims))]
    for f in fracs:                                      # halve the list one coordinate at a time
        f = f if flat.ndim == 1 else f[:, None]
        values = [a + f * (b - a) for a, b in zip(values[::2], values[1::2])]
    return values[0]


def multilinear_interpolate(grid, points, spacing=None, origin=None):
    r"""Bilinear (2D) or trilinear (3D) interpolation of grid samples at arbitrary points.

    ``scivis.interpolate`` is this function under its old name (not the interpolation inside a
    triangle: that is :func:`course_lib.texturing.barycentric_interpolate`).

    In 3D, with :math:`(f_x, f_y, f_z)` the fractional position inside the cell,

    .. math:: f = \sum_{a, b, c \in \{0, 1\}} f_{i+a, j+b, k+c}\;
              w_a(f_x)\, w_b(f_y)\, w_c(f_z), \quad w_0(u) = 1 - u,\ w_1(u) = u,

    computed as seven linear interpolations: four along x, two along y, one along z. Points
    outside the grid take the value at the nearest point of its border (clamping).

    Parameters
    ----------
    grid : array_like
        Samples, shape (ny, nx) or (nz, ny, nx) (last axis x); with one more trailing axis
        (vector components) for vector data.
    points : array_like, shape (..., d)
        (x, y) or (x, y, z) positions; d decides whether the grid is 2D or 3D.
    spacing, origin : tuple of float, optional
        Grid geometry in coordinate order; default spacing 1 and origin 0.

    Returns
    -------
    ndarray, shape points.shape[:-1] (+ (k,) for vector data)

    Examples
    --------
    >>> multilinear_interpolate([[0, 1], [2, 3]], [[0.5, 0.5], [1, 0], [0, 2]])
    array([1.5, 1. , 2. ])
    """
    p = as_points(points, "points", dims=(2, 3))
    d = p.shape[-1]
    g = as_array(grid, "grid")
    if g.ndim not in (d, d + 1) or min(g.shape[:d]) < 2 or (g.ndim == d + 1 and g.shape[-1] < 1):
        raise ValueError(f"grid must hold {d}D samples (shape with {d} axes of >= 2 samples, "
                         f"plus optionally an axis of vector components) for {d}D points, got "
                         f"shape {g.shape}")
    sp = np.ones(d) if spacing is None else _spacing(spacing, d)
    org = np.zeros(d) if origin is None else as_vector(origin, "origin", d)
    dims = g.shape[:d][::-1]
    flat = g.reshape(int(np.prod(dims)), -1) if g.ndim == d + 1 else g.ravel()
    q = ((p - org) / sp).reshape(-1, d)
    out = _lerp_grid(flat, dims, [q[:, c] for c in range(d)])
    return out.reshape(p.shape[:-1] + out.shape[1:])


interpolate = multilinear_interpolate     # the old name (not in __all__): the same function
