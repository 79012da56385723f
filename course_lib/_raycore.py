r"""The ray core: rays, triangles and the bounding-volume hierarchy, implemented once.

Chapter 5's ray casting (:mod:`course_lib.visibility`), chapter 12's ambient occlusion (which
casts its rays through :mod:`course_lib.visibility`) and chapter 15's ray tracer
(:mod:`course_lib.raytracing`) all ask the same question: *which triangle does each ray meet
first?* Everything that answers it lives here, in the order of the lesson section "Making it
fast: acceleration structures":

1. **input checks**: :func:`as_rays`, :func:`as_triangles`, :func:`as_t_min`, :func:`as_t_max`;
2. **Möller-Trumbore** ray-triangle intersection: :func:`moller_trumbore` (component by
   component, so that every (ray, triangle) pair gives the same bits however the work is
   batched);
3. **brute force**, the reference: :func:`brute_force` tests every ray against every triangle and
   keeps the nearest hit (:func:`keep_nearest`: equal distances go to the lower triangle index);
4. **the slab test** of a ray against an axis-aligned box: :func:`slab`;
5. **the BVH** (:class:`BVH`): *build* (bounds, split, leaves) and two traversals of the same
   tree, each with the steps *slab test*, *near/far order* and *cull beyond the nearest hit so
   far*:

   * :meth:`BVH.cast` (chapter 5) moves **packets** of rays down the tree, one numpy array of
     ray indices per node, and counts the triangle and box tests for the lesson;
   * :meth:`BVH.intersect` (chapter 15, the fast path) gives **every ray its own stack**, all
     stacks in one array, and can stop a shadow ray at its first hit (``any_hit``).

   Both return exactly what :func:`brute_force` returns (the same triangle, the same :math:`t`
   bit for bit); only the number of tests differs.

``visibility.BVH`` and ``raytracing.BVH`` are this one class; :class:`Hits` and
:class:`TriangleHits` are re-exported by those packages too.
"""

from typing import NamedTuple

import numpy as np

from ._validate import as_array, as_points, as_scalar, as_whole, broadcast_stacks


# ---------------------------------------------------------------------------------------------
# 1. Input checks
# ---------------------------------------------------------------------------------------------

def as_rays(origins, directions, flat=False):
    """Origins and directions as contiguous (p, 3) float arrays, and their common leading shape.

    One origin (or one direction) may be shared by all rays; stacks broadcast as
    :func:`course_lib._validate.broadcast_stacks` says. With ``flat=True`` (chapter 5's
    :func:`course_lib.visibility.ray_cast`) only ``(p, 3)`` arrays or single points are accepted,
    and at least one ray is required.

    Raises
    ------
    ValueError
        For malformed or non-finite input, stacks that do not broadcast, or a zero direction.

    Examples
    --------
    >>> o, d, lead = as_rays([0, 0, 5], [[0, 0, -1], [1, 0, 0]])
    >>> o.shape, d.shape, lead
    ((2, 3), (2, 3), (2,))
    >>> as_rays([0, 0, 0], [0, 0, 0])
    Traceback (most recent call last):
    ...
    ValueError: directions must not contain the zero vector: a ray needs a direction
    """
    o = as_points(origins, "origins", dims=3)
    d = as_points(directions, "directions", dims=3)
    if flat and (o.ndim > 2 or d.ndim > 2):
        raise ValueError(f"origins and directions must be (p, 3) arrays or single points, got "
                         f"shapes {o.shape} and {d.shape}")
    lead = broadcast_stacks(origins=(o, 1), directions=(d, 1))
    if flat and (0 in o.shape or 0 in d.shape):
        raise ValueError("origins and directions must contain at least one ray")
    o = np.ascontiguousarray(np.broadcast_to(o, lead + (3,)).reshape(-1, 3))
    d = np.ascontiguousarray(np.broadcast_to(d, lead + (3,)).reshape(-1, 3))
    zero = ~np.any(d != 0, axis=-1)
    if zero.any():
        where = ""
        if len(lead) > 1 or (lead and not flat):
            at = np.unravel_index(int(np.argmax(zero)), lead)
            where = f" (at index {tuple(int(i) for i in at)})"
        raise ValueError(f"directions must not contain the zero vector{where}: a ray needs a "
                         "direction")
    return o, d, (lead if lead or not flat else (1,))


def as_triangles(value, name="triangles", dim=3):
    """`value` as an (m, 3, dim) float array of m >= 1 triangles (one (3, dim) triangle allowed).

    Examples
    --------
    >>> as_triangles([[0, 0, 0], [1, 0, 0], [0, 1, 0]]).shape
    (1, 3, 3)
    >>> as_triangles([[0, 0, 0], [1, 0, 0]])
    Traceback (most recent call last):
    ...
    ValueError: triangles must be an array of triangles of shape (m, 3, 3) (m triangles, 3 vertices, 3 coordinates), got shape (2, 3)
    """
    t = as_array(value, name)
    if t.shape == (3, dim):
        t = t[None]
    if t.ndim != 3 or t.shape[1:] != (3, dim):
        raise ValueError(f"{name} must be an array of triangles of shape (m, 3, {dim}) "
                         f"(m triangles, 3 vertices, {dim} coordinates), got shape {t.shape}")
    if len(t) == 0:
        raise ValueError(f"{name} must contain at least one triangle, got an empty array")
    return t


def as_t_min(value, nonnegative=True):
    """The lower end of the ray's range; chapter 15 wants it >= 0, chapter 5 allows any number.

    Examples
    --------
    >>> as_t_min(-1.0, nonnegative=False)
    -1.0
    """
    t = as_scalar(value, "t_min")
    if nonnegative and t < 0:
        raise ValueError(f"t_min must be >= 0 (hits behind the ray's origin are never wanted), "
                         f"got {t}")
    return t


def as_t_max(value, t_min):
    """The upper end of the ray's range (``inf``: unbounded), not below `t_min`.

    Examples
    --------
    >>> as_t_max(np.inf, 0.0), as_t_max(2, 0.0)
    (inf, 2.0)
    """
    if np.isscalar(value) and np.isposinf(value):
        return np.inf
    t = as_scalar(value, "t_max")
    if t < t_min:
        raise ValueError(f"t_max must not be below t_min (got t_min = {t_min}, t_max = {t})")
    return t


def as_leaf_size(value):
    """The most triangles a BVH leaf may hold: a whole number >= 1."""
    return as_whole(value, "leaf_size", 1)


# ---------------------------------------------------------------------------------------------
# 2. Möller-Trumbore
# ---------------------------------------------------------------------------------------------

def moller_trumbore(o, d, tri):
    r"""(t, u, v) of rays against triangles, component by component; ``t = inf`` on a miss.

    Solves :math:`o + t\,d = v_0 + u\,e_1 + v\,e_2` by Cramer's rule with :math:`p = d \times
    e_2`, :math:`s = o - v_0`, :math:`q = s \times e_1`: :math:`(t, u, v) = (q \cdot e_2,\;
    p \cdot s,\; q \cdot d) / (p \cdot e_1)`; a hit needs :math:`u, v \ge 0`, :math:`u + v \le 1`
    and a non-zero determinant (both sides of a triangle are hit).

    `o` and `d` are sequences of 3 arrays (x, y, z), `tri` a sequence of 9 arrays (v0, e1 =
    v1 - v0, e2 = v2 - v0, as :func:`triangle_soa` stores them); all broadcast. Written out per
    component so that each (ray, triangle) pair goes through the same floating-point operations
    whatever the batching: brute force and both traversals agree bit for bit.

    Examples
    --------
    >>> soa = triangle_soa(np.array([[[0.0, 0, 0], [1, 0, 0], [0, 1, 0]]]))
    >>> t, u, v = moller_trumbore([0.25, 0.25, 2.0], [0.0, 0.0, -1.0], soa[:, 0])
    >>> float(t), float(u), float(v)
    (2.0, 0.25, 0.25)
    """
    dx, dy, dz = d[0], d[1], d[2]
    ax, ay, az = tri[3], tri[4], tri[5]
    bx, by, bz = tri[6], tri[7], tri[8]
    px, py, pz = dy * bz - dz * by, dz * bx - dx * bz, dx * by - dy * bx       # d x e2
    det = ax * px + ay * py + az * pz
    tx, ty, tz = o[0] - tri[0], o[1] - tri[1], o[2] - tri[2]                    # s = o - v0
    qx, qy, qz = ty * az - tz * ay, tz * ax - tx * az, tx * ay - ty * ax       # s x e1
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inv = 1.0 / det
        u = (tx * px + ty * py + tz * pz) * inv
        v = (dx * qx + dy * qy + dz * qz) * inv
        t = (bx * qx + by * qy + bz * qz) * inv
        hit = (det != 0) & (u >= 0) & (v >= 0) & (u + v <= 1)
    return np.where(hit, t, np.inf), u, v


def triangle_soa(tris):
    """(9, m + 1) rows v0, e1, e2 (x, y, z each); column m is a zero triangle that never hits
    (it pads the rows of the leaf table)."""
    v0 = tris[:, 0]
    out = np.zeros((9, len(tris) + 1))
    out[0:3, :-1] = v0.T
    out[3:6, :-1] = (tris[:, 1] - v0).T
    out[6:9, :-1] = (tris[:, 2] - v0).T
    return out


def triangle_normals(tris):
    """Unit normals :math:`(v_1 - v_0) \\times (v_2 - v_0)` normalized; zero for a degenerate
    triangle. The triangles are a soup, shape (m, 3, 3): :func:`course_lib.mesh.face_normals`
    is the same normal for an indexed mesh (it normalises with ``np.linalg.norm``, this one with
    ``einsum``; the last bit may differ, and stored pictures depend on it)."""
    c = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    length = np.sqrt(np.einsum("ij,ij->i", c, c))
    return np.divide(c, length[:, None], out=np.zeros_like(c), where=length[:, None] > 0)


# ---------------------------------------------------------------------------------------------
# 3. The nearest hit, and brute force (the reference every traversal must equal)
# ---------------------------------------------------------------------------------------------

def keep_nearest(t, u, v, ids, rays, best):
    """Update the nearest hits `best` = [t, ids, u, v] of `rays` with their tests (k, n).

    Within a row the lowest column wins among equal ``t`` (``argmin``); against the hit kept so
    far a new one must be nearer, or as near with a lower triangle index. So the answer is the
    lowest index among equally near triangles whatever order the triangles are tested in.
    Returns the rays whose nearest hit changed.
    """
    j = np.argmin(t, axis=1)
    k = np.arange(len(rays))
    tj, idj = t[k, j], ids[k, j] if ids.ndim == 2 else ids[j]
    cur_t, cur_id = best[0][rays], best[1][rays]
    better = (tj < cur_t) | ((tj == cur_t) & (idj < cur_id) & np.isfinite(tj))
    rb = rays[better]
    best[0][rb], best[1][rb] = tj[better], idj[better]
    best[2][rb], best[3][rb] = u[k, j][better], v[k, j][better]
    return rb


def _empty_hits(p):
    return [np.full(p, np.inf), np.full(p, -1, dtype=np.intp), np.zeros(p), np.zeros(p)]


def brute_force(o, d, soa, t_min, t_max):
    """Nearest hits of rays (p, 3) against all triangles of `soa`: every pair is tested.

    `t_max` is an array (p,). Returns ``(t, ids, u, v, triangle_tests, box_tests)`` with
    ``triangle_tests = p * m`` and no box tests: the textbook's :math:`O(pP)`. Blocks of rays
    and triangles bound the memory.
    """
    p, m = len(o), soa.shape[1] - 1
    best = _empty_hits(p)
    ray_chunk = max(1, min(p, 1 << 12))
    tri_chunk = max(1, (1 << 18) // ray_chunk)
    for r0 in range(0, p, ray_chunk):
        rays = np.arange(r0, min(r0 + ray_chunk, p))
        ot, dt = o[rays].T[:, :, None], d[rays].T[:, :, None]
        for s in range(0, m, tri_chunk):
            e = min(s + tri_chunk, m)
            t, u, v = moller_trumbore(ot, dt, soa[:, None, s:e])     # a view, not a copy
            t[(t < t_min) | (t > t_max[rays, None])] = np.inf
            keep_nearest(t, u, v, np.arange(s, e), rays, best)
    return (*best, p * m, 0)


# ---------------------------------------------------------------------------------------------
# 4. The slab test
# ---------------------------------------------------------------------------------------------

def slab(lo, hi, o, d):
    r"""Where the rays' lines enter and leave the slabs of boxes: ``near, far``, shape (..., 3).

    The box is the intersection of three slabs :math:`lo_k \le x_k \le hi_k`; the line is inside
    slab :math:`k` for :math:`t` between :math:`(lo_k - o_k)/d_k` and :math:`(hi_k - o_k)/d_k`.
    A ray parallel to a slab (:math:`d_k = 0`) is inside it for all :math:`t` or for none. The
    box is entered at ``near.max(-1)`` and left at ``far.min(-1)``.

    Examples
    --------
    >>> o, d = np.array([[0.5, 0.5, 5.0]]), np.array([[0.0, 0.0, -1.0]])
    >>> near, far = slab(np.zeros(3), np.ones(3), o, d)
    >>> float(near.max()), float(far.min())
    (4.0, 5.0)
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (lo - o) / d
        t2 = (hi - o) / d
    near, far = np.minimum(t1, t2), np.maximum(t1, t2)
    parallel = d == 0                               # inside the slab: all t; else none
    within = (o >= lo) & (o <= hi)
    near = np.where(parallel, np.where(within, -np.inf, np.inf), near)
    far = np.where(parallel, np.where(within, np.inf, -np.inf), far)
    return near, far


# ---------------------------------------------------------------------------------------------
# 5. The BVH
# ---------------------------------------------------------------------------------------------

class Hits(NamedTuple):
    """The nearest hits of :func:`course_lib.visibility.ray_cast` and :meth:`BVH.cast`, with the
    work it took.

    Attributes
    ----------
    t : ndarray, shape (p,)
        Ray parameter of the nearest hit, the hit point being ``origin + t * direction``
        (the distance when the directions are unit vectors); ``inf`` on a miss.
    ids : ndarray of int, shape (p,)
        Index of the triangle hit, -1 on a miss.
    triangle_tests : int
        Ray-triangle intersection tests performed (``p * P`` for brute force).
    box_tests : int
        Ray-box tests performed (0 for brute force).

    Examples
    --------
    >>> from course_lib.visibility import ray_cast
    >>> hits = ray_cast([0, 0, 5], [0, 0, -1], [[[-1, -1, 0], [1, -1, 0], [0, 1, 0]]])
    >>> hits.t.tolist(), hits.ids.tolist(), hits.triangle_tests
    ([5.0], [0], 1)
    """
    t: np.ndarray
    ids: np.ndarray
    triangle_tests: int
    box_tests: int


class TriangleHits(NamedTuple):
    """Nearest hits of rays with a set of triangles
    (:func:`course_lib.raytracing.intersect_triangles`, :meth:`BVH.intersect`), with the work it
    took.

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
    >>> from course_lib.raytracing import intersect_triangles
    >>> tri = [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]]
    >>> hits = intersect_triangles([0.25, 0.25, 2], [0, 0, -1], tri)
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


def triangle_hits(t, ids, u, v, normals_of, lead, tri_tests, box_tests):
    """:class:`TriangleHits` of flat results, shaped as the rays (`lead`)."""
    hit = ids >= 0
    normals = np.zeros((len(t), 3))
    normals[hit] = normals_of[ids[hit]]
    u = np.where(hit, u, 0.0)
    v = np.where(hit, v, 0.0)
    return TriangleHits(t.reshape(lead), ids.reshape(lead), u.reshape(lead), v.reshape(lead),
                        normals.reshape(lead + (3,)), int(tri_tests), int(box_tests))


class BVH:
    r"""A bounding-volume hierarchy of axis-aligned boxes over triangles (chapters 5, 12, 15).

    **Build** (once, :math:`O(P \log P)`), one level of the tree at a time, all nodes of a level
    at once (numpy, no loop over nodes):

    * *bounds*: every node stores the box of its triangles, padded by a hair (:math:`10^{-9}` of
      the coordinates' size) so that rounding never loses a hit;
    * *split*: a node with more than `leaf_size` triangles is split at the **median** of their
      box centres along the axis where those centres spread most (an object-median split:
      balanced, depth :math:`\lceil \log_2(P / \text{leaf size}) \rceil`). Equal centres send the
      lower triangle index to the left child, so the tree is the same on every machine;
    * *leaves*: a node with at most `leaf_size` triangles becomes a leaf; its triangles are kept
      in ascending index order.

    **Traversal**: a ray that misses a node's box (the *slab test*), or reaches it only beyond
    the nearest hit found so far (*cull*), skips the whole subtree; otherwise the *nearer child
    is visited first*, so that its hits prune the farther one. At a leaf the ray is tested
    against the leaf's triangles (Möller-Trumbore) and the nearest hit so far is kept. Two ways
    of running this over many rays, on the same tree:

    * :meth:`cast` (chapter 5) moves **packets** down the tree: a numpy array of ray indices per
      node, the nearer child chosen by the packet's summed direction along the split axis. It
      counts a box test for every ray of every packet that reaches a node.
    * :meth:`intersect` (chapter 15, the fast path) gives **every ray its own stack** of nodes,
      all stacks in one array: each step pops one node per ray, tests both children's boxes,
      and pushes the ones hit, the farther first; ``any_hit`` stops a shadow ray at its first
      hit.

    Both equal brute force exactly (:func:`brute_force`: the same nearest triangle, the same
    :math:`t` bit for bit, the lowest index among equally near triangles); only the number of
    tests differs: about :math:`O(\log P)` box tests and a few triangle tests per ray instead
    of :math:`P` triangle tests.

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
    leaf_size : int, optional
        At most this many triangles per leaf (default 4).

    Attributes
    ----------
    triangles : ndarray, shape (m, 3, 3)
    leaf_size : int
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
    >>> fast, packets = bvh.intersect(o, d), bvh.cast(o, d)
    >>> slow = brute_force(o, d, triangle_soa(tris), 0.0, np.full(500, np.inf))
    >>> all(np.array_equal(a, b) for a, b in [(fast.ids, slow[1]), (fast.t, slow[0]),
    ...                                       (packets.ids, slow[1]), (packets.t, slow[0])])
    True
    >>> fast.triangle_tests < slow[4] / 50      # 1,000,000 tests by brute force
    True
    """

    def __init__(self, triangles, leaf_size=4):
        tris = as_triangles(triangles)
        self.leaf_size = as_leaf_size(leaf_size)
        self.triangles = tris
        self._soa = triangle_soa(tris)
        self._normals = triangle_normals(tris)
        self._build()

    # -- build ---------------------------------------------------------------------------------

    def _build(self):
        tris, leaf_size = self.triangles, self.leaf_size
        m = len(tris)
        # bounds: each triangle's box and its centre
        tmin, tmax = tris.min(axis=1), tris.max(axis=1)
        centre = (tmin + tmax) / 2
        pad = 1e-9 * max(float(np.abs(tris).max()), 1e-300)
        # the median split sorts by (centre along the axis, triangle index): as one integer
        # rank per axis, computed once (a stable sort keeps equal centres in index order)
        rank = np.empty((3, m), dtype=np.intp)
        for axis in range(3):
            rank[axis, np.argsort(centre[:, axis], kind="stable")] = np.arange(m)
        n_max = 2 * m
        lo, hi = np.zeros((n_max, 3)), np.zeros((n_max, 3))
        children = np.full((n_max, 2), -1, dtype=np.intp)
        axes = np.zeros(n_max, dtype=np.intp)
        spans = np.zeros((n_max, 2), dtype=np.intp)
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
            now = ~done
            # bounds of this level's nodes
            box_lo = np.minimum.reduceat(tmin[order], starts)
            box_hi = np.maximum.reduceat(tmax[order], starts)
            lo[node[now]] = box_lo[now] - pad
            hi[node[now]] = box_hi[now] + pad
            spans[node[now], 0], spans[node[now], 1] = starts[now], ends[now]
            # leaves: a row of the leaf table each, padded with the zero triangle m
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
            # split: the axis of widest centre spread, then the median by (centre, index)
            c_lo = np.minimum.reduceat(centre[order], starts)
            c_hi = np.maximum.reduceat(centre[order], starts)
            axis = np.argmax(c_hi - c_lo, axis=1)
            order = order[np.argsort(seg * m + rank[axis[seg], order])]   # unique keys
            k = np.nonzero(split)[0]
            mid = (starts[k] + ends[k]) // 2
            first = n_nodes + 2 * np.arange(len(k))
            n_nodes += 2 * len(k)
            children[node[k], 0] = first
            children[node[k], 1] = first + 1
            axes[node[k]] = axis[k]
            keep = ~split
            starts = np.concatenate([starts[keep], starts[k], mid])
            ends = np.concatenate([ends[keep], mid, ends[k]])
            node = np.concatenate([node[keep], first, first + 1])
            done = np.concatenate([done[keep], np.zeros(2 * len(k), dtype=bool)])
            by_start = np.argsort(starts, kind="stable")
            starts, ends, node, done = starts[by_start], ends[by_start], node[by_start], \
                done[by_start]
        # within each leaf's span of `order`, ascending triangle index (as in the leaf table)
        seg = np.repeat(np.arange(len(starts)), ends - starts)
        self._order = order[np.argsort(seg * m + order)]
        self.lo, self.hi = lo[:n_nodes], hi[:n_nodes]
        self.children = children[:n_nodes]
        self.depth = depth
        self._axes = axes[:n_nodes]
        self._spans = spans[:n_nodes]
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

    # -- traversal with packets (chapter 5) ----------------------------------------------------

    def cast(self, origins, directions, t_min=0.0, t_max=np.inf):
        """Nearest hits of many rays, packet by packet: as :func:`course_lib.visibility.ray_cast`
        with ``accelerate=True``.

        Parameters
        ----------
        origins, directions : array_like, shape (p, 3) or (3,)
        t_min, t_max : float, optional
            Only hits with ``t_min <= t <= t_max`` count (any `t_min`, also negative).

        Returns
        -------
        Hits

        Examples
        --------
        >>> bvh = BVH([[[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[-1, -1, 2], [1, -1, 2], [0, 1, 2]]])
        >>> bvh.cast([[0, 0, 5], [0, 0, -5]], [0, 0, -1]).ids.tolist()
        [1, -1]
        """
        o, d, _ = as_rays(origins, directions, flat=True)
        t_min = as_t_min(t_min, nonnegative=False)
        return self._cast(o, d, t_min, as_t_max(t_max, t_min))

    def _cast(self, o, d, t_min, t_max):
        p = len(o)
        best = _empty_hits(p)
        ot, dt = o.T, d.T
        tri_tests = box_tests = 0
        stack = [(0, np.arange(p))]
        while stack:
            node, rays = stack.pop()
            # slab test of the packet against the node's box, and cull beyond the nearest hit
            box_tests += len(rays)
            near, far = slab(self.lo[node], self.hi[node], o[rays], d[rays])
            t_in, t_out = near.max(axis=1), far.min(axis=1)
            ok = (t_in <= t_out) & (t_out >= t_min) & (t_in <= np.minimum(best[0][rays], t_max))
            rays = rays[ok]
            if len(rays) == 0:
                continue
            left, right = self.children[node]
            if left < 0:                                # a leaf: Möller-Trumbore
                s, e = self._spans[node]
                ids = self._order[s:e]
                t, u, v = moller_trumbore(ot[:, rays, None], dt[:, rays, None],
                                          self._soa[:, None, ids])
                t[(t < t_min) | (t > t_max)] = np.inf
                tri_tests += len(rays) * len(ids)
                keep_nearest(t, u, v, ids, rays, best)
                continue
            # near/far order: the child nearer to the packet is visited first (pushed last)
            if d[rays, self._axes[node]].sum() >= 0:
                stack += [(right, rays), (left, rays)]
            else:
                stack += [(left, rays), (right, rays)]
        return Hits(best[0], best[1], tri_tests, box_tests)

    # -- traversal with a stack per ray (chapter 15, the fast path) ----------------------------

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
        o, d, lead = as_rays(origins, directions)
        t_min = as_t_min(t_min)
        t_max = as_t_max(t_max, t_min)
        res = self._intersect(o, d, t_min, np.full(len(o), t_max), any_hit)
        return triangle_hits(*res[:4], self._normals, lead, *res[4:])

    def _intersect(self, o, d, t_min, t_max, any_hit=False, chunk=1 << 17):
        """Traversal in chunks of rays (bounded memory); t_max is an array (p,). Returns
        ``(t, ids, u, v, triangle_tests, box_tests)``."""
        p = len(o)
        out = _empty_hits(p)
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
        # the slab test with 1/d precomputed (zero components replaced by a tiny positive
        # number: the slab of a parallel ray then spans (-huge, +huge) or lies wholly on one
        # side, as it should, with no 0 * inf); valid for t_min >= 0
        inv = 1.0 / np.where(dt == 0, 1e-300, dt)
        best = _empty_hits(p)
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
                live = stack_t[slot] <= best[0][active]  # cull: boxes beyond the nearest hit
                rays, nodes = active[live], nodes[live]
                rows = leaf_row[nodes]
                at_leaf = rows >= 0
                if at_leaf.any():                       # leaves: Möller-Trumbore
                    r = rays[at_leaf]
                    tri = table[rows[at_leaf]]                                 # (k, leaf_size)
                    t, u, v = moller_trumbore(ot[:, r, None], dt[:, r, None], self._soa[:, tri])
                    t[(t < t_min) | (t > t_max[r, None])] = np.inf
                    tri_tests += int(np.count_nonzero(tri < m))
                    rb = keep_nearest(t, u, v, tri, r, best)
                    if any_hit:
                        top[rb] = base[rb]              # done: forget the rest of the stack
                if not at_leaf.all():
                    inner = ~at_leaf
                    r, n = rays[inner], nodes[inner]
                    b = boxes[:, n]
                    o_r, i_r = ot[:, r], inv[:, r]
                    bound = np.minimum(best[0][r], t_max[r])
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
                        hit.append(t_in <= np.minimum(t_out, bound))   # and cull
                    box_tests += 2 * len(r)
                    second_first = near[1] < near[0]            # near/far: child 1 is nearer
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
        return (*best, tri_tests, box_tests)
