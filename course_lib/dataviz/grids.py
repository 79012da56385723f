r"""Chapter 10.3, data aspects: the kinds of grid a data set is sampled on, and interpolation.

Five kinds, from the most regular to the least (what must be stored grows at each step):

* **uniform** (regular, "image data"): samples on a lattice with one spacing per axis; the
  origin, the spacings and the sample counts describe every position. With the same spacing on
  every axis it is also called *Cartesian*.
* **rectilinear**: the samples still lie on axis-parallel lines, but the spacing varies along
  each axis; one coordinate array per axis.
* **curvilinear** (structured): the topology is still an ``(ny, nx)`` lattice (each sample has
  its left, right, lower and upper neighbours), but every sample has its own position: the
  lattice is bent; one position per sample.
* **unstructured**: positions *and* an explicit list of cells (triangles, quads, tetrahedra),
  each given by the indices of its corners.
* **scattered**: positions only, no cells at all; neighbours must be found (or a
  triangulation built) before anything can be interpolated.

Finding the cell that holds a point is a division on a uniform grid, a binary search per axis on
a rectilinear one, and a search among the cells on the others (here: buckets over the points,
then an inside test per candidate cell).

Conventions: sample arrays are ``(ny, nx)`` or ``(nz, ny, nx)`` (last axis x, as in
:mod:`course_lib.scivis`); coordinates, spacings and origins are in coordinate order
``(x, y(, z))``. A structured cell ``(j, i)`` has the corners ``p00 = P[j, i]``,
``p10 = P[j, i+1]``, ``p11 = P[j+1, i+1]``, ``p01 = P[j+1, i]`` (counter-clockwise).
"""
from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_choice, as_points, as_whole
from ..scivis import multilinear_interpolate
from ..texturing import barycentric
from ._buckets import _box_point_pairs

__all__ = [
    "GRID_DESCRIPTIONS",
    "GRID_KINDS",
    "Grid",
    "curvilinear_grid",
    "curvilinear_interpolate",
    "grid_interpolate",
    "grid_kind",
    "grid_memory",
    "inverse_bilinear",
    "rectilinear_grid",
    "rectilinear_interpolate",
    "scattered_points",
    "triangle_interpolate",
    "uniform_grid",
    "unstructured_grid",
]

#: The kinds of grid, from the most to the least regular.
GRID_KINDS = ("uniform", "rectilinear", "curvilinear", "unstructured", "scattered")

#: What each kind stores, and how a point's cell is found.
GRID_DESCRIPTIONS = {
    "uniform": ("origin, spacing and sample count per axis (3d numbers)",
                "implicit lattice", "a division per axis: i = floor((x - x0) / dx)"),
    "rectilinear": ("one coordinate array per axis (nx + ny (+ nz) numbers)",
                    "implicit lattice", "a binary search per axis"),
    "curvilinear": ("a position per sample (d numbers each)", "implicit lattice",
                    "a search among the cells (or a walk from a known cell)"),
    "unstructured": ("a position per sample and the corner indices of every cell",
                     "explicit cells", "a search among the cells (with a spatial index)"),
    "scattered": ("a position per sample", "none", "no cells: find neighbours, or build a "
                  "triangulation first"),
}


class Grid(NamedTuple):
    """A grid of any kind: where its samples are, its cells, and what it must store.

    Attributes
    ----------
    kind : str
        One of :data:`GRID_KINDS`.
    nodes : ndarray, shape (n, d)
        The position of every sample (for structured kinds in C order: x fastest).
    shape : tuple or None
        The shape of the sample array (``(ny, nx)``, ``(nz, ny, nx)``) for the structured
        kinds; None for unstructured and scattered.
    cells : ndarray of intp, shape (m, k) or None
        Corner indices into ``nodes`` of every cell (quads of 4 counter-clockwise corners or
        hexahedra of 8 for the structured kinds; given for unstructured; None for scattered).
    stored : dict
        What this kind must keep in memory to describe the geometry and topology: name ->
        array (its ``size`` counts the numbers).

    Examples
    --------
    >>> g = uniform_grid((3, 4), spacing=(0.5, 1.0))
    >>> g.kind, g.nodes.shape, g.cells.shape, sorted(g.stored)
    ('uniform', (12, 2), (6, 4), ['counts', 'origin', 'spacing'])
    """

    kind: str
    nodes: np.ndarray
    shape: tuple
    cells: np.ndarray
    stored: dict


def _structured_cells(shape):
    """Corner indices of the cells of a structured lattice of sample-array `shape`."""
    if len(shape) == 2:
        ny, nx = shape
        j, i = np.meshgrid(np.arange(ny - 1), np.arange(nx - 1), indexing="ij")
        base = (j * nx + i).ravel()
        return np.stack([base, base + 1, base + nx + 1, base + nx], axis=1).astype(np.intp)
    nz, ny, nx = shape
    k, j, i = np.meshgrid(np.arange(nz - 1), np.arange(ny - 1), np.arange(nx - 1),
                          indexing="ij")
    base = ((k * ny + j) * nx + i).ravel()
    quad = np.stack([base, base + 1, base + nx + 1, base + nx], axis=1)
    return np.concatenate([quad, quad + nx * ny], axis=1).astype(np.intp)


def _lattice_shape(shape):
    s = tuple(as_whole(n, "shape", 2) for n in np.atleast_1d(np.asarray(shape, dtype=object)))
    if len(s) not in (2, 3):
        raise ValueError(f"shape must be (ny, nx) or (nz, ny, nx), got {tuple(shape)}")
    return s


def uniform_grid(shape, spacing=1.0, origin=0.0):
    """A uniform grid: samples at ``origin + index * spacing`` along every axis.

    Parameters
    ----------
    shape : tuple of int
        The sample array's shape ``(ny, nx)`` or ``(nz, ny, nx)``, at least 2 per axis.
    spacing, origin : float or sequence of float
        Per axis in coordinate order (x, y(, z)); a single number for every axis.

    Returns
    -------
    Grid

    Examples
    --------
    >>> uniform_grid((2, 3), spacing=(1.0, 2.0), origin=(10.0, 0.0)).nodes
    array([[10.,  0.],
           [11.,  0.],
           [12.,  0.],
           [10.,  2.],
           [11.,  2.],
           [12.,  2.]])
    """
    s = _lattice_shape(shape)
    d = len(s)
    sp = np.broadcast_to(as_array(spacing, "spacing"), (d,)).astype(float)
    if (sp <= 0).any():
        raise ValueError(f"spacing must be positive along every axis, got {tuple(sp)}")
    org = np.broadcast_to(as_array(origin, "origin"), (d,)).astype(float)
    axes = [org[c] + sp[c] * np.arange(s[d - 1 - c]) for c in range(d)]
    nodes = _tensor_nodes(axes)
    return Grid("uniform", nodes, s, _structured_cells(s),
                {"origin": org.copy(), "spacing": sp.copy(), "counts": np.array(s[::-1])})


def _tensor_nodes(axes):
    """All positions of the tensor-product lattice of 1D `axes` (coordinate order), x fastest."""
    mesh = np.meshgrid(*axes[::-1], indexing="ij")[::-1]
    return np.stack([m.ravel() for m in mesh], axis=1)


def _grid_axis(values, name):
    a = as_array(values, name)
    if a.ndim != 1 or a.size < 2:
        raise ValueError(f"{name} must be a 1D array of at least 2 coordinates, got shape "
                         f"{a.shape}")
    if np.any(np.diff(a) <= 0):
        raise ValueError(f"{name} must be strictly increasing (one coordinate per sample "
                         f"along the axis), got {a.tolist()}")
    return a


def rectilinear_grid(*axes):
    """A rectilinear grid: the tensor product of one increasing coordinate array per axis.

    Parameters
    ----------
    *axes : array_like
        The x, y (and z) coordinates of the samples along each axis, strictly increasing.

    Returns
    -------
    Grid

    Examples
    --------
    >>> g = rectilinear_grid([0, 1, 3], [0, 2])
    >>> g.shape, g.nodes[:4].tolist()
    ((2, 3), [[0.0, 0.0], [1.0, 0.0], [3.0, 0.0], [0.0, 2.0]])
    """
    if len(axes) not in (2, 3):
        raise ValueError(f"rectilinear_grid takes 2 or 3 coordinate arrays (x, y(, z)), got "
                         f"{len(axes)}")
    ax = [_grid_axis(a, "xyz"[c]) for c, a in enumerate(axes)]
    s = tuple(len(a) for a in ax[::-1])
    return Grid("rectilinear", _tensor_nodes(ax), s, _structured_cells(s),
                {**{"xyz"[c]: a.copy() for c, a in enumerate(ax)}, "counts": np.array(s[::-1])})


def curvilinear_grid(coordinates):
    """A curvilinear grid: a lattice of samples, each at its own position.

    Parameters
    ----------
    coordinates : array_like, shape (ny, nx, 2) or (nz, ny, nx, 3)
        The position of each sample (e.g. ``np.stack([X, Y], axis=-1)``).

    Returns
    -------
    Grid

    Examples
    --------
    >>> r, t = np.meshgrid([1.0, 2.0], np.radians([0, 45, 90]))    # a quarter annulus
    >>> g = curvilinear_grid(np.stack([r * np.cos(t), r * np.sin(t)], axis=-1))
    >>> g.kind, g.shape, g.cells.shape, g.stored["coordinates"].size, g.stored["counts"]
    ('curvilinear', (3, 2), (2, 4), 12, array([2, 3]))
    """
    c = as_array(coordinates, "coordinates")
    if c.ndim not in (3, 4) or c.shape[-1] != c.ndim - 1 or min(c.shape[:-1]) < 2:
        raise ValueError("coordinates must be the positions of a lattice, shape (ny, nx, 2) "
                         f"or (nz, ny, nx, 3) with at least 2 samples per axis, got shape "
                         f"{c.shape}")
    s = c.shape[:-1]
    return Grid("curvilinear", c.reshape(-1, c.shape[-1]).copy(), s, _structured_cells(s),
                {"coordinates": c.copy(), "counts": np.array(s[::-1])})


def _cell_indices(cells, n_nodes, name="cells"):
    arr = np.asarray(cells)
    if arr.dtype.kind not in "iu" or arr.ndim != 2 or arr.shape[0] < 1 or arr.shape[1] < 3:
        raise ValueError(f"{name} must be an (m, k) array of whole-number corner indices, "
                         f"k >= 3, got {arr.dtype} of shape {arr.shape}")
    if arr.min() < 0 or arr.max() >= n_nodes:
        raise ValueError(f"{name} refer to corners {int(arr.min())}..{int(arr.max())}, but "
                         f"there are only {n_nodes} nodes (0..{n_nodes - 1})")
    return arr.astype(np.intp)


def _grid_nodes_array(points, name="points"):
    p = as_array(points, name)
    if p.ndim != 2 or p.shape[1] not in (2, 3) or p.shape[0] < 1:
        raise ValueError(f"{name} must have shape (n, 2) or (n, 3), got shape {p.shape}")
    return p


def unstructured_grid(points, cells):
    """An unstructured grid: positions and an explicit list of cells.

    Parameters
    ----------
    points : array_like, shape (n, 2) or (n, 3)
    cells : array_like of int, shape (m, k)
        The corner indices of each cell (3 for triangles, 4 for quads or tetrahedra...).

    Returns
    -------
    Grid

    Examples
    --------
    >>> g = unstructured_grid([[0, 0], [1, 0], [0, 1], [1, 1]], [[0, 1, 2], [1, 3, 2]])
    >>> g.kind, sum(a.size for a in g.stored.values())          # 8 coordinates + 6 indices
    ('unstructured', 14)
    """
    p = _grid_nodes_array(points)
    c = _cell_indices(cells, len(p))
    return Grid("unstructured", p.copy(), None, c, {"points": p.copy(), "cells": c.copy()})


def scattered_points(points):
    """Scattered data: positions only, no cells.

    Parameters
    ----------
    points : array_like, shape (n, 2) or (n, 3)

    Returns
    -------
    Grid

    Examples
    --------
    >>> g = scattered_points([[0.2, 0.1], [0.7, 0.4], [0.5, 0.9]])
    >>> g.kind, g.cells is None, g.stored["points"].size
    ('scattered', True, 6)
    """
    p = _grid_nodes_array(points)
    return Grid("scattered", p.copy(), None, None, {"points": p.copy()})


def grid_kind(x, y=None, z=None, *, cells=None, explain=False, rtol=1e-6):
    """Tell the kind of a grid from how its coordinates are given.

    * 1D arrays ``x, y(, z)``, one per axis: **uniform** if each is evenly spaced, else
      **rectilinear**;
    * full arrays ``X, Y(, Z)`` of one shape (a coordinate per sample, as ``np.meshgrid``
      makes): **uniform** or **rectilinear** when they are a tensor product after all (X varies
      along one array axis only, Y along another), else **curvilinear**;
    * one ``(n, d)`` array of points: **unstructured** with ``cells``, **scattered** without.

    Parameters
    ----------
    x, y, z : array_like
        The coordinates, in one of the three forms above.
    cells : array_like of int, shape (m, k), optional
        Corner indices of cells (points form only).
    explain : bool
        Also return a sentence saying why.
    rtol : float
        Relative tolerance for "evenly spaced" and "constant along an axis".

    Returns
    -------
    str, or (str, str) with `explain`

    Raises
    ------
    ValueError
        For coordinates in none of the forms, axes that do not increase, or bad cells.

    Examples
    --------
    >>> grid_kind([0, 1, 2, 3], [0, 0.5, 1.0])
    'uniform'
    >>> grid_kind([0, 1, 2, 3], [0, 0.1, 0.5, 2.0])
    'rectilinear'
    >>> X, Y = np.meshgrid([0, 1, 3], [0, 2])
    >>> grid_kind(X, Y)
    'rectilinear'
    >>> grid_kind(X + 0.3 * Y, Y)               # a sheared lattice
    'curvilinear'
    >>> grid_kind([[0, 0], [1, 0], [0, 1]], cells=[[0, 1, 2]]), grid_kind([[0, 0], [1, 0]])
    ('unstructured', 'scattered')
    """
    kind, why = _grid_kind(x, y, z, cells, rtol)
    return (kind, why) if explain else kind


def _grid_kind(x, y, z, cells, rtol):
    if y is None:
        if z is not None:
            raise ValueError("give the coordinates as x, y(, z) or as one (n, d) array of "
                             "points, not x and z alone")
        p = _grid_nodes_array(x, "points")
        if cells is None:
            return "scattered", (f"{len(p)} positions and no cells: nothing says which points "
                                 "are neighbours")
        c = _cell_indices(cells, len(p))
        return "unstructured", (f"{len(p)} positions and {len(c)} explicit cells of "
                                f"{c.shape[1]} corners each")
    if cells is not None:
        raise ValueError("cells belong to an unstructured grid: give its points as one (n, d) "
                         "array, not as separate x, y(, z)")
    arrays = [as_array(a, "xyz"[c]) for c, a in enumerate((x, y, z)) if a is not None]
    d = len(arrays)
    if all(a.ndim == 1 for a in arrays):
        axes = [_grid_axis(a, "xyz"[c]) for c, a in enumerate(arrays)]
        return _uniform_or_rectilinear(axes, rtol, "one coordinate array per axis")
    shape = arrays[0].shape
    if not all(a.shape == shape for a in arrays) or len(shape) != d or min(shape) < 2:
        raise ValueError("the coordinates must be 1D arrays (one per axis) or arrays of one "
                         f"shape with {d} axes (a coordinate per sample), got shapes "
                         + ", ".join(str(a.shape) for a in arrays))
    axes = []
    for c, a in enumerate(arrays):
        scale = max(np.abs(a).max(), np.ptp(a), 1e-300)
        varies = [ax for ax in range(d)
                  if np.abs(np.diff(a, axis=ax)).max() > rtol * scale]
        if len(varies) != 1:
            return "curvilinear", (f"a position per sample, and {'xyz'[c]} changes along "
                                   f"{len(varies)} array axes: the lattice is bent")
        line = np.moveaxis(a, varies[0], 0)[(slice(None),) + (0,) * (d - 1)]
        axes.append((varies[0], line))
    if len({ax for ax, _ in axes}) != d:
        return "curvilinear", ("two coordinates change along the same array axis: the lattice "
                               "is not axis-parallel")
    lines = [line if line[-1] > line[0] else line[::-1] for _, line in axes]
    if any(np.any(np.diff(line) <= 0) for line in lines):
        return "curvilinear", "the samples are not in order along an axis: a folded lattice"
    return _uniform_or_rectilinear(lines, rtol, "full coordinate arrays that are a tensor "
                                   "product")


def _uniform_or_rectilinear(axes, rtol, given):
    steps = [np.diff(a) for a in axes]
    even = [np.abs(s - s.mean()).max() <= rtol * s.mean() for s in steps]
    if all(even):
        means = [s.mean() for s in steps]
        same = max(means) - min(means) <= rtol * max(means)
        return "uniform", (f"{given}, each evenly spaced (spacing "
                           + ", ".join(f"{m:.4g}" for m in means) + ")"
                           + (": the same on every axis, so also Cartesian" if same else ""))
    uneven = [("xyz"[c]) for c, e in enumerate(even) if not e]
    return "rectilinear", (f"{given}, and the spacing varies along {', '.join(uneven)}")


_NUMBERS_PER_CELL = {"triangle": (2, 3), "quad": (1, 4), "tetrahedron": (6, 4),
                     "hexahedron": (1, 8)}


def grid_memory(kind, shape, components=1, *, cell=None, bytes_per_number=None):
    r"""How many numbers a grid of `kind` stores for its samples: geometry, topology, values.

    Conventions (the same for every kind, so that the counts compare):

    * **geometry**: uniform, origin and spacing per axis (2d numbers); rectilinear, the
      coordinates along each axis (:math:`n_x + n_y (+ n_z)`); curvilinear, unstructured and
      scattered, d coordinates per sample (:math:`d N`);
    * **topology**: the structured kinds, the sample count per axis (d numbers);
      unstructured, the corner indices of its cells, here the cells of the same lattice split
      into ``cell`` s (2 triangles per quad, 6 tetrahedra per hexahedron, or quads and
      hexahedra as they are); scattered, nothing;
    * **values**: :math:`N` times `components`, for every kind.

    Parameters
    ----------
    kind : str
        One of :data:`GRID_KINDS`.
    shape : tuple of int
        The samples per axis as an array shape, ``(ny, nx)`` or ``(nz, ny, nx)``.
    components : int
        Numbers per sample (1 for a scalar, d for a vector...).
    cell : str, optional
        Unstructured only: ``"triangle"`` (default in 2D) or ``"quad"``; ``"tetrahedron"``
        (default in 3D) or ``"hexahedron"``.
    bytes_per_number : int, optional
        If given, also the total in bytes (every number the same size).

    Returns
    -------
    dict
        ``"geometry"``, ``"topology"``, ``"values"``, ``"total"`` (numbers) and ``"bytes"``.

    Examples
    --------
    >>> grid_memory("uniform", (50, 100))
    {'geometry': 4, 'topology': 2, 'values': 5000, 'total': 5006}
    >>> grid_memory("rectilinear", (50, 100))["geometry"]
    150
    >>> m = grid_memory("unstructured", (50, 100), bytes_per_number=4)
    >>> m["geometry"], m["topology"], m["bytes"]          # 2 * 49 * 99 triangles, 3 indices each
    (10000, 29106, 176424)
    """
    kind = as_choice(kind, "kind", GRID_KINDS)
    s = _lattice_shape(shape)
    d = len(s)
    n = int(np.prod(s))
    k = as_whole(components, "components", 1)
    cells = int(np.prod([m - 1 for m in s]))
    if cell is not None and kind != "unstructured":
        raise ValueError(f"cell applies to unstructured grids only, not to {kind} grids")
    if kind == "uniform":
        geometry, topology = 2 * d, d
    elif kind == "rectilinear":
        geometry, topology = sum(s), d
    elif kind == "curvilinear":
        geometry, topology = d * n, d
    elif kind == "scattered":
        geometry, topology = d * n, 0
    else:
        allowed = ("triangle", "quad") if d == 2 else ("tetrahedron", "hexahedron")
        name = as_choice(allowed[0] if cell is None else cell, "cell", allowed)
        per, corners = _NUMBERS_PER_CELL[name]
        geometry, topology = d * n, per * cells * corners
    out = {"geometry": geometry, "topology": topology, "values": n * k,
           "total": geometry + topology + n * k}
    if bytes_per_number is not None:
        out["bytes"] = out["total"] * as_whole(bytes_per_number, "bytes_per_number", 1)
    return out


# ---------------------------------------------------------------------------------------------
# Interpolation on grids
# ---------------------------------------------------------------------------------------------

def _grid_outside_policy(outside, allowed):
    if isinstance(outside, str):
        return as_choice(outside, "outside", allowed)
    if isinstance(outside, (bool, np.bool_)) or not isinstance(outside, (int, float)):
        raise TypeError(f"outside must be one of {', '.join(map(repr, allowed))} or a number "
                        f"to fill with, got {outside!r}")
    return float(outside)


def _grid_samples(values, name="values"):
    """Sample values as a finite float array; NaN (missing data) named as such."""
    v = np.asarray(values)
    if v.dtype.kind == "f" and np.isnan(v).any():
        raise ValueError(f"{name} contains NaN (missing data): fill or mask it first")
    return as_array(v, name)


def rectilinear_interpolate(values, axes, points, outside="raise"):
    r"""Bilinear (2D) or trilinear (3D) interpolation on a rectilinear grid.

    A rectilinear grid is a uniform grid in *index space*: along each axis, a binary search
    finds the interval :math:`x_i \le x < x_{i+1}` holding the coordinate, and

    .. math:: u = i + \frac{x - x_i}{x_{i+1} - x_i}

    is its continuous index. Multilinear interpolation at the indices :math:`(u, v(, w))` with
    spacing 1 (:func:`course_lib.scivis.multilinear_interpolate`) is then exactly the
    bilinear/trilinear interpolation of the rectilinear cell.

    Parameters
    ----------
    values : array_like, shape (ny, nx) or (nz, ny, nx), optionally (..., k)
    axes : sequence of array_like
        The coordinates along x, y (, z), strictly increasing, as long as the matching axes of
        `values`.
    points : array_like, shape (..., d)
    outside : {"raise", "clamp"} or float
        Points outside the grid: an error (default), the value at the nearest border point,
        or this fill value.

    Returns
    -------
    ndarray, shape points.shape[:-1] (+ (k,))

    Examples
    --------
    >>> x, y = [0.0, 1.0, 4.0], [0.0, 2.0]
    >>> f = [[0.0, 1.0, 4.0], [2.0, 3.0, 6.0]]                 # f = x + y
    >>> rectilinear_interpolate(f, (x, y), [[2.5, 1.0], [0.5, 0.5]])
    array([3.5, 1. ])
    """
    policy = _grid_outside_policy(outside, ("raise", "clamp"))
    ax = [_grid_axis(a, f"axes[{c}]") for c, a in enumerate(axes)]
    d = len(ax)
    if d not in (2, 3):
        raise ValueError(f"axes must hold 2 or 3 coordinate arrays (x, y(, z)), got {d}")
    v = _grid_samples(values)
    if v.ndim not in (d, d + 1) or v.shape[:d] != tuple(len(a) for a in ax[::-1]):
        raise ValueError(f"values must have shape {tuple(len(a) for a in ax[::-1])} (ny, nx"
                         f"{', ' if d == 2 else ', nz first, '}last axis x) optionally with an "
                         f"axis of components, to match the axes; got shape {v.shape}")
    p = as_points(points, "points", dims=d)
    flat = p.reshape(-1, d)
    out_mask = np.zeros(len(flat), dtype=bool)
    index = np.empty_like(flat)
    for c, a in enumerate(ax):
        coord = flat[:, c]
        tol = 1e-12 * (a[-1] - a[0])
        out_mask |= (coord < a[0] - tol) | (coord > a[-1] + tol)
        coord = np.clip(coord, a[0], a[-1])
        i = np.clip(np.searchsorted(a, coord, side="right") - 1, 0, len(a) - 2)
        index[:, c] = i + (coord - a[i]) / (a[i + 1] - a[i])
    if policy == "raise" and out_mask.any():
        box = " x ".join(f"[{a[0]:g}, {a[-1]:g}]" for a in ax)
        raise ValueError(f"{int(out_mask.sum())} of the points lie outside the grid {box}; "
                         "pass outside='clamp' or a fill value")
    out = multilinear_interpolate(v, index)
    if not isinstance(policy, str):
        out[out_mask] = policy
    return out.reshape(p.shape[:-1] + out.shape[1:])


def _bilinear_newton(corners, points, iterations=30):
    """(u, v) with B(u, v) = point for quads (..., 4, 2), by Newton's method; and whether it
    converged (False for a degenerate map at the iterate)."""
    p00, p10, p11, p01 = (corners[..., k, :] for k in range(4))
    e, f, g = p10 - p00, p01 - p00, p00 - p10 + p11 - p01
    h = points - p00
    u = np.full(h.shape[:-1], 0.5)
    v = np.full(h.shape[:-1], 0.5)
    ok = np.ones(h.shape[:-1], dtype=bool)
    for _ in range(iterations):
        r = u[..., None] * e + v[..., None] * f + (u * v)[..., None] * g - h
        ju = e + v[..., None] * g                       # dB/du
        jv = f + u[..., None] * g                       # dB/dv
        det = ju[..., 0] * jv[..., 1] - ju[..., 1] * jv[..., 0]
        scale = np.einsum("...i,...i->...", e, e) + np.einsum("...i,...i->...", f, f)
        good = np.abs(det) > 1e-12 * scale
        ok &= good
        det = np.where(good, det, 1.0)
        du = (r[..., 0] * jv[..., 1] - r[..., 1] * jv[..., 0]) / det
        dv = (ju[..., 0] * r[..., 1] - ju[..., 1] * r[..., 0]) / det
        u = np.where(ok, u - du, u)
        v = np.where(ok, v - dv, v)
        u = np.clip(u, -1e6, 1e6)
        v = np.clip(v, -1e6, 1e6)
    r = u[..., None] * e + v[..., None] * f + (u * v)[..., None] * g - h
    size = np.sqrt(np.maximum(np.einsum("...i,...i->...", e, e),
                              np.einsum("...i,...i->...", f, f)))
    ok &= np.sqrt(np.einsum("...i,...i->...", r, r)) <= 1e-9 * np.maximum(size, 1e-300)
    return u, v, ok


def inverse_bilinear(corners, points):
    r"""The local coordinates :math:`(u, v)` of points in a quadrilateral cell.

    A curvilinear cell maps the unit square onto the quad by the bilinear map

    .. math:: B(u, v) = (1-u)(1-v)\,p_{00} + u(1-v)\,p_{10} + uv\,p_{11} + (1-u)v\,p_{01}
              = p_{00} + u\,e + v\,f + uv\,g,

    with :math:`e = p_{10} - p_{00}`, :math:`f = p_{01} - p_{00}`,
    :math:`g = p_{00} - p_{10} + p_{11} - p_{01}`. Inverting it (which :math:`(u, v)` lands on
    the point?) is two equations in two unknowns, quadratic because of the :math:`uv` term;
    here it is solved by Newton's method from the centre :math:`(\tfrac12, \tfrac12)`, each
    step solving the 2x2 system with the Jacobian :math:`[e + v g,\; f + u g]`. For a
    parallelogram :math:`g = 0` and one step suffices. The point is inside the cell exactly when
    :math:`0 \le u, v \le 1`.

    Parameters
    ----------
    corners : array_like, shape (..., 4, 2)
        :math:`p_{00}, p_{10}, p_{11}, p_{01}` (counter-clockwise), one quad or one per point.
    points : array_like, shape (..., 2)

    Returns
    -------
    ndarray, shape (..., 2)
        :math:`(u, v)` per point.

    Raises
    ------
    ValueError
        If Newton's method does not converge (a degenerate or folded cell, or a point far
        outside a non-parallelogram cell).

    Examples
    --------
    >>> quad = [[0, 0], [2, 0], [3, 2], [0, 2]]              # a trapezoid
    >>> inverse_bilinear(quad, [[1.25, 1.0], [0.0, 0.0]])
    array([[0.5, 0.5],
           [0. , 0. ]])
    """
    q = as_array(corners, "corners")
    if q.ndim < 2 or q.shape[-2:] != (4, 2):
        raise ValueError(f"corners must have shape (..., 4, 2): the 4 corners p00, p10, p11, "
                         f"p01 of a quad, got shape {q.shape}")
    p = as_points(points, "points", dims=2)
    try:
        shape = np.broadcast_shapes(q.shape[:-2], p.shape[:-1])
    except ValueError:
        raise ValueError(f"corners {q.shape} and points {p.shape} do not broadcast: give one "
                         "quad, or one per point") from None
    qb = np.broadcast_to(q, shape + (4, 2))
    pb = np.broadcast_to(p, shape + (2,))
    u, v, ok = _bilinear_newton(qb, pb)
    if not np.all(ok):
        raise ValueError(f"the bilinear map could not be inverted for {int((~ok).sum())} "
                         "point(s): the cell is degenerate or folded (corners not in "
                         "counter-clockwise order p00, p10, p11, p01?), or the point lies far "
                         "outside it")
    return np.stack([u, v], axis=-1)


def _locate_cells(lo, hi, points, inside_test):
    """For each point, the lowest-numbered cell (box) that holds it, or -1, and the inside
    test's extra result for that pair. `inside_test(cells, pts_idx)` returns (inside, extra)."""
    cell_of = np.full(len(points), -1, dtype=np.intp)
    extra_of = None
    pad = 1e-9 * max(float(np.ptp(points)) if points.size else 1.0, 1e-300)
    for cells, idx in _box_point_pairs(lo - pad, hi + pad, points):
        inside, extra = inside_test(cells, idx)
        cells, idx, extra = cells[inside], idx[inside], extra[inside]
        fresh = cell_of[idx] < 0
        cells, idx, extra = cells[fresh], idx[fresh], extra[fresh]
        first_idx, first = np.unique(idx, return_index=True)   # pairs run by cell: the lowest
        if extra_of is None:
            extra_of = np.zeros((len(points),) + extra.shape[1:])
        cell_of[first_idx] = cells[first]
        extra_of[first_idx] = extra[first]
    if extra_of is None:
        extra_of = np.zeros((len(points), 3))
    return cell_of, extra_of


def _fill_outside(out, found, policy, what):
    if not found.all():
        if policy == "raise":
            raise ValueError(f"{int((~found).sum())} of the points lie outside every {what}; "
                             "pass outside=<a fill value> (e.g. outside=np.nan) to fill them")
        out[~found] = policy
    return out


def triangle_interpolate(nodes, triangles, values, points, outside="raise"):
    r"""Linear interpolation on a triangle mesh (an unstructured grid of triangles).

    The triangle holding the point is found (buckets over the points, then the sign test of
    the barycentric coordinates per candidate); inside it the value is the barycentric
    combination of its corners' values, :math:`f = \lambda_a f_a + \lambda_b f_b +
    \lambda_c f_c` (:func:`course_lib.texturing.barycentric`): linear in the triangle,
    continuous across edges, never beyond the corners' values. A point on a shared edge takes
    the lowest-numbered triangle (the same value either way).

    Parameters
    ----------
    nodes : array_like, shape (n, 2)
    triangles : array_like of int, shape (m, 3)
    values : array_like, shape (n,) or (n, k)
    points : array_like, shape (..., 2)
    outside : "raise" or float
        Points in no triangle: an error (default) or this fill value (``np.nan`` allowed).

    Returns
    -------
    ndarray, shape points.shape[:-1] (+ (k,))

    Examples
    --------
    >>> nodes = [[0, 0], [4, 0], [0, 4], [4, 4]]
    >>> tris = [[0, 1, 2], [1, 3, 2]]
    >>> triangle_interpolate(nodes, tris, [0.0, 4.0, 8.0, 12.0], [[1, 2], [3, 3]])
    array([5., 9.])
    """
    policy = _grid_outside_policy(outside, ("raise",))
    nd = as_array(nodes, "nodes")
    if nd.ndim != 2 or nd.shape[1] != 2 or len(nd) < 3:
        raise ValueError(f"nodes must have shape (n, 2) with n >= 3, got shape {nd.shape}")
    tri = _cell_indices(triangles, len(nd), "triangles")
    if tri.shape[1] != 3:
        raise ValueError(f"triangles must have 3 corners each, got shape {tri.shape}")
    v = _grid_samples(values)
    if v.ndim not in (1, 2) or len(v) != len(nd):
        raise ValueError(f"values must have one entry (or row) per node ({len(nd)}), got "
                         f"shape {v.shape}")
    p = as_points(points, "points", dims=2)
    flat = p.reshape(-1, 2)
    corners = nd[tri]
    lo, hi = corners.min(axis=1), corners.max(axis=1)

    def inside(cells, idx):
        c = corners[cells]
        lam = barycentric(flat[idx], c[:, 0], c[:, 1], c[:, 2])
        return np.all(lam >= -1e-10, axis=1), lam

    cell, lam = _locate_cells(lo, hi, flat, inside)
    found = cell >= 0
    vals = v[tri[np.maximum(cell, 0)]]                     # (m, 3) or (m, 3, k)
    lam = np.clip(lam, 0.0, 1.0)
    lam /= np.where(found, lam.sum(axis=1), 1.0)[:, None]
    out = np.einsum("mi,mi...->m...", lam, vals)
    out = _fill_outside(out, found, policy, "triangle")
    return out.reshape(p.shape[:-1] + out.shape[1:])


def curvilinear_interpolate(coordinates, values, points, method="bilinear", outside="raise"):
    r"""Interpolation on a 2D curvilinear grid: find the cell, then interpolate inside it.

    ``"bilinear"``: the cell's local coordinates :math:`(u, v)` by :func:`inverse_bilinear`,
    then the bilinear blend of its corner values with the same weights,
    :math:`f = (1-u)(1-v) f_{00} + u(1-v) f_{10} + uv f_{11} + (1-u)v f_{01}`. This
    reproduces any function linear in x and y exactly (it is bilinear in (u, v) and right at
    the corners). ``"triangles"``: each cell split along its diagonal
    :math:`p_{00} p_{11}` into two triangles, linear in each (:func:`triangle_interpolate`):
    no inverse map needed, but a crease along the diagonal.

    Parameters
    ----------
    coordinates : array_like, shape (ny, nx, 2)
        The position of each sample.
    values : array_like, shape (ny, nx) or (ny, nx, k)
    points : array_like, shape (..., 2)
    method : {"bilinear", "triangles"}
    outside : "raise" or float
        Points in no cell: an error (default) or this fill value.

    Returns
    -------
    ndarray, shape points.shape[:-1] (+ (k,))

    Examples
    --------
    >>> r, t = np.meshgrid([1.0, 2.0, 3.0], np.radians([0, 30, 60, 90]))
    >>> xy = np.stack([r * np.cos(t), r * np.sin(t)], axis=-1)     # part of an annulus
    >>> f = xy[..., 0] + 2 * xy[..., 1]                           # linear: reproduced exactly
    >>> curvilinear_interpolate(xy, f, [[1.5, 1.0], [0.5, 2.0]]).round(12)
    array([3.5, 4.5])
    """
    method = as_choice(method, "method", ("bilinear", "triangles"))
    policy = _grid_outside_policy(outside, ("raise",))
    grid = curvilinear_grid(coordinates)
    if len(grid.shape) != 2:
        raise ValueError("curvilinear_interpolate handles 2D grids, shape (ny, nx, 2)")
    v = _grid_samples(values)
    if v.shape[:2] != grid.shape or v.ndim not in (2, 3):
        raise ValueError(f"values must have shape {grid.shape} (one per sample) optionally "
                         f"with an axis of components, got shape {v.shape}")
    flat_values = v.reshape((-1,) + v.shape[2:])
    if method == "triangles":
        quads = grid.cells
        tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
        order = np.argsort(np.r_[np.arange(len(quads)), np.arange(len(quads))],
                           kind="stable")                 # cell by cell: lower, then upper
        return triangle_interpolate(grid.nodes, tris[order], flat_values, points, outside)
    p = as_points(points, "points", dims=2)
    flat = p.reshape(-1, 2)
    corners = grid.nodes[grid.cells]
    lo, hi = corners.min(axis=1), corners.max(axis=1)

    def inside(cells, idx):
        u, w, ok = _bilinear_newton(corners[cells], flat[idx])
        tol = 1e-9
        ins = ok & (u >= -tol) & (u <= 1 + tol) & (w >= -tol) & (w <= 1 + tol)
        return ins, np.stack([u, w], axis=1)

    cell, uv = _locate_cells(lo, hi, flat, inside)
    found = cell >= 0
    u, w = np.clip(uv[:, 0], 0, 1), np.clip(uv[:, 1], 0, 1)
    weights = np.stack([(1 - u) * (1 - w), u * (1 - w), u * w, (1 - u) * w], axis=1)
    vals = flat_values[grid.cells[np.maximum(cell, 0)]]
    out = np.einsum("mi,mi...->m...", weights, vals)
    out = _fill_outside(out, found, policy, "cell")
    return out.reshape(p.shape[:-1] + out.shape[1:])


def grid_interpolate(grid, values, points, outside="raise"):
    """Interpolate the samples of any :class:`Grid` with cells at `points`.

    Uniform and rectilinear grids: multilinear in the cell; curvilinear (2D): bilinear through
    the inverse map; unstructured triangles: linear. Scattered data have no cells: use the
    methods of :mod:`course_lib.dataviz.scattered`.

    Parameters
    ----------
    grid : Grid
    values : array_like
        One value (or row) per sample: shaped like the grid's sample array for the structured
        kinds, ``(n,)`` or ``(n, k)`` for unstructured.
    points : array_like, shape (..., d)
    outside : "raise" or float
        Points outside the grid: an error (default) or this fill value.

    Returns
    -------
    ndarray

    Examples
    --------
    >>> g = uniform_grid((2, 3), spacing=(0.5, 1.0))
    >>> grid_interpolate(g, [[0, 1, 2], [10, 11, 12]], [[0.25, 0.5]])
    array([5.5])
    """
    if not isinstance(grid, Grid):
        raise TypeError(f"grid must be a Grid (uniform_grid(...), rectilinear_grid(...), ...), "
                        f"got {type(grid).__name__}")
    if grid.kind == "scattered":
        raise ValueError("scattered data have no cells to interpolate in: use "
                         "course_lib.dataviz.scattered (nearest, linear on a Delaunay "
                         "triangulation, Shepard, radial basis functions)")
    if grid.kind in ("uniform", "rectilinear"):
        d = len(grid.shape)
        axes = [np.unique(grid.nodes[:, c]) for c in range(d)]
        return rectilinear_interpolate(values, axes, points, outside)
    if grid.kind == "curvilinear":
        coords = grid.nodes.reshape(grid.shape + (grid.nodes.shape[1],))
        return curvilinear_interpolate(coords, values, points, outside=outside)
    if grid.cells.shape[1] != 3 or grid.nodes.shape[1] != 2:
        raise ValueError("grid_interpolate handles unstructured grids of 2D triangles only")
    return triangle_interpolate(grid.nodes, grid.cells, values, points, outside)
