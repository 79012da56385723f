"""Chapter 5, hidden-surface elimination (lesson section 5): ray casting, brute force and with a
BVH.
"""

from typing import NamedTuple

import numpy as np

from .. import transforms
from .._validate import as_mesh, as_points, as_scalar, as_whole
from ._common import _camera, _triangles

__all__ = ["BVH", "Hits", "RayCastImage", "ray_cast", "ray_cast_image", "ray_triangle"]


# ---------------------------------------------------------------------------------------------
# Ray casting
# ---------------------------------------------------------------------------------------------

class Hits(NamedTuple):
    """The nearest hits of :func:`ray_cast`, with the work it took.

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
    >>> hits = ray_cast([0, 0, 5], [0, 0, -1], [[[-1, -1, 0], [1, -1, 0], [0, 1, 0]]])
    >>> hits.t.tolist(), hits.ids.tolist(), hits.triangle_tests
    ([5.0], [0], 1)
    """
    t: np.ndarray
    ids: np.ndarray
    triangle_tests: int
    box_tests: int


def _moller_trumbore(o, d, v0, e1, e2):
    """(t, u, v) of rays (o, d) against triangles (v0, e1, e2), t = inf on a miss.

    All arguments broadcast (last axis 3); see :func:`_moller_trumbore_soa`.
    """
    return _moller_trumbore_soa((o[..., 0], o[..., 1], o[..., 2]),
                                (d[..., 0], d[..., 1], d[..., 2]),
                                (v0[..., 0], v0[..., 1], v0[..., 2], e1[..., 0], e1[..., 1],
                                 e1[..., 2], e2[..., 0], e2[..., 1], e2[..., 2]))


def _moller_trumbore_soa(o, d, tri):
    """(t, u, v) of rays against triangles, component by component; t = inf on a miss.

    `o` and `d` are sequences of 3 arrays (x, y, z), `tri` a sequence of 9 arrays
    (v0, e1 = v1 - v0, e2 = v2 - v0); all broadcast. Written out per component so that each
    (ray, triangle) pair goes through the same floating-point operations whatever the batching:
    brute force and a BVH then agree bit for bit (also used by :mod:`course_lib.raytracing`).
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


def _rays(origins, directions):
    o = as_points(origins, "origins", dims=3)
    d = as_points(directions, "directions", dims=3)
    if o.ndim > 2 or d.ndim > 2:
        raise ValueError(f"origins and directions must be (p, 3) arrays or single points, got "
                         f"shapes {o.shape} and {d.shape}")
    try:
        o, d = np.broadcast_arrays(np.atleast_2d(o), np.atleast_2d(d))
    except ValueError:
        raise ValueError(f"origins ({o.shape}) and directions ({d.shape}) must hold the same "
                         "number of rays, or one of them a single one") from None
    if len(o) == 0:
        raise ValueError("origins and directions must contain at least one ray")
    if np.any(np.abs(d).max(axis=1) == 0):
        raise ValueError("directions must not contain the zero vector: a ray needs a direction")
    return np.ascontiguousarray(o), np.ascontiguousarray(d)


def _t_range(t_min, t_max):
    t_min = as_scalar(t_min, "t_min")
    t_max = np.inf if np.isscalar(t_max) and np.isposinf(t_max) else as_scalar(t_max, "t_max")
    if t_max < t_min:
        raise ValueError(f"t_max must not be below t_min (got t_min = {t_min}, t_max = {t_max})")
    return t_min, t_max


def ray_triangle(origins, directions, triangle):
    r"""Möller-Trumbore ray-triangle intersection: ray parameter and barycentric coordinates.

    Solve :math:`o + t\,d = v_0 + u\,(v_1 - v_0) + v\,(v_2 - v_0)` for :math:`(t, u, v)` by
    Cramer's rule with :math:`e_1 = v_1 - v_0`, :math:`e_2 = v_2 - v_0`, :math:`s = o - v_0`:

    .. math:: \begin{bmatrix} t \\ u \\ v \end{bmatrix} = \frac{1}{(d \times e_2) \cdot e_1}
              \begin{bmatrix} (s \times e_1) \cdot e_2 \\ (d \times e_2) \cdot s \\
              (s \times e_1) \cdot d \end{bmatrix}

    The ray hits when :math:`u, v \ge 0` and :math:`u + v \le 1` (the point is inside the
    triangle) and the determinant is not 0 (the ray is not parallel to its plane). Both sides of
    the triangle are hit (no back-face culling). About 30 multiplications, no square root.

    Parameters
    ----------
    origins, directions : array_like, shape (p, 3) or (3,)
    triangle : array_like, shape (3, 3)

    Returns
    -------
    t, u, v : ndarray, shape (p,)
        ``t`` is ``inf`` where the ray's line misses (negative ``t``, behind the origin, is
        reported: filter it as needed).

    Raises
    ------
    ValueError
        For malformed rays or triangle, or a zero direction.

    Examples
    --------
    >>> t, u, v = ray_triangle([0.25, 0.25, 2], [0, 0, -1], [[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    >>> t.tolist(), u.tolist(), v.tolist()
    ([2.0], [0.25], [0.25])
    """
    o, d = _rays(origins, directions)
    tri = _triangles(triangle, "triangle")
    if len(tri) != 1:
        raise ValueError(f"triangle must be a single triangle of shape (3, 3), got {tri.shape}")
    tri = tri[0]
    return _moller_trumbore(o, d, tri[0], tri[1] - tri[0], tri[2] - tri[0])


def _brute_force(o, d, v0, e1, e2, t_min, t_max):
    p, n = len(o), len(v0)
    best_t = np.full(p, np.inf)
    best_id = np.full(p, -1, dtype=np.intp)
    chunk = max(1, (1 << 18) // p)
    rows = np.arange(p)
    for s in range(0, n, chunk):
        t = _moller_trumbore(o[:, None], d[:, None], v0[None, s:s + chunk], e1[None, s:s + chunk],
                             e2[None, s:s + chunk])[0]
        t[(t < t_min) | (t > t_max)] = np.inf
        j = np.argmin(t, axis=1)                  # the lowest index among equal distances
        tj = t[rows, j]
        better = tj < best_t
        best_t[better] = tj[better]
        best_id[better] = j[better] + s
    return Hits(best_t, best_id, p * n, 0)


def _lower_part(key, k):
    """Boolean mask of the `k` smallest entries of `key`, ties going to the lower positions.

    O(n), like ``np.argpartition``, but deterministic: argpartition leaves ties at the k-th
    value in whatever order numpy's CPU-specific kernel produces (its AVX-512, AVX2 and
    baseline kernels differ), which changed the BVH and its test counts from one machine to the
    next. Here only the k-th *value* comes from ``np.partition``, the same on every machine.
    """
    kth = np.partition(key, k)[k]
    left = key < kth
    short = k - np.count_nonzero(left)
    if short:                                   # ties at the k-th value: the first ones go left
        left[np.flatnonzero(key == kth)[:short]] = True
    return left


class BVH:
    r"""A bounding-volume hierarchy of axis-aligned boxes over triangles, for ray casting.

    **Build** (once, :math:`O(P \log P)`): put all triangles in the root; split a node's
    triangles at the median of their box centres along the axis where those centres spread
    most (equal centres: the lower triangle index goes left, so the tree is the same on every
    machine); recurse until at most `leaf_size` triangles remain. Every node stores the box
    bounding its triangles (padded by a hair so rounding never loses a hit).

    **Traversal** (per ray): a ray that misses a node's box, or reaches it only beyond the
    nearest hit found so far, skips the whole subtree; otherwise the nearer child is visited
    first, so that hits found early prune the rest. Rays are processed together as a packet (a
    numpy array of ray indices per node), so the Python loop runs over nodes, not rays. The
    result equals brute force exactly (same nearest triangle, same distance bit for bit, the
    lowest index among equal distances); only the number of tests differs.

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
    leaf_size : int, optional
        Most triangles per leaf (default 4).

    Attributes
    ----------
    triangles : ndarray, shape (m, 3, 3)
    lo, hi : ndarray, shape (nodes, 3)
        The nodes' boxes (node 0 is the root).
    children : ndarray of int, shape (nodes, 2)
        Left and right child, -1 for leaves.
    depth : int
        Levels below the root.

    Raises
    ------
    ValueError
        For malformed triangles or a leaf size below 1.

    Examples
    --------
    >>> import numpy as np
    >>> rng = np.random.default_rng(0)
    >>> tris = rng.uniform(-1, 1, (1000, 1, 3)) + 0.05 * rng.normal(size=(1000, 3, 3))
    >>> bvh = BVH(tris)
    >>> o = np.array([[0.0, 0.0, 5.0]]); d = np.array([[0.01, 0.02, -1.0]])
    >>> fast, slow = bvh.cast(o, d), ray_cast(o, d, tris)
    >>> bool(fast.ids[0] == slow.ids[0] and fast.t[0] == slow.t[0])
    True
    >>> fast.triangle_tests < slow.triangle_tests // 20
    True
    """

    def __init__(self, triangles, leaf_size=4):
        tris = _triangles(triangles, "triangles")
        leaf_size = as_whole(leaf_size, "leaf_size", 1)
        self.triangles = tris
        self._v0 = np.ascontiguousarray(tris[:, 0])
        self._e1 = tris[:, 1] - tris[:, 0]
        self._e2 = tris[:, 2] - tris[:, 0]
        tmin, tmax = tris.min(axis=1), tris.max(axis=1)
        centre = (tmin + tmax) / 2
        pad = 1e-9 * max(float(np.abs(tris).max()), 1e-300)
        order = np.arange(len(tris))
        lo, hi, children, axes, spans = [], [], [], [], []

        def new_node():
            lo.append(None), hi.append(None), children.append([-1, -1]), axes.append(0)
            spans.append((0, 0))
            return len(lo) - 1

        depth = 0
        stack = [(new_node(), 0, len(tris), 0)]
        while stack:
            node, s, e, level = stack.pop()
            depth = max(depth, level)
            idx = order[s:e]
            lo[node] = tmin[idx].min(axis=0) - pad
            hi[node] = tmax[idx].max(axis=0) + pad
            if e - s <= leaf_size:
                order[s:e] = np.sort(idx)           # lowest index first within a leaf
                spans[node] = (s, e)
                continue
            c = centre[idx]
            axis = int(np.argmax(c.max(axis=0) - c.min(axis=0)))
            mid = (s + e) // 2
            # idx is in ascending triangle index (each side keeps its order), so equal
            # centres send the lower triangle index left
            lower = _lower_part(c[:, axis], mid - s)
            order[s:mid], order[mid:e] = idx[lower], idx[~lower]
            left, right = new_node(), new_node()
            children[node] = [left, right]
            axes[node] = axis
            stack.append((right, mid, e, level + 1))
            stack.append((left, s, mid, level + 1))
        self.lo, self.hi = np.array(lo), np.array(hi)
        self.children = np.array(children, dtype=np.intp)
        self._axes = np.array(axes)
        self._spans = np.array(spans, dtype=np.intp)
        self._order = order
        self.depth = depth

    def __repr__(self):
        return (f"BVH({len(self.triangles)} triangles, {len(self.lo)} nodes, "
                f"depth {self.depth})")

    def cast(self, origins, directions, t_min=0.0, t_max=np.inf):
        """Nearest hits of many rays: as :func:`ray_cast` with ``accelerate=True``.

        Parameters
        ----------
        origins, directions : array_like, shape (p, 3) or (3,)
        t_min, t_max : float, optional
            Only hits with ``t_min <= t <= t_max`` count.

        Returns
        -------
        Hits

        Examples
        --------
        >>> bvh = BVH([[[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[-1, -1, 2], [1, -1, 2], [0, 1, 2]]])
        >>> bvh.cast([[0, 0, 5], [0, 0, -5]], [0, 0, -1]).ids.tolist()
        [1, -1]
        """
        o, d = _rays(origins, directions)
        t_min, t_max = _t_range(t_min, t_max)
        return self._cast(o, d, t_min, t_max)

    def _cast(self, o, d, t_min, t_max):
        p = len(o)
        best_t = np.full(p, np.inf)
        best_id = np.full(p, -1, dtype=np.intp)
        tri_tests = box_tests = 0
        stack = [(0, np.arange(p))]
        while stack:
            node, rays = stack.pop()
            box_tests += len(rays)
            ro, rd = o[rays], d[rays]
            with np.errstate(divide="ignore", invalid="ignore"):
                t1 = (self.lo[node] - ro) / rd
                t2 = (self.hi[node] - ro) / rd
            near, far = np.minimum(t1, t2), np.maximum(t1, t2)
            parallel = rd == 0                          # inside the slab: all t; else none
            within = (ro >= self.lo[node]) & (ro <= self.hi[node])
            near = np.where(parallel, np.where(within, -np.inf, np.inf), near)
            far = np.where(parallel, np.where(within, np.inf, -np.inf), far)
            t_in, t_out = near.max(axis=1), far.min(axis=1)
            ok = (t_in <= t_out) & (t_out >= t_min) & (t_in <= np.minimum(best_t[rays], t_max))
            rays = rays[ok]
            if len(rays) == 0:
                continue
            left, right = self.children[node]
            if left < 0:
                s, e = self._spans[node]
                ids = self._order[s:e]
                t = _moller_trumbore(o[rays][:, None], d[rays][:, None], self._v0[ids][None],
                                     self._e1[ids][None], self._e2[ids][None])[0]
                t[(t < t_min) | (t > t_max)] = np.inf
                tri_tests += len(rays) * len(ids)
                j = np.argmin(t, axis=1)
                tj, idj = t[np.arange(len(rays)), j], ids[j]
                cur_t, cur_id = best_t[rays], best_id[rays]
                better = (tj < cur_t) | ((tj == cur_t) & (idj < cur_id) & np.isfinite(tj))
                best_t[rays[better]] = tj[better]
                best_id[rays[better]] = idj[better]
                continue
            # visit the child nearer to the packet first (pushed last)
            if d[rays, self._axes[node]].sum() >= 0:
                stack += [(right, rays), (left, rays)]
            else:
                stack += [(left, rays), (right, rays)]
        return Hits(best_t, best_id, tri_tests, box_tests)


def ray_cast(origins, directions, triangles, t_min=0.0, t_max=np.inf, accelerate=False):
    r"""Ray casting: the nearest triangle along each ray.

    Brute force tests every ray against every triangle (:func:`ray_triangle`) and keeps the
    smallest :math:`t` in :math:`[t_{min}, t_{max}]`: exactly :math:`p \cdot P` tests for
    :math:`p` rays and :math:`P` triangles, the textbook's :math:`O(pP)`. Vectorized over rays
    and blocks of triangles. With ``accelerate=True`` a :class:`BVH` is built first (or pass a
    ready-made :class:`BVH` as `triangles` to reuse it across frames) and most tests are skipped;
    the answer is identical. Equal distances go to the lower triangle index.

    Parameters
    ----------
    origins, directions : array_like, shape (p, 3) or (3,)
        The rays ``origin + t * direction``; one origin (or direction) is shared by all rays.
    triangles : array_like, shape (m, 3, 3), or BVH
    t_min, t_max : float, optional
        Only hits with ``t_min <= t <= t_max`` count (default: in front of the origin).
    accelerate : bool, optional
        Use a bounding-volume hierarchy.

    Returns
    -------
    Hits
        ``t``, ``ids``, and the numbers of ``triangle_tests`` and ``box_tests`` performed.

    Raises
    ------
    ValueError
        For malformed or empty rays or triangles, a zero direction, or ``t_max < t_min``.

    Examples
    --------
    Two parallel triangles; the ray from above hits the upper one at distance 3:

    >>> tris = [[[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[-1, -1, 2], [1, -1, 2], [0, 1, 2]]]
    >>> hits = ray_cast([[0, 0, 5], [9, 9, 5]], [0, 0, -1], tris)
    >>> hits.t.tolist(), hits.ids.tolist(), hits.triangle_tests      # 2 rays x 2 triangles
    ([3.0, inf], [1, -1], 4)
    """
    o, d = _rays(origins, directions)
    t_min, t_max = _t_range(t_min, t_max)
    if isinstance(triangles, BVH):
        return triangles._cast(o, d, t_min, t_max)
    if accelerate:
        return BVH(triangles)._cast(o, d, t_min, t_max)
    tris = _triangles(triangles, "triangles")
    return _brute_force(o, d, tris[:, 0], tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0],
                        t_min, t_max)


class RayCastImage(NamedTuple):
    """The result of :func:`ray_cast_image`: one ray per pixel, row 0 at the bottom.

    Attributes
    ----------
    depth : ndarray, shape (height, width)
        Viewport depth in [0, 1] of the visible surface, as the z-buffer stores it; inf on
        background.
    ids : ndarray of int, shape (height, width)
        Index of the visible face, -1 for background.
    triangle_tests, box_tests : int
        The work done (see :class:`Hits`).

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import viewing
    >>> V = viewing.look_at([0, 0, 3], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    >>> tri = [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]
    >>> ray_cast_image(tri, [[0, 1, 2]], V, P, 4, 4, accelerate=False).triangle_tests  # 16 x 1
    16
    """
    depth: np.ndarray
    ids: np.ndarray
    triangle_tests: int
    box_tests: int


def _pixel_rays(pv, width, height):
    """World rays through the pixel centres, from the near plane (t = 0) to the far (t = 1)."""
    i = (np.arange(width) + 0.5) * 2 / width - 1
    j = (np.arange(height) + 0.5) * 2 / height - 1
    x, y = np.meshgrid(i, j)
    inv = np.linalg.inv(pv)
    near = transforms.apply(inv, np.stack([x, y, -np.ones_like(x)], axis=-1).reshape(-1, 3))
    far = transforms.apply(inv, np.stack([x, y, np.ones_like(x)], axis=-1).reshape(-1, 3))
    return near, far - near


def ray_cast_image(vertices, faces, view, projection, width, height, accelerate=True):
    r"""Hidden-surface elimination by ray casting: the visible face at each pixel centre.

    For every pixel the ray through its centre is built by undoing the viewing pipeline
    (the inverse of `projection` @ `view` applied to the pixel's points on the near and far
    planes), so the ray covers exactly the view volume's depth range, as the z-buffer's clipping
    does. The nearest hit is found by :func:`ray_cast` and its depth mapped back to the
    viewport's [0, 1]. The result agrees with :func:`render_depth` (ids, and depths to rounding)
    at every pixel whose centre does not lie on an edge.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    view, projection : array_like, shape (4, 4)
    width, height : int
    accelerate : bool, optional
        Use a :class:`BVH` (default True; False shows the brute-force cost).

    Returns
    -------
    RayCastImage

    Raises
    ------
    ValueError
        For malformed input or a singular camera.

    Examples
    --------
    >>> from course_lib.visibility import render_depth
    >>> import numpy as np
    >>> from course_lib import viewing
    >>> V = viewing.look_at([0, 0, 3], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    >>> square = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    >>> faces = [[0, 1, 2], [0, 2, 3]]
    >>> rc = ray_cast_image(square, faces, V, P, 8, 8, accelerate=False)
    >>> zb = render_depth(square, faces, V, P, 8, 8)
    >>> bool(np.all(rc.ids == zb.ids)), bool(np.allclose(rc.depth[2:6, 2:6], zb.depth[2:6, 2:6]))
    (True, True)
    """
    v, f = as_mesh(vertices, faces)
    view, projection = _camera(view, projection)
    width, height = as_whole(width, "width", 1), as_whole(height, "height", 1)
    pv = projection @ view
    if abs(np.linalg.det(pv)) < 1e-300:
        raise ValueError("projection @ view is singular: the camera cannot be inverted into rays")
    origins, directions = _pixel_rays(pv, width, height)
    hits = ray_cast(origins, directions, v[f], t_min=0.0, t_max=1.0, accelerate=accelerate)
    depth = np.full(len(origins), np.inf)
    hit = hits.ids >= 0
    points = origins[hit] + hits.t[hit, None] * directions[hit]
    depth[hit] = (transforms.apply(pv, points)[:, 2] + 1) / 2
    return RayCastImage(depth.reshape(height, width), hits.ids.reshape(height, width),
                        hits.triangle_tests, hits.box_tests)
