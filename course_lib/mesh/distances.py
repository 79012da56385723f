r"""Chapter 6: how far is a simplified mesh from the original? Hausdorff, RMS and quadric error.

A simplification is judged by the distance between two *surfaces*, not between vertex lists
(the simplified vertices are not a subset of the original ones in general).

* The **one-sided** distance from surface :math:`A` to surface :math:`B` is
  :math:`d(A \to B) = \max_{a \in A} \min_{b \in B} \lVert a - b \rVert`: the worst of the
  distances from a point of :math:`A` to its closest point on :math:`B`. It is not symmetric: a
  small patch :math:`A` lying on a large :math:`B` has :math:`d(A \to B) = 0` while
  :math:`d(B \to A)` is large.
* The (symmetric) **Hausdorff distance** :math:`d_H = \max(d(A \to B), d(B \to A))`: the worst
  case, sensitive to a single spike.
* The **RMS** (root mean square) surface distance: the square root of the mean squared
  point-to-surface distance over both surfaces, an average error that forgives a few bad spots.

Both are estimated by sampling points on each surface, uniformly by area (a face is chosen with
probability proportional to its area, then a uniform point in it), and measuring each sample's
exact distance to the other mesh (closest point on a triangle, Ericson's region test). The
maximum over samples underestimates the true one-sided distance a little (a sample rarely
lands exactly on the worst point); the vertices of the meshes are added to the samples, where
the worst point of a simplification usually is.

The **quadric error** uses no sampling: each simplified vertex carries the quadrics of the
original vertices merged into it, and :math:`\bar v^T Q \bar v` is the sum of squared distances
from the vertex to the planes of the original faces around them (Garland and Heckbert).
"""

from typing import NamedTuple

import numpy as np

from .._validate import as_mesh, as_points, as_rng, as_whole
from .geometry import collapse_cost, face_areas, vertex_quadrics

__all__ = ["SurfaceDistance", "closest_point_on_triangle", "point_mesh_distance",
           "quadric_error", "sample_surface", "surface_distance"]


def closest_point_on_triangle(points, a, b, c):
    r"""The closest point of triangle :math:`abc` to each point (vectorised, broadcasting).

    The point is projected onto the triangle's plane; by its barycentric position it lies in
    one of seven regions (the inside, three edge strips, three corner wedges), and the answer is
    the projection, the projection onto that edge, or that corner (Ericson, *Real-Time Collision
    Detection*, 5.1.5).

    Parameters
    ----------
    points, a, b, c : array_like, shape (..., 3)
        Broadcast against each other.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> tri = [0, 0, 0], [2, 0, 0], [0, 2, 0]
    >>> closest_point_on_triangle([[0.5, 0.5, 3], [3, 3, 0], [-1, -1, 1]], *tri)
    array([[0.5, 0.5, 0. ],
           [1. , 1. , 0. ],
           [0. , 0. , 0. ]])
    """
    p = as_points(points, "points", dims=3)
    a, b, c = (as_points(x, n, dims=3) for x, n in ((a, "a"), (b, "b"), (c, "c")))
    p, a, b, c = np.broadcast_arrays(p, a, b, c)
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = (ab * ap).sum(-1), (ac * ap).sum(-1)
    bp = p - b
    d3, d4 = (ab * bp).sum(-1), (ac * bp).sum(-1)
    cp = p - c
    d5, d6 = (ab * cp).sum(-1), (ac * cp).sum(-1)
    va = d3 * d6 - d5 * d4
    vb = d5 * d2 - d1 * d6
    vc = d1 * d4 - d3 * d2
    with np.errstate(divide="ignore", invalid="ignore"):
        denom = va + vb + vc
        v = np.where(denom != 0, vb / denom, 0.0)
        w = np.where(denom != 0, vc / denom, 0.0)
        out = a + ab * v[..., None] + ac * w[..., None]                       # inside
        t_ab = np.clip(d1 / np.where(d1 - d3 != 0, d1 - d3, 1), 0, 1)
        t_ac = np.clip(d2 / np.where(d2 - d6 != 0, d2 - d6, 1), 0, 1)
        e43, e56 = d4 - d3, d5 - d6
        t_bc = np.clip(e43 / np.where(e43 + e56 != 0, e43 + e56, 1), 0, 1)
    # the regions, tested from the last to the first so that the first match wins
    regions = [
        ((va <= 0) & (e43 >= 0) & (e56 >= 0), b + (c - b) * t_bc[..., None]),    # edge bc
        ((vb <= 0) & (d2 >= 0) & (d6 <= 0), a + ac * t_ac[..., None]),           # edge ac
        ((d6 >= 0) & (d5 <= d6), c),                                              # corner c
        ((vc <= 0) & (d1 >= 0) & (d3 <= 0), a + ab * t_ab[..., None]),           # edge ab
        ((d3 >= 0) & (d4 <= d3), b),                                              # corner b
        ((d1 <= 0) & (d2 <= 0), a),                                               # corner a
    ]
    for mask, value in regions:
        out = np.where(mask[..., None], value, out)
    return out


def _cell_groups(points, size):
    """Split point indices into spatially compact groups of about `size` (a coarse grid).

    Points on a surface fill about g^2 of the g^3 cells: g ~ sqrt(n / size) cells per axis."""
    n = len(points)
    g = max(1, int(np.ceil(np.sqrt(n / size))))
    lo = points.min(axis=0)
    ext = np.maximum(np.ptp(points, axis=0), 1e-300)
    ijk = np.minimum(((points - lo) / ext * g).astype(np.int64), g - 1)
    key = (ijk[:, 0] * g + ijk[:, 1]) * g + ijk[:, 2]
    order = np.argsort(key, kind="stable")
    cuts = np.flatnonzero(np.diff(key[order])) + 1
    groups = []
    for grp in np.split(order, cuts):
        groups.extend(np.array_split(grp, max(1, int(np.ceil(len(grp) / (4 * size))))))
    return groups


def point_mesh_distance(points, vertices, faces, chunk=48):
    r"""The exact distance from each point to a triangle mesh (its closest point on any face).

    Brute force over all faces would cost points x faces. The points are processed in
    spatially compact groups (cells of a coarse grid); for a group with bounding box :math:`G`,
    each face's bounding sphere (centre :math:`c_t`, radius :math:`r_t`) gives a lower bound
    :math:`\ell_t = \operatorname{dist}(c_t, G) - r_t` of the distance of any point of the group
    to that face. The exact distances to the 8 faces with the smallest bounds give an upper
    bound :math:`U` per point; only faces with :math:`\ell_t \le \max U` can hold a closer point,
    and those are measured exactly. The result is exact (no approximation), only faster.

    Parameters
    ----------
    points : array_like, shape (k, 3)
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    chunk : int, optional
        The typical number of points per group (memory: group x candidate faces x 3 floats).

    Returns
    -------
    ndarray, shape (k,)

    Examples
    --------
    >>> from course_lib.mesh import cube
    >>> v, f = cube(triangulated=True)
    >>> point_mesh_distance([[0, 0, 3], [0, 0, 0.5], [2, 2, 2]], v, f).round(6)
    array([2.      , 0.5     , 1.732051])
    """
    p = as_points(points, "points", dims=3).reshape(-1, 3)
    v, f = as_mesh(vertices, faces)
    chunk = as_whole(chunk, "chunk", 1)
    if len(p) == 0:
        return np.zeros(0)
    tri = v[f]                                                    # (m, 3, 3)
    centre = tri.mean(axis=1)
    radius = np.linalg.norm(tri - centre[:, None], axis=2).max(axis=1)
    out = np.empty(len(p))
    for grp in _cell_groups(p, chunk):
        q = p[grp]
        lo, hi = q.min(axis=0), q.max(axis=0)
        gap = np.linalg.norm(np.maximum(0, np.maximum(lo - centre, centre - hi)), axis=1)
        lower = gap - radius
        k = min(8, len(f))
        near = np.argpartition(lower, k - 1)[:k] if k < len(f) else np.arange(len(f))
        d_near = _pairwise(q, tri[near]).min(axis=1)
        cand = np.flatnonzero(lower <= d_near.max())
        out[grp] = _pairwise(q, tri[cand]).min(axis=1)
    return out


def _pairwise(q, tri):
    """Distances (k, t) from k points to t triangles, in blocks of about 2 million pairs."""
    out = np.empty((len(q), len(tri)))
    step = max(1, 2_000_000 // max(len(q), 1))
    for s in range(0, len(tri), step):
        t = tri[s:s + step]
        cp = closest_point_on_triangle(q[:, None], t[None, :, 0], t[None, :, 1], t[None, :, 2])
        out[:, s:s + step] = np.linalg.norm(q[:, None] - cp, axis=-1)
    return out


def sample_surface(vertices, faces, count, seed=0):
    r"""Points uniformly distributed over the area of a triangle mesh.

    A face is drawn with probability proportional to its area; in it, the point
    :math:`(1 - \sqrt{r_1}) a + \sqrt{r_1}(1 - r_2) b + \sqrt{r_1} r_2 c` with :math:`r_1, r_2`
    uniform in [0, 1] is uniform over the triangle (the square root undoes the crowding
    towards the corner :math:`a`).

    Parameters
    ----------
    vertices, faces : array_like
        A triangle mesh with a positive total area.
    count : int
        Number of samples.
    seed : int or numpy.random.Generator, optional

    Returns
    -------
    points : ndarray, shape (count, 3)
    face_index : ndarray of int, shape (count,)

    Examples
    --------
    >>> from course_lib.mesh import cube
    >>> pts, fi = sample_surface(*cube(triangulated=True), 1000, seed=1)
    >>> bool(np.allclose(np.abs(pts).max(axis=1), 1)), pts.shape
    (True, (1000, 3))
    """
    v, f = as_mesh(vertices, faces)
    count = as_whole(count, "count", 0)
    rng = as_rng(seed)
    area = face_areas(v, f)
    total = area.sum()
    if not total > 0:
        raise ValueError("the mesh must have a positive area to sample its surface")
    face = np.minimum(np.searchsorted(np.cumsum(area) / total, rng.random(count), side="right"),
                      len(f) - 1)
    r1, r2 = np.sqrt(rng.random(count)), rng.random(count)
    a, b, c = (v[f[face, i]] for i in range(3))
    pts = (1 - r1)[:, None] * a + (r1 * (1 - r2))[:, None] * b + (r1 * r2)[:, None] * c
    return pts, face


class SurfaceDistance(NamedTuple):
    """What :func:`surface_distance` returns (all in the meshes' length unit).

    Attributes
    ----------
    hausdorff : float
        The symmetric Hausdorff distance, ``max(forward, backward)``.
    forward, backward : float
        The one-sided distances A -> B (worst sample of A to B) and B -> A.
    rms : float
        Root mean square of all sample distances, both directions pooled.
    mean : float
        Mean of all sample distances, both directions pooled.

    Examples
    --------
    >>> SurfaceDistance(2.0, 1.0, 2.0, 0.5, 0.4).hausdorff
    2.0
    """
    hausdorff: float
    forward: float
    backward: float
    rms: float
    mean: float


def surface_distance(vertices_a, faces_a, vertices_b, faces_b, samples=5000, seed=0):
    r"""One-sided and symmetric Hausdorff distances and the RMS distance between two meshes.

    `samples` area-uniform points on each mesh (:func:`sample_surface`, seeded) plus the
    mesh's vertices are measured against the other mesh (:func:`point_mesh_distance`, exact).

    Parameters
    ----------
    vertices_a, faces_a, vertices_b, faces_b : array_like
        Two triangle meshes (A, usually the original, and B, the simplified one).
    samples : int, optional
        Samples per surface.
    seed : int, optional

    Returns
    -------
    SurfaceDistance

    Examples
    --------
    Two parallel unit squares 0.5 apart:

    >>> sq = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.]]), [[0, 1, 2], [0, 2, 3]]
    >>> up = sq[0] + [0, 0, 0.5], sq[1]
    >>> d = surface_distance(*sq, *up, samples=200)
    >>> d.hausdorff, d.forward, d.backward, round(d.rms, 12)
    (0.5, 0.5, 0.5, 0.5)
    """
    va, fa = as_mesh(vertices_a, faces_a, "faces_a")
    vb, fb = as_mesh(vertices_b, faces_b, "faces_b")
    samples = as_whole(samples, "samples", 1)
    rng = as_rng(seed)
    pa = np.concatenate([sample_surface(va, fa, samples, rng)[0], va[np.unique(fa)]])
    pb = np.concatenate([sample_surface(vb, fb, samples, rng)[0], vb[np.unique(fb)]])
    da, db = point_mesh_distance(pa, vb, fb), point_mesh_distance(pb, va, fa)
    both = np.concatenate([da, db])
    fwd, bwd = float(da.max()), float(db.max())
    return SurfaceDistance(max(fwd, bwd), fwd, bwd, float(np.sqrt(np.mean(both ** 2))),
                           float(both.mean()))


def quadric_error(vertices, faces, simplified_vertices, vertex_map):
    r"""The quadric error of each vertex of a simplified mesh, measured against the original.

    :math:`E_j = \bar w_j^T \big(\sum_{i \to j} Q_i\big) \bar w_j`: the quadrics :math:`Q_i`
    (:func:`vertex_quadrics` of the original) of all original vertices :math:`i` that
    `vertex_map` sends to simplified vertex :math:`j`, evaluated at its position :math:`w_j`:
    the sum of squared distances to the planes of the original faces around those vertices.

    Parameters
    ----------
    vertices, faces : array_like
        The original triangle mesh.
    simplified_vertices : array_like, shape (k, 3)
    vertex_map : array_like of int, shape (n,)
        For each original vertex the simplified vertex it became (the cell map of
        :func:`course_lib.mesh.vertex_clustering`, the ``vertex_map`` of
        :func:`course_lib.mesh.decimate`), or -1 for an unused vertex.

    Returns
    -------
    ndarray, shape (k,)
        Non-negative.

    Examples
    --------
    Moving the corner (1, 1, 1) of the cube up by 0.5: the triangles of the sides stay in
    their planes, the two top triangles at this corner (plane z = 1) are 0.5 away: 2 x 0.25.

    >>> from course_lib.mesh import cube
    >>> v, f = cube(triangulated=True)
    >>> w = v.copy(); w[7] = [1, 1, 1.5]
    >>> float(quadric_error(v, f, w, np.arange(8))[7])
    0.5
    """
    v, f = as_mesh(vertices, faces)
    w = as_points(simplified_vertices, "simplified_vertices", dims=3).reshape(-1, 3)
    m = np.asarray(vertex_map)
    if m.shape != (len(v),) or not np.issubdtype(m.dtype, np.integer):
        raise ValueError(f"vertex_map must be an integer array of shape ({len(v)},), one entry "
                         f"per original vertex, got shape {m.shape} and type {m.dtype}")
    if m.size and (m.min() < -1 or m.max() >= len(w)):
        raise ValueError(f"vertex_map must hold indices from -1 to {len(w) - 1}")
    Q = vertex_quadrics(v, f).reshape(-1, 16)
    use = m >= 0
    S = np.zeros((len(w), 16))
    np.add.at(S, m[use], Q[use])
    return np.maximum(collapse_cost(S.reshape(-1, 4, 4), w), 0.0)
