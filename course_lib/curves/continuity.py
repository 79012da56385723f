r"""Chapter 7 (curve basics): parametric and implicit curves, continuity at a join, curvature.

A **parametric** curve is a map :math:`t \mapsto P(t)`; an **implicit** curve is the zero set
:math:`f(x, y) = 0`. Where two curve segments A (parameter 0..1) and B (0..1) meet, A(1) = B(0),
the join is

* :math:`C^k` (parametric continuity) when the derivatives :math:`A^{(j)}(1) = B^{(j)}(0)` for
  every :math:`j \le k`;
* :math:`G^k` (geometric continuity) when the *shape* is as smooth: G1 = the unit tangents are
  equal (same direction, any speed), G2 = in addition the curvature vectors
  :math:`\kappa N` are equal (same curvature, same side, same osculating plane).

:math:`C^k` with a non-zero tangent implies :math:`G^k`; the converse fails (a G1 join may
have the speed jump). The curvature of a curve is

.. math:: \kappa = \frac{\lVert P' \times P'' \rVert}{\lVert P' \rVert^3}

in 2D (the cross product's z component) and 3D.
"""

from collections import namedtuple

import numpy as np

from .._validate import as_array, as_choice, as_positive, as_scalar, as_whole
from ._common import _control_points
from .bezier_curves import bezier, bezier_derivative

__all__ = ["JoinContinuity", "bezier_curvature", "circle_implicit", "circle_parametric",
           "circle_rational", "constrain_join", "curvature", "curvature_comb",
           "curvature_vector", "join_continuity", "join_points"]

JOINS = ("C0", "G1", "C1", "G2", "C2")

JoinContinuity = namedtuple("JoinContinuity", ["C", "G", "gap", "tangent_angle", "curvatures"])
JoinContinuity.__doc__ = """The measured continuity of a join (see :func:`join_continuity`).

``C`` and ``G`` are the highest k <= 2 with C^k and G^k (-1: the segments do not even meet);
``gap`` is the distance A(1) - B(0), ``tangent_angle`` the angle (radians) between the end
tangents (nan where a tangent vanishes), ``curvatures`` the pair (kappa_A(1), kappa_B(0)).

Examples
--------
>>> JoinContinuity(1, 1, 0.0, 0.0, (0.5, 2.0)).G
1
"""


# ---------------------------------------------------------------------------------------------
# parametric and implicit: the circle both ways
# ---------------------------------------------------------------------------------------------

def circle_parametric(t, radius=1.0, center=(0.0, 0.0)):
    r"""The circle as a parametric curve: :math:`P(t) = c + r(\cos t, \sin t)`.

    Parameters
    ----------
    t : float or array_like
        Angles in radians.
    radius : float, default 1
    center : array_like, shape (2,)

    Returns
    -------
    ndarray, shape t.shape + (2,)

    Examples
    --------
    >>> circle_parametric([0, np.pi / 2], 2.0).round(12)
    array([[2., 0.],
           [0., 2.]])
    """
    t = as_array(t, "t")
    r = as_positive(radius, "radius")
    c = _circle_center(center)
    return c + r * np.stack([np.cos(t), np.sin(t)], axis=-1)


def circle_implicit(points, radius=1.0, center=(0.0, 0.0)):
    r"""The circle as an implicit curve: :math:`f(x, y) = (x - c_x)^2 + (y - c_y)^2 - r^2`.

    f = 0 on the circle, f < 0 inside, f > 0 outside: an implicit form answers "is this point on
    (inside) the curve?" at once, while a parametric form lists the curve's points. Eliminating
    t from :func:`circle_parametric` (:math:`\cos^2 t + \sin^2 t = 1`) gives this f.

    Parameters
    ----------
    points : array_like, shape (..., 2)
    radius : float, default 1
    center : array_like, shape (2,)

    Returns
    -------
    float or ndarray, shape points.shape[:-1]

    Examples
    --------
    >>> circle_implicit([[1, 0], [0, 0], [2, 0]])
    array([ 0., -1.,  3.])
    """
    p = as_array(points, "points")
    if p.ndim < 1 or p.shape[-1] != 2:
        raise ValueError(f"points must have 2 coordinates in the last axis, got shape {p.shape}")
    r = as_positive(radius, "radius")
    q = p - _circle_center(center)
    return np.sum(q * q, axis=-1) - r * r


def circle_rational(s, radius=1.0, center=(0.0, 0.0)):
    r"""A parametrization found from the implicit circle: lines through (-r, 0) of slope s.

    Substituting :math:`y = s (x + r)` into :math:`x^2 + y^2 = r^2` and dividing out the known
    root x = -r leaves

    .. math:: P(s) = c + r \left( \frac{1 - s^2}{1 + s^2}, \frac{2 s}{1 + s^2} \right),

    a *rational* parametrization (the one NURBS use for exact circles): s in [-1, 1] covers the
    right half, s -> ±inf reaches (-r, 0).

    Parameters
    ----------
    s : float or array_like
    radius : float, default 1
    center : array_like, shape (2,)

    Returns
    -------
    ndarray, shape s.shape + (2,)

    Examples
    --------
    >>> circle_rational([0.0, 1.0])
    array([[1., 0.],
           [0., 1.]])
    """
    s = as_array(s, "s")
    r = as_positive(radius, "radius")
    d = 1.0 + s * s
    return _circle_center(center) + r * np.stack([(1 - s * s) / d, 2 * s / d], axis=-1)


def _circle_center(value):
    c = as_array(value, "center")
    if c.shape != (2,):
        raise ValueError(f"center must be a vector of 2 numbers, got shape {c.shape}")
    return c


# ---------------------------------------------------------------------------------------------
# curvature
# ---------------------------------------------------------------------------------------------

def _derivative_pair(d1, d2):
    a = as_array(d1, "d1")
    b = as_array(d2, "d2")
    if a.ndim < 1 or a.shape[-1] not in (2, 3):
        raise ValueError(f"d1 must hold 2D or 3D vectors in its last axis, got shape {a.shape}")
    if b.shape != a.shape:
        raise ValueError(f"d2 must have the shape of d1 {a.shape}, got {b.shape}")
    return a, b


def curvature(d1, d2, signed=False):
    r"""Curvature :math:`\kappa = \lVert P' \times P'' \rVert / \lVert P' \rVert^3` from P', P''.

    Why: with arc length s, :math:`\kappa = \lVert dT/ds \rVert`; writing
    :math:`P' = v T` (speed v) gives :math:`P'' = v' T + v^2 \kappa N`, so
    :math:`P' \times P'' = v^3 \kappa\, T \times N`. A circle of radius r has
    :math:`\kappa = 1/r`; a straight line 0. Where P' = 0 the curvature is undefined: 0 is
    returned there (no NaN).

    Parameters
    ----------
    d1, d2 : array_like, shape (..., 2) or (..., 3)
        First and second derivatives of the curve at the same parameters.
    signed : bool, default False
        2D only: positive when the curve turns left (counter-clockwise).

    Returns
    -------
    float or ndarray, shape d1.shape[:-1]

    Examples
    --------
    >>> curvature([0, 2], [-2, 0])              # circle of radius 2 at (2, 0): 1/2
    0.5
    >>> curvature([1, 0], [0, -2], signed=True)  # parabola y = -x^2 at its top: turns right
    -2.0
    """
    a, b = _derivative_pair(d1, d2)
    if a.shape[-1] == 2:
        cross = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
        if not signed:
            cross = np.abs(cross)
    else:
        if signed:
            raise ValueError("signed=True needs 2D vectors: a space curve's curvature has no "
                             "sign")
        cross = np.linalg.norm(np.cross(a, b), axis=-1)
    speed = np.linalg.norm(a, axis=-1)
    k = np.where(speed > 0, cross / np.where(speed > 0, speed, 1.0) ** 3, 0.0)
    return float(k) if k.ndim == 0 else k


def curvature_vector(d1, d2):
    r"""The curvature vector :math:`\kappa N = (P'' - (P'' \cdot T) T) / \lVert P' \rVert^2`.

    It points to the centre of the osculating circle and its length is :math:`\kappa`: two
    segments are G2 at a join when these vectors agree (equal curvature, same side, same
    osculating plane). Zero where P' = 0.

    Parameters
    ----------
    d1, d2 : array_like, shape (..., d), d = 2 or 3

    Returns
    -------
    ndarray, shape (..., d)

    Examples
    --------
    >>> curvature_vector([0, 2], [-2, 0])       # circle of radius 2 at (2, 0): towards the centre
    array([-0.5,  0. ])
    """
    a, b = _derivative_pair(d1, d2)
    v2 = np.sum(a * a, axis=-1, keepdims=True)
    safe = np.where(v2 > 0, v2, 1.0)
    normal_part = b - np.sum(a * b, axis=-1, keepdims=True) / safe * a
    return np.where(v2 > 0, normal_part / safe, 0.0)


def bezier_curvature(control_points, t, signed=False):
    r"""Curvature of a Bézier curve at t, from :func:`bezier_derivative` (orders 1 and 2).

    At the start of a degree-n curve this is
    :math:`\kappa(0) = \frac{n-1}{n} \frac{\lVert \Delta_0 \times \Delta_1 \rVert}
    {\lVert \Delta_0 \rVert^3}` with :math:`\Delta_0 = P_1 - P_0`, :math:`\Delta_1 = P_2 - P_1`.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d), d = 2 or 3
    t : float or array_like
        In [0, 1].
    signed : bool, default False
        2D only: positive where the curve turns left.

    Returns
    -------
    float or ndarray, shape t.shape

    Examples
    --------
    >>> bezier_curvature([[0, 0], [1, 0], [1, 1]], 0.0)   # (1/2) |(1,0) x (0,1)| / 1
    0.5
    """
    p = _control_points(control_points)
    return curvature(bezier_derivative(p, t, 1), bezier_derivative(p, t, 2), signed)


def curvature_comb(control_points, t, scale=1.0):
    r"""A curvature comb: at each sample, a tooth of length scale·κ along the normal.

    The teeth stand on the *outer* side of the bend (opposite the curvature vector), so their
    tips trace a second curve whose jumps show where the curvature jumps: at a G1 join the comb
    breaks, at a G2 join it is continuous. A straight piece has no teeth.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d), d = 2 or 3
        A Bézier curve.
    t : array_like, shape (k,)
        Samples in [0, 1].
    scale : float, default 1
        Tooth length per unit curvature (> 0).

    Returns
    -------
    base, tips : ndarray, shape (k, d)
        The curve points and the tooth tips, base - scale * kappa * N.

    Examples
    --------
    >>> base, tips = curvature_comb([[0, 0], [1, 0], [1, 1]], [0.0], scale=2.0)
    >>> tips                              # kappa(0) = 1/2, the bend turns to +y: tooth to -y
    array([[ 0., -1.]])
    """
    p = _control_points(control_points)
    s = as_positive(scale, "scale")
    tt = as_array(t, "t")
    if tt.ndim != 1:
        raise ValueError(f"t must be a 1D array of parameters, got shape {tt.shape}")
    if p.shape[1] not in (2, 3):
        raise ValueError(f"control_points must be 2D or 3D points, got {p.shape[1]} coordinates")
    base = bezier(p, tt)
    k_vec = curvature_vector(bezier_derivative(p, tt, 1), bezier_derivative(p, tt, 2))
    return base, base - s * k_vec


# ---------------------------------------------------------------------------------------------
# continuity at a join
# ---------------------------------------------------------------------------------------------

def _end_derivatives(curve, end, name):
    """[P, P', P''] at parameter `end` of a Bézier polygon or a callable f(t, order), and the
    curve's size for the relative tolerances (the polygon's extent; for a callable the larger
    of |P| and |P'| at the end)."""
    if callable(curve):
        out = []
        for k in range(3):
            v = as_array(curve(float(end), k), f"{name}({end}, {k})")
            if v.ndim != 1 or v.shape[0] not in (2, 3):
                raise ValueError(f"{name}(t, order) must return a 2D or 3D vector, got shape "
                                 f"{v.shape}")
            out.append(v)
        return np.array(out), float(max(np.max(np.abs(out[0])), np.max(np.abs(out[1]))))
    p = _control_points(curve, name)
    if p.shape[1] not in (2, 3):
        raise ValueError(f"{name} must be 2D or 3D points, got {p.shape[1]} coordinates")
    return (np.array([bezier_derivative(p, end, k) for k in range(3)]),
            float(np.max(np.abs(p - p.mean(axis=0)))))


def join_continuity(a, b, tol=1e-6):
    r"""The highest C^k and G^k (k <= 2) of the join A(1) = B(0) of two curve segments.

    Tests, in order (each level needs the previous one):

    * C0 = G0: :math:`\lVert A(1) - B(0) \rVert \le tol \cdot L` (L: the size of the control
      polygons, so the test does not depend on the units);
    * C1: :math:`A'(1) = B'(0)` and C2: also :math:`A''(1) = B''(0)`, each up to
      tol times the larger of the two vectors' lengths;
    * G1: the unit tangents differ by at most tol (the same direction; opposite tangents make a
      cusp and are *not* G1) and neither tangent vanishes;
    * G2: G1 and the curvature vectors :math:`\kappa N` (:func:`curvature_vector`) agree up to
      tol times the larger curvature (or 1/L): equal curvature, same side, same osculating
      plane.

    Both segments run over t in [0, 1]; for segments meant for parameter intervals of
    different lengths, scale the derivatives first (or compare G^k, which ignores the speed).

    Parameters
    ----------
    a, b : array_like, shape (n + 1, d), or callable
        Bézier control polygons (d = 2 or 3; any degrees), or functions ``f(t, order)``
        returning the `order`-th derivative (0, 1, 2) at t; A is taken at t = 1, B at t = 0.
    tol : float, default 1e-6
        Relative tolerance (> 0).

    Returns
    -------
    JoinContinuity
        ``(C, G, gap, tangent_angle, curvatures)``; C, G = -1 when the segments do not meet.

    Examples
    --------
    >>> A = [[0, 0], [1, 0], [2, 0], [3, 1]]
    >>> join_continuity(A, [[3, 1], [5, 3], [6, 3], [7, 2]])[:2]     # B' = 2 A': G1, not C1
    (0, 1)
    >>> join_continuity(A, [[3, 1], [4, 2], [5, 3], [6, 3]])[:2]     # C1, curvature jumps
    (1, 1)
    """
    tol = as_positive(tol, "tol")
    da, size_a = _end_derivatives(a, 1.0, "a")
    db, size_b = _end_derivatives(b, 0.0, "b")
    if da.shape != db.shape:
        raise ValueError(f"a and b must live in the same dimension, got {da.shape[1]}D and "
                         f"{db.shape[1]}D")
    size = max(size_a, size_b, 1e-300)
    gap = float(np.linalg.norm(da[0] - db[0]))
    ka = curvature_vector(da[1], da[2])
    kb = curvature_vector(db[1], db[2])
    kappas = (float(np.linalg.norm(ka)), float(np.linalg.norm(kb)))
    va, vb = np.linalg.norm(da[1]), np.linalg.norm(db[1])
    angle = (float(np.arccos(np.clip(da[1] @ db[1] / (va * vb), -1.0, 1.0)))
             if va > 0 and vb > 0 else float("nan"))
    if gap > tol * size:
        return JoinContinuity(-1, -1, gap, angle, kappas)

    def same(u, v, scale):
        return np.linalg.norm(u - v) <= tol * max(np.linalg.norm(u), np.linalg.norm(v), scale)

    c = 0
    if same(da[1], db[1], 0.0) and va > 0:
        c = 2 if same(da[2], db[2], 0.0) else 1
    g = 0
    if va > 1e-12 * size and vb > 1e-12 * size and np.linalg.norm(da[1] / va - db[1] / vb) <= tol:
        g = 2 if same(ka, kb, 1.0 / size) else 1
    return JoinContinuity(c, max(g, c), gap, angle, kappas)


def _continuity_order(value):
    c = as_choice(value, "continuity", JOINS)
    return c[0], int(c[1])


def join_points(control_points, continuity, degree=None, ratio=1.0, beta2=0.0):
    r"""The first points of the next Bézier segment that a continuity fixes.

    With A = control points :math:`P_0..P_n` (degree n, parameter interval length
    :math:`h_0`) and the next segment :math:`Q_0..Q_m` (degree m, interval :math:`h_1`), set
    the end derivatives equal in the *global* parameter (:math:`A' / h_0 = B' / h_1`):

    * C0: :math:`Q_0 = P_n` (nothing free in Q beyond Q0's rule);
    * C1: :math:`Q_1 = Q_0 + \frac{n}{m} r (P_n - P_{n-1})`, r = ratio = :math:`h_1 / h_0`
      (for equal degrees and intervals: Q1 is P_{n-1} mirrored through P_n);
    * C2: :math:`Q_2 = 2Q_1 - Q_0 + \frac{n(n-1)}{m(m-1)} r^2 (P_n - 2P_{n-1} + P_{n-2})`;
    * G1: as C1 with ratio = :math:`\beta_1 > 0` **free** (one free number: how far Q1 lies
      along the tangent);
    * G2: :math:`B''(0) = \beta_1^2 A''(1) + \beta_2 A'(1)` (the "beta constraints"), i.e.
      :math:`Q_2 = 2Q_1 - Q_0 + \frac{\beta_1^2 n(n-1) (P_n - 2P_{n-1} + P_{n-2})
      + \beta_2 n (P_n - P_{n-1})}{m(m-1)}` with :math:`\beta_1 > 0`, :math:`\beta_2`
      free: Q2 may slide on a line parallel to the tangent.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
        The previous segment (n >= the order of the continuity).
    continuity : {"C0", "G1", "C1", "G2", "C2"}
    degree : int, optional
        m, the next segment's degree (default n; must be >= the order, and >= 2 for G2/C2).
    ratio : float, default 1
        :math:`h_1 / h_0` for C1/C2, :math:`\beta_1` for G1/G2 (> 0).
    beta2 : float, default 0
        G2 only.

    Returns
    -------
    ndarray, shape (k + 1, d)
        :math:`Q_0, ..., Q_k` with k the order (0, 1 or 2).

    Examples
    --------
    >>> P = [[0, 0], [1, 1], [2, 1], [3, 0]]
    >>> join_points(P, "C1")                      # P2 mirrored through P3
    array([[ 3.,  0.],
           [ 4., -1.]])
    >>> join_points(P, "C1", degree=2)[1]         # a quadratic next: 3/2 of the step
    array([ 4.5, -1.5])
    """
    p = _control_points(control_points)
    kind, k = _continuity_order(continuity)
    n = len(p) - 1
    m = n if degree is None else as_whole(degree, "degree", 1, at_least=True)
    r = as_positive(ratio, "ratio", "h1 / h0 for C^k, beta1 for G^k")
    b2 = as_scalar(beta2, "beta2")
    if n < k:
        raise ValueError(f"control_points must have at least {k + 1} points for {continuity} "
                         f"(the {k}th derivative needs them), got {n + 1}")
    if m < max(k, 1) or (k == 2 and m < 2):
        raise ValueError(f"degree must be at least {max(k, 1)} for {continuity}, got {m}")
    if kind == "C" and b2 != 0:
        raise ValueError("beta2 is the free parameter of G2 only; use 0 for C^k")
    d1 = n * (p[n] - p[n - 1]) if n >= 1 else None
    if kind == "G" and not np.linalg.norm(d1) > 0:
        raise ValueError("control_points end with a repeated point: the end tangent vanishes "
                         "and G1 has no direction to follow")
    q = [p[n]]
    if k >= 1:
        q.append(q[0] + r * d1 / m)
    if k == 2:
        d2 = n * (n - 1) * (p[n] - 2 * p[n - 1] + p[n - 2])
        q.append(2 * q[1] - q[0] + (r * r * d2 + b2 * d1) / (m * (m - 1)))
    return np.array(q)


def constrain_join(P, Q, continuity):
    r"""Move as few of Q's first points as needed to make the join P -> Q reach a continuity.

    C0 moves Q0 onto P_n; C1 and C2 also set Q1 (and Q2) by :func:`join_points` with
    ratio 1 (equal parameter intervals); G1 keeps the length of Q's first leg
    :math:`\lVert Q_1 - Q_0 \rVert` (so :math:`\beta_1` = that length over
    :math:`\lVert P_n - P_{n-1} \rVert` times n/m) and turns it onto the tangent; G2 also slides
    Q2 to the nearest point of its allowed line (the :math:`\beta_2` closest to where it was).
    The other points of Q stay where they are.

    Parameters
    ----------
    P : array_like, shape (n + 1, d)
    Q : array_like, shape (m + 1, d)
    continuity : {"C0", "G1", "C1", "G2", "C2"}

    Returns
    -------
    ndarray, shape (m + 1, d)
        The new Q.

    Examples
    --------
    >>> P = [[0, 0], [1, 1], [2, 1], [3, 0]]
    >>> constrain_join(P, [[3, 0], [3, 2], [5, 1], [6, 0]], "G1").round(6)
    array([[ 3.      ,  0.      ],
           [ 4.414214, -1.414214],
           [ 5.      ,  1.      ],
           [ 6.      ,  0.      ]])
    """
    p = _control_points(P, "P")
    q = _control_points(Q, "Q").copy()
    if q.shape[1] != p.shape[1]:
        raise ValueError(f"Q must have the dimension of P ({p.shape[1]}), got {q.shape[1]}")
    kind, k = _continuity_order(continuity)
    n, m = len(p) - 1, len(q) - 1
    if m < k:
        raise ValueError(f"Q must have at least {k + 1} points for {continuity}, got {m + 1}")
    if kind == "C":
        new = join_points(p, continuity, degree=m)
        q[:k + 1] = new
        return q
    step = np.linalg.norm(p[n] - p[n - 1])
    leg = np.linalg.norm(q[1] - q[0])
    beta1 = (leg if leg > 0 else step * n / m) * m / (n * step) if step > 0 else 1.0
    new = join_points(p, "G1", degree=m, ratio=beta1)
    if k == 2:
        base = join_points(p, "G2", degree=m, ratio=beta1)[2]
        d1 = n * (p[n] - p[n - 1]) / (m * (m - 1))
        beta2 = float((q[2] - base) @ d1 / (d1 @ d1))
        new = join_points(p, "G2", degree=m, ratio=beta1, beta2=beta2)
    q[:k + 1] = new
    return q
