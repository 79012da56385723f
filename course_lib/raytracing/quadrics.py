r"""Chapter 15 (lesson section "Quadrics and implicit surfaces"): rays against quadrics, disks
and any implicit surface :math:`f(x) = 0`.

**Quadrics.** Every surface of degree two is the zero set of :math:`f(x) = \tilde x^T Q \tilde
x` with :math:`\tilde x = (x, y, z, 1)` and a symmetric 4x4 matrix :math:`Q`. The sphere of
radius :math:`r` is :math:`Q = \mathrm{diag}(1, 1, 1, -r^2)`, the infinite cylinder around the
z axis :math:`\mathrm{diag}(1, 1, 0, -r^2)`, the cone :math:`\mathrm{diag}(1, 1, -s^2, 0)`
(:func:`quadric_matrix` builds them all). Moving the surface by an affine map :math:`M` changes
the matrix to :math:`M^{-T} Q M^{-1}` (:func:`transform_quadric`).

**A ray gives a quadratic.** Substituting :math:`\tilde x = \tilde o + t \tilde d` (the origin
with :math:`w = 1`, the direction with :math:`w = 0`) and using :math:`Q = Q^T`:

.. math:: f(t) = (\tilde d^T Q \tilde d)\, t^2 + 2 (\tilde d^T Q \tilde o)\, t +
          \tilde o^T Q \tilde o = a t^2 + b t + c

(:func:`ray_quadratic`). :math:`a = 0` (a ray parallel to the cylinder's axis, to a cone's
generator) leaves a linear equation with the single root :math:`-c/b`.

**The normal** is the gradient of :math:`f`, :math:`\nabla f = 2 (Q \tilde x)_{xyz}`; it points
to the side where :math:`f > 0` (outside, for the matrices of :func:`quadric_matrix`).

**Any implicit surface.** For a general :math:`f` (a torus is of degree four, a blob is not
a polynomial) :func:`intersect_implicit` samples :math:`f` along the ray, takes the first change
of sign and refines it by bisection. A thin part of the surface that enters and leaves between
two samples produces no change of sign and is missed: the step must be smaller than the
thinnest feature.
"""

from typing import NamedTuple

import numpy as np

from .._raycore import as_rays as _rays, as_t_max as _t_max, as_t_min as _t_min
from .._validate import as_choice, as_matrix, as_points, as_positive, as_vector, as_whole
from ._common import _dot, _unit_vectors
from .intersections import SurfaceHits, _plane_t

__all__ = ["QUADRIC_KINDS", "QuadricHits", "intersect_cylinder", "intersect_disk",
           "intersect_implicit", "intersect_quadric", "quadric_matrix", "quadric_value",
           "ray_quadratic", "torus_function", "transform_quadric"]

QUADRIC_KINDS = ("sphere", "ellipsoid", "cylinder", "cone", "paraboloid", "hyperboloid1",
                 "hyperboloid2")


class QuadricHits(NamedTuple):
    """Nearest hits of rays with a quadric (:func:`intersect_quadric`).

    Attributes
    ----------
    t : ndarray, shape (...)
        Ray parameter of the hit; ``inf`` for a miss.
    normals : ndarray, shape (..., 3)
        Unit normal :math:`\\nabla f / \\lVert \\nabla f \\rVert` at the hit (towards
        :math:`f > 0`, or facing the ray with ``face_ray=True``); zero for a miss.
    points : ndarray, shape (..., 3)
        The hit points ``o + t d`` (NaN for a miss).

    Examples
    --------
    >>> hits = intersect_quadric([0, 0, 5], [0, 0, -1], quadric_matrix("sphere", radius=2))
    >>> float(hits.t), hits.normals.tolist(), hits.points.tolist()
    (3.0, [0.0, 0.0, 1.0], [0.0, 0.0, 2.0])
    """
    t: np.ndarray
    normals: np.ndarray
    points: np.ndarray


# ---------------------------------------------------------------------------------------------
# The matrices
# ---------------------------------------------------------------------------------------------

def _as_quadric(Q, name="Q"):
    """A symmetric, finite, non-zero 4x4 matrix, or a clear error (no silent nonsense)."""
    q = as_matrix(Q, name, sizes=4)
    scale = np.abs(q).max()
    if scale == 0:
        raise ValueError(f"{name} must not be all zero: every point would satisfy 0 = 0")
    if not np.allclose(q, q.T, rtol=0, atol=1e-12 * scale):
        raise ValueError(f"{name} must be symmetric (Q == Q.T): x^T Q x only sees (Q + Q^T)/2, "
                         f"so write that matrix instead")
    if not np.any(q[:3, :] != 0):
        raise ValueError(f"{name} has no x, y, z terms: it describes no surface")
    return 0.5 * (q + q.T)


def quadric_matrix(kind, radius=1.0, radii=(1.0, 1.0, 1.0), slope=1.0, center=(0.0, 0.0, 0.0)):
    r"""The symmetric 4x4 matrix :math:`Q` of a standard quadric (axis along z).

    ========================  ==============================================  ====================
    kind                      surface :math:`f(x, y, z) = 0`                  diagonal of Q
    ========================  ==============================================  ====================
    ``"sphere"``              :math:`x^2 + y^2 + z^2 - r^2`                   (1, 1, 1, -r²)
    ``"ellipsoid"``           :math:`x^2/a^2 + y^2/b^2 + z^2/c^2 - 1`         (1/a², 1/b², 1/c², -1)
    ``"cylinder"``            :math:`x^2 + y^2 - r^2` (infinite)              (1, 1, 0, -r²)
    ``"cone"``                :math:`x^2 + y^2 - s^2 z^2` (apex at 0)         (1, 1, -s², 0)
    ``"paraboloid"``          :math:`s (x^2 + y^2) - z`                       (s, s, 0, 0), Q₂₃ = -½
    ``"hyperboloid1"``        :math:`x^2 + y^2 - s^2 z^2 - r^2` (one sheet)   (1, 1, -s², -r²)
    ``"hyperboloid2"``        :math:`x^2 + y^2 - s^2 z^2 + r^2` (two sheets)  (1, 1, -s², r²)
    ========================  ==============================================  ====================

    :math:`f > 0` is outside (away from the axis) for all of them, so the gradient points out.

    Parameters
    ----------
    kind : str
        One of :data:`QUADRIC_KINDS`.
    radius : float, optional
        :math:`r > 0` (sphere, cylinder, hyperboloids: the waist radius, or for two sheets the
        half-gap :math:`r/s` along z).
    radii : array_like, shape (3,), optional
        :math:`(a, b, c) > 0` of the ellipsoid.
    slope : float, optional
        :math:`s > 0`: the cone's :math:`\tan` of its half-angle, the hyperboloids' asymptotic
        slope, the paraboloid's curvature.
    center : array_like, shape (3,), optional
        Where the shape's origin is moved (:func:`transform_quadric` with a translation).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        For an unknown kind, a non-positive radius/slope, NaN.

    Examples
    --------
    >>> quadric_matrix("cylinder", radius=2).tolist()
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, -4.0]]
    >>> quadric_matrix("sphere", radius=1, center=[0, 0, 2])[2:, 2:].tolist()
    [[1.0, -2.0], [-2.0, 3.0]]
    """
    kind = as_choice(kind, "kind", QUADRIC_KINDS)
    r = as_positive(radius, "radius")
    s = as_positive(slope, "slope")
    ab = as_vector(radii, "radii", 3)
    if np.any(ab <= 0):
        raise ValueError(f"radii must be positive (the ellipsoid's semi-axes), got {ab.tolist()}")
    c = as_vector(center, "center", 3)
    diag = {"sphere": (1, 1, 1, -r * r), "ellipsoid": tuple(1 / ab ** 2) + (-1,),
            "cylinder": (1, 1, 0, -r * r), "cone": (1, 1, -s * s, 0),
            "paraboloid": (s, s, 0, 0), "hyperboloid1": (1, 1, -s * s, -r * r),
            "hyperboloid2": (1, 1, -s * s, r * r)}[kind]
    q = np.diag(np.asarray(diag, dtype=float))
    if kind == "paraboloid":
        q[2, 3] = q[3, 2] = -0.5
    if np.any(c != 0):
        m = np.eye(4)
        m[:3, 3] = c
        q = transform_quadric(q, m)
    return q


def transform_quadric(Q, M):
    r"""The matrix of the quadric moved by the invertible affine 4x4 map `M`: :math:`M^{-T} Q
    M^{-1}`.

    A point :math:`\tilde y = M \tilde x` of the moved surface satisfies :math:`\tilde x^T Q
    \tilde x = 0` with :math:`\tilde x = M^{-1} \tilde y`, which is :math:`\tilde y^T (M^{-T} Q
    M^{-1}) \tilde y = 0`. Scaling the unit sphere by (a, b, c) gives the ellipsoid.

    Parameters
    ----------
    Q : array_like, shape (4, 4)
        Symmetric.
    M : array_like, shape (4, 4)
        Invertible, last row (0, 0, 0, 1).

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> S = np.diag([2.0, 3.0, 4.0, 1.0])
    >>> np.allclose(transform_quadric(quadric_matrix("sphere"), S),
    ...             quadric_matrix("ellipsoid", radii=[2, 3, 4]))
    True
    """
    q = _as_quadric(Q)
    m = as_matrix(M, "M", sizes=4)
    if not np.allclose(m[3], [0, 0, 0, 1]):
        raise ValueError(f"M must be an affine map (last row 0, 0, 0, 1), got {m[3].tolist()}")
    if abs(np.linalg.det(m[:3, :3])) < 1e-12:
        raise ValueError("M must be invertible (a singular map flattens the surface)")
    inv = np.linalg.inv(m)
    out = inv.T @ q @ inv
    return 0.5 * (out + out.T)


def quadric_value(Q, points):
    r"""The implicit function :math:`f(p) = \tilde p^T Q \tilde p` at points (negative inside).

    Parameters
    ----------
    Q : array_like, shape (4, 4)
    points : array_like, shape (..., 3)

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> quadric_value(quadric_matrix("cylinder", radius=1), [[2, 0, 7], [0, 0, 0]])
    array([ 3., -1.])
    """
    q = _as_quadric(Q)
    p = as_points(points, "points", dims=3)
    h = np.concatenate([p, np.ones(p.shape[:-1] + (1,))], axis=-1)
    return np.einsum("...i,ij,...j->...", h, q, h)


def _quadric_coefficients(oc, dc, q):
    """a, b, c of f(o + t d) for rays given as coordinate columns oc, dc (3, p) (b the full
    linear coefficient).

    Written entry by entry over the columns, skipping the zeros of Q (most quadrics are nearly
    diagonal): much faster than (p, 4) @ (4, 4) products for many rays."""
    a = np.zeros(oc.shape[1])
    b = np.zeros(oc.shape[1])
    c = np.full(oc.shape[1], q[3, 3])
    for i in range(3):
        for j in range(i, 3):
            k = q[i, j] * (1.0 if i == j else 2.0)
            if k != 0:
                a += k * dc[i] * dc[j]
                b += k * (oc[i] * dc[j] + oc[j] * dc[i])
                c += k * oc[i] * oc[j]
        if q[i, 3] != 0:
            b += 2.0 * q[i, 3] * dc[i]
            c += 2.0 * q[i, 3] * oc[i]
    return a, b, c


def ray_quadratic(origins, directions, Q):
    r"""The coefficients of :math:`f(o + t d) = a t^2 + b t + c` for a quadric.

    :math:`a = \tilde d^T Q \tilde d`, :math:`b = 2 \tilde d^T Q \tilde o`, :math:`c = \tilde
    o^T Q \tilde o` with :math:`\tilde o = (o, 1)` and :math:`\tilde d = (d, 0)`. (:math:`c`
    is :math:`f` at the origin: negative when the ray starts inside.)

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    Q : array_like, shape (4, 4)

    Returns
    -------
    a, b, c : ndarray, shape (...)

    Examples
    --------
    The unit cylinder and a ray from (3, 0, 0) along -x: :math:`t^2 - 6 t + 8`, roots 2 and 4.

    >>> [float(v) for v in ray_quadratic([3, 0, 0], [-1, 0, 0], quadric_matrix("cylinder"))]
    [1.0, -6.0, 8.0]
    """
    o, d, lead = _rays(origins, directions)
    a, b, c = _quadric_coefficients(o.T, d.T, _as_quadric(Q))
    return a.reshape(lead), b.reshape(lead), c.reshape(lead)


def _quadratic_roots(a, b, c, scale):
    """Both real roots (t1 <= t2) of a t^2 + b t + c, stable; a ~ 0 gives the linear root twice;
    inf where there is none."""
    linear = np.abs(a) <= 1e-12 * scale
    disc = b * b - 4 * a * c
    real = (disc >= 0) & ~linear
    q = -0.5 * (b + np.copysign(np.sqrt(np.where(real, disc, 0.0)), b))
    with np.errstate(divide="ignore", invalid="ignore"):
        r1 = np.where(real, q / np.where(real, a, 1.0), np.inf)
        r2 = np.where(real & (q != 0), c / np.where(q != 0, q, 1.0), r1)
        lin = np.where(b != 0, -c / np.where(b != 0, b, 1.0), np.inf)
    t1 = np.where(linear, lin, np.minimum(r1, r2))
    t2 = np.where(linear, lin, np.maximum(r1, r2))
    return t1, t2


def _quadric_clip(clip):
    if clip is None:
        return None
    lo, hi = as_vector(clip, "clip", 2)
    if not lo < hi:
        raise ValueError(f"clip must be (z_min, z_max) with z_min < z_max, got ({lo:g}, {hi:g})")
    return lo, hi


def _select_quadric_root(t1, t2, oc, dc, t_min, clip):
    """The first of the two roots >= t_min whose point lies inside the clip range."""
    def ok(t):
        good = np.isfinite(t) & (t >= t_min)
        if clip is not None:
            with np.errstate(invalid="ignore"):
                z = oc[2] + np.where(good, t, 0.0) * dc[2]
            good &= (z >= clip[0]) & (z <= clip[1])
        return good
    return np.where(ok(t1), t1, np.where(ok(t2), t2, np.inf))


def _quadric_normals(q, pc, dc, face_ray):
    """Unit normals (3, p) from the gradient (Q x~)_xyz at points given as columns pc (3, p);
    -d where the gradient vanishes (a cone's apex); turned against d if `face_ray`."""
    g = np.empty_like(pc)
    for i in range(3):
        g[i] = q[i, 3]
        for j in range(3):
            if q[i, j] != 0:
                g[i] += q[i, j] * pc[j]
    length = np.sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2])
    flat = ~(length > 0)                     # a cone's apex (or a miss): no tangent plane
    g /= np.where(flat, 1.0, length)
    if flat.any():
        g[:, flat] = -dc[:, flat] / np.sqrt((dc[:, flat] ** 2).sum(axis=0))
    if face_ray:
        g *= np.where(g[0] * dc[0] + g[1] * dc[1] + g[2] * dc[2] > 0, -1.0, 1.0)
    return g


def intersect_quadric(origins, directions, Q, t_min=0.0, clip=None, face_ray=False):
    r"""Ray-quadric intersection: the nearest root :math:`t \ge t_{min}` of :math:`a t^2 + b t
    + c = 0`.

    The coefficients are those of :func:`ray_quadratic`. Negative discriminant: a miss. With
    :math:`a = 0` (relative to the size of Q) the equation is linear, :math:`t = -c/b`. The two
    roots are computed in the stable form (:math:`q = -\frac12 (b + \mathrm{sign}(b)
    \sqrt{b^2 - 4ac})`, roots :math:`q/a` and :math:`c/q`). With `clip` = (z_min, z_max) a root
    whose point lies outside that height range is skipped and the other root tried (the inside
    of an open, finite cylinder is seen through its open end). The normal is the normalised
    gradient :math:`(Q \tilde x)_{xyz}`.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    Q : array_like, shape (4, 4)
        Symmetric, finite, not all zero.
    t_min : float, optional
        Only hits with :math:`t \ge t_{min} \ge 0` count.
    clip : (float, float), optional
        Keep only hits with :math:`z_{min} \le z \le z_{max}`.
    face_ray : bool, optional
        Turn each normal to face the ray (:math:`n \cdot d \le 0`).

    Returns
    -------
    QuadricHits

    Raises
    ------
    ValueError
        For a non-symmetric, all-zero, non-4x4 or non-finite Q, zero directions, a negative
        `t_min`, a bad `clip`.

    Examples
    --------
    The unit cylinder from (3, 0, 0) along -x enters at t = 2 with normal +x; clipped to
    z in [1, 2] the same ray at height 0 misses:

    >>> Q = quadric_matrix("cylinder")
    >>> hits = intersect_quadric([3, 0, 0], [-1, 0, 0], Q)
    >>> float(hits.t), hits.normals.tolist()
    (2.0, [1.0, 0.0, 0.0])
    >>> float(intersect_quadric([3, 0, 0], [-1, 0, 0], Q, clip=(1, 2)).t)
    inf
    """
    o, d, lead = _rays(origins, directions)
    q = _as_quadric(Q)
    t_min = _t_min(t_min)
    clip = _quadric_clip(clip)
    oc, dc = np.ascontiguousarray(o.T), np.ascontiguousarray(d.T)
    a, b, c = _quadric_coefficients(oc, dc, q)
    scale = np.abs(q).max() * (dc[0] * dc[0] + dc[1] * dc[1] + dc[2] * dc[2])
    t = _select_quadric_root(*_quadratic_roots(a, b, c, scale), oc, dc, t_min, clip)
    hit = np.isfinite(t)
    pc = oc + np.where(hit, t, 0.0) * dc
    nc = _quadric_normals(q, pc, dc, bool(face_ray))
    nc *= hit
    pc[:, ~hit] = np.nan
    points, normals = np.ascontiguousarray(pc.T), np.ascontiguousarray(nc.T)
    return QuadricHits(t.reshape(lead), normals.reshape(lead + (3,)),
                       points.reshape(lead + (3,)))


def intersect_disk(origins, directions, center, normal, radius, t_min=0.0):
    r"""Ray-disk intersection: the plane through `center` with `normal`, then :math:`\lVert p -
    c \rVert \le r`.

    :math:`t = \frac{(c - o) \cdot n}{d \cdot n}` (a miss when :math:`d \cdot n = 0` or
    :math:`t < t_{min}`), then the hit point :math:`p = o + t d` must lie within `radius` of the
    centre.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    center, normal : array_like, shape (3,)
        The normal need not be unit; not zero. It is returned for every hit.
    radius : float
        Positive.
    t_min : float, optional

    Returns
    -------
    SurfaceHits

    Examples
    --------
    >>> intersect_disk([[0.5, 0, 3], [2, 0, 3]], [0, 0, -1], [0, 0, 1], [0, 0, 1], 1.0).t
    array([ 2., inf])
    """
    o, d, lead = _rays(origins, directions)
    c = as_vector(center, "center", 3)
    n = _unit_vectors(as_vector(normal, "normal", 3), "normal")
    r = as_positive(radius, "radius", "the disk's radius")
    t = _plane_t(o, d, c, n, _t_min(t_min))
    hit = np.isfinite(t)
    p = o[hit] + t[hit, None] * d[hit] - c
    inside = np.zeros_like(hit)
    inside[hit] = _dot(p, p) <= r * r
    t = np.where(inside, t, np.inf)
    normals = np.where(inside[:, None], n, 0.0)
    return SurfaceHits(t.reshape(lead), normals.reshape(lead + (3,)))


def intersect_cylinder(origins, directions, radius=1.0, z_range=(0.0, 1.0), caps=True,
                       t_min=0.0):
    r"""A finite cylinder around the z axis: the quadric clipped to `z_range`, plus two disks.

    The side is :func:`intersect_quadric` of ``quadric_matrix("cylinder", radius)`` with
    ``clip=z_range``; the caps (``caps=True``) are :func:`intersect_disk` at both ends with
    outward normals :math:`\mp z`. The nearest of the three hits wins.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    radius : float, optional
    z_range : (float, float), optional
        Bottom and top heights.
    caps : bool, optional
        Closed (True) or open tube.
    t_min : float, optional

    Returns
    -------
    SurfaceHits
        Outward normals.

    Examples
    --------
    Straight down onto the top cap, and sideways into the side:

    >>> hits = intersect_cylinder([[0, 0, 5], [3, 0, 0.5]], [[0, 0, -1], [-1, 0, 0]])
    >>> hits.t.tolist(), hits.normals.tolist()
    ([4.0, 2.0], [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]])
    """
    o, d, lead = _rays(origins, directions)
    r = as_positive(radius, "radius", "the cylinder's radius")
    z0, z1 = _quadric_clip(z_range) if z_range is not None else (None, None)
    if z0 is None:
        raise ValueError("z_range must be (z_min, z_max): a finite cylinder needs both ends")
    side = intersect_quadric(o, d, quadric_matrix("cylinder", radius=r), t_min, clip=(z0, z1))
    t, normals = side.t, side.normals
    if caps:
        for z, nz in ((z0, -1.0), (z1, 1.0)):
            cap = intersect_disk(o, d, [0, 0, z], [0, 0, nz], r, t_min)
            closer = cap.t < t
            t = np.where(closer, cap.t, t)
            normals = np.where(closer[:, None], cap.normals, normals)
    return SurfaceHits(t.reshape(lead), normals.reshape(lead + (3,)))


# ---------------------------------------------------------------------------------------------
# Any implicit surface
# ---------------------------------------------------------------------------------------------

def torus_function(major=1.0, minor=0.25):
    r"""The implicit function of the torus around the z axis, :math:`(|p|^2 + R^2 - r^2)^2 - 4
    R^2 (x^2 + y^2)`, negative inside the tube (degree 4: a ray meets it up to four times).

    Parameters
    ----------
    major, minor : float
        :math:`R > r > 0`: the radius of the tube's centre circle and of the tube.

    Returns
    -------
    callable
        ``f(points)`` for points of shape (..., 3).

    Examples
    --------
    >>> f = torus_function(2.0, 0.5)
    >>> f(np.array([[2.5, 0, 0], [2.0, 0, 0]])).tolist()
    [0.0, -3.9375]
    """
    big = as_positive(major, "major", "the torus's centre-circle radius")
    small = as_positive(minor, "minor", "the tube's radius")
    if small >= big:
        raise ValueError(f"minor must be smaller than major (a ring torus), got {small:g} >= "
                         f"{big:g}")

    def f(points):
        p = np.asarray(points, dtype=float)
        s = np.sum(p * p, axis=-1) + big * big - small * small
        return s * s - 4 * big * big * (p[..., 0] ** 2 + p[..., 1] ** 2)
    return f


def _call_implicit(f, p, name):
    try:
        v = np.asarray(f(p), dtype=float)
    except Exception as err:                # the user's function failed: say which one
        raise ValueError(f"{name} failed on points of shape {p.shape}: {err}") from err
    want = p.shape[:-1] if name == "f" else p.shape
    if v.shape != want:
        raise ValueError(f"{name} must return shape {want} for points of shape {p.shape}, got "
                         f"{v.shape}")
    return v


def _implicit_gradient(f, p, h):
    g = np.empty_like(p)
    for k in range(3):
        e = np.zeros(3)
        e[k] = h
        g[:, k] = (_call_implicit(f, p + e, "f") - _call_implicit(f, p - e, "f")) / (2 * h)
    return g


def intersect_implicit(origins, directions, f, grad=None, t_min=0.0, t_max=10.0, steps=200,
                       iterations=60, face_ray=False):
    r"""Rays against any implicit surface :math:`f(p) = 0`: sampling, bracketing, bisection.

    :math:`g(t) = f(o + t d)` is evaluated at `steps` + 1 equally spaced :math:`t` in
    :math:`[t_{min}, t_{max}]` (all rays at once); the first interval where :math:`g` changes
    sign (or is exactly zero) brackets the nearest root, and `iterations` bisection steps shrink
    the bracket (each halves it, so 60 reach rounding level). The normal is :math:`\nabla f`
    normalised, from `grad` or by central differences. A part of the surface thinner than one
    step (:math:`(t_{max} - t_{min}) / steps` along the ray) can fall between two samples of the
    same sign and be missed, as can a tangent touch (no change of sign at all).

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    f : callable
        ``f(points)`` for points of shape (n, 3), returning shape (n,); the surface is
        :math:`f = 0` (not required to be a polynomial).
    grad : callable, optional
        ``grad(points)`` of shape (n, 3); default central differences.
    t_min, t_max : float, optional
        The searched range (finite).
    steps : int, optional
        Number of sampling intervals (>= 1).
    iterations : int, optional
        Bisection steps (>= 0).
    face_ray : bool, optional
        Turn the normals to face the rays.

    Returns
    -------
    SurfaceHits
        ``t`` (``inf`` for no root found) and unit normals (towards :math:`f > 0`).

    Raises
    ------
    ValueError
        For a non-callable `f`, output of the wrong shape, an infinite `t_max`, bad steps.

    Examples
    --------
    The unit sphere written as a function: the same t = 4 as the closed form.

    >>> f = lambda p: np.sum(p * p, axis=-1) - 1.0
    >>> hits = intersect_implicit([0, 0, 5], [0, 0, -1], f)
    >>> round(float(hits.t), 9), np.round(hits.normals, 6).tolist()
    (4.0, [0.0, 0.0, 1.0])
    """
    if not callable(f):
        raise TypeError(f"f must be a function of points (n, 3) -> (n,), got {type(f).__name__}")
    if grad is not None and not callable(grad):
        raise TypeError(f"grad must be a function of points (n, 3) -> (n, 3) or None, got "
                        f"{type(grad).__name__}")
    o, d, lead = _rays(origins, directions)
    lo = _t_min(t_min)
    hi = _t_max(t_max, lo)
    if not np.isfinite(hi) or hi == lo:
        raise ValueError(f"t_max must be finite and above t_min (the range is sampled), got "
                         f"{t_max}")
    n = as_whole(steps, "steps", 1)
    iterations = as_whole(iterations, "iterations", 0)
    p = len(o)
    ts = np.linspace(lo, hi, n + 1)
    pts = o[:, None, :] + ts[None, :, None] * d[:, None, :]
    g = _call_implicit(f, pts.reshape(-1, 3), "f").reshape(p, n + 1)
    if not np.all(np.isfinite(g)):
        raise ValueError("f must return finite values along the rays")
    zero = g[:, :-1] == 0
    change = zero | (np.sign(g[:, :-1]) * np.sign(g[:, 1:]) < 0)
    found = change.any(axis=1)
    k = np.argmax(change, axis=1)
    rows = np.nonzero(found)[0]
    t = np.full(p, np.inf)
    if len(rows):
        kk = k[rows]
        a, b = ts[kk], ts[kk + 1]
        ga = g[rows, kk]
        exact = ga == 0
        oo, dd = o[rows], d[rows]
        for _ in range(iterations):
            m = 0.5 * (a + b)
            gm = _call_implicit(f, oo + m[:, None] * dd, "f")
            left = np.sign(gm) * np.sign(ga) <= 0        # the root is in [a, m]
            b = np.where(left, m, b)
            a = np.where(left, a, m)
            ga = np.where(left, ga, gm)
        t[rows] = np.where(exact, ts[kk], 0.5 * (a + b))
    hit = np.isfinite(t)
    normals = np.zeros_like(o)
    if hit.any():
        x = o[hit] + t[hit, None] * d[hit]
        if grad is None:
            h = 1e-6 * max(1.0, float(np.abs(x).max()))
            gv = _implicit_gradient(f, x, h)
        else:
            gv = _call_implicit(grad, x, "grad")
        length = np.sqrt(_dot(gv, gv))
        dh = d[hit] / np.sqrt(_dot(d[hit], d[hit]))[:, None]
        nv = np.where((length > 0)[:, None], gv / np.where(length > 0, length, 1.0)[:, None],
                      -dh)
        if face_ray:
            nv = np.where((_dot(nv, dh) > 0)[:, None], -nv, nv)
        normals[hit] = nv
    return SurfaceHits(t.reshape(lead), normals.reshape(lead + (3,)))
