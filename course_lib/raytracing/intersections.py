"""Chapter 15 (lesson sections 15.2, 15.6): ray-object intersections, the slab test and the BVH.

Spheres, planes and boxes are here; triangles, brute force and the :class:`BVH` live in
:mod:`course_lib._raycore`, shared with chapter 5's ray casting (``visibility.BVH`` is the same
class), and are re-exported from here.
"""

from typing import NamedTuple

import numpy as np

from .._raycore import (BVH, TriangleHits, as_triangles, brute_force, slab, triangle_normals,
                        triangle_hits, triangle_soa)
from .._raycore import as_rays as _rays, as_t_max as _t_max, as_t_min as _t_min
from .._validate import as_positive, as_vector
from ._common import _dot, _unit_vectors

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
    near, far = slab(lo_v, hi_v, o, d)
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
        tris = as_triangles(triangles)
        res = brute_force(o, d, triangle_soa(tris), t_min, t_max)
        return triangle_hits(*res[:4], triangle_normals(tris), lead, *res[4:])
    res = bvh._intersect(o, d, t_min, t_max)
    return triangle_hits(*res[:4], bvh._normals, lead, *res[4:])
