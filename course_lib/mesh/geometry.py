"""Chapter 6 (lesson section 5): face normals, areas, planes and the fundamental quadrics."""

import numpy as np

from .._validate import as_array, as_points
from ._common import _face_table, _SINGULAR, _vertices

__all__ = ["collapse_cost", "face_areas", "face_cross_products", "face_normals", "face_planes",
    "optimal_position", "plane_quadric", "vertex_quadrics"]


# ---------------------------------------------------------------------------------------------
# Normals, areas, planes and quadrics
# ---------------------------------------------------------------------------------------------

def _fan_cross(v, corners, starts):
    """Sum of (p_i - p_0) x (p_(i+1) - p_0), i = 1 .. k-2, per face: (b - a) x (c - a) for a
    triangle, Newell's sum about the face's first vertex for a polygon (unvalidated)."""
    counts = np.diff(starts)
    if (counts == 3).all():
        f = corners.reshape(-1, 3)
        a = v[f[:, 0]]
        return np.cross(v[f[:, 1]] - a, v[f[:, 2]] - a)
    pos = np.arange(len(corners)) - np.repeat(starts[:-1], counts)
    fan = np.flatnonzero((pos >= 1) & (pos <= np.repeat(counts, counts) - 2))
    a = v[np.repeat(corners[starts[:-1]], counts - 2)]
    terms = np.cross(v[corners[fan]] - a, v[corners[fan + 1]] - a)
    return np.add.reduceat(terms, np.concatenate([[0], np.cumsum(counts - 2)[:-1]]), axis=0)


def face_cross_products(vertices, faces):
    r"""The cross product of each face: its normal times **twice its area** (not unit length).

    For a triangle :math:`(a, b, c)` it is :math:`(b - a) \times (c - a)`; for a polygon
    :math:`p_0 \ldots p_{k-1}` Newell's sum :math:`\sum_i p_i \times p_{i+1}`, computed about
    the first vertex, :math:`\sum_{i=1}^{k-2} (p_i - p_0) \times (p_{i+1} - p_0)` (the same
    vector, with less rounding for a face far from the origin). It points by the right-hand
    rule, outwards for faces listed counter-clockwise seen from outside, and needs no convex
    face. Back-face culling needs only its direction
    (:func:`course_lib.clipping.back_faces`); summed over the faces around a vertex it weights
    each face by its area (:func:`course_lib.shading.vertex_normals`). :func:`face_normals` is
    this vector normalized, :func:`face_areas` half its length.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : (m, k) int array or list of int lists

    Returns
    -------
    ndarray, shape (m, 3)

    Raises
    ------
    ValueError
        For a face of fewer than 3 vertices or an index out of range.

    Examples
    --------
    >>> face_cross_products([[0, 0, 0], [2, 0, 0], [0, 3, 0]], [[0, 1, 2]])   # area 3
    array([[0., 0., 6.]])
    >>> face_cross_products([[0, 0, 0], [2, 0, 0], [2, 3, 0], [0, 3, 0]], [[0, 1, 2, 3]])
    array([[ 0.,  0., 12.]])
    """
    v = _vertices(vertices)
    corners, starts = _face_table(faces)
    if corners.min() < 0 or corners.max() >= len(v):
        bad = int(corners.max() if corners.max() >= len(v) else corners.min())
        raise ValueError(f"faces refers to vertex {bad}, but there are only {len(v)} vertices")
    if (np.diff(starts) < 3).any():
        f = int(np.flatnonzero(np.diff(starts) < 3)[0])
        raise ValueError(f"face {f} has fewer than 3 vertices")
    return _fan_cross(v, corners, starts)


def face_normals(vertices, faces):
    r"""Unit normals of the faces, by the right-hand rule (outwards for counter-clockwise faces).

    :func:`face_cross_products` normalized: for a triangle :math:`n = (p_1 - p_0) \times (p_2 -
    p_0) / \lVert \cdot \rVert`, for a polygon Newell's sum. A face of zero area gets the zero
    vector. The one face normal of the library: :func:`course_lib.shading.face_normals` and
    :func:`course_lib.draw.face_normals` are this function.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : (m, k) int array or list of int lists

    Returns
    -------
    ndarray, shape (m, 3)

    Examples
    --------
    >>> from course_lib.mesh import cube
    >>> face_normals(*cube())[:2]
    array([[ 0.,  0., -1.],
           [ 0.,  0.,  1.]])
    >>> face_normals([[0, 0, 0], [2, 0, 0], [0, 3, 0]], [[0, 1, 2], [0, 2, 1]])
    array([[ 0.,  0.,  1.],
           [ 0.,  0., -1.]])
    """
    c = face_cross_products(vertices, faces)
    length = np.linalg.norm(c, axis=1, keepdims=True)
    return np.divide(c, length, out=np.zeros_like(c), where=length > 0)


def face_areas(vertices, faces):
    r"""Areas of the faces: half the length of :func:`face_cross_products` (planar faces).

    Examples
    --------
    >>> from course_lib.mesh import cube
    >>> face_areas(*cube())
    array([4., 4., 4., 4., 4., 4.])
    >>> face_areas([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1, 2]])   # collinear: zero area
    array([0.])
    """
    return 0.5 * np.linalg.norm(face_cross_products(vertices, faces), axis=1)


def face_planes(vertices, faces):
    r"""The plane :math:`(a, b, c, d)` of each face, :math:`ax + by + cz + d = 0`, unit normal.

    :math:`(a, b, c)` is the unit normal :math:`n` and :math:`d = -n \cdot \bar p` with
    :math:`\bar p` the mean of the face's vertices. Zero-area faces get the zero row.

    Returns
    -------
    ndarray, shape (m, 4)

    Examples
    --------
    >>> face_planes([[0, 0, 2], [1, 0, 2], [0, 1, 2]], [[0, 1, 2]])
    array([[ 0.,  0.,  1., -2.]])
    """
    v = _vertices(vertices)
    n = face_normals(v, faces)
    corners, starts = _face_table(faces)
    centre = np.add.reduceat(v[corners], starts[:-1], axis=0) / np.diff(starts)[:, None]
    return np.column_stack([n, -(n * centre).sum(axis=1)])


def plane_quadric(plane):
    r"""The fundamental error quadric :math:`K_p = p p^T` of a plane :math:`p = (a, b, c, d)`.

    For :math:`v = (x, y, z, 1)`, :math:`v^T K_p v = (p \cdot v)^2`, the squared distance of the
    point from the plane when :math:`(a, b, c)` is a unit vector. Vectorized over leading axes.

    Examples
    --------
    >>> plane_quadric([0, 0, 1, -2])
    array([[ 0.,  0.,  0.,  0.],
           [ 0.,  0.,  0.,  0.],
           [ 0.,  0.,  1., -2.],
           [ 0.,  0., -2.,  4.]])
    """
    p = as_points(plane, "plane", dims=4)
    return p[..., :, None] * p[..., None, :] + 0.0          # + 0.0: no negative zeros


def vertex_quadrics(vertices, faces):
    r"""The quadric :math:`Q_i = \sum_{p \ni v_i} K_p` of every vertex (Garland-Heckbert).

    The sum over the planes of the faces around vertex :math:`i` (unweighted, as in the
    original paper); :math:`v^T Q_i v` is the sum of squared distances of :math:`v` from those
    planes, zero at the vertex itself.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : (m, k) int array or list of int lists

    Returns
    -------
    ndarray, shape (n, 4, 4)
        Symmetric; zero for a vertex no face uses.

    Examples
    --------
    A corner of the cube has three faces: the planes x = -1, y = -1, z = -1.

    >>> from course_lib.mesh import cube
    >>> Q = vertex_quadrics(*cube())
    >>> Q[0]
    array([[1., 0., 0., 1.],
           [0., 1., 0., 1.],
           [0., 0., 1., 1.],
           [1., 1., 1., 3.]])
    >>> float(collapse_cost(Q[0], [-1, -1, -1])), float(collapse_cost(Q[0], [1, -1, -1]))
    (0.0, 4.0)
    """
    v = _vertices(vertices)
    k = plane_quadric(face_planes(v, faces))
    corners, starts = _face_table(faces)
    face_of = np.repeat(np.arange(len(starts) - 1), np.diff(starts))
    q = np.zeros((len(v), 16))
    np.add.at(q, corners, k.reshape(-1, 16)[face_of])
    return q.reshape(-1, 4, 4)


def collapse_cost(Q, v):
    r"""The quadric error :math:`\bar v^T Q \bar v` of position `v`, :math:`\bar v = (v, 1)`.

    Vectorized: `Q` of shape (..., 4, 4) and `v` of shape (..., 3) broadcast.

    Examples
    --------
    The quadric of the plane z = 2 at the point (5, 5, 5): distance 3, cost 9.

    >>> float(collapse_cost(plane_quadric([0, 0, 1, -2]), [5, 5, 5]))
    9.0
    """
    q = as_array(Q, "Q")
    if q.ndim < 2 or q.shape[-2:] != (4, 4):
        raise ValueError(f"Q must be a 4x4 quadric (shape (..., 4, 4)), got shape {q.shape}")
    p = as_points(v, "v", dims=3)
    h = np.concatenate([p, np.ones(p.shape[:-1] + (1,))], axis=-1)
    return np.einsum("...i,...ij,...j->...", h, q, h)


def _solvable(a):
    """Which symmetric 3x3 quadric blocks (..., 3, 3) are safely invertible (see _SINGULAR).

    The determinant by cofactors, in the arithmetic of _target10 rather than LAPACK's (whose
    last bit depends on the CPU's kernel), so that a block near the threshold is judged alike
    on every machine and alike in the batch and in the loop of simplify_qem.
    """
    q0, q1, q2, q4, q5, q7 = (a[..., i, j] for i, j in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2),
                                                        (2, 2)))
    det = q0 * (q4 * q7 - q5 * q5) + q1 * (q2 * q5 - q1 * q7) + q2 * (q1 * q5 - q2 * q4)
    trace = q0 + q4 + q7
    return (trace > 0) & (det > _SINGULAR * trace * trace * trace)


def _optimal(Qe, p1, p2):
    """Batched best positions and costs: solve A v = -b, or the best of p1, p2, midpoint.

    _target10 for many edges, operation for operation (cofactors, no LAPACK or BLAS): the
    results are the same bits on every machine, and the same as the loop's. That matters:
    simplify_qem's heap orders the edges by these costs, and on a symmetric mesh many are
    equal up to the last bit, which LAPACK's and BLAS's CPU-specific kernels round differently.
    """
    q = Qe[:, _UPPER[0], _UPPER[1]]                     # the 10 distinct entries, as Q10
    ok = _solvable(Qe[:, :3, :3])
    x = np.empty_like(p1)
    if ok.any():
        q0, q1, q2, q3, q4, q5, q6, q7, q8, _ = q[ok].T
        c00, c01, c02 = q4 * q7 - q5 * q5, q2 * q5 - q1 * q7, q1 * q5 - q2 * q4
        c11, c12, c22 = q0 * q7 - q2 * q2, q1 * q2 - q0 * q5, q0 * q4 - q1 * q1
        det = q0 * c00 + q1 * c01 + q2 * c02
        r0, r1, r2 = -q3 / det, -q6 / det, -q8 / det
        x[ok] = np.stack([c00 * r0 + c01 * r1 + c02 * r2, c01 * r0 + c11 * r1 + c12 * r2,
                          c02 * r0 + c12 * r1 + c22 * r2], axis=1)
    bad = ~ok
    if bad.any():
        cand = np.stack([p1[bad], p2[bad], (p1[bad] + p2[bad]) / 2], axis=1)      # (k, 3, 3)
        c = _cost10(q[bad].T[:, :, None], cand[..., 0], cand[..., 1], cand[..., 2])
        x[bad] = cand[np.arange(len(cand)), np.argmin(c, axis=1)]   # ties: the first, as min
    cost = _cost10(q.T, x[:, 0], x[:, 1], x[:, 2])
    return x, np.where(cost > 0, cost, 0.0)


def optimal_position(Q, p1=None, p2=None):
    r"""The position minimizing :math:`\bar v^T Q \bar v`, and its cost.

    With :math:`Q = \begin{pmatrix} A & b \\ b^T & c \end{pmatrix}` the minimum is where
    :math:`A v = -b`. When :math:`A` is singular or badly conditioned (the planes do not pin
    down a point: :math:`\det A \le 10^{-10} (\operatorname{tr} A)^3`, which for the positive
    semi-definite :math:`A` means :math:`\lambda_1 \lambda_2 \lambda_3 \le 10^{-10}
    (\lambda_1 + \lambda_2 + \lambda_3)^3`) the best of `p1`, `p2` and their midpoint is
    returned, as Garland and Heckbert do.

    Parameters
    ----------
    Q : array_like, shape (4, 4)
    p1, p2 : array_like, shape (3,), optional
        The end points of the edge, needed only for a singular `Q`.

    Returns
    -------
    position : ndarray, shape (3,)
    cost : float

    Raises
    ------
    ValueError
        When `Q` is singular and no end points are given.

    Examples
    --------
    Three planes meeting at a cube corner pin down the corner itself, at cost 0:

    >>> from course_lib.mesh import cube
    >>> Q = vertex_quadrics(*cube())[7]
    >>> x, cost = optimal_position(Q)
    >>> x.tolist(), cost
    ([1.0, 1.0, 1.0], 0.0)
    >>> optimal_position(plane_quadric([0, 0, 1, 0]), [0, 0, 1], [2, 0, 3])
    (array([0., 0., 1.]), 1.0)
    """
    q = as_array(Q, "Q")
    if q.shape != (4, 4):
        raise ValueError(f"Q must be a 4x4 quadric, got shape {q.shape}")
    q = (q + q.T) / 2           # the form v^T Q v only sees the symmetric part (a quadric is)
    if p1 is None or p2 is None:
        if not _solvable(q[:3, :3]):
            raise ValueError("Q is singular (its planes meet in a line or a plane, not a point): "
                             "give the edge's end points p1 and p2 to choose among")
        p1 = p2 = np.zeros(3)
    p1 = as_points(p1, "p1", dims=3).reshape(1, 3)
    p2 = as_points(p2, "p2", dims=3).reshape(1, 3)
    x, cost = _optimal(q[None], p1, p2)
    return x[0], float(cost[0])


# The loop of simplify_qem works on a handful of numbers per step, where plain Python floats are
# faster than numpy calls. A symmetric quadric is kept as its 10 distinct entries
# (q00, q01, q02, q03, q11, q12, q13, q22, q23, q33).
_UPPER = (np.array([0, 0, 0, 0, 1, 1, 1, 2, 2, 3]), np.array([0, 1, 2, 3, 1, 2, 3, 2, 3, 3]))


def _cost10(q, x, y, z):
    """v^T Q v for v = (x, y, z, 1), Q given by its 10 distinct entries."""
    q0, q1, q2, q3, q4, q5, q6, q7, q8, q9 = q
    return (x * (q0 * x + 2 * (q1 * y + q2 * z + q3)) + y * (q4 * y + 2 * (q5 * z + q6)) +
            z * (q7 * z + 2 * q8) + q9)
