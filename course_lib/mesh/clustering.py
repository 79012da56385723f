r"""Chapter 6: vertex clustering (Rossignac and Borrel), simplification on a grid.

The cheapest simplification there is: lay a grid of cubic cells over the model's bounding box,
merge all the vertices in one cell into one **representative** vertex, and rewrite every
triangle with the representatives of its corners.

1. Cell of a vertex: :math:`(i, j, k) = \lfloor (v - o) / h \rfloor` for the grid origin
   :math:`o` (the bounding box's minimum corner) and cell size :math:`h` (the top face of the box
   belongs to the last cell).
2. One representative per occupied cell: the mean of its vertices, or the **quadric-optimal**
   point: the point minimising :math:`\bar v^T (\sum Q_i) \bar v` over the quadrics of the
   cell's vertices (Lindstrom's variant, used by VTK's ``vtkQuadricClustering``), which keeps
   sharp edges and corners that the mean rounds off. When the planes do not pin down a point
   (a flat cell, or a cell on a crease) the minimiser nearest to the mean is taken (through
   the pseudo-inverse); if the point leaves the cell by more than half a cell, the mean is
   used.
3. Each triangle :math:`(a, b, c)` becomes (cell(a), cell(b), cell(c)). A triangle with two
   corners in one cell **degenerates** (into an edge or a point) and is dropped; two triangles
   that became the same triangle are kept once.

One pass over the vertices and faces, no priority queue: very fast, but blind to the shape
(the grid is not aligned with features) and it may change the topology: holes smaller than a
cell close, thin parts merge, and the result need not be manifold.
"""

from typing import NamedTuple

import numpy as np

from .._validate import as_choice, as_mesh, as_positive, as_whole
from .geometry import vertex_quadrics

__all__ = ["Clustered", "cluster_cells", "vertex_clustering"]


class Clustered(NamedTuple):
    """What :func:`vertex_clustering` returns.

    Attributes
    ----------
    vertices : ndarray, shape (k, 3)
        One representative per occupied cell, in the order of the cells' indices (i, j, k).
    faces : ndarray of int, shape (m', 3)
        The surviving triangles, in the order of their first original.
    vertex_map : ndarray of int, shape (n,)
        The cell map: for each original vertex the index of its representative.
    cells : ndarray of int, shape (k, 3)
        The (i, j, k) index of each representative's cell.
    cell_size : float

    Examples
    --------
    >>> from course_lib.mesh import icosphere
    >>> out = vertex_clustering(*icosphere(3), cells=4)
    >>> out.vertex_map.shape, out.cells.shape[1], out.cell_size
    ((642,), 3, 0.5)
    """
    vertices: np.ndarray
    faces: np.ndarray
    vertex_map: np.ndarray
    cells: np.ndarray
    cell_size: float


def cluster_cells(vertices, cell_size, origin=None):
    r"""The grid cell :math:`\lfloor (v - o) / h \rfloor` of each vertex.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    cell_size : float
        The edge :math:`h` of the cubic cells, > 0.
    origin : array_like, shape (3,), optional
        The grid's corner :math:`o`; the bounding box's minimum corner by default.

    Returns
    -------
    ndarray of int, shape (n, 3)

    Examples
    --------
    >>> cluster_cells([[0, 0, 0], [0.9, 1.2, 0], [2.5, 0.1, 0]], 1.0)
    array([[0, 0, 0],
           [0, 1, 0],
           [2, 0, 0]])
    """
    v = np.asarray(vertices, dtype=float)
    if v.ndim != 2 or v.shape[1] != 3 or not np.isfinite(v).all():
        raise ValueError(f"vertices must be a finite (n, 3) array, got shape {v.shape}")
    h = as_positive(cell_size, "cell_size", "the edge of a grid cell")
    o = v.min(axis=0) if origin is None else np.asarray(origin, dtype=float).reshape(3)
    return np.floor((v - o) / h + 1e-9).astype(np.int64)


def _least_squares_point(Q, mean):
    """The minimiser of v^T Q v nearest to `mean` (pseudo-inverse, Lindstrom's rule).

    With A the 3x3 block and b the last column, v = m + sum over the eigenvectors u_i of A
    with eigenvalue lambda_i > 1e-3 lambda_max of u_i (u_i . (-b - A m)) / lambda_i: the exact
    minimiser when the planes meet in a point (rank 3), the point of their common line
    (rank 2) or plane (rank 1) nearest to the mean otherwise.
    """
    A, b = Q[:, :3, :3], Q[:, :3, 3]
    lam, U = np.linalg.eigh(A)
    r = -b - np.einsum("kij,kj->ki", A, mean)
    coef = np.einsum("kji,kj->ki", U, r)
    keep = lam > 1e-3 * np.maximum(lam[:, -1:], 1e-300)
    step = np.where(keep, coef / np.where(keep, lam, 1.0), 0.0)
    return mean + np.einsum("kij,kj->ki", U, step)


def vertex_clustering(vertices, faces, cell_size=None, cells=None, representative="mean"):
    r"""Simplify a triangle mesh by vertex clustering on a uniform grid (Rossignac-Borrel).

    Give either `cell_size` (the cells' edge length) or `cells` (the number of cells along the
    longest side of the bounding box; the cells are cubes of edge ``longest side / cells``).

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    cell_size : float, optional
    cells : int, optional
        At least 1.
    representative : {"mean", "quadric"}
        The merged vertex: the mean of the cell's vertices, or the point minimising the sum of
        their quadrics (:func:`course_lib.mesh.vertex_quadrics`) nearest to the mean, falling
        back on the mean if it leaves the cell by more than half a cell.

    Returns
    -------
    Clustered
        ``(vertices, faces, vertex_map, cells, cell_size)``; cells and representatives are
        ordered by the cells' (i, j, k) indices, faces by their first original: deterministic.

    Raises
    ------
    ValueError
        Without exactly one of `cell_size` and `cells`, for a cell size <= 0 or fewer than one
        cell, an unknown `representative`, or a malformed mesh.

    Examples
    --------
    A 4 x 4 grid of squares (2 triangles each) in cells of size 2: 3 x 3 representatives.

    >>> x, y = np.meshgrid(np.arange(5.0), np.arange(5.0))
    >>> v = np.column_stack([x.ravel(), y.ravel(), np.zeros(25)])
    >>> q = np.array([[i + 5 * j, i + 1 + 5 * j, i + 6 + 5 * j, i + 5 + 5 * j]
    ...               for j in range(4) for i in range(4)])
    >>> f = np.concatenate([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])
    >>> out = vertex_clustering(v, f, cell_size=2.0)
    >>> len(out.vertices), len(out.faces), out.vertices[0].tolist()
    (9, 8, [0.5, 0.5, 0.0])
    """
    v, f = as_mesh(vertices, faces)
    if (cell_size is None) == (cells is None):
        raise ValueError("give exactly one of cell_size (the cells' edge) and cells (the "
                         "number of cells along the longest side)")
    mode = as_choice(representative, "representative", ("mean", "quadric"))
    extent = float(np.ptp(v, axis=0).max())
    if cells is not None:
        if isinstance(cells, (int, np.integer)) and not isinstance(cells, bool) and cells <= 0:
            raise ValueError(f"cells must be at least 1 (cells along the longest side), "
                             f"got {cells}")
        n_cells = as_whole(cells, "cells", 1)
        h = extent / n_cells if extent > 0 else 1.0
    else:
        h = as_positive(cell_size, "cell_size", "the edge of a grid cell")
    ijk = cluster_cells(v, h)
    if cells is not None:
        ijk = np.minimum(ijk, n_cells - 1)             # the top of the box: in the last cell
    cell_ids, vmap = np.unique(ijk, axis=0, return_inverse=True)      # sorted by (i, j, k)
    vmap = vmap.reshape(-1)
    k = len(cell_ids)
    count = np.bincount(vmap, minlength=k).astype(float)
    mean = np.stack([np.bincount(vmap, v[:, d], minlength=k) for d in range(3)], axis=1)
    rep = mean / count[:, None]
    if mode == "quadric":
        Q = vertex_quadrics(v, f).reshape(-1, 16)
        S = np.stack([np.bincount(vmap, Q[:, i], minlength=k) for i in range(16)], axis=1)
        x = _least_squares_point(S.reshape(-1, 4, 4), rep)
        lo = v.min(axis=0) + cell_ids * h
        inside = np.all((x >= lo - h / 2) & (x <= lo + 1.5 * h), axis=1)
        rep = np.where(inside[:, None], x, rep)
    g = vmap[f]
    ok = (g[:, 0] != g[:, 1]) & (g[:, 1] != g[:, 2]) & (g[:, 2] != g[:, 0])
    g = g[ok]
    key = np.sort(g, axis=1)
    _, first = np.unique(key, axis=0, return_index=True)
    g = g[np.sort(first)]
    return Clustered(rep, g.astype(np.int64), vmap.astype(np.int64), cell_ids, float(h))
