"""Chapter 15 (lesson sections 15.2, 15.6): ray-object intersections, the slab test and the BVH."""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_positive, as_vector, as_whole
from ..visibility.ray_casting import _moller_trumbore_soa as _moller_trumbore
from ._common import _dot, _rays, _t_max, _t_min, _unit_vectors

__all__ = ["BVH", "BoxHits", "SurfaceHits", "TriangleHits", "intersect_box", "intersect_plane",
    "intersect_sphere", "intersect_triangles"]


# ---------------------------------------------------------------------------------------------
# Ray-object intersections
# ---------------------------------------------------------------------------------------------

class SurfaceHits(NamedTuple):
    """Nearest hits of rays with one surface (:func:`intersect_sphere`, :func:`intersect_plane`).

    Attributes
    ----------
    t : ndarray, shape (...)
        Ray parameter of the hit (the distance for unit directions); ``inf`` for a miss.
    normals : ndarray, shape (..., 3)
        Unit *outward* normal at the hit point ``origin + t * direction``; zero for a miss.

    Examples
    --------
    >>> hits = intersect_sphere([[0, 0, 5], [3, 0, 5]], [0, 0, -1], [0, 0, 0], 1.0)
    >>> hits.t, hits.normals[0]
    (array([ 4., inf]), array([0., 0., 1.]))
    """
    t: np.ndarray
    normals: np.ndarray


def _sphere_roots(o, d, center, radius):
    r"""Both roots (t1 <= t2) of |o + t d - c|^2 = r^2 for rays (p, 3); inf where no root.

    The numerically stable form: b = d.(o - c), a = d.d, the discriminant written as
    a (r^2 - |l|^2) with l = (o - c) - (b/a) d the vector from the centre to the line's nearest
    point (no cancellation between b^2 and a c), and the two roots as q/a and c/q with
    q = -(b + sign(b) sqrt(disc)) (no cancellation between -b and sqrt(disc)).
    """
    f = o - center
    a = _dot(d, d)
    b = _dot(f, d)
    l = f - (b / a)[:, None] * d
    disc = a * (radius * radius - _dot(l, l))
    c = _dot(f, f) - radius * radius
    hit = disc >= 0
    q = -(b + np.copysign(np.sqrt(np.where(hit, disc, 0.0)), b))
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = q / a
        t2 = np.where(q != 0, c / q, t1)
    near, far = np.minimum(t1, t2), np.maximum(t1, t2)
    return np.where(hit, near, np.inf), np.where(hit, far, np.inf)


def _first_root(near, far, t_min):
    return np.where(near >= t_min, near, np.where(far >= t_min, far, np.inf))


def _before(t, t_max):
    """Hits at `t` that lie no farther than `t_max`. A miss is encoded as ``t = inf``, and a
    shadow ray towards a directional light has ``t_max = inf``: ``inf <= inf`` is true, so a
    plain comparison would let every missed object block such a ray."""
    return np.isfinite(t) & (t <= t_max)


def intersect_sphere(origins, directions, center, radius, t_min=0.0):
    r"""Ray-sphere intersection: the nearest hit at or beyond `t_min` of each ray.

    Substituting the ray :math:`o + t\,d` into the sphere :math:`\lVert p - c \rVert^2 = r^2`
    gives the quadratic

    .. math:: (d \cdot d)\, t^2 + 2\, (d \cdot f)\, t + (f \cdot f - r^2) = 0, \qquad f = o - c

    No real root (negative discriminant): a miss. Otherwise the ray enters at the smaller root
    and leaves at the larger one; the answer is the smallest root :math:`\ge t_{min}` (the far
    root for a ray starting inside the sphere). Both roots are computed in a numerically stable
    form (no cancellation for rays far from the sphere or grazing it). The outward normal at
    the hit is :math:`(p - c) / r`.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
        The rays (directions need not be unit vectors; then :math:`t` is in units of their
        length). One origin or one direction may be shared by all rays.
    center : array_like, shape (3,)
    radius : float
        Positive.
    t_min : float, optional
        Only hits with :math:`t \ge t_{min} \ge 0` count.

    Returns
    -------
    SurfaceHits
        ``t`` (``inf`` for a miss) and the outward unit ``normals`` (zero for a miss).

    Raises
    ------
    ValueError
        For zero directions, a non-positive radius, a negative `t_min`, NaN, or malformed
        shapes.

    Examples
    --------
    From outside (enters at t = 4) and from the centre (leaves at t = 1):

    >>> intersect_sphere([[0, 0, 5], [0, 0, 0]], [0, 0, -1], [0, 0, 0], 1.0).t
    array([4., 1.])
    """
    o, d, lead = _rays(origins, directions)
    c = as_vector(center, "center", 3)
    r = as_positive(radius, "radius", "the sphere's radius")
    t_min = _t_min(t_min)
    t = _first_root(*_sphere_roots(o, d, c, r), t_min)
    hit = np.isfinite(t)
    normals = np.zeros_like(o)
    p = o[hit] + t[hit, None] * d[hit] - c
    normals[hit] = p / np.sqrt(_dot(p, p))[:, None]
    return SurfaceHits(t.reshape(lead), normals.reshape(lead + (3,)))


def _plane_t(o, d, point, normal, t_min):
    denom = d @ normal
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((point - o) @ normal) / denom
    return np.where((denom != 0) & (t >= t_min), t, np.inf)


def intersect_plane(origins, directions, point, normal, t_min=0.0):
    r"""Ray-plane intersection: :math:`t = \frac{(q - o) \cdot n}{d \cdot n}`.

    The plane passes through :math:`q` with normal :math:`n`: the points :math:`p` with
    :math:`(p - q) \cdot n = 0`. A ray parallel to the plane (:math:`d \cdot n = 0`) misses it
    (even when it lies in it), and a hit with :math:`t < t_{min}` (behind the origin) does not
    count. Both sides of the plane are hit.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    point : array_like, shape (3,)
        A point :math:`q` of the plane.
    normal : array_like, shape (3,)
        The plane's normal (normalized here; not zero). It is returned as the "outward" normal
        of every hit, whichever side the ray comes from.
    t_min : float, optional

    Returns
    -------
    SurfaceHits

    Raises
    ------
    ValueError
        For zero directions or normal, a negative `t_min`, NaN, or malformed shapes.

    Examples
    --------
    >>> hits = intersect_plane([[0, 2, 0], [0, 2, 0]], [[0, -1, 0], [1, 0, 0]],
    ...                        [0, 0, 0], [0, 1, 0])
    >>> hits.t
    array([ 2., inf])
    """
    o, d, lead = _rays(origins, directions)
    q = as_vector(point, "point", 3)
    n = _unit_vectors(as_vector(normal, "normal", 3), "normal")
    t = _plane_t(o, d, q, n, _t_min(t_min))
    normals = np.where(np.isfinite(t)[:, None], n, 0.0)
    return SurfaceHits(t.reshape(lead), normals.reshape(lead + (3,)))


class BoxHits(NamedTuple):
    """The result of :func:`intersect_box` (the slab method).

    Attributes
    ----------
    t : ndarray, shape (...)
        The nearest hit at or beyond ``t_min``: where the ray enters the box, or where it leaves
        it for a ray starting inside; ``inf`` for a miss.
    normals : ndarray, shape (..., 3)
        Outward unit normal of the face hit (an axis direction); zero for a miss.
    t_enter, t_exit : ndarray, shape (...)
        Where the ray's *line* enters and leaves the box (``t_enter > t_exit``: it misses).

    Examples
    --------
    >>> hits = intersect_box([0.5, 0.5, 5], [0, 0, -1], [0, 0, 0], [1, 1, 1])
    >>> float(hits.t), float(hits.t_exit), hits.normals
    (4.0, 5.0, array([0., 0., 1.]))
    """
    t: np.ndarray
    normals: np.ndarray
    t_enter: np.ndarray
    t_exit: np.ndarray


def intersect_box(origins, directions, lo, hi, t_min=0.0):
    r"""Ray-box intersection by the slab method (an axis-aligned box, as a BVH node's).

    The box is the intersection of three *slabs* :math:`lo_k \le x_k \le hi_k`. The ray's line
    is inside slab :math:`k` for :math:`t` between :math:`(lo_k - o_k)/d_k` and
    :math:`(hi_k - o_k)/d_k` (in either order), so it is inside the box for

    .. math:: t_{enter} = \max_k \min\left(\frac{lo_k - o_k}{d_k}, \frac{hi_k - o_k}{d_k}\right)
              \le t \le t_{exit} = \min_k \max(\dots)

    and it hits the box when :math:`t_{enter} \le t_{exit}` and :math:`t_{exit} \ge t_{min}`.
    A ray parallel to a slab (:math:`d_k = 0`) is inside it for all :math:`t` or for none,
    depending on :math:`o_k`. Six subtractions, six multiplications (with precomputed
    :math:`1/d_k`) and a few comparisons: far cheaper than testing what the box contains.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    lo, hi : array_like, shape (3,)
        The box's minimum and maximum corners (``lo <= hi``).
    t_min : float, optional

    Returns
    -------
    BoxHits

    Raises
    ------
    ValueError
        For zero directions, ``lo > hi``, a negative `t_min`, NaN, or malformed shapes.

    Examples
    --------
    A ray starting inside the unit cube leaves it through the face x = 1:

    >>> hits = intersect_box([0.5, 0.5, 0.5], [1, 0, 0], [0, 0, 0], [1, 1, 1])
    >>> float(hits.t), hits.normals
    (0.5, array([1., 0., 0.]))
    """
    o, d, lead = _rays(origins, directions)
    lo_v = as_vector(lo, "lo", 3)
    hi_v = as_vector(hi, "hi", 3)
    if np.any(lo_v > hi_v):
        raise ValueError(f"lo must not exceed hi in any coordinate (got lo = {lo_v.tolist()}, "
                         f"hi = {hi_v.tolist()})")
    t_min = _t_min(t_min)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (lo_v - o) / d
        t2 = (hi_v - o) / d
    near, far = np.minimum(t1, t2), np.maximum(t1, t2)
    parallel = d == 0
    inside = (o >= lo_v) & (o <= hi_v)
    near = np.where(parallel, np.where(inside, -np.inf, np.inf), near)
    far = np.where(parallel, np.where(inside, np.inf, -np.inf), far)
    t_enter, t_exit = near.max(axis=1), far.min(axis=1)
    hit = (t_enter <= t_exit) & (t_exit >= t_min)
    from_outside = t_enter >= t_min
    t = np.where(hit, np.where(from_outside, t_enter, t_exit), np.inf)
    # the face: the slab whose entering (or leaving) plane defines t
    axis = np.where(from_outside, near.argmax(axis=1), far.argmin(axis=1))
    rows = np.arange(len(o))
    sign = np.sign(d[rows, axis]) * np.where(from_outside, -1.0, 1.0)
    normals = np.zeros_like(o)
    normals[rows, axis] = np.where(hit, sign, 0.0)
    return BoxHits(t.reshape(lead), normals.reshape(lead + (3,)), t_enter.reshape(lead),
                   t_exit.reshape(lead))


class TriangleHits(NamedTuple):
    """Nearest hits of rays with a set of triangles (:func:`intersect_triangles`,
    :meth:`BVH.intersect`), with the work it took.

    Attributes
    ----------
    t : ndarray, shape (...)
        Ray parameter of the nearest hit; ``inf`` for a miss.
    ids : ndarray of int, shape (...)
        Index of the triangle hit (the lowest index among equally near ones); -1 for a miss.
    u, v : ndarray, shape (...)
        Barycentric coordinates of the hit in its triangle: the point is
        :math:`(1 - u - v)\\, v_0 + u\\, v_1 + v\\, v_2` (0 for a miss).
    normals : ndarray, shape (..., 3)
        Unit normal of the triangle hit, :math:`(v_1 - v_0) \\times (v_2 - v_0)` normalized (the
        side from which the vertices are counter-clockwise); zero for a miss.
    triangle_tests : int
        Ray-triangle tests performed (rays x triangles for brute force).
    box_tests : int
        Ray-box (slab) tests performed (0 for brute force).

    Examples
    --------
    >>> hits = intersect_triangles([0.25, 0.25, 2], [0, 0, -1], [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]])
    >>> float(hits.t), int(hits.ids), float(hits.u), float(hits.v), hits.normals
    (2.0, 0, 0.25, 0.25, array([0., 0., 1.]))
    """
    t: np.ndarray
    ids: np.ndarray
    u: np.ndarray
    v: np.ndarray
    normals: np.ndarray
    triangle_tests: int
    box_tests: int


def _triangles(value, name="triangles"):
    t = as_array(value, name)
    if t.shape == (3, 3):
        t = t[None]
    if t.ndim != 3 or t.shape[1:] != (3, 3):
        raise ValueError(f"{name} must be an array of triangles of shape (m, 3, 3) (m triangles, "
                         f"3 vertices, 3 coordinates), got shape {t.shape}")
    if len(t) == 0:
        raise ValueError(f"{name} must contain at least one triangle, got an empty array")
    return t


def _soa(tris):
    """(9, m + 1) rows v0, e1, e2 (x, y, z each); column m is a zero triangle that never hits."""
    v0 = tris[:, 0]
    out = np.zeros((9, len(tris) + 1))
    out[0:3, :-1] = v0.T
    out[3:6, :-1] = (tris[:, 1] - v0).T
    out[6:9, :-1] = (tris[:, 2] - v0).T
    return out


def _unit_face_normals(tris):
    c = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    length = np.sqrt(_dot(c, c))
    return np.divide(c, length[:, None], out=np.zeros_like(c), where=length[:, None] > 0)


def _brute_force(o, d, soa, t_min, t_max):
    """Nearest hits of rays (p, 3) against all triangles; t_max is an array (p,)."""
    p, m = len(o), soa.shape[1] - 1
    best_t = np.full(p, np.inf)
    best_id = np.full(p, -1, dtype=np.intp)
    best_u, best_v = np.zeros(p), np.zeros(p)
    ray_chunk = max(1, min(p, 1 << 12))
    tri_chunk = max(1, (1 << 18) // ray_chunk)
    for r0 in range(0, p, ray_chunk):
        rs = slice(r0, r0 + ray_chunk)
        ot, dt = o[rs].T[:, :, None], d[rs].T[:, :, None]
        rows = np.arange(len(ot[0]))
        for s in range(0, m, tri_chunk):
            t, u, v = _moller_trumbore(ot, dt, soa[:, None, s:min(s + tri_chunk, m)])
            t[(t < t_min) | (t > t_max[rs, None])] = np.inf
            j = np.argmin(t, axis=1)                  # the lowest index among equal distances
            tj = t[rows, j]
            better = tj < best_t[rs]
            idx = np.nonzero(better)[0] + r0
            best_t[idx] = tj[better]
            best_id[idx] = j[better] + s
            best_u[idx] = u[rows, j][better]
            best_v[idx] = v[rows, j][better]
    return best_t, best_id, best_u, best_v, p * m, 0


class BVH:
    r"""A bounding volume hierarchy over triangles, built and traversed with numpy arrays.

    **Build** (once, :math:`O(P \log P)`): start with all triangles in the root; split every
    node's triangles at the *median* of their box centres along the axis where those centres
    spread most (an object-median split: balanced, depth :math:`\lceil \log_2(P /
    \text{leaf size}) \rceil`), until at most `leaf_size` triangles remain. All nodes of a level
    are split at once (one sort of all triangles by (node, centre) per level), so the build is
    vectorized. Each node stores the axis-aligned box of its triangles, padded by a hair
    (:math:`10^{-9}` of the coordinates' size) so that rounding never loses a hit.

    **Traversal** (:meth:`intersect`), for all rays at once: every ray keeps its own stack of
    nodes still to visit, and all stacks live in one numpy array. Each step pops one node per
    ray: a node whose box starts beyond the nearest hit found so far is skipped; at a leaf its
    triangles are tested (Möller-Trumbore); at an inner node both children's boxes are tested
    (the slab method) and the children hit are pushed, the farther first, so that the nearer
    one is visited first and its hits prune the other. The Python loop runs once per step (a
    few dozen to a few hundred steps), never once per ray or per node.

    The answer equals brute force exactly: the same nearest triangle, the same :math:`t`, u and
    v bit for bit, the lowest index among equally near triangles. Only the work differs: about
    :math:`O(\log P)` box tests and a few triangle tests per ray instead of :math:`P` triangle
    tests.

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
    leaf_size : int, optional
        At most this many triangles per leaf (default 4).

    Attributes
    ----------
    triangles : ndarray, shape (m, 3, 3)
    lo, hi : ndarray, shape (nodes, 3)
        The nodes' boxes; node 0 is the root.
    children : ndarray of int, shape (nodes, 2)
        The two children of each inner node (always consecutive numbers); -1 for leaves.
    leaves : list of ndarray
        ``leaves[k]`` holds the triangle indices of node k (empty for inner nodes).
    depth : int
        Levels below the root.

    Raises
    ------
    ValueError
        For malformed or empty triangles, NaN, or a leaf size below 1.

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> tris = rng.uniform(-1, 1, (2000, 1, 3)) + 0.05 * rng.normal(size=(2000, 3, 3))
    >>> bvh = BVH(tris)
    >>> o, d = np.zeros((500, 3)) + [0, 0, 5], rng.normal(size=(500, 3)) * 0.1 - [0, 0, 1]
    >>> fast = bvh.intersect(o, d)
    >>> slow = intersect_triangles(o, d, tris, accelerate=False)
    >>> bool(np.array_equal(fast.ids, slow.ids) and np.array_equal(fast.t, slow.t))
    True
    >>> fast.triangle_tests < slow.triangle_tests / 50      # 1,000,000 tests by brute force
    True
    """

    def __init__(self, triangles, leaf_size=4):
        tris = _triangles(triangles)
        self.leaf_size = as_whole(leaf_size, "leaf_size", 1)
        self.triangles = tris
        self._soa = _soa(tris)
        self._normals = _unit_face_normals(tris)
        self._build()

    def _build(self):
        tris, leaf_size = self.triangles, self.leaf_size
        m = len(tris)
        tmin, tmax = tris.min(axis=1), tris.max(axis=1)
        centre = (tmin + tmax) / 2
        pad = 1e-9 * max(float(np.abs(tris).max()), 1e-300)
        n_max = 2 * m
        lo, hi = np.zeros((n_max, 3)), np.zeros((n_max, 3))
        children = np.full((n_max, 2), -1, dtype=np.intp)
        leaf_row = np.full(n_max, -1, dtype=np.intp)
        rows = []
        order = np.arange(m)
        # the segments of `order` that tile [0, m): one per node of the current level, plus the
        # leaves of earlier levels ("done"), which are carried along unchanged
        starts, ends = np.array([0]), np.array([m])
        node = np.array([0])
        done = np.array([False])
        n_nodes, n_rows, depth = 1, 0, 0
        while True:
            count = ends - starts
            seg = np.repeat(np.arange(len(starts)), count)
            box_lo = np.minimum.reduceat(tmin[order], starts)
            box_hi = np.maximum.reduceat(tmax[order], starts)
            now = ~done
            lo[node[now]] = box_lo[now] - pad
            hi[node[now]] = box_hi[now] + pad
            leaf = now & (count <= leaf_size)
            if leaf.any():
                k = np.nonzero(leaf)[0]
                table = np.full((len(k), leaf_size), m, dtype=np.intp)
                at = leaf[seg]
                slot = np.cumsum(leaf) - 1
                table[slot[seg[at]], np.arange(m)[at] - starts[seg[at]]] = order[at]
                table.sort(axis=1)                      # lowest index first within a leaf
                leaf_row[node[k]] = n_rows + np.arange(len(k))
                n_rows += len(k)
                rows.append(table)
            split = now & ~leaf
            done = done | leaf
            if not split.any():
                break
            depth += 1
            c_lo = np.minimum.reduceat(centre[order], starts)
            c_hi = np.maximum.reduceat(centre[order], starts)
            axis = np.argmax(c_hi - c_lo, axis=1)
            key = centre[order, axis[seg]]
            order = order[np.lexsort((key, seg))]     # sorted by centre within each segment
            k = np.nonzero(split)[0]
            mid = (starts[k] + ends[k]) // 2
            first = n_nodes + 2 * np.arange(len(k))
            n_nodes += 2 * len(k)
            children[node[k], 0] = first
            children[node[k], 1] = first + 1
            keep = ~split
            starts = np.concatenate([starts[keep], starts[k], mid])
            ends = np.concatenate([ends[keep], mid, ends[k]])
            node = np.concatenate([node[keep], first, first + 1])
            done = np.concatenate([done[keep], np.zeros(2 * len(k), dtype=bool)])
            by_start = np.argsort(starts, kind="stable")
            starts, ends, node, done = starts[by_start], ends[by_start], node[by_start], \
                done[by_start]
        self.lo, self.hi = lo[:n_nodes], hi[:n_nodes]
        self.children = children[:n_nodes]
        self.depth = depth
        self._leaf_row = leaf_row[:n_nodes]
        self._leaf_table = np.concatenate(rows)
        # the boxes of both children of every node in one row: 12 numbers, gathered at once
        c0 = np.where(self.children[:, 0] >= 0, self.children[:, 0], 0)
        c1 = np.where(self.children[:, 1] >= 0, self.children[:, 1], 0)
        self._child_boxes = np.ascontiguousarray(
            np.concatenate([self.lo[c0].T, self.hi[c0].T, self.lo[c1].T, self.hi[c1].T]))

    @property
    def leaves(self):
        m = len(self.triangles)
        return [self._leaf_table[r][self._leaf_table[r] < m] if r >= 0
                else np.zeros(0, dtype=np.intp) for r in self._leaf_row]

    def __repr__(self):
        return (f"BVH({len(self.triangles)} triangles, {len(self.lo)} nodes, depth {self.depth}, "
                f"leaf size {self.leaf_size})")

    def intersect(self, origins, directions, t_min=0.0, t_max=np.inf, any_hit=False):
        r"""The nearest triangle hit by each ray, by traversing the hierarchy.

        Parameters
        ----------
        origins, directions : array_like, shape (..., 3)
        t_min, t_max : float, optional
            Only hits with :math:`t_{min} \le t \le t_{max}` count.
        any_hit : bool, optional
            Stop each ray at the first hit found, nearest or not (enough for a shadow ray,
            which only asks *whether* something is in the way): ``t`` and ``ids`` are then
            *a* hit, not necessarily the nearest.

        Returns
        -------
        TriangleHits

        Raises
        ------
        ValueError
            For zero directions, NaN, malformed shapes, or ``t_max < t_min``.

        Examples
        --------
        Two parallel triangles; the ray from above hits the upper one first:

        >>> tris = [[[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[-1, -1, 2], [1, -1, 2], [0, 1, 2]]]
        >>> hits = BVH(tris, leaf_size=1).intersect([[0, 0, 5], [9, 9, 5]], [0, 0, -1])
        >>> hits.t, hits.ids, hits.box_tests
        (array([ 3., inf]), array([ 1, -1]), 4)
        """
        o, d, lead = _rays(origins, directions)
        t_min = _t_min(t_min)
        t_max = _t_max(t_max, t_min)
        t, ids, u, v, tri_tests, box_tests = self._intersect(o, d, t_min, np.full(len(o), t_max),
                                                             any_hit)
        return _triangle_hits(t, ids, u, v, self._normals, lead, tri_tests, box_tests)

    def _intersect(self, o, d, t_min, t_max, any_hit=False, chunk=1 << 17):
        """Traversal in chunks of rays (bounded memory); t_max is an array (p,)."""
        p = len(o)
        out = [np.full(p, np.inf), np.full(p, -1, dtype=np.intp), np.zeros(p), np.zeros(p)]
        tri_tests = box_tests = 0
        for s in range(0, p, chunk):
            res = self._traverse(o[s:s + chunk], d[s:s + chunk], t_min, t_max[s:s + chunk],
                                 any_hit)
            for arr, part in zip(out, res[:4]):
                arr[s:s + chunk] = part
            tri_tests += res[4]
            box_tests += res[5]
        return (*out, tri_tests, box_tests)

    def _traverse(self, o, d, t_min, t_max, any_hit):
        p = len(o)
        m = len(self.triangles)
        ot = np.ascontiguousarray(o.T)
        dt = np.ascontiguousarray(d.T)
        # 1/d with zero components replaced by a tiny positive number: the slab of a parallel
        # ray then spans (-huge, +huge) or lies wholly on one side, as it should (no 0 * inf)
        inv = 1.0 / np.where(dt == 0, 1e-300, dt)
        best_t = np.full(p, np.inf)
        best_id = np.full(p, -1, dtype=np.intp)
        best_u, best_v = np.zeros(p), np.zeros(p)
        depth = self.depth + 2
        stack_node = np.zeros(p * depth, dtype=np.intp)
        stack_t = np.zeros(p * depth)
        base = np.arange(p) * depth
        top = base.copy()                              # next free slot of each ray's stack
        lo, hi = self.lo[0], self.hi[0]
        tri_tests = 0
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            t1, t2 = (lo[:, None] - ot) * inv, (hi[:, None] - ot) * inv
            t_in = np.maximum(np.minimum(t1, t2).max(axis=0), t_min)
            t_out = np.minimum(np.maximum(t1, t2).min(axis=0), t_max)
            active = np.nonzero(t_in <= t_out)[0]
            stack_t[base[active]] = t_in[active]        # the root, node 0
            top[active] += 1
            box_tests = p
            leaf_row, table, boxes, first_child = (self._leaf_row, self._leaf_table,
                                                   self._child_boxes, self.children[:, 0])
            while active.size:
                top[active] -= 1
                slot = top[active]
                nodes = stack_node[slot]
                live = stack_t[slot] <= best_t[active]  # skip boxes beyond the nearest hit
                rays, nodes = active[live], nodes[live]
                rows = leaf_row[nodes]
                at_leaf = rows >= 0
                if at_leaf.any():
                    r = rays[at_leaf]
                    tri = table[rows[at_leaf]]                                 # (k, leaf_size)
                    t, u, v = _moller_trumbore(ot[:, r, None], dt[:, r, None], self._soa[:, tri])
                    t[(t < t_min) | (t > t_max[r, None])] = np.inf
                    tri_tests += int(np.count_nonzero(tri < m))
                    j = np.argmin(t, axis=1)
                    k = np.arange(len(r))
                    tj, idj = t[k, j], tri[k, j]
                    better = (tj < best_t[r]) | ((tj == best_t[r]) & (idj < best_id[r])
                                                 & np.isfinite(tj))
                    rb = r[better]
                    best_t[rb], best_id[rb] = tj[better], idj[better]
                    best_u[rb], best_v[rb] = u[k, j][better], v[k, j][better]
                    if any_hit:
                        top[rb] = base[rb]              # done: forget the rest of the stack
                if not at_leaf.all():
                    inner = ~at_leaf
                    r, n = rays[inner], nodes[inner]
                    b = boxes[:, n]
                    o_r, i_r = ot[:, r], inv[:, r]
                    bound = np.minimum(best_t[r], t_max[r])
                    near = []
                    hit = []
                    for c in (0, 6):                    # the slab test of both children
                        a1 = (b[c] - o_r[0]) * i_r[0]
                        a2 = (b[c + 3] - o_r[0]) * i_r[0]
                        t_in, t_out = np.minimum(a1, a2), np.maximum(a1, a2)
                        for axis in (1, 2):
                            a1 = (b[c + axis] - o_r[axis]) * i_r[axis]
                            a2 = (b[c + 3 + axis] - o_r[axis]) * i_r[axis]
                            np.maximum(t_in, np.minimum(a1, a2), out=t_in)
                            np.minimum(t_out, np.maximum(a1, a2), out=t_out)
                        np.maximum(t_in, t_min, out=t_in)
                        near.append(t_in)
                        hit.append(t_in <= np.minimum(t_out, bound))
                    box_tests += 2 * len(r)
                    second_first = near[1] < near[0]            # child 1 is the nearer one
                    first = first_child[n]
                    # push the farther child, then the nearer one (popped first)
                    for is_second, h, t_push in (
                            (~second_first, np.where(second_first, hit[0], hit[1]),
                             np.where(second_first, near[0], near[1])),
                            (second_first, np.where(second_first, hit[1], hit[0]),
                             np.where(second_first, near[1], near[0]))):
                        rr = r[h]
                        pos = top[rr]
                        stack_node[pos] = (first + is_second)[h]
                        stack_t[pos] = t_push[h]
                        top[rr] = pos + 1
                active = active[top[active] > base[active]]
        return best_t, best_id, best_u, best_v, tri_tests, box_tests


def _triangle_hits(t, ids, u, v, face_normals, lead, tri_tests, box_tests):
    hit = ids >= 0
    normals = np.zeros((len(t), 3))
    normals[hit] = face_normals[ids[hit]]
    u = np.where(hit, u, 0.0)
    v = np.where(hit, v, 0.0)
    return TriangleHits(t.reshape(lead), ids.reshape(lead), u.reshape(lead), v.reshape(lead),
                        normals.reshape(lead + (3,)), int(tri_tests), int(box_tests))


def intersect_triangles(origins, directions, triangles, t_min=0.0, t_max=np.inf,
                        accelerate=True):
    r"""Ray-triangle intersection (Möller-Trumbore) of many rays with many triangles.

    For each ray, solve :math:`o + t\,d = v_0 + u\,(v_1 - v_0) + v\,(v_2 - v_0)` for
    :math:`(t, u, v)` by Cramer's rule, with :math:`e_1 = v_1 - v_0`, :math:`e_2 = v_2 - v_0`,
    :math:`s = o - v_0`, :math:`p = d \times e_2`, :math:`q = s \times e_1`:

    .. math:: \begin{bmatrix} t \\ u \\ v \end{bmatrix} = \frac{1}{p \cdot e_1}
              \begin{bmatrix} q \cdot e_2 \\ p \cdot s \\ q \cdot d \end{bmatrix}

    The ray hits when :math:`u \ge 0`, :math:`v \ge 0`, :math:`u + v \le 1` (inside the
    triangle), :math:`p \cdot e_1 \ne 0` (not parallel to its plane) and :math:`t_{min} \le t
    \le t_{max}`; both sides of a triangle are hit. The nearest hit over all triangles is
    kept (the lowest index among equal :math:`t`). Brute force costs rays x triangles tests;
    with `accelerate` a :class:`BVH` is built (:math:`O(P \log P)`, once; pass a ready
    :class:`BVH` as `triangles` to reuse it) and the answer is exactly the same, with far
    fewer tests.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    triangles : array_like, shape (m, 3, 3), or BVH
    t_min, t_max : float, optional
    accelerate : bool, optional
        Build a BVH (default True). Ignored when `triangles` is a BVH.

    Returns
    -------
    TriangleHits
        ``t, ids, u, v, normals`` and the numbers of triangle and box tests.

    Raises
    ------
    ValueError
        For zero directions, NaN, malformed or empty triangles, a negative `t_min` or
        ``t_max < t_min``.

    Examples
    --------
    >>> tri = [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]]
    >>> hits = intersect_triangles([[0.2, 0.3, 1], [0.9, 0.9, 1]], [0, 0, -1], tri,
    ...                            accelerate=False)
    >>> hits.t, hits.ids, hits.u, hits.v
    (array([ 1., inf]), array([ 0, -1]), array([0.2, 0. ]), array([0.3, 0. ]))
    """
    o, d, lead = _rays(origins, directions)
    t_min = _t_min(t_min)
    t_max = np.full(len(o), _t_max(t_max, t_min))
    if isinstance(triangles, BVH):
        bvh = triangles
    elif accelerate:
        bvh = BVH(triangles)
    else:
        tris = _triangles(triangles)
        res = _brute_force(o, d, _soa(tris), t_min, t_max)
        return _triangle_hits(*res[:4], _unit_face_normals(tris), lead, *res[4:])
    res = bvh._intersect(o, d, t_min, t_max)
    return _triangle_hits(*res[:4], bvh._normals, lead, *res[4:])
