r"""Chapter 6: vertex decimation (Schroeder, Zarge and Lorensen), and half- vs full-edge collapse.

**Vertex decimation** removes one vertex at a time, with all its triangles, and fills the hole
with new triangles over the vertex's neighbours. No vertex moves: the survivors are a subset
of the original vertices.

1. **Classify** each vertex by its star (the triangles around it). Walking the link (the edges
   opposite the vertex) gives one closed loop (**simple** vertex), one open chain (**boundary**
   vertex), or something else (**complex**: non-manifold, never removed). A simple vertex whose
   edges include *feature edges* (dihedral angle above the feature angle) is an **interior
   edge** vertex with exactly two of them, a **corner** otherwise (one, or three and more:
   never removed).
2. **Criterion**: how much the surface changes if the vertex goes. For a simple vertex, the
   distance to the *average plane* of its triangles: normal :math:`n = \sum A_i n_i / \lVert
   \sum A_i n_i \rVert` and point :math:`\bar x = \sum A_i c_i / \sum A_i` (area-weighted unit
   normals :math:`n_i` and centroids :math:`c_i`), :math:`d = |n \cdot (v - \bar x)|`. For a
   boundary vertex, the distance to the line through its two boundary neighbours; for an
   interior edge vertex, to the line through its two feature neighbours.
3. **Remove** the vertex with the smallest :math:`d` (if below the threshold) and
   **re-triangulate** its loop: project it onto the average plane and clip ears (a corner whose
   triangle contains no other loop vertex), keeping the orientation. A loop around an interior
   edge vertex is split along the feature line first, so the feature survives. A removal is
   refused if a new triangle would flip against the average normal, or create an edge or a
   triangle that already exists (that would make the mesh non-manifold).
4. Update the neighbours' criteria and repeat until the target face count.

Removing an interior vertex of valence :math:`k` deletes :math:`k` triangles and adds
:math:`k - 2`: two fewer faces per step (one fewer for a boundary vertex), as an edge collapse.

**Half-edge vs full-edge collapse.** A *full-edge* collapse :math:`(u, w) \to \bar v` moves both
end points to a new, optimised position (QEM's :func:`course_lib.mesh.simplify_qem`). A
*half-edge* collapse :math:`u \to w` moves :math:`u` onto :math:`w`: no new position, so the
vertices stay a subset of the original ones (like decimation; progressive meshes and GPU-friendly
LOD use it, as the vertex buffer never changes). Its quadric cost :math:`\bar w^T (Q_u + Q_w)
\bar w` can only be higher than the full collapse's optimum (the optimum is taken over all
positions, :math:`w` is one of them).
"""

import heapq
from math import acos, inf, sqrt
from typing import NamedTuple

import numpy as np

from .._validate import as_mesh, as_scalar, as_whole
from .geometry import _optimal, collapse_cost, vertex_quadrics

__all__ = ["Decimated", "classify_vertices", "decimate", "decimation_criterion",
           "full_edge_collapse_cost", "half_edge_collapse_cost", "triangulate_loop"]

_KINDS = ("simple", "boundary", "interior edge", "corner", "complex")


class _Star:
    """The mesh as lists and sets for the loop of :func:`decimate`, and the per-vertex maths."""

    def __init__(self, v, f, cos_feature):
        self.v, self.F, self.P = v, f.tolist(), [tuple(p) for p in v.tolist()]
        self.alive = [True] * len(f)
        self.faces_at = [set() for _ in range(len(v))]
        for i, (a, b, c) in enumerate(self.F):
            self.faces_at[a].add(i)
            self.faces_at[b].add(i)
            self.faces_at[c].add(i)
        self.cos_feature = cos_feature

    def link(self, x):
        """The faces around x and its link: ('closed' | 'open' | 'complex', loop, faces)."""
        F = self.F
        fs = sorted(self.faces_at[x])
        if not fs:
            return "complex", [], []
        nxt, face_of = {}, {}
        for i in fs:
            a, b, c = F[i]
            s, e = (b, c) if a == x else (c, a) if b == x else (a, b)
            if s in nxt:
                return "complex", [], fs
            nxt[s], face_of[s] = e, i
        ends = set(nxt.values())
        if len(ends) != len(nxt):
            return "complex", [], fs
        starts = sorted(set(nxt) - ends)
        if len(starts) > 1:
            return "complex", [], fs
        start = starts[0] if starts else min(nxt)
        loop, order, s = [start], [], start
        while s in nxt and len(order) < len(nxt):
            order.append(face_of[s])
            s = nxt[s]
            if s == start:
                break
            loop.append(s)
        if len(order) != len(fs):
            return "complex", [], fs
        return ("open" if starts else "closed"), loop, order

    def geometry(self, fs):
        """Per face of fs: unit normal, area and centroid, in Python floats (a few faces per
        call: plain floats beat numpy's per-call overhead)."""
        P, F = self.P, self.F
        out = []
        for i in fs:
            a, b, c = F[i]
            (ax, ay, az), (bx, by, bz), (cx, cy, cz) = P[a], P[b], P[c]
            ux, uy, uz, wx, wy, wz = bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az
            nx, ny, nz = uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx
            length = sqrt(nx * nx + ny * ny + nz * nz)
            inv = 1.0 / length if length > 0 else 0.0
            out.append(((nx * inv, ny * inv, nz * inv), length / 2,
                        ((ax + bx + cx) / 3, (ay + by + cy) / 3, (az + bz + cz) / 3)))
        return out

    def average_normal(self, geo):
        """The area-weighted normal sum of faces (as :meth:`geometry` gives them)."""
        return (sum(g[0][0] * g[1] for g in geo), sum(g[0][1] * g[1] for g in geo),
                sum(g[0][2] * g[1] for g in geo))

    def analyse(self, x):
        """(kind, distance, loop, feature neighbours) of vertex x."""
        shape, loop, fs = self.link(x)
        if shape == "complex" or len(loop) < 2:
            return "complex", inf, loop, ()
        P = self.P
        p = P[x]
        if shape == "open":
            return "boundary", _line_distance(p, P[loop[0]], P[loop[-1]]), loop, ()
        geo = self.geometry(fs)
        k = len(loop)
        # face fs[i] is (x, loop[i], loop[i+1]); edge (x, loop[i]) lies between fs[i-1] and fs[i]
        feature = []
        cos_feature = self.cos_feature
        for i in range(k):
            n0, n1 = geo[i - 1][0], geo[i][0]
            if n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2] < cos_feature:
                feature.append(loop[i])
        if not feature:
            return "simple", _plane_distance(p, geo), loop, ()
        if len(feature) == 2:
            d = _line_distance(p, P[feature[0]], P[feature[1]])
            return "interior edge", d, loop, tuple(feature)
        return "corner", inf, loop, tuple(feature)

    def has_edge(self, a, b):
        return bool(self.faces_at[a] & self.faces_at[b])

    def has_face(self, tri):
        a, b, c = tri
        return bool(self.faces_at[a] & self.faces_at[b] & self.faces_at[c])


def _line_distance(p, a, b):
    """Distance from p to the line through a and b (to a if a == b), in Python floats."""
    dx, dy, dz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
    ux, uy, uz = p[0] - a[0], p[1] - a[1], p[2] - a[2]
    L = dx * dx + dy * dy + dz * dz
    if L == 0:
        return sqrt(ux * ux + uy * uy + uz * uz)
    cx, cy, cz = uy * dz - uz * dy, uz * dx - ux * dz, ux * dy - uy * dx
    return sqrt((cx * cx + cy * cy + cz * cz) / L)


def _plane_distance(p, geo):
    """Distance from p to the area-weighted average plane of triangles (:meth:`_Star.geometry`)."""
    total = sum(g[1] for g in geo)
    nx = sum(g[0][0] * g[1] for g in geo)
    ny = sum(g[0][1] * g[1] for g in geo)
    nz = sum(g[0][2] * g[1] for g in geo)
    length = sqrt(nx * nx + ny * ny + nz * nz)
    if length == 0 or total == 0:
        return inf
    xs = [sum(g[2][d] * g[1] for g in geo) / total for d in range(3)]
    return abs(nx * (p[0] - xs[0]) + ny * (p[1] - xs[1]) + nz * (p[2] - xs[2])) / length


def triangulate_loop(points, normal=None):
    r"""Triangulate a simple polygon loop by ear clipping, keeping its orientation.

    The loop is projected onto the plane of `normal` (by default Newell's normal of the loop);
    a corner is an **ear** when it turns counter-clockwise (seen from the normal) and its
    triangle holds no other loop vertex; ears are cut off one at a time (among the ears, the one
    with the largest smallest angle, ties by position in the loop) until a triangle remains.

    Parameters
    ----------
    points : array_like, shape (k, 3)
        The loop in order, counter-clockwise seen from the side `normal` points to; k >= 3.
    normal : array_like, shape (3,), optional

    Returns
    -------
    ndarray of int, shape (k - 2, 3)
        Triangles as indices into `points`, each counter-clockwise around `normal`.

    Raises
    ------
    ValueError
        For fewer than 3 points, or a loop with no ear (self-intersecting, or clockwise).

    Examples
    --------
    An L-shaped hexagon: the reflex corner 3 is never an ear.

    >>> L = [[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]]
    >>> t = triangulate_loop(L)
    >>> t.tolist()
    [[1, 2, 3], [0, 1, 3], [5, 0, 3], [3, 4, 5]]
    >>> 3 in t[:, 1]                    # never the tip of an ear (the middle corner)
    False
    """
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or P.shape[1] != 3 or len(P) < 3 or not np.isfinite(P).all():
        raise ValueError(f"points must be a finite (k, 3) loop with k >= 3, got shape {P.shape}")
    if normal is None:
        normal = np.cross(P, np.roll(P, -1, axis=0)).sum(axis=0)
    n = np.asarray(normal, dtype=float).reshape(3)
    n = n / max(np.linalg.norm(n), 1e-300)
    e1 = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    q = np.column_stack([P @ e1, P @ e2])
    tris = _ear_clip([tuple(r) for r in q.tolist()])
    if tris is None:
        raise ValueError("the loop has no ear: it is not a simple counter-clockwise polygon "
                         "in the plane of the normal")
    return np.array(tris, dtype=np.int64)


def _ear_clip(q):
    """Ear clipping of a 2D loop (list of (x, y)), Python floats: triangles or None."""
    xs = [r[0] for r in q]
    ys = [r[1] for r in q]
    scale = max(max(xs) - min(xs), max(ys) - min(ys), 1e-300)
    eps = 1e-12 * scale * scale
    idx = list(range(len(q)))
    out = []
    while len(idx) > 3:
        best, best_q = None, -1.0
        m = len(idx)
        for j in range(m):
            a, b, c = idx[j - 1], idx[j], idx[(j + 1) % m]
            (ax, ay), (bx, by), (cx, cy) = q[a], q[b], q[c]
            if (bx - ax) * (cy - by) - (by - ay) * (cx - bx) <= eps:
                continue                                                  # reflex or flat
            blocked = False
            for i in idx:
                if i == a or i == b or i == c:
                    continue
                px, py = q[i]
                if ((bx - ax) * (py - ay) - (by - ay) * (px - ax) >= 0 and
                        (cx - bx) * (py - by) - (cy - by) * (px - bx) >= 0 and
                        (ax - cx) * (py - cy) - (ay - cy) * (px - cx) >= 0):
                    blocked = True
                    break
            if blocked:
                continue
            quality = _min_angle(q[a], q[b], q[c])
            if quality > best_q:
                best, best_q = j, quality
        if best is None:
            return None
        out.append([idx[best - 1], idx[best], idx[(best + 1) % m]])
        del idx[best]
    a, b, c = idx
    (ax, ay), (bx, by), (cx, cy) = q[a], q[b], q[c]
    if (bx - ax) * (cy - by) - (by - ay) * (cx - bx) <= eps:
        return None
    out.append([a, b, c])
    return out


def _min_angle(a, b, c):
    """The smallest angle of a 2D triangle (radians): the ear's quality, larger is better."""
    best = np.pi
    for p, q, r in ((a, b, c), (b, c, a), (c, a, b)):
        ux, uy, wx, wy = q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1]
        norm = sqrt((ux * ux + uy * uy) * (wx * wx + wy * wy))
        cosang = (ux * wx + uy * wy) / norm if norm > 0 else 1.0
        best = min(best, acos(max(-1.0, min(1.0, cosang))))
    return best


def classify_vertices(vertices, faces, feature_angle=np.pi / 6):
    r"""The kind of every vertex for vertex decimation.

    Parameters
    ----------
    vertices, faces : array_like
        A triangle mesh.
    feature_angle : float, optional
        Radians: an edge whose two faces' normals differ by more is a feature edge.

    Returns
    -------
    ndarray of str, shape (n,)
        ``"simple"``, ``"boundary"``, ``"interior edge"``, ``"corner"`` or ``"complex"``
        (non-manifold, or used by no face).

    Examples
    --------
    >>> from course_lib.mesh import cube, disc
    >>> sorted(set(classify_vertices(*cube(triangulated=True)).tolist()))
    ['corner']
    >>> k = classify_vertices(*disc(rings=2, segments=6)).tolist()
    >>> k[0], k[-1]
    ('simple', 'boundary')
    """
    v, f = as_mesh(vertices, faces)
    star = _Star(v, f, _cos_angle(feature_angle))
    return np.array([star.analyse(x)[0] for x in range(len(v))], dtype="<U13")


def decimation_criterion(vertices, faces, feature_angle=np.pi / 6):
    r"""The decimation criterion of every vertex: how far the surface moves if it is removed.

    Distance to the area-weighted average plane of its triangles (simple vertex), to the line
    through its boundary neighbours (boundary vertex) or its two feature neighbours (interior
    edge vertex); infinite for corners and complex vertices (never removed).

    Parameters
    ----------
    vertices, faces : array_like
    feature_angle : float, optional
        Radians.

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    The apex of a square pyramid of height 1 over its four neighbours: the average plane of
    its 4 triangles is parallel to the base, at the centroids' height 1/3: distance 2/3.

    >>> v = [[0, 0, 1], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]]
    >>> f = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]
    >>> round(float(decimation_criterion(v, f, feature_angle=np.pi)[0]), 12)
    0.666666666667
    """
    v, f = as_mesh(vertices, faces)
    star = _Star(v, f, _cos_angle(feature_angle))
    return np.array([star.analyse(x)[1] for x in range(len(v))])


def _cos_angle(feature_angle):
    a = as_scalar(feature_angle, "feature_angle")
    if not 0 < a <= np.pi:
        raise ValueError(f"feature_angle must be in (0, pi] radians, got {feature_angle!r}")
    return float(np.cos(a))


class Decimated(NamedTuple):
    """What :func:`decimate` returns.

    Attributes
    ----------
    vertices, faces : ndarray
        The decimated mesh, compacted (surviving vertices in their original order).
    vertex_map : ndarray of int, shape (n,)
        For each original vertex its index in `vertices`; a removed vertex maps to the
        neighbour nearest to it at its removal (for :func:`course_lib.mesh.quadric_error`).
    removed : ndarray of int
        The original indices of the removed vertices, in removal order.
    stop_reason : str

    Examples
    --------
    >>> from course_lib.mesh import icosphere
    >>> out = decimate(*icosphere(2), target_faces=200)
    >>> len(out.faces), len(out.removed), out.vertex_map.shape
    (200, 60, (162,))
    """
    vertices: np.ndarray
    faces: np.ndarray
    vertex_map: np.ndarray
    removed: np.ndarray
    stop_reason: str


def decimate(vertices, faces, target_faces, max_error=None, feature_angle=np.pi / 6):
    r"""Simplify a triangle mesh by vertex decimation (Schroeder, Zarge and Lorensen, 1992).

    Repeatedly removes the vertex with the smallest :func:`decimation_criterion` (simple,
    boundary and interior edge vertices only) and re-triangulates its loop by ear clipping
    (:func:`triangulate_loop`), until at most `target_faces` faces remain, no vertex's criterion
    is below `max_error`, or no removal is valid (see the module notes).

    Parameters
    ----------
    vertices, faces : array_like
        A triangle mesh, consistently oriented; non-manifold vertices are kept as they are.
    target_faces : int
    max_error : float, optional
        The threshold: vertices farther than this from their average plane stay (default:
        no threshold, only the target counts).
    feature_angle : float, optional
        Radians (default 30 degrees).

    Returns
    -------
    Decimated

    Raises
    ------
    ValueError
        For a malformed mesh, a negative target or error, an angle outside (0, pi].

    Examples
    --------
    A flat 5 x 5 grid: every inner vertex lies in its average plane (criterion 0) and goes.

    >>> x, y = np.meshgrid(np.arange(5.0), np.arange(5.0))
    >>> v = np.column_stack([x.ravel(), y.ravel(), np.zeros(25)])
    >>> q = np.array([[i + 5 * j, i + 1 + 5 * j, i + 6 + 5 * j, i + 5 + 5 * j]
    ...               for j in range(4) for i in range(4)])
    >>> f = np.concatenate([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])
    >>> out = decimate(v, f, target_faces=0, max_error=1e-9)
    >>> len(out.vertices), len(out.faces)
    (4, 2)
    """
    v, f = as_mesh(vertices, faces)
    target = as_whole(target_faces, "target_faces", 0)
    limit = np.inf if max_error is None else as_scalar(max_error, "max_error")
    if not limit >= 0:
        raise ValueError(f"max_error must be >= 0, got {max_error!r}")
    star = _Star(v, f, _cos_angle(feature_angle))
    n = len(v)
    version = [0] * n
    heap = []
    for x in range(n):
        d = star.analyse(x)[1]
        if d < np.inf:
            heap.append((d, x, 0))
    heapq.heapify(heap)
    n_faces = len(f)
    gone = np.zeros(n, dtype=bool)
    parent = np.arange(n)
    removed = []
    reason = None
    while n_faces > target:
        if not heap:
            reason = "no removable vertex left (corners, complex vertices or refused removals)"
            break
        d, x, ver = heapq.heappop(heap)
        if gone[x] or ver != version[x]:
            continue
        if d > limit:
            reason = f"every remaining vertex is farther than max_error = {limit:g}"
            break
        new = _retriangulate(star, x)
        if new is None:
            continue                        # refused; retried when a neighbour changes
        loop, old = new[1], new[2]
        for i in old:
            star.alive[i] = False
            for y in star.F[i]:
                star.faces_at[y].discard(i)
        for tri in new[3]:
            star.F.append(list(tri))
            star.alive.append(True)
            for y in tri:
                star.faces_at[y].add(len(star.F) - 1)
        n_faces += len(new[3]) - len(old)
        gone[x] = True
        removed.append(x)
        parent[x] = loop[int(np.argmin(np.linalg.norm(v[loop] - v[x], axis=1)))]
        for y in loop:
            version[y] += 1
            d = star.analyse(y)[1]
            if d < np.inf:
                heapq.heappush(heap, (d, y, version[y]))
    if reason is None:
        reason = f"reached the target: {n_faces} faces (target {target})"
    F = np.array([t for t, ok in zip(star.F, star.alive) if ok], dtype=np.int64).reshape(-1, 3)
    while True:
        up = parent[parent]
        if np.array_equal(up, parent):
            break
        parent = up
    used = np.zeros(n, dtype=bool)
    used[F] = True
    new_index = np.cumsum(used) - 1
    vmap = np.where(used[parent], new_index[parent], -1)
    return Decimated(v[used], new_index[F].astype(np.int64), vmap.astype(np.int64),
                     np.array(removed, dtype=np.int64), reason)


def _retriangulate(star, x):
    """The new triangles filling the hole of vertex x, or None if the removal is invalid.

    Returns (kind, loop, old faces, new triangles as vertex triples)."""
    kind, d, loop, feature = star.analyse(x)
    if d == inf:
        return None
    _, _, fs = star.link(x)
    geo = star.geometry(fs)
    P = star.P
    if kind == "interior edge":
        i, j = loop.index(feature[0]), loop.index(feature[1])
        if i > j:
            i, j = j, i
        parts = [(loop[i:j + 1], fs[i:j]), (loop[j:] + loop[:i + 1], fs[j:] + fs[:i])]
    else:
        parts = [(loop, fs)]
    tris = []
    for poly, pf in parts:
        if len(poly) < 3:
            continue
        nx, ny, nz = star.average_normal([geo[fs.index(t)] for t in pf])
        # a basis (e1, e2) of the average plane: e1 = n x (the axis least aligned with n)
        axis = min(range(3), key=lambda i: abs((nx, ny, nz)[i]))
        ax = [0.0, 0.0, 0.0]
        ax[axis] = 1.0
        e1x, e1y, e1z = ny * ax[2] - nz * ax[1], nz * ax[0] - nx * ax[2], nx * ax[1] - ny * ax[0]
        e2x, e2y, e2z = ny * e1z - nz * e1y, nz * e1x - nx * e1z, nx * e1y - ny * e1x
        q = [(P[i][0] * e1x + P[i][1] * e1y + P[i][2] * e1z,
              P[i][0] * e2x + P[i][1] * e2y + P[i][2] * e2z) for i in poly]
        local = _ear_clip(q)
        if local is None:
            return None
        for a, b, c in local:
            t = (poly[a], poly[b], poly[c])
            (ax_, ay_, az_), (bx, by, bz), (cx, cy, cz) = P[t[0]], P[t[1]], P[t[2]]
            ux, uy, uz, wx, wy, wz = bx - ax_, by - ay_, bz - az_, cx - ax_, cy - ay_, cz - az_
            if ((uy * wz - uz * wy) * nx + (uz * wx - ux * wz) * ny +
                    (ux * wy - uy * wx) * nz) <= 0:
                return None
            tris.append(t)
    ring = loop + loop[:1] if kind != "boundary" else loop
    loop_edges = {frozenset(e) for e in zip(ring, ring[1:])}
    if kind == "interior edge" and frozenset(feature) not in loop_edges:
        if star.has_edge(*feature):
            return None
        loop_edges.add(frozenset(feature))
    for t in tris:
        if star.has_face(t):
            return None
        for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            if frozenset(e) not in loop_edges and star.has_edge(*e):
                return None
    if not tris:
        return None
    return kind, loop, fs, tris


def _edges(edges, n):
    e = np.asarray(edges)
    if e.ndim == 1 and e.shape == (2,):
        e = e[None]
    if e.ndim != 2 or e.shape[1] != 2 or not np.issubdtype(e.dtype, np.integer):
        raise ValueError(f"edges must be an (k, 2) integer array of vertex pairs, got shape "
                         f"{e.shape}")
    if e.size and (e.min() < 0 or e.max() >= n):
        raise ValueError(f"edges must hold vertex indices from 0 to {n - 1}")
    return e


def half_edge_collapse_cost(vertices, faces, edges):
    r"""The quadric cost of the half-edge collapses :math:`u \to w` (u moves onto w).

    :math:`\bar w^T (Q_u + Q_w) \bar w`, with :math:`Q` the vertex quadrics
    (:func:`course_lib.mesh.vertex_quadrics`); since :math:`\bar w^T Q_w \bar w = 0` this is
    :math:`\bar w^T Q_u \bar w`: the squared distances of :math:`w` from the planes around
    :math:`u`. Not symmetric: collapsing :math:`u \to w` and :math:`w \to u` differ.

    Parameters
    ----------
    vertices, faces : array_like
    edges : array_like of int, shape (k, 2)
        Rows ``(u, w)``.

    Returns
    -------
    ndarray, shape (k,)

    Examples
    --------
    On the cube, moving a corner along an edge to the next corner: two of its three planes
    are 2 away (one per triangle at that corner in each plane, so 2 + 2 triangles x 4).

    >>> from course_lib.mesh import cube
    >>> v, f = cube(triangulated=True)
    >>> half_edge_collapse_cost(v, f, [[7, 3], [3, 7]]).tolist()
    [8.0, 8.0]
    """
    v, f = as_mesh(vertices, faces)
    e = _edges(edges, len(v))
    Q = vertex_quadrics(v, f)
    return np.maximum(collapse_cost(Q[e[:, 0]] + Q[e[:, 1]], v[e[:, 1]]), 0.0)


def full_edge_collapse_cost(vertices, faces, edges):
    r"""The optimal position and quadric cost of full-edge collapses :math:`(u, w) \to \bar v`.

    :math:`\bar v` minimises :math:`\bar v^T (Q_u + Q_w) \bar v` (the best of u, w and the
    midpoint when the quadric is singular), as :func:`course_lib.mesh.simplify_qem` does; its
    cost is never above :func:`half_edge_collapse_cost` in either direction.

    Parameters
    ----------
    vertices, faces : array_like
    edges : array_like of int, shape (k, 2)

    Returns
    -------
    positions : ndarray, shape (k, 3)
    costs : ndarray, shape (k,)

    Examples
    --------
    >>> from course_lib.mesh import cube
    >>> x, c = full_edge_collapse_cost(*cube(triangulated=True), [[7, 3]])
    >>> bool(c[0] <= 8.0)
    True
    """
    v, f = as_mesh(vertices, faces)
    e = _edges(edges, len(v))
    Q = vertex_quadrics(v, f)
    return _optimal(Q[e[:, 0]] + Q[e[:, 1]], v[e[:, 0]], v[e[:, 1]])
