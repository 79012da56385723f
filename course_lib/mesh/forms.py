r"""The forms a 3D model can take, one small example of each, and the conversions between them.

The same solid (a torus, say) can be stored in very different ways:

* **polygon mesh**: vertices and faces (:mod:`course_lib.mesh.procedural`); what GPUs draw;
  an approximation of a curved surface.
* **implicit surface**: a signed function :math:`f(p)`, negative inside, zero on the surface,
  positive outside (:func:`implicit_sphere`, :func:`implicit_torus`, :func:`implicit_box`).
  The inside test is one evaluation; the outward normal is :math:`\nabla f / |\nabla f|`
  (:func:`implicit_normals`); drawing needs a search (ray marching) or a conversion.
* **parametric patch**: :math:`p(u, v)` over a rectangle (:func:`torus_patch`, or the Bézier,
  B-spline and NURBS patches of :mod:`course_lib.surfaces`); easy to walk over and to draw
  (:func:`tessellate`), hard to ask "is this point inside?".
* **CSG** (constructive solid geometry): a tree whose leaves are primitive solids and whose
  nodes are Boolean operations. With signed functions union is ``min``, intersection ``max``,
  difference ``max(a, -b)`` (:func:`csg_union`, :func:`csg_intersection`,
  :func:`csg_difference`, :func:`csg_evaluate` for a tree); point membership classification
  (:func:`classify_points`) is exact and cheap.
* **voxels**: the solid sampled on a regular grid (:func:`voxelize`), one bit or value per cell;
  memory grows with the cube of the resolution (:func:`voxel_memory`).
* **point cloud**: samples on the surface, often with normals (:func:`sample_point_cloud`), what a
  3D scanner delivers; no connectivity at all.
* **boundary representation** (B-rep): faces bounded by loops of edges, with inner loops
  (rings) for holes in a face: :mod:`course_lib.mesh.brep`.

A pipeline converts: implicit to voxels by sampling (:func:`voxelize`), voxels to a mesh by
marching cubes (:func:`voxels_to_mesh`, which calls :func:`course_lib.scivis.marching_cubes`),
a mesh to a point cloud by area-weighted sampling (:func:`sample_point_cloud`), a parametric patch to
a mesh by tessellation (:func:`tessellate`). Each conversion loses something (exactness,
connectivity, sharp edges) and is chosen for what the next stage needs. :data:`MODEL_FORMS`
sums up the properties.
"""

import numpy as np

from .._validate import as_array, as_choice, as_points, as_positive, as_scalar, as_whole
from ._common import _vertices, _face_table

__all__ = ["FORM_PROPERTIES", "MODEL_FORMS", "classify_points", "csg_difference",
           "csg_evaluate", "csg_intersection", "csg_union", "implicit_box", "implicit_normals",
           "implicit_sphere", "implicit_torus", "sample_point_cloud", "tessellate", "torus_patch",
           "voxel_memory", "voxelize", "voxels_to_mesh"]


#: The properties compared in :data:`MODEL_FORMS`, with what each one asks.
FORM_PROPERTIES = {
    "exact": "represents a curved solid exactly (no approximation by flat pieces or cells)",
    "inside test": "is 'is this point inside the solid?' cheap and reliable?",
    "render": "can a rasterizing GPU draw it directly (without a conversion)?",
    "memory": "how the storage grows with the detail",
    "editing": "what kind of editing it makes easy",
}

#: Each model form: its properties (keys of :data:`FORM_PROPERTIES`) and what it is good for.
MODEL_FORMS = {
    "mesh": {"exact": False, "inside test": False, "render": True,
             "memory": "grows with the number of faces (detail where needed)",
             "editing": "moving vertices; topology edits need care (half-edge structures)",
             "good for": "real-time rendering, games, simplification and LOD"},
    "implicit": {"exact": True, "inside test": True, "render": False,
                 "memory": "a formula: a few numbers",
                 "editing": "smooth blends and offsets by changing the function",
                 "good for": "collision and inside tests, blobs, distance fields"},
    "parametric": {"exact": True, "inside test": False, "render": False,
                   "memory": "control points: small",
                   "editing": "dragging control points, smooth free-form shapes",
                   "good for": "CAD, car bodies, fonts, textures mapped by (u, v)"},
    "csg": {"exact": True, "inside test": True, "render": False,
            "memory": "a small tree of primitives",
            "editing": "changing a primitive or an operation; the history is kept",
            "good for": "mechanical parts (drilled holes, pockets), solid modelling"},
    "voxels": {"exact": False, "inside test": True, "render": False,
               "memory": "cubic in the resolution (n^3 cells)",
               "editing": "carving and painting cells (sculpting, Booleans are per cell)",
               "good for": "medical and scientific volumes, simulation, 3D printing slices"},
    "point cloud": {"exact": False, "inside test": False, "render": False,
                    "memory": "grows with the number of samples",
                    "editing": "hardly: no connectivity, no faces",
                    "good for": "the raw output of 3D scanners, before reconstruction"},
    "brep": {"exact": True, "inside test": False, "render": False,
             "memory": "faces, edges, vertices plus the surface of each face",
             "editing": "local edits of faces and edges that keep the topology valid",
             "good for": "CAD kernels: exact faces, edges and topology for manufacturing"},
}


# ---------------------------------------------------------------------------------------------
# Implicit surfaces and CSG
# ---------------------------------------------------------------------------------------------

def implicit_sphere(points, center=(0.0, 0.0, 0.0), radius=1.0):
    r"""The signed distance to a sphere: :math:`f(p) = |p - c| - r`.

    Negative inside, zero on the surface, positive outside.

    Parameters
    ----------
    points : array_like, shape (..., 3)
    center : (float, float, float)
    radius : float, positive

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> implicit_sphere([[0, 0, 0], [1, 0, 0], [0, 3, 0]]).tolist()
    [-1.0, 0.0, 2.0]
    """
    p = as_points(points, "points", dims=3)
    c = as_points(center, "center", dims=3)
    r = as_positive(radius, "radius")
    return np.linalg.norm(p - c, axis=-1) - r


def implicit_torus(points, major=1.0, minor=0.4):
    r"""The signed distance to a torus around the z-axis.

    The tube's centre circle has radius :math:`R` (``major``) in the xy-plane; a point at
    distance :math:`q = \sqrt{x^2 + y^2}` from the axis is at distance
    :math:`\sqrt{(q - R)^2 + z^2}` from that circle, so :math:`f = \sqrt{(q - R)^2 + z^2} - r`.

    Parameters
    ----------
    points : array_like, shape (..., 3)
    major, minor : float, positive
        :math:`R > r`: the ring's radius and the tube's radius.

    Returns
    -------
    ndarray, shape (...)

    Raises
    ------
    ValueError
        If ``minor >= major`` (a self-intersecting spindle torus).

    Examples
    --------
    >>> implicit_torus([[1, 0, 0], [1.4, 0, 0], [0, 0, 0]]).round(6).tolist()
    [-0.4, 0.0, 0.6]
    """
    p = as_points(points, "points", dims=3)
    R, r = as_positive(major, "major"), as_positive(minor, "minor")
    if r >= R:
        raise ValueError(f"minor must be smaller than major (a ring torus), got minor={r} "
                         f"and major={R}")
    q = np.hypot(p[..., 0], p[..., 1])
    return np.hypot(q - R, p[..., 2]) - r


def implicit_box(points, center=(0.0, 0.0, 0.0), half=(1.0, 1.0, 1.0)):
    r"""The signed distance to an axis-aligned box.

    With :math:`d = |p - c| - h` per axis: :math:`f = |\max(d, 0)| + \min(\max_i d_i, 0)`
    (the distance to the box outside, minus the distance to the nearest face inside).

    Parameters
    ----------
    points : array_like, shape (..., 3)
    center : (float, float, float)
    half : (float, float, float), positive
        The half sizes along x, y, z.

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> implicit_box([[0, 0, 0], [2, 0, 0], [2, 2, 1]]).round(6).tolist()
    [-1.0, 1.0, 1.414214]
    """
    p = as_points(points, "points", dims=3)
    c = as_points(center, "center", dims=3)
    h = as_points(half, "half", dims=3)
    if h.shape != (3,) or np.any(h <= 0):
        raise ValueError(f"half must be three positive half sizes, got {h.tolist()}")
    d = np.abs(p - c) - h
    return np.linalg.norm(np.maximum(d, 0.0), axis=-1) + np.minimum(d.max(axis=-1), 0.0)


def implicit_normals(function, points, step=1e-5):
    r"""Outward unit normals of an implicit surface: the normalized gradient of :math:`f`.

    The gradient is taken by central differences,
    :math:`\partial f / \partial x \approx (f(p + h e_x) - f(p - h e_x)) / 2h`.

    Parameters
    ----------
    function : callable
        ``function(points)`` gives the signed values of points shaped (..., 3).
    points : array_like, shape (..., 3)
    step : float, positive
        The difference step :math:`h`.

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        Where the gradient vanishes (no normal: e.g. the centre of a sphere).

    Examples
    --------
    >>> implicit_normals(implicit_sphere, [[0, 0, 2], [3, 0, 0]]).round(6).tolist()
    [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]
    """
    if not callable(function):
        raise TypeError(f"function must be callable (points -> values), got "
                        f"a {type(function).__name__}")
    p = as_points(points, "points", dims=3)
    h = as_positive(step, "step")
    grad = np.empty(p.shape)
    for axis in range(3):
        e = np.zeros(3)
        e[axis] = h
        grad[..., axis] = (np.asarray(function(p + e)) - np.asarray(function(p - e))) / (2 * h)
    length = np.linalg.norm(grad, axis=-1, keepdims=True)
    if np.any(length < 1e-12):
        raise ValueError("the gradient of function vanishes at some of the points: no normal "
                         "there")
    return grad / length


def csg_union(a, b):
    """Union of two solids given by their signed values: ``min(a, b)``.

    Examples
    --------
    >>> csg_union([-1.0, 2.0], [0.5, 1.0]).tolist()
    [-1.0, 1.0]
    """
    return np.minimum(as_array(a, "a"), as_array(b, "b"))


def csg_intersection(a, b):
    """Intersection of two solids given by their signed values: ``max(a, b)``.

    Examples
    --------
    >>> csg_intersection([-1.0, 2.0], [0.5, 1.0]).tolist()
    [0.5, 2.0]
    """
    return np.maximum(as_array(a, "a"), as_array(b, "b"))


def csg_difference(a, b):
    """Difference a minus b of two solids given by their signed values: ``max(a, -b)``.

    Inside a and outside b: the complement of b has the signed values ``-b``.

    Examples
    --------
    >>> csg_difference([-1.0, -1.0], [0.5, -0.5]).tolist()
    [-0.5, 0.5]
    """
    return np.maximum(as_array(a, "a"), -as_array(b, "b"))


_CSG_OPS = {"union": csg_union, "intersection": csg_intersection, "difference": csg_difference}


def csg_evaluate(tree, points):
    """The signed values of a CSG tree at points.

    Parameters
    ----------
    tree : callable or tuple
        A leaf is a callable ``points -> signed values`` (a primitive solid); a node is a tuple
        ``(operation, left, right)`` with operation ``"union"``, ``"intersection"`` or
        ``"difference"``.
    points : array_like, shape (..., 3)

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> drilled = ("difference", implicit_box,
    ...            lambda p: implicit_box(p, half=(0.4, 0.4, 2.0)))   # a square hole along z
    >>> csg_evaluate(drilled, [[0, 0, 0], [0.7, 0, 0], [2, 0, 0]]).round(6).tolist()
    [0.4, -0.3, 1.0]
    """
    p = as_points(points, "points", dims=3)
    if callable(tree):
        return as_array(tree(p), "the values of a CSG leaf")
    if not (isinstance(tree, tuple) and len(tree) == 3):
        raise TypeError(f"tree must be a callable leaf or a tuple (operation, left, right), "
                        f"got {tree!r}")
    op = as_choice(tree[0], "the operation of a CSG node", tuple(_CSG_OPS))
    return _CSG_OPS[op](csg_evaluate(tree[1], p), csg_evaluate(tree[2], p))


def classify_points(values, tolerance=1e-9):
    """Point membership classification from signed values: -1 inside, 0 on, +1 outside.

    Parameters
    ----------
    values : array_like
        Signed values (negative inside).
    tolerance : float, >= 0
        Values within it of zero count as on the boundary.

    Returns
    -------
    ndarray of int

    Examples
    --------
    >>> classify_points(implicit_sphere([[0, 0, 0], [1, 0, 0], [2, 0, 0]])).tolist()
    [-1, 0, 1]
    """
    v = as_array(values, "values")
    tol = as_scalar(tolerance, "tolerance")
    if tol < 0:
        raise ValueError(f"tolerance must be a finite number >= 0, got {tolerance!r}")
    return np.where(np.abs(v) <= tol, 0, np.sign(v)).astype(np.int64)


# ---------------------------------------------------------------------------------------------
# Voxels
# ---------------------------------------------------------------------------------------------

def voxelize(function, lower, upper, resolution):
    r"""Sample an implicit solid on a regular grid: the values and the occupancy.

    The samples are at the cell centres of ``resolution`` cells per axis between ``lower`` and
    ``upper``; a voxel is occupied when :math:`f < 0` at its centre.

    Parameters
    ----------
    function : callable
        ``function(points)`` gives signed values (negative inside).
    lower, upper : (float, float, float)
        The corners of the box sampled, ``lower < upper``.
    resolution : int >= 2
        The number of cells along each axis.

    Returns
    -------
    values : ndarray, shape (n, n, n)
        ``values[k, j, i]`` at the centre of cell (i, j, k) (z, y, x order, as
        :func:`course_lib.scivis.marching_cubes` reads volumes).
    occupied : ndarray of bool, shape (n, n, n)
    spacing : ndarray, shape (3,)
        The cell size along x, y, z.
    origin : ndarray, shape (3,)
        The centre of cell (0, 0, 0).

    Examples
    --------
    >>> values, occ, spacing, origin = voxelize(implicit_sphere, (-1, -1, -1), (1, 1, 1), 4)
    >>> occ.shape, int(occ.sum()), spacing.tolist(), origin.tolist()
    ((4, 4, 4), 32, [0.5, 0.5, 0.5], [-0.75, -0.75, -0.75])
    """
    if not callable(function):
        raise TypeError(f"function must be callable (points -> values), got "
                        f"a {type(function).__name__}")
    lo = as_points(lower, "lower", dims=3)
    hi = as_points(upper, "upper", dims=3)
    if lo.shape != (3,) or hi.shape != (3,) or np.any(hi <= lo):
        raise ValueError(f"lower and upper must be two points with lower < upper on every "
                         f"axis, got {lo.tolist()} and {hi.tolist()}")
    n = as_whole(resolution, "resolution", minimum=2)
    spacing = (hi - lo) / n
    origin = lo + spacing / 2
    axes = [origin[a] + spacing[a] * np.arange(n) for a in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    values = np.asarray(function(np.stack([x, y, z], axis=-1)), dtype=float)
    return values, values < 0, spacing, origin


def voxel_memory(resolution, bits_per_voxel=1):
    """The memory of a voxel grid in bytes: ``resolution**3 * bits_per_voxel / 8``.

    Doubling the resolution multiplies it by 8.

    Examples
    --------
    >>> voxel_memory(256), voxel_memory(512), voxel_memory(256, bits_per_voxel=16)
    (2097152, 16777216, 33554432)
    """
    n = as_whole(resolution, "resolution", minimum=1)
    b = as_whole(bits_per_voxel, "bits_per_voxel", minimum=1)
    return n ** 3 * b // 8


def voxels_to_mesh(values, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), level=0.0):
    """A triangle mesh of the surface of sampled signed values, by marching cubes.

    A thin wrapper of :func:`course_lib.scivis.marching_cubes` that takes the output of
    :func:`voxelize`. Sampling the signed values (not only the occupancy bits) lets the
    vertices be interpolated on the surface instead of sitting on a staircase.

    Parameters
    ----------
    values : array_like, shape (nz, ny, nx)
    spacing, origin : (float, float, float)
    level : float
        The iso-value of the surface (0 for a signed function).

    Returns
    -------
    vertices : ndarray, shape (n, 3)
    triangles : ndarray of int, shape (m, 3)
        Counter-clockwise seen from outside (from where the values exceed ``level``), so the
        normals point out of the solid, as for the other meshes of :mod:`course_lib.mesh`
        (marching cubes itself winds them the other way round).

    Examples
    --------
    >>> values, _, spacing, origin = voxelize(implicit_sphere, (-1.2,) * 3, (1.2,) * 3, 12)
    >>> v, t = voxels_to_mesh(values, spacing, origin)
    >>> bool(np.allclose(np.linalg.norm(v, axis=1), 1.0, atol=0.05)), t.shape[1]
    (True, 3)
    """
    from ..scivis import marching_cubes
    out = marching_cubes(values, level, spacing=spacing, origin=origin)
    return out[0], np.ascontiguousarray(out[1][:, ::-1])


# ---------------------------------------------------------------------------------------------
# Meshes, point clouds and parametric patches
# ---------------------------------------------------------------------------------------------

def sample_point_cloud(vertices, triangles, count, seed=0):
    r"""A point cloud sampled on a triangle mesh, uniformly by area, with the faces' normals.

    The points are :func:`course_lib.mesh.sample_surface`'s (a triangle picked with
    probability proportional to its area, then a point in it with the barycentric coordinates
    :math:`(1 - \sqrt{r_1},\ \sqrt{r_1}(1 - r_2),\ \sqrt{r_1} r_2)` for uniform
    :math:`r_1, r_2`); each gets the unit normal of its triangle.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    triangles : array_like of int, shape (m, 3)
    count : int >= 1
    seed : int or numpy.random.Generator

    Returns
    -------
    points : ndarray, shape (count, 3)
    normals : ndarray, shape (count, 3)
        The unit normal of the triangle each point lies on.

    Examples
    --------
    >>> from course_lib.mesh import cube
    >>> p, n = sample_point_cloud(*cube(triangulated=True), 100, seed=1)
    >>> p.shape, bool(np.allclose(np.abs(p).max(axis=1), 1.0))
    ((100, 3), True)
    """
    from .distances import sample_surface

    v = _vertices(vertices)
    corners, starts = _face_table(triangles)
    if np.any(np.diff(starts) != 3):
        raise ValueError("triangles must all have 3 vertices (triangulate the mesh first)")
    t = corners.reshape(-1, 3)
    if t.size and (t.min() < 0 or t.max() >= len(v)):
        raise ValueError(f"triangles refer to vertex indices outside 0..{len(v) - 1}")
    n = as_whole(count, "count", minimum=1)
    points, face = sample_surface(v, t, n, seed)
    cross = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])[face]
    return points, cross / np.linalg.norm(cross, axis=1)[:, None]


def torus_patch(u, v, major=1.0, minor=0.4):
    r"""The parametric torus :math:`p(u, v)`, with :math:`u, v \in [0, 1]` once around.

    :math:`p = ((R + r\cos 2\pi v)\cos 2\pi u,\ (R + r\cos 2\pi v)\sin 2\pi u,\
    r \sin 2\pi v)`.

    Examples
    --------
    >>> torus_patch([0.0, 0.25], [0.0, 0.0]).round(6).tolist()
    [[1.4, 0.0, 0.0], [0.0, 1.4, 0.0]]
    """
    u, v = np.broadcast_arrays(as_array(u, "u"), as_array(v, "v"))
    R, r = as_positive(major, "major"), as_positive(minor, "minor")
    a, b = 2 * np.pi * u, 2 * np.pi * v
    ring = R + r * np.cos(b)
    return np.stack([ring * np.cos(a), ring * np.sin(a), r * np.sin(b)], axis=-1)


def tessellate(evaluate, nu, nv, wrap_u=False, wrap_v=False):
    """A parametric surface as a triangle mesh: a grid of (u, v) in [0, 1]^2, two triangles a cell.

    Parameters
    ----------
    evaluate : callable
        ``evaluate(u, v)`` gives points of shape (..., 3) for arrays u, v of the same shape
        (the grid, ``indexing="ij"``). A tensor-product patch of :mod:`course_lib.surfaces`
        takes the two axes: ``lambda u, v: bezier_surface(grid, u[:, 0], v[0])``.
    nu, nv : int >= 1
        The numbers of cells along u and v.
    wrap_u, wrap_v : bool
        The surface is closed in that direction (u = 1 is u = 0, as for a torus): the last
        row of vertices is the first one, so the mesh is closed there instead of having a seam
        of duplicated vertices.

    Returns
    -------
    vertices : ndarray, shape (n, 3)
    triangles : ndarray of int, shape (2 nu nv, 3)

    Examples
    --------
    >>> v, t = tessellate(torus_patch, 8, 6, wrap_u=True, wrap_v=True)
    >>> len(v), len(t), len(v) - len(t) * 3 // 2 + len(t)       # V, F and V - E + F = 0
    (48, 96, 0)
    """
    if not callable(evaluate):
        raise TypeError(f"evaluate must be callable (u, v -> points), got "
                        f"a {type(evaluate).__name__}")
    nu, nv = as_whole(nu, "nu", minimum=1), as_whole(nv, "nv", minimum=1)
    mu, mv = (nu if wrap_u else nu + 1), (nv if wrap_v else nv + 1)
    if (wrap_u and nu < 3) or (wrap_v and nv < 3):
        raise ValueError("a wrapped direction needs at least 3 cells")
    uu, vv = np.meshgrid(np.arange(mu) / nu, np.arange(mv) / nv, indexing="ij")
    points = as_points(evaluate(uu, vv), "the points of evaluate", dims=3).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    i, j = i.ravel(), j.ravel()
    i1, j1 = (i + 1) % mu, (j + 1) % mv
    a, b, c, d = i * mv + j, i1 * mv + j, i1 * mv + j1, i * mv + j1
    tris = np.concatenate([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    return points, tris.astype(np.int64)
