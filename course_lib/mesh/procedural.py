"""Chapter 6: the example meshes of the lesson and the tests.

Closed surfaces of genus 0, 1 and 2 (tetrahedron, cube, icosphere, torus, double torus), one with
a boundary (disc), and two that are not manifold (bow tie, three faces on an edge).
"""

import numpy as np

from .. import shapes
from ..shapes import torus   # one torus: the course's test shape, re-exported with the meshes
from .._validate import as_positive, as_whole
from ._common import _compact

__all__ = ["bow_tie", "cube", "disc", "double_torus", "icosphere", "tetrahedron",
    "three_faces_on_an_edge", "torus"]


# ---------------------------------------------------------------------------------------------
# Procedural meshes
# ---------------------------------------------------------------------------------------------

def tetrahedron():
    """A regular tetrahedron inscribed in the unit sphere: 4 vertices, 4 outward triangles.

    Examples
    --------
    >>> v, f = tetrahedron()
    >>> v.shape, f.tolist()
    ((4, 3), [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])
    """
    v = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float) / np.sqrt(3)
    return v, np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], dtype=np.int64)


def cube(triangulated=False):
    """The cube [-1, 1]^3: 8 vertices and 6 outward quads (or 12 triangles).

    Vertex ``i`` has coordinates ``x = +1`` if bit 0 of ``i`` is set, ``y`` from bit 1, ``z``
    from bit 2 (else -1).

    Parameters
    ----------
    triangulated : bool, optional
        Split each quad ``(a, b, c, d)`` into ``(a, b, c)`` and ``(a, c, d)``.

    Returns
    -------
    vertices : ndarray, shape (8, 3)
    faces : ndarray of int, shape (6, 4) or (12, 3)
        Counter-clockwise seen from outside.

    Examples
    --------
    >>> v, f = cube()
    >>> f.tolist()
    [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    >>> cube(triangulated=True)[1].shape
    (12, 3)
    """
    i = np.arange(8)
    v = np.column_stack([i & 1, (i >> 1) & 1, (i >> 2) & 1]).astype(float) * 2 - 1
    quads = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2],
                      [1, 3, 7, 5]], dtype=np.int64)
    return v, (_split_quads(quads) if triangulated else quads)


def _split_quads(quads):
    """Each quad (a, b, c, d) -> triangles (a, b, c), (a, c, d), kept together per quad."""
    return np.stack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]], axis=1).reshape(-1, 3)


def _midpoint_subdivide(v, f):
    """Split each triangle into four at its edge midpoints (shared midpoints made once)."""
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    keys = np.sort(e, axis=1)
    unique, inverse = np.unique(keys, axis=0, return_inverse=True)
    mid = (len(v) + inverse.ravel()).reshape(3, -1)
    ab, bc, ca = mid
    a, b, c = f.T
    faces = np.stack([np.stack([a, ab, ca], -1), np.stack([b, bc, ab], -1),
                      np.stack([c, ca, bc], -1), np.stack([ab, bc, ca], -1)], axis=1)
    return np.vstack([v, v[unique].mean(axis=1)]), faces.reshape(-1, 3)


def icosphere(subdivisions=0, radius=1.0):
    """A sphere meshed by subdividing an icosahedron: 20 * 4**subdivisions outward triangles.

    Each step splits every triangle into four at its edge midpoints and pushes the new vertices
    onto the sphere. ``subdivisions=6`` gives 81,920 faces and 40,962 vertices.

    Parameters
    ----------
    subdivisions : int, optional
        0 is the icosahedron itself.
    radius : float, optional

    Returns
    -------
    vertices : ndarray, shape (10 * 4**s + 2, 3)
    faces : ndarray of int, shape (20 * 4**s, 3)

    Examples
    --------
    >>> [icosphere(s)[1].shape[0] for s in range(3)]
    [20, 80, 320]
    """
    s = as_whole(subdivisions, "subdivisions", 0, integer_type=True, at_least=True)
    if s > 8:
        raise ValueError(f"subdivisions must be at most 8 (20 * 4**8 = 1,310,720 faces), got {s}")
    r = as_positive(radius, "radius")
    t = (1 + np.sqrt(5)) / 2
    v = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
                  [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]])
    f = np.array([[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9],
                  [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2],
                  [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
                  [8, 6, 7], [9, 8, 1]], dtype=np.int64)
    for _ in range(s):
        v, f = _midpoint_subdivide(v, f)
    return r * v / np.linalg.norm(v, axis=1, keepdims=True), f


def double_torus(major=1.0, minor=0.4, segments=24, rings=12, gap=None):
    r"""A closed double torus (genus 2, :math:`\chi = -2`): two tori joined by a short tube.

    Torus A (centre :math:`(-d, 0, 0)`) loses a rectangular patch of its grid on the outer
    equator facing +x; torus B is A turned by 180 degrees about the z axis (a rotation, so the
    orientation is kept), with its hole facing -x. A tube of triangles joins the two hole rims
    point by point (the grid point at angle :math:`u` on A to the one at :math:`-u` on B, the
    mirror image across the plane x = 0). Cutting a disc out of a surface lowers
    :math:`\chi` by 1 (the disc's :math:`\chi = 1`; its rim, a circle, has :math:`\chi = 0`),
    and gluing in a tube (an annulus, :math:`\chi = 0`) along two circles changes nothing, so
    :math:`\chi = (0 - 1) + (0 - 1) + 0 = -2`: genus 2.

    Parameters
    ----------
    major, minor : float, optional
        Radii of each torus.
    segments, rings : int, optional
        Grid of each torus (at least 6 and 4).
    gap : float, optional
        The distance between the two tori, ``minor / 2`` by default.

    Returns
    -------
    vertices : ndarray, shape (n, 3)
    faces : ndarray of int, shape (m, 3)
        Outward triangles.

    Examples
    --------
    >>> from course_lib.mesh import HalfEdgeMesh
    >>> m = HalfEdgeMesh.from_faces(*double_torus())
    >>> m.euler_characteristic(), m.genus(), m.is_closed()
    (-2, 2, True)
    """
    major, minor = as_positive(major, "major"), as_positive(minor, "minor")
    s = as_whole(segments, "segments", 6, integer_type=True, at_least=True)
    r = as_whole(rings, "rings", 4, integer_type=True, at_least=True)
    gap = minor / 2 if gap is None else as_positive(gap, "gap")
    if minor >= major:
        raise ValueError(f"minor must be smaller than major (a ring torus), got {minor} >= {major}")
    v, f = shapes.torus(major, minor, s, r)
    d = major + minor + gap / 2
    hs, hr = max(1, s // 12), max(1, r // 12)
    # the cells of the hole: grid cells (i, j) with i in [-hs, hs), j in [-hr, hr) (mod s, r)
    cell = np.arange(s * r)
    ci, cj = cell // r, cell % r
    hole = (((ci + hs) % s) < 2 * hs) & (((cj + hr) % r) < 2 * hr)
    keep = np.concatenate([~hole, ~hole])           # torus faces: [a, b, c] block, [a, c, d]
    f = f[keep]
    rim = ([(i, -hr) for i in range(-hs, hs)] + [(hs, j) for j in range(-hr, hr)] +
           [(i, hr) for i in range(hs, -hs, -1)] + [(-hs, j) for j in range(hr, -hr, -1)])
    loop_a = np.array([(i % s) * r + j % r for i, j in rim])
    loop_b = np.array([(-i % s) * r + j % r for i, j in rim]) + s * r
    va = v + [-d, 0, 0]
    vb = va * [-1, -1, 1]
    n_tube = 2
    rings_v = [va[loop_a] + (vb[loop_b - s * r] - va[loop_a]) * (k / (n_tube + 1))
               for k in range(1, n_tube + 1)]
    base = 2 * s * r
    ids = [loop_a] + [base + k * len(rim) + np.arange(len(rim)) for k in range(n_tube)] + [loop_b]
    # orient the tube against A's faces along the rim: A must not walk loop_a[0] -> loop_a[1]
    a0, a1 = loop_a[0], loop_a[1]
    walks = ((f == a0) & (np.roll(f, -1, axis=1) == a1)).any()
    quads = []
    for k in range(n_tube + 1):
        p, q = ids[k], ids[k + 1]
        quads.append(np.column_stack([p, np.roll(p, -1), np.roll(q, -1), q]))
    quads = np.vstack(quads)
    if walks:
        quads = quads[:, ::-1]
    faces = np.vstack([f, f + s * r, _split_quads(quads)])
    return _compact(np.vstack([va, vb, *rings_v]), faces)    # drop the grid points of the holes


def disc(rings=4, segments=16, radius=1.0):
    """A flat disc in the plane z = 0 (one boundary loop), triangles facing +z.

    Vertex 0 is the centre; ring ``k = 1..rings`` (radius ``k / rings * radius``) holds the
    vertices ``1 + (k - 1) * segments + i`` at angles ``2 pi i / segments``. The first
    ``segments`` faces are the fan around the centre, face ``i`` being
    ``(0, 1 + i, 1 + (i + 1) % segments)``.

    Returns
    -------
    vertices : ndarray, shape (1 + rings * segments, 3)
    faces : ndarray of int, shape ((2 * rings - 1) * segments, 3)

    Examples
    --------
    >>> from course_lib.mesh import HalfEdgeMesh
    >>> v, f = disc(rings=1, segments=4)
    >>> f.tolist()
    [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]
    >>> m = HalfEdgeMesh.from_faces(*disc())
    >>> m.euler_characteristic(), m.boundary_components()
    (1, 1)
    """
    k = as_whole(rings, "rings", 1, integer_type=True, at_least=True)
    s = as_whole(segments, "segments", 3, integer_type=True, at_least=True)
    rad = as_positive(radius, "radius")
    angle = 2 * np.pi * np.arange(s) / s
    radii = rad * np.arange(1, k + 1) / k
    ring_pts = np.stack([radii[:, None] * np.cos(angle), radii[:, None] * np.sin(angle),
                         np.zeros((k, s))], axis=-1).reshape(-1, 3)
    v = np.vstack([[0.0, 0.0, 0.0], ring_pts])
    i = np.arange(s)
    faces = [np.column_stack([np.zeros(s, dtype=np.int64), 1 + i, 1 + (i + 1) % s])]
    for ring in range(k - 1):
        a = 1 + ring * s + i
        b = 1 + ring * s + (i + 1) % s
        c, d = b + s, a + s
        faces.append(np.column_stack([a, d, c]))
        faces.append(np.column_stack([a, c, b]))
    return v, np.vstack(faces).astype(np.int64)


def three_faces_on_an_edge():
    """Three triangles sharing the edge (0, 1), like the pages of a book: a non-manifold edge.

    Examples
    --------
    >>> from course_lib.mesh import HalfEdgeMesh
    >>> HalfEdgeMesh.from_faces(*three_faces_on_an_edge())
    Traceback (most recent call last):
    ...
    ValueError: edge (0, 1) is shared by 3 faces [0, 1, 2]: a non-manifold edge (on a manifold surface an edge has one face on each side, two at most)
    """
    v = np.array([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -0.5, 0.87], [0.5, -0.5, -0.87]])
    return v, np.array([[0, 1, 2], [1, 0, 3], [1, 0, 4]], dtype=np.int64)


def bow_tie():
    """Two triangles that share only vertex 0: a bow tie, the classic non-manifold vertex.

    Examples
    --------
    >>> from course_lib.mesh import mesh_problems
    >>> [p.vertices for p in mesh_problems(*bow_tie())]
    [(0,)]
    """
    v = np.array([[0, 0, 0], [1, -0.5, 0], [1, 0.5, 0], [-1, 0.5, 0], [-1, -0.5, 0]])
    return v, np.array([[0, 1, 2], [0, 3, 4]], dtype=np.int64)
