r"""Chapter 10.3, data transformations: interpolating scattered data.

Scattered data are values :math:`f_i` at positions :math:`x_i` with no grid and no cells
(weather stations, boreholes, GPS tracks). To draw them as a field, contour them or take
derivatives, we need a function :math:`s(x)` defined everywhere with :math:`s(x_i) = f_i`
(an *interpolant*), usually evaluated on a grid (*resampling*). Four classic answers:

* **nearest neighbour**: :math:`s(x) = f_j` for the closest :math:`x_j`; constant on the
  Voronoi cell of each point, so it jumps at the cells' borders.
* **linear on a triangulation**: connect the points into triangles (the Delaunay
  triangulation: no point inside any triangle's circumcircle, which avoids thin triangles) and
  interpolate linearly in each; continuous, but with creases along the edges, and undefined
  outside the convex hull of the points.
* **Shepard's inverse-distance weighting**: a weighted average
  :math:`s(x) = \sum_i w_i f_i / \sum_i w_i` with :math:`w_i = 1/d_i^p`; defined everywhere,
  never beyond the data's range, flat spots at the data points (for p > 1).
* **radial basis functions**: :math:`s(x) = \sum_i \lambda_i\,\phi(\lVert x - x_i\rVert)`
  (plus a low-degree polynomial), the coefficients from the linear system
  :math:`s(x_j) = f_j`; smooth, but may overshoot the data, and the system is dense.

Input rules (checked by every function): points ``(n, 2)`` or ``(n, 3)``, values ``(n,)`` or
``(n, k)`` of the same length, all finite (NaN is refused: drop missing samples first). A
position that occurs twice with **the same** value is merged into one sample (it adds nothing);
with **different** values it is refused: an interpolant cannot take two values at one point.

Size: every method here is vectorised and bounds its memory (the distance matrix is built in
chunks). Shepard's global form costs n x m distances (10,000 points on a 100 x 100 grid: 10^8,
well under a second). A *global* RBF needs the dense n x n system: at n = 10,000 that is 800 MB and
about 3 x 10^11 operations, so :func:`rbf_interpolate` refuses more than
:data:`MAX_GLOBAL_RBF_CENTRES` centres and asks for ``neighbors=k``: the local form, which for
each query point fits an RBF to its k nearest data points only (as scipy's
``RBFInterpolator(neighbors=k)`` does; scipy without ``neighbors`` builds the same dense
system and hits the same wall).
"""
from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_choice, as_points, as_positive, as_whole
from ..scivis import gradient
from ._buckets import _k_nearest, _pairs_within
from .grids import triangle_interpolate, uniform_grid

__all__ = [
    "MAX_GLOBAL_RBF_CENTRES",
    "RBF_KERNELS",
    "RBFModel",
    "SCATTERED_METHODS",
    "delaunay_triangulation",
    "gradient_magnitude",
    "linear_interpolate",
    "nearest_interpolate",
    "rbf_evaluate",
    "rbf_fit",
    "rbf_interpolate",
    "rbf_kernel",
    "resample_to_grid",
    "scattered_data",
    "scattered_interpolate",
    "shepard_interpolate",
]

#: The interpolation methods for scattered data.
SCATTERED_METHODS = ("nearest", "linear", "shepard", "rbf")
#: The radial basis functions, named as scipy names them.
RBF_KERNELS = ("gaussian", "multiquadric", "inverse_multiquadric", "thin_plate_spline")
#: The most centres a global RBF accepts (a dense system of this size: 72 MB, well under a
#: second); beyond, use the local form ``neighbors=k``.
MAX_GLOBAL_RBF_CENTRES = 3000

_CHUNK = 2_000_000             # distance-matrix entries computed at once


# ---------------------------------------------------------------------------------------------
# Input
# ---------------------------------------------------------------------------------------------

def scattered_data(points, values):
    """Check scattered data and merge repeated samples: the input rule of this module.

    Parameters
    ----------
    points : array_like, shape (n, 2) or (n, 3)
    values : array_like, shape (n,) or (n, k)

    Returns
    -------
    points : ndarray, shape (n', d)
    values : ndarray, shape (n',) or (n', k)
        Without repeats: a position given twice with the same value is kept once (its first
        occurrence; the order is otherwise kept).

    Raises
    ------
    ValueError
        For NaN or infinite entries, mismatched lengths, or one position with two different
        values.

    Examples
    --------
    >>> p, v = scattered_data([[0, 0], [1, 0], [0, 0]], [5.0, 6.0, 5.0])
    >>> p.tolist(), v.tolist()
    ([[0.0, 0.0], [1.0, 0.0]], [5.0, 6.0])
    >>> scattered_data([[0, 0], [1, 0], [0, 0]], [5.0, 6.0, 7.0])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: points 0 and 2 are the same position (0, 0) with different values 5 and 7: ...
    """
    p = _finite_data(points, "points")
    if p.ndim != 2 or p.shape[1] not in (2, 3) or len(p) < 1:
        raise ValueError(f"points must have shape (n, 2) or (n, 3), got shape {p.shape}")
    v = _finite_data(values, "values")
    if v.ndim not in (1, 2) or len(v) != len(p):
        raise ValueError(f"values must have one entry (or row) per point: {len(p)} points but "
                         f"values of shape {v.shape}")
    _, first, inverse, counts = np.unique(p, axis=0, return_index=True, return_inverse=True,
                                          return_counts=True)
    inverse = inverse.ravel()
    if (counts > 1).any():
        rows = v.reshape(len(v), -1)
        same = np.all(rows == rows[first[inverse]], axis=1)
        if not same.all():
            j = int(np.flatnonzero(~same)[0])
            i = int(first[inverse[j]])
            where = ", ".join(f"{c:g}" for c in p[j])
            a, b = (", ".join(f"{x:g}" for x in rows[k]) for k in (i, j))
            raise ValueError(f"points {i} and {j} are the same position ({where}) with "
                             f"different values {a} and {b}: an interpolant cannot take two "
                             "values at one point (average them, or drop one)")
        keep = np.sort(first)
        return p[keep], v[keep]
    return p, v


def _finite_data(value, name):
    arr = np.asarray(value) if not isinstance(value, (str, bytes)) else value
    if isinstance(arr, np.ndarray) and arr.dtype.kind == "f" and np.isnan(arr).any():
        where = np.argwhere(np.isnan(arr))[0]
        raise ValueError(f"{name} contains NaN (a missing sample?) at index "
                         f"{tuple(int(i) for i in where)}: drop the missing samples before "
                         "interpolating")
    return as_array(value, name)


def _query_points(query, d):
    q = as_points(query, "query", dims=d)
    return q, q.reshape(-1, d)


# ---------------------------------------------------------------------------------------------
# Nearest neighbour
# ---------------------------------------------------------------------------------------------

def nearest_interpolate(points, values, query):
    """Nearest-neighbour interpolation: each query takes the value of its closest data point.

    The result is constant on the Voronoi cell of each data point. A query exactly as far
    from two points takes the one given first.

    Parameters
    ----------
    points : array_like, shape (n, d)
    values : array_like, shape (n,) or (n, k)
    query : array_like, shape (..., d)

    Returns
    -------
    ndarray, shape query.shape[:-1] (+ (k,))

    Examples
    --------
    >>> nearest_interpolate([[0, 0], [4, 0], [0, 4]], [1.0, 2.0, 3.0], [[1, 1], [3, 1], [2, 2]])
    array([1., 2., 1.])
    """
    p, v = scattered_data(points, values)
    q, flat = _query_points(query, p.shape[1])
    index, _ = _k_nearest(p, flat, 1)
    out = v[index[:, 0]]
    return out.reshape(q.shape[:-1] + v.shape[1:])


# ---------------------------------------------------------------------------------------------
# Delaunay triangulation and linear interpolation
# ---------------------------------------------------------------------------------------------

def _orient_2d(a, b, p):
    """Twice the signed area of (a, b, p): > 0 when p is left of a -> b."""
    return (b[..., 0] - a[..., 0]) * (p[..., 1] - a[..., 1]) \
        - (b[..., 1] - a[..., 1]) * (p[..., 0] - a[..., 0])


def _incircle(a, b, c, p):
    """> 0 when p is strictly inside the circumcircle of the counter-clockwise (a, b, c)."""
    ad, bd, cd = a - p, b - p, c - p
    la, lb, lc = (np.sum(x * x, axis=-1) for x in (ad, bd, cd))
    return (la * (bd[..., 0] * cd[..., 1] - cd[..., 0] * bd[..., 1])
            + lb * (cd[..., 0] * ad[..., 1] - ad[..., 0] * cd[..., 1])
            + lc * (ad[..., 0] * bd[..., 1] - bd[..., 0] * ad[..., 1]))


def delaunay_triangulation(points):
    r"""The Delaunay triangulation of 2D points, by the Bowyer-Watson algorithm.

    A triangulation is Delaunay when no point lies inside the circumcircle of any triangle;
    of all triangulations it maximises the smallest angle (few thin triangles), and it is
    unique when no four points lie on one circle. Bowyer-Watson builds it by inserting the
    points one at a time:

    1. find the triangles whose circumcircle contains the new point (they are no longer
       Delaunay);
    2. remove them: they form a star-shaped hole around the point;
    3. connect the point to every edge of the hole's border.

    Points outside the current hull are handled with *ghost triangles*: each hull edge has an
    imaginary triangle to a vertex at infinity, whose "circumcircle" is the open half-plane
    outside the edge. (The classic variant with a big super-triangle can miss hull edges.)
    Every step is vectorised over the triangles; the whole costs O(n^2) at worst, fine for a
    few thousand points.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        At least 3 distinct points, not all on one line.

    Returns
    -------
    ndarray of intp, shape (m, 3)
        Corner indices of the triangles, each counter-clockwise.

    Raises
    ------
    ValueError
        For fewer than 3 points, repeated points, points all on a line, or NaN.

    Examples
    --------
    >>> tris = delaunay_triangulation([[0, 0], [2, 0], [2, 1], [0, 1.2]])
    >>> sorted(tuple(sorted(t)) for t in tris.tolist())
    [(0, 1, 2), (0, 2, 3)]
    """
    p = _finite_data(points, "points")
    if p.ndim != 2 or p.shape[1] != 2 or len(p) < 3:
        raise ValueError(f"points must have shape (n, 2) with n >= 3 for a triangulation, got "
                         f"shape {p.shape}")
    if len(np.unique(p, axis=0)) != len(p):
        raise ValueError("points must be distinct: a repeated position cannot be a corner of "
                         "two triangles at once (merge repeated samples first, see "
                         "scattered_data)")
    n = len(p)
    area = _orient_2d(p[0], p[1], p[2:])
    scale = np.ptp(p, axis=0).max() ** 2
    off = np.flatnonzero(np.abs(area) > 1e-12 * scale)
    if off.size == 0:
        raise ValueError("all points lie on one line: they have no triangulation")
    k = int(off[0]) + 2
    a, b = (0, 1) if area[k - 2] > 0 else (1, 0)
    # vertex -1 is the vertex at infinity; a ghost triangle keeps it last
    tri = np.array([[a, b, k], [b, a, -1], [k, b, -1], [a, k, -1]], dtype=np.intp)
    # the triangles live in buffers that grow by doubling; `used` rows are filled
    store = _TriangleStore(p, tri, capacity=2 * n + 16)
    for i in range(n):
        if i not in (0, 1, k):
            _bowyer_watson_insert(p, store, i)
    tri = store.tri[:store.used]
    return tri[store.alive[:store.used] & (tri[:, 2] >= 0)]


class _TriangleStore:
    """The triangles of a Bowyer-Watson run (corners, alive flags, circumcircles) in buffers."""

    def __init__(self, p, tri, capacity):
        self.tri = np.zeros((capacity, 3), dtype=np.intp)
        self.alive = np.zeros(capacity, dtype=bool)
        self.centre = np.zeros((capacity, 2))
        self.r2 = np.zeros(capacity)
        self.used = 0
        self.add(p, tri)

    def add(self, p, new):
        end = self.used + len(new)
        if end > len(self.tri):
            keep = self.alive[:self.used]              # compact, then grow if still needed
            live = int(keep.sum())
            size = max(len(self.tri), 2 * (live + len(new)))
            for name in ("tri", "centre", "r2"):
                old = getattr(self, name)[:self.used][keep]
                buffer = np.zeros((size,) + old.shape[1:], dtype=old.dtype)
                buffer[:live] = old
                setattr(self, name, buffer)
            self.alive = np.zeros(size, dtype=bool)
            self.alive[:live] = True
            self.used, end = live, live + len(new)
        self.tri[self.used:end] = new
        self.alive[self.used:end] = True
        self.centre[self.used:end], self.r2[self.used:end] = _circumcircles(p, new)
        self.used = end


def _circumcircles(p, tri):
    """Centres and squared radii of the triangles' circumcircles (ghosts: everywhere)."""
    centre = np.zeros((len(tri), 2))
    r2 = np.full(len(tri), np.inf)
    real = tri[:, 2] >= 0
    if real.any():
        a, b, c = (p[tri[real, k]] for k in range(3))
        ab, ac = b - a, c - a
        d = 2 * (ab[:, 0] * ac[:, 1] - ab[:, 1] * ac[:, 0])
        lb = ab[:, 0] * ab[:, 0] + ab[:, 1] * ab[:, 1]
        lc = ac[:, 0] * ac[:, 0] + ac[:, 1] * ac[:, 1]
        ox = (ac[:, 1] * lb - ab[:, 1] * lc) / d
        oy = (ab[:, 0] * lc - ac[:, 0] * lb) / d
        centre[real, 0] = a[:, 0] + ox
        centre[real, 1] = a[:, 1] + oy
        r2[real] = ox * ox + oy * oy
    return centre, r2


def _bowyer_watson_insert(p, store, i):
    """Bowyer-Watson step: insert point i into the triangles of `store`."""
    q = p[i]
    used = store.used
    centre, r2 = store.centre[:used], store.r2[:used]
    gap = (centre[:, 0] - q[0]) ** 2 + (centre[:, 1] - q[1]) ** 2
    near = np.flatnonzero(store.alive[:used] & (gap <= r2 * (1 + 1e-6) + 1e-300))
    t = store.tri[near]
    ghost = t[:, 2] < 0
    conflict = np.zeros(len(t), dtype=bool)
    real = ~ghost
    if real.any():                                  # the exact test on the candidates
        tr = t[real]
        conflict[real] = _incircle(p[tr[:, 0]], p[tr[:, 1]], p[tr[:, 2]], q) > 0
    if ghost.any():
        tg = t[ghost]
        a, b = p[tg[:, 0]], p[tg[:, 1]]
        side = _orient_2d(a, b, q)
        ab, aq = b - a, q - a
        along = aq[:, 0] * ab[:, 0] + aq[:, 1] * ab[:, 1]
        between = (side == 0) & (along > 0) & (along < ab[:, 0] ** 2 + ab[:, 1] ** 2)
        conflict[ghost] = (side > 0) | between
    bad = near[conflict]
    if bad.size == 0:
        raise ValueError(f"point {i} could not be inserted (it repeats a point or the "
                         "predicates failed in rounding): jitter the points slightly")
    cavity = store.tri[bad]
    edges = np.concatenate([cavity[:, [0, 1]], cavity[:, [1, 2]], cavity[:, [2, 0]]])
    n1 = len(p) + 1
    key = (edges[:, 0] + 1) * n1 + (edges[:, 1] + 1)
    reverse = (edges[:, 1] + 1) * n1 + (edges[:, 0] + 1)
    border = edges[~(reverse[:, None] == key[None, :]).any(axis=1)]   # edges met once
    starts, ends = border[:, 0].tolist(), border[:, 1].tolist()
    if len(set(starts)) != len(starts) or len(set(ends)) != len(ends):
        raise ValueError(f"point {i}: the cavity of the Bowyer-Watson step is not a simple "
                         "polygon (points nearly on one circle, beyond the precision of the "
                         "tests): jitter the points slightly")
    new = np.column_stack([border, np.full(len(border), i)])
    first_ghost = new[:, 0] < 0                     # (-1, b, i) -> (b, i, -1)
    new[first_ghost] = new[first_ghost][:, [1, 2, 0]]
    second_ghost = new[:, 1] < 0                    # (a, -1, i) -> (i, a, -1)
    new[second_ghost] = new[second_ghost][:, [2, 0, 1]]
    store.alive[bad] = False
    store.add(p, new)


def linear_interpolate(points, values, query, triangles=None, outside="raise"):
    r"""Piecewise-linear interpolation on a triangulation of the scattered points.

    Inside each triangle the interpolant is the plane through its three samples (barycentric
    weights, :func:`course_lib.dataviz.triangle_interpolate`). By default the triangulation
    is the Delaunay triangulation of the points; give `triangles` to use another. Outside the
    convex hull of the points there is no triangle and no value.

    Parameters
    ----------
    points : array_like, shape (n, 2)
    values : array_like, shape (n,) or (n, k)
    query : array_like, shape (..., 2)
    triangles : array_like of int, shape (m, 3), optional
        Corner indices into `points` (after merging repeated samples: give distinct points).
    outside : "raise" or float
        Queries outside the triangulation: an error (default) or this fill value
        (``np.nan`` allowed, as an explicit choice).

    Returns
    -------
    ndarray, shape query.shape[:-1] (+ (k,))

    Examples
    --------
    >>> pts = [[0, 0], [4, 0], [0, 4], [4, 4]]
    >>> linear_interpolate(pts, [0.0, 4.0, 4.0, 8.0], [[1, 2], [3, 3]])      # f = x + y
    array([3., 6.])
    >>> linear_interpolate(pts, [0.0, 4.0, 4.0, 8.0], [[5, 5]], outside=-1.0)
    array([-1.])
    """
    p, v = scattered_data(points, values)
    if p.shape[1] != 2:
        raise ValueError("linear_interpolate triangulates 2D points, shape (n, 2)")
    if triangles is None:
        tri = delaunay_triangulation(p)
    else:
        if len(p) != len(np.asarray(points)):
            raise ValueError("triangles refer to the points as given, but some points repeat: "
                             "remove the repeats (scattered_data) before triangulating")
        tri = triangles
    return triangle_interpolate(p, tri, v, query, outside)


# ---------------------------------------------------------------------------------------------
# Shepard's inverse-distance weighting
# ---------------------------------------------------------------------------------------------

def shepard_interpolate(points, values, query, power=2.0, radius=None, outside="raise"):
    r"""Shepard's inverse-distance weighting, global or local (modified).

    Global: every data point contributes, weighted by its inverse distance to the power p,

    .. math:: s(x) = \frac{\sum_i w_i(x)\, f_i}{\sum_i w_i(x)}, \qquad
              w_i(x) = \frac{1}{d_i(x)^p},\quad d_i(x) = \lVert x - x_i \rVert,

    and :math:`s(x_i) = f_i` (the weight of a point grows without bound as x approaches it).
    Dividing by the sum of the weights makes them sum to 1, so s never leaves the range of the
    data. Small p (1 or less) gives cusps at the data points and lets far points pull
    everything towards the overall mean; p > 1 gives flat spots (zero gradient) at the data
    points; large p approaches nearest-neighbour interpolation.

    Local (modified Shepard, Franke and Little): only the points within `radius` R count,
    with weights that fall to 0 at the edge of the disc,

    .. math:: w_i(x) = \left(\frac{(R - d_i)_+}{R\, d_i}\right)^p,

    which makes the interpolant local (a sample affects only its neighbourhood) and cheaper.

    Parameters
    ----------
    points : array_like, shape (n, d)
    values : array_like, shape (n,) or (n, k)
    query : array_like, shape (..., d)
    power : float
        p > 0.
    radius : float, optional
        R > 0 for the local form; None (default) for the global one.
    outside : "raise" or float
        Local form only: queries with no data point within R: an error, or this fill value.

    Returns
    -------
    ndarray, shape query.shape[:-1] (+ (k,))

    Raises
    ------
    ValueError
        For p <= 0, a bad radius, bad data, or (local form) a query with no point within R.

    Examples
    --------
    >>> pts, f = [[1, 0], [0, 2], [-4, 0]], [7.0, 3.0, 1.0]
    >>> shepard_interpolate(pts, f, [[0, 0]], power=1)    # d = 1, 2, 4: (7 + 3/2 + 1/4) / (7/4)
    array([5.])
    >>> shepard_interpolate(pts, f, [[0, 2]])             # at a data point: its value
    array([3.])
    >>> shepard_interpolate(pts, f, [[0, 0]], power=0)
    Traceback (most recent call last):
    ...
    ValueError: power must be positive (the p of the weights 1/d^p), got 0
    """
    p_exp = as_positive(power, "power", "the p of the weights 1/d^p")
    p, v = scattered_data(points, values)
    q, flat = _query_points(query, p.shape[1])
    rows = v.reshape(len(v), -1)
    if radius is None:
        out = _shepard_global(p, rows, flat, p_exp)
    else:
        r = as_positive(radius, "radius", "the radius of the local form")
        policy = _scattered_fill_policy(outside)
        out = _shepard_local(p, rows, flat, p_exp, r, policy)
    return out.reshape(q.shape[:-1] + v.shape[1:])


def _scattered_fill_policy(outside):
    if isinstance(outside, str):
        return as_choice(outside, "outside", ("raise",))
    if isinstance(outside, (bool, np.bool_)) or not isinstance(outside, (int, float)):
        raise TypeError(f"outside must be 'raise' or a number to fill with, got {outside!r}")
    return float(outside)


def _shepard_global(p, rows, flat, power):
    m = len(flat)
    out = np.empty((m, rows.shape[1]))
    step = max(1, _CHUNK // len(p))
    for start in range(0, m, step):
        q = flat[start:start + step]
        d2 = _squared_distances(q, p)
        nearest = d2.min(axis=1, keepdims=True)
        hit = nearest[:, 0] == 0
        # weights divided by the largest one: (d_min / d_i)^p in (0, 1], no overflow
        with np.errstate(divide="ignore", invalid="ignore"):
            w = (np.where(hit[:, None], 0.0, nearest) / d2) ** (power / 2)
        w[hit] = (d2[hit] == 0).astype(float)
        out[start:start + step] = (w @ rows) / w.sum(axis=1, keepdims=True)
    return out


def _shepard_local(p, rows, flat, power, radius, policy):
    qi, pj, d2 = _pairs_within(p, flat, radius)
    d = np.sqrt(d2)
    m = len(flat)
    hit = d == 0
    t = np.where(hit, np.inf, (radius - d) / (radius * np.where(hit, 1.0, d)))
    has = np.bincount(qi, minlength=m) > 0
    top = np.zeros(m)
    np.maximum.at(top, qi, t)
    exact = np.isinf(top)
    safe = np.where(exact | (top == 0), 1.0, top)
    w = (t / safe[qi]) ** power
    w = np.where(exact[qi], hit.astype(float), w)
    total = np.bincount(qi, weights=w, minlength=m).astype(float)
    out = np.stack([np.bincount(qi, weights=w * rows[pj, c], minlength=m)
                    for c in range(rows.shape[1])], axis=1).astype(float)
    found = has & (total > 0)
    out[found] /= total[found, None]
    if not found.all():
        if policy == "raise":
            raise ValueError(f"{int((~found).sum())} query point(s) have no data point within "
                             f"radius {radius:g}: increase the radius, or pass outside=<a fill "
                             "value>")
        out[~found] = policy
    return out


# ---------------------------------------------------------------------------------------------
# Radial basis functions
# ---------------------------------------------------------------------------------------------

def rbf_kernel(r, kernel="gaussian", epsilon=1.0):
    r"""A radial basis function :math:`\phi(\varepsilon r)` at distances r.

    ==================== ==========================================
    ``gaussian``         :math:`e^{-(\varepsilon r)^2}`
    ``multiquadric``     :math:`\sqrt{1 + (\varepsilon r)^2}`
    ``inverse_multiquadric`` :math:`1 / \sqrt{1 + (\varepsilon r)^2}`
    ``thin_plate_spline`` :math:`(\varepsilon r)^2 \ln(\varepsilon r)` (0 at r = 0)
    ==================== ==========================================

    The shape parameter :math:`\varepsilon` sets the width: a small one gives wide, flat bumps
    (smooth, but the linear system becomes nearly singular), a large one narrow spikes. (scipy's
    multiquadric is :math:`-\sqrt{1 + (\varepsilon r)^2}`: the interpolant is the same.)

    Parameters
    ----------
    r : array_like
        Distances, >= 0.
    kernel : str
        One of :data:`RBF_KERNELS`.
    epsilon : float
        The shape parameter, > 0.

    Returns
    -------
    ndarray, shaped like r

    Examples
    --------
    >>> rbf_kernel([0.0, 1.0], "gaussian", 2.0).round(6)
    array([1.      , 0.018316])
    >>> rbf_kernel([0.0, 1.0, np.e], "thin_plate_spline").round(6)
    array([0.      , 0.      , 7.389056])
    >>> rbf_kernel([1.0], "cubic")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: kernel must be one of 'gaussian', 'multiquadric', ... got 'cubic'
    """
    name = as_choice(kernel, "kernel", RBF_KERNELS)
    eps = as_positive(epsilon, "epsilon", "the shape parameter")
    r = as_array(r, "r")
    if (r < 0).any():
        raise ValueError("r must be distances (>= 0)")
    return _rbf_phi((r * eps) ** 2, name)


def _rbf_phi(s2, name):
    """The kernel at squared scaled distances s2 = (eps r)^2, in place where it can (s2 is
    consumed): no square root for the Gaussian and the thin-plate spline."""
    if name == "gaussian":
        np.negative(s2, out=s2)
        return np.exp(s2, out=s2)
    if name in ("multiquadric", "inverse_multiquadric"):
        s2 += 1.0
        np.sqrt(s2, out=s2)
        return s2 if name == "multiquadric" else np.reciprocal(s2, out=s2)
    out = np.zeros_like(s2)                           # r^2 ln r = s2 ln(s2) / 2, 0 at r = 0
    np.log(s2, out=out, where=s2 > 0)
    out *= s2
    out *= 0.5
    return out


class RBFModel(NamedTuple):
    """A fitted radial-basis-function interpolant (see :func:`rbf_fit`).

    Attributes
    ----------
    centres : ndarray, shape (n, d)
    weights : ndarray, shape (n, k)
        The coefficients :math:`\\lambda_i` of the basis functions.
    poly : ndarray, shape (m, k)
        The coefficients of the polynomial term (m = 0, 1 or d + 1).
    kernel : str
    epsilon : float
    degree : int
        -1 (no polynomial), 0 (a constant) or 1 (linear).
    shift, scale : ndarray
        The polynomial is in the coordinates ``(x - shift) / scale`` (for a well-conditioned
        system; the interpolant does not depend on them).
    value_shape : tuple
        ``()`` for scalar values, ``(k,)`` for rows of k values.

    Examples
    --------
    >>> m = rbf_fit([[0, 0], [1, 0], [0, 1]], [1.0, 2.0, 3.0], "gaussian", 1.0)
    >>> m.weights.shape, m.poly.shape, m.degree
    ((3, 1), (0, 1), -1)
    """

    centres: np.ndarray
    weights: np.ndarray
    poly: np.ndarray
    kernel: str
    epsilon: float
    degree: int
    shift: np.ndarray
    scale: np.ndarray
    value_shape: tuple


def _rbf_options(kernel, epsilon, degree):
    name = as_choice(kernel, "kernel", RBF_KERNELS)
    eps = as_positive(epsilon, "epsilon", "the shape parameter")
    least = 1 if name == "thin_plate_spline" else -1
    if degree is None:
        deg = least
    else:
        if isinstance(degree, (bool, np.bool_)):
            raise TypeError("degree must be -1, 0 or 1, got a bool")
        deg = as_whole(degree, "degree", -1)
        if deg > 1:
            raise ValueError(f"degree must be -1 (no polynomial), 0 or 1, got {deg}")
        if deg < least:
            raise ValueError("the thin-plate spline needs the linear polynomial term "
                             f"(degree=1): without it the system is not well posed; got "
                             f"degree={deg}")
    return name, eps, deg


def _rbf_poly(x, degree):
    """The polynomial basis at (already shifted and scaled) points x (..., d)."""
    if degree < 0:
        return np.zeros(x.shape[:-1] + (0,))
    ones = np.ones(x.shape[:-1] + (1,))
    return ones if degree == 0 else np.concatenate([ones, x], axis=-1)


def _squared_distances(a, b):
    """Squared distances between the rows of a (..., m, d) and b (..., n, d), computed
    coordinate by coordinate in place (no m x n x d temporary)."""
    d2 = None
    for c in range(a.shape[-1]):
        diff = a[..., :, None, c] - b[..., None, :, c]
        diff *= diff
        if d2 is None:
            d2 = diff
        else:
            d2 += diff
    return d2


def _solve_rbf(centres, rows, name, eps, degree):
    """Solve the (batched) RBF systems for centres (..., n, d) and values (..., n, k): the
    weights, polynomial coefficients, shift and scale."""
    shift = centres.mean(axis=-2, keepdims=True)
    scale = np.abs(centres - shift).max(axis=(-2, -1), keepdims=True)
    scale = np.where(scale > 0, scale, 1.0)
    a = _rbf_phi(_squared_distances(centres, centres) * eps ** 2, name)
    pm = _rbf_poly((centres - shift) / scale, degree)
    n, m = a.shape[-1], pm.shape[-1]
    system = np.zeros(a.shape[:-2] + (n + m, n + m))
    system[..., :n, :n] = a
    system[..., :n, n:] = pm
    system[..., n:, :n] = np.swapaxes(pm, -1, -2)
    rhs = np.zeros(a.shape[:-2] + (n + m, rows.shape[-1]))
    rhs[..., :n, :] = rows
    try:
        sol = np.linalg.solve(system, rhs)
    except np.linalg.LinAlgError:
        sol = None
    if sol is not None:
        residual = np.abs(system @ sol - rhs).max()
        size = max(np.abs(rows).max(), 1e-300)
    if sol is None or not np.isfinite(sol).all() or residual > 1e-6 * size:
        hint = (" (a small epsilon makes the Gaussian and inverse multiquadric nearly flat: "
                "increase it)" if name != "thin_plate_spline" else "")
        raise ValueError("the RBF system is singular or too ill-conditioned to solve"
                         f"{hint}; with degree={degree} the points must also not all lie on "
                         "a line")
    return sol[..., :n, :], sol[..., n:, :], shift, scale


def rbf_fit(points, values, kernel="gaussian", epsilon=1.0, degree=None):
    r"""Fit a global radial-basis-function interpolant: solve for its coefficients.

    .. math:: s(x) = \sum_{i=1}^n \lambda_i\, \phi(\lVert x - x_i \rVert) + \sum_j c_j\, q_j(x)

    The conditions :math:`s(x_j) = f_j` give n equations; with a polynomial term of basis
    :math:`q_j` (1, or 1, x, y) the side conditions :math:`\sum_i \lambda_i q_j(x_i) = 0` make
    the system square:

    .. math:: \begin{bmatrix} A & P \\ P^T & 0 \end{bmatrix}
              \begin{bmatrix} \lambda \\ c \end{bmatrix} =
              \begin{bmatrix} f \\ 0 \end{bmatrix}, \qquad
              A_{ij} = \phi(\lVert x_i - x_j \rVert),\ P_{ij} = q_j(x_i).

    Gaussian, multiquadric and inverse multiquadric need no polynomial (degree -1, the default;
    A is invertible for distinct points); the thin-plate spline needs the linear one
    (degree 1, its default; then :math:`\varepsilon` does not change the interpolant).

    Parameters
    ----------
    points : array_like, shape (n, d)
        At most :data:`MAX_GLOBAL_RBF_CENTRES` (the system is dense).
    values : array_like, shape (n,) or (n, k)
    kernel : str
        One of :data:`RBF_KERNELS`.
    epsilon : float
        The shape parameter, > 0.
    degree : {None, -1, 0, 1}
        The polynomial term; None: the kernel's default.

    Returns
    -------
    RBFModel

    Raises
    ------
    ValueError
        For too many centres, an unknown kernel, a bad degree, or a singular system.

    Examples
    --------
    >>> m = rbf_fit([[0, 0], [1, 0], [0, 1], [1, 1]], [0.0, 1.0, 1.0, 2.0], "thin_plate_spline")
    >>> rbf_evaluate(m, [[0.5, 0.5], [2.0, 0.0]]).round(9)    # a linear f: reproduced exactly
    array([1., 2.])
    """
    name, eps, deg = _rbf_options(kernel, epsilon, degree)
    p, v = scattered_data(points, values)
    if len(p) > MAX_GLOBAL_RBF_CENTRES:
        mb = 8 * len(p) ** 2 / 1e6
        raise ValueError(f"a global RBF on {len(p)} centres needs a dense {len(p)} x {len(p)} "
                         f"system ({mb:,.0f} MB, about {len(p) ** 3 / 3:.1e} operations to "
                         f"solve); the limit is {MAX_GLOBAL_RBF_CENTRES}. Pass neighbors=k "
                         "(e.g. 50) to rbf_interpolate for the local form")
    rows = v.reshape(len(v), -1)
    weights, poly, shift, scale = _solve_rbf(p, rows, name, eps, deg)
    return RBFModel(p, weights, poly, name, eps, deg, shift[0], scale.reshape(()), v.shape[1:])


def rbf_evaluate(model, query):
    """Evaluate a fitted :class:`RBFModel` at query points (in chunks: bounded memory).

    Parameters
    ----------
    model : RBFModel
    query : array_like, shape (..., d)

    Returns
    -------
    ndarray, shape query.shape[:-1] (+ (k,) if the model was fitted to rows of k values)

    Examples
    --------
    >>> m = rbf_fit([[0, 0], [1, 0]], [2.0, 5.0], "gaussian", 1.0)
    >>> rbf_evaluate(m, [[0, 0], [1, 0]]).round(12)
    array([2., 5.])
    """
    if not isinstance(model, RBFModel):
        raise TypeError(f"model must be an RBFModel from rbf_fit, got {type(model).__name__}")
    q, flat = _query_points(query, model.centres.shape[1])
    out = np.empty((len(flat), model.weights.shape[1]))
    step = max(1, _CHUNK // len(model.centres))
    for start in range(0, len(flat), step):
        x = flat[start:start + step]
        phi = _rbf_phi(_squared_distances(x, model.centres) * model.epsilon ** 2,
                       model.kernel)
        out[start:start + step] = phi @ model.weights \
            + _rbf_poly((x - model.shift) / model.scale, model.degree) @ model.poly
    return out.reshape(q.shape[:-1] + tuple(model.value_shape))


def rbf_interpolate(points, values, query, kernel="gaussian", epsilon=1.0, degree=None,
                    neighbors=None):
    """Radial-basis-function interpolation, global (:func:`rbf_fit`) or local.

    Local (``neighbors=k``): each query point gets its own small RBF, fitted to its k nearest
    data points (queries that share the same k points share the fit, and all the small systems
    are solved at once). This is scipy's ``RBFInterpolator(neighbors=k)``: the result is
    continuous only approximately (it jumps a little where the set of neighbours changes), but
    the cost grows like the number of queries times k^3 instead of n^3.

    Parameters
    ----------
    points : array_like, shape (n, d)
    values : array_like, shape (n,) or (n, k)
    query : array_like, shape (..., d)
    kernel, epsilon, degree
        See :func:`rbf_fit`.
    neighbors : int, optional
        k for the local form (at least 1 + d with the linear term); None: global.

    Returns
    -------
    ndarray, shape query.shape[:-1] (+ (k,))

    Examples
    --------
    >>> pts = [[0, 0], [1, 0], [0, 1], [1, 1], [2, 2]]
    >>> f = [0.0, 1.0, 2.0, 3.0, 6.0]                    # f = x + 2y
    >>> rbf_interpolate(pts, f, [[0.5, 0.5]], "thin_plate_spline").round(9)
    array([1.5])
    >>> rbf_interpolate(pts, f, [[0.5, 0.5]], "thin_plate_spline", neighbors=4).round(9)
    array([1.5])
    """
    name, eps, deg = _rbf_options(kernel, epsilon, degree)
    p, v = scattered_data(points, values)
    q, flat = _query_points(query, p.shape[1])
    if neighbors is None:
        return rbf_evaluate(rbf_fit(p, v, name, eps, deg), q)
    k = as_whole(neighbors, "neighbors", 1)
    least = 1 if deg < 0 else (1 if deg == 0 else p.shape[1] + 1)
    if k < least or k > len(p):
        raise ValueError(f"neighbors must be between {least} and the number of points "
                         f"({len(p)}), got {k}")
    rows = v.reshape(len(v), -1)
    index, _ = _k_nearest(p, flat, k)
    sets, inverse = np.unique(np.sort(index, axis=1), axis=0, return_inverse=True)
    inverse = inverse.ravel()
    out = np.empty((len(flat), rows.shape[1]))
    per = max(1, 50_000_000 // (8 * (k + 4) ** 2))               # systems solved at once
    order = np.argsort(inverse, kind="stable")
    bounds = np.searchsorted(inverse[order], np.arange(len(sets) + 1))
    for start in range(0, len(sets), per):
        group = sets[start:start + per]
        weights, poly, shift, scale = _solve_rbf(p[group], rows[group], name, eps, deg)
        members = order[bounds[start]:bounds[min(start + per, len(sets))]]
        g = inverse[members] - start
        x = flat[members][:, None, :]
        phi = _rbf_phi(_squared_distances(x, p[group[g]]) * eps ** 2, name)[:, 0, :]
        out[members] = np.einsum("mi,mik->mk", phi, weights[g]) + np.einsum(
            "mj,mjk->mk", _rbf_poly((x[:, 0, :] - shift[g, 0]) / scale[g, 0], deg), poly[g])
    return out.reshape(q.shape[:-1] + v.shape[1:])


# ---------------------------------------------------------------------------------------------
# Resampling and derived quantities
# ---------------------------------------------------------------------------------------------

def scattered_interpolate(points, values, query, method="shepard", **options):
    """Interpolate scattered data at query points by any of :data:`SCATTERED_METHODS`.

    Parameters
    ----------
    points, values, query
        As for the single methods.
    method : str
        ``"nearest"``, ``"linear"``, ``"shepard"`` or ``"rbf"``.
    **options
        Passed on: ``power``, ``radius`` (Shepard); ``kernel``, ``epsilon``, ``degree``,
        ``neighbors`` (RBF); ``triangles`` (linear); ``outside`` (linear, local Shepard).

    Returns
    -------
    ndarray

    Examples
    --------
    >>> pts, f = [[0, 0], [4, 0], [0, 4]], [0.0, 4.0, 8.0]
    >>> [float(scattered_interpolate(pts, f, [[1, 1]], m)[0]) for m in ("nearest", "linear")]
    [0.0, 3.0]
    """
    method = as_choice(method, "method", SCATTERED_METHODS)
    allowed = {"nearest": (), "linear": ("triangles", "outside"),
               "shepard": ("power", "radius", "outside"),
               "rbf": ("kernel", "epsilon", "degree", "neighbors")}[method]
    unknown = sorted(set(options) - set(allowed))
    if unknown:
        raise TypeError(f"method {method!r} takes the options {', '.join(allowed) or 'none'}; "
                        f"got {', '.join(unknown)}")
    function = {"nearest": nearest_interpolate, "linear": linear_interpolate,
                "shepard": shepard_interpolate, "rbf": rbf_interpolate}[method]
    return function(points, values, query, **options)


def resample_to_grid(points, values, shape, extent=None, method="shepard", **options):
    """Resample 2D scattered data onto a uniform grid.

    Parameters
    ----------
    points : array_like, shape (n, 2)
    values : array_like, shape (n,) or (n, k)
    shape : tuple of int
        The grid's sample array ``(ny, nx)``.
    extent : tuple of float, optional
        ``(xmin, xmax, ymin, ymax)``, the grid's corner samples; default the points'
        bounding box.
    method, **options
        See :func:`scattered_interpolate`.

    Returns
    -------
    grid_values : ndarray, shape (ny, nx) (+ (k,))
    grid : Grid
        The uniform grid (origin, spacing) the values are sampled on.

    Examples
    --------
    >>> pts = [[0, 0], [2, 0], [0, 2], [2, 2]]
    >>> g, grid = resample_to_grid(pts, [0.0, 2.0, 2.0, 4.0], (3, 3), method="linear")
    >>> g, grid.stored["spacing"]
    (array([[0., 1., 2.],
           [1., 2., 3.],
           [2., 3., 4.]]), array([1., 1.]))
    """
    p, v = scattered_data(points, values)
    if p.shape[1] != 2:
        raise ValueError("resample_to_grid resamples 2D points, shape (n, 2)")
    ny, nx = (as_whole(s, "shape", 2) for s in _shape_pair(shape, "shape"))
    if extent is None:
        lo, hi = p.min(axis=0), p.max(axis=0)
        box = (lo[0], hi[0], lo[1], hi[1])
    else:
        box = tuple(as_array(extent, "extent").ravel())
        if len(box) != 4:
            raise ValueError(f"extent must be (xmin, xmax, ymin, ymax), got {extent!r}")
    x0, x1, y0, y1 = (float(b) for b in box)
    if not (x1 > x0 and y1 > y0):
        raise ValueError(f"extent must have xmin < xmax and ymin < ymax, got {box}")
    grid = uniform_grid((ny, nx), spacing=((x1 - x0) / (nx - 1), (y1 - y0) / (ny - 1)),
                        origin=(x0, y0))
    out = scattered_interpolate(p, v, grid.nodes, method, **options)
    return out.reshape((ny, nx) + v.shape[1:]), grid


def _shape_pair(value, name):
    s = np.asarray(value, dtype=object).ravel()
    if s.size != 2:
        raise ValueError(f"{name} must be (ny, nx), got {value!r}")
    return s


def gradient_magnitude(values, spacing=(1.0, 1.0)):
    r"""The gradient magnitude of a resampled 2D field, by finite differences: a derived
    quantity.

    :math:`\lVert\nabla f\rVert = \sqrt{f_x^2 + f_y^2}` with central differences inside and
    one-sided ones at the border (:func:`course_lib.scivis.gradient`). It shows where the
    field changes fastest (edges, fronts) and, on an interpolated field, where the
    interpolation method leaves its marks: jumps of nearest neighbour, creases of linear,
    flat spots of Shepard.

    Parameters
    ----------
    values : array_like, shape (ny, nx)
    spacing : tuple of float
        (dx, dy).

    Returns
    -------
    ndarray, shape (ny, nx)

    Examples
    --------
    >>> f = np.add.outer(4.0 * np.arange(3), 3.0 * np.arange(4))      # f = 3x + 4y
    >>> gradient_magnitude(f)
    array([[5., 5., 5., 5.],
           [5., 5., 5., 5.],
           [5., 5., 5., 5.]])
    """
    v = np.asarray(values)
    if v.dtype.kind == "f" and np.isnan(v).any():
        raise ValueError("values contains NaN (e.g. outside the convex hull of a linear "
                         "interpolation): fill or crop the field before differentiating")
    v = as_array(values, "values")
    if v.ndim != 2:
        raise ValueError(f"values must be a 2D field (ny, nx), got shape {v.shape}")
    g = gradient(v, spacing)
    return np.sqrt(np.sum(g * g, axis=-1))
