r"""Chapter 7: Bézier, B-spline and rational (NURBS) curves.

A curve of this chapter is a weighted sum of **control points** :math:`P_0, \dots, P_n`,

.. math:: C(t) = \sum_{i=0}^{n} F_i(t)\, P_i ,

where the blending functions :math:`F_i` are the Bernstein polynomials (Bézier curves), the
B-spline basis functions of a knot vector (B-spline curves), or either of them multiplied by
weights and divided by their weighted sum (rational Bézier curves and NURBS).

Conventions used throughout the module:

* Control points are the **rows** of an array of shape ``(n + 1, d)``, in any dimension
  ``d >= 1`` (a curve in 1D is a column, shape ``(n + 1, 1)``). At least two are needed.
* Every evaluation function is vectorized over the parameter: ``t`` may be a number or an array
  of any shape, and the result has shape ``t.shape + (d,)``.
* A Bézier curve is defined for :math:`t \in [0, 1]`. A B-spline of degree :math:`p` with
  ``n_control`` control points needs ``n_control + p + 1`` non-decreasing knots
  :math:`u_0 \le \dots \le u_{n+p+1}`; it is defined on its **domain**
  :math:`[u_p, u_{n_{control}}]` (see :func:`domain`), where the basis functions sum to one.
  Each knot span :math:`[u_k, u_{k+1})` is closed on the left and open on the right, except the
  last one, which also contains the end of the domain: ``t = b`` gives the left-hand limit of
  the curve, as ``scipy.interpolate.BSpline(..., extrapolate=False)`` does.
* A parameter outside the domain raises ``ValueError`` (no silent extrapolation); values within
  ``1e-12`` of the domain's length outside an end are rounded onto it.

References: L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer 1997 (chapters 1-5 and
7); G. Farin, *Curves and Surfaces for CAGD*, 5th ed., Morgan Kaufmann 2002.
"""
import math
from collections import namedtuple

import numpy as np

from ._validate import as_array, as_scalar, as_vector

__all__ = [
    "NurbsCurve",
    "bernstein",
    "bezier",
    "bezier_derivative",
    "bezier_elevate",
    "bezier_hodograph",
    "bezier_subdivide",
    "bezier_tangent",
    "bspline",
    "bspline_basis",
    "bspline_basis_derivative",
    "bspline_derivative",
    "clamped_knots",
    "conic_type",
    "de_boor",
    "de_casteljau",
    "domain",
    "find_span",
    "insert_knot",
    "nurbs",
    "nurbs_circle",
    "rational_bezier",
    "rational_quadratic_conic",
    "uniform_knots",
]

NurbsCurve = namedtuple("NurbsCurve", ["control_points", "weights", "knots", "degree"])
NurbsCurve.__doc__ = """A NURBS curve's data: unpacks as ``control_points, weights, knots, degree``.

Examples
--------
>>> curve = NurbsCurve([[0, 0], [1, 1]], [1, 1], [0, 0, 1, 1], 1)
>>> curve.degree
1
"""

_ROUND = 1e-12          # parameters this close (relative) outside the domain are rounded onto it


# ---------------------------------------------------------------------------------------------
# input checks (private: what _validate offers, specialised to curves)
# ---------------------------------------------------------------------------------------------

def _integer(value, name, minimum=0):
    """`value` as an int >= minimum (a whole float such as 3.0 is accepted), or raise."""
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got a bool")
    x = as_scalar(value, name)
    if not x.is_integer():
        raise ValueError(f"{name} must be a whole number, got {x!r}")
    if x < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {int(x)}")
    return int(x)


def _control_points(value, name="control_points", minimum=2):
    """Control points as a float array of shape (n + 1, d), with n + 1 >= minimum and d >= 1."""
    p = as_array(value, name)
    if p.ndim != 2:
        hint = (" (for a curve in 1D make the values a column: np.reshape(values, (-1, 1)))"
                if p.ndim == 1 else "")
        raise ValueError(f"{name} must be an array of points, one per row, shape (n + 1, d), "
                         f"got shape {p.shape}{hint}")
    if p.shape[0] < minimum:
        raise ValueError(f"{name} must hold at least {minimum} points (a curve of degree >= 1 "
                         f"needs two), got {p.shape[0]}")
    if p.shape[1] < 1:
        raise ValueError(f"{name} must have at least one coordinate per point, got shape "
                         f"{p.shape}")
    return p


def _degree(value, n_control, name="degree"):
    """A B-spline degree p with 1 <= p <= n_control - 1."""
    p = _integer(value, name)
    if p < 1:
        raise ValueError(f"{name} must be at least 1 (1 = linear, 2 = quadratic, 3 = cubic), "
                         f"got {p}")
    if p >= n_control:
        raise ValueError(f"{name} must be less than the number of control points (with "
                         f"n_control = {n_control} the degree is at most {n_control - 1}), "
                         f"got {p}")
    return p


def _knot_vector(value, degree, n_control=None, name="knots"):
    """A valid knot vector for `degree` (and `n_control` control points, when given).

    Returns ``(knots, n_control)``. Checks: a 1D array of finite numbers, of length
    n_control + degree + 1, non-decreasing, no value repeated more than degree + 1 times, and a
    non-empty domain ``[knots[degree], knots[n_control]]``.
    """
    u = as_array(value, name)
    if u.ndim != 1:
        raise ValueError(f"{name} must be a 1D array of numbers, got shape {u.shape}")
    if n_control is None:
        p = _integer(degree, "degree", 1)
        if len(u) < 2 * p + 2:
            raise ValueError(f"{name} must have at least 2 * degree + 2 = {2 * p + 2} values "
                             f"for degree {p} (n_control + degree + 1 with at least "
                             f"degree + 1 control points), got {len(u)}")
        n_control = len(u) - p - 1
    p = _degree(degree, n_control)
    wanted = n_control + p + 1
    if len(u) != wanted:
        raise ValueError(f"{name} must have n_control + degree + 1 = {n_control} + {p} + 1 = "
                         f"{wanted} values, got {len(u)}")
    step = np.diff(u)
    if np.any(step < 0):
        i = int(np.argmax(step < 0))
        raise ValueError(f"{name} must be non-decreasing, but {name}[{i}] = {float(u[i])!r} > "
                         f"{name}[{i + 1}] = {float(u[i + 1])!r}")
    values, counts = np.unique(u, return_counts=True)
    if counts.max() > p + 1:
        j = int(np.argmax(counts))
        raise ValueError(f"{name} must not repeat a value more than degree + 1 = {p + 1} times, "
                         f"but {float(values[j])!r} appears {counts[j]} times (a basis function "
                         "would vanish everywhere)")
    if not u[p] < u[n_control]:
        raise ValueError(f"{name} leave an empty domain: {name}[degree] = {name}[{p}] = "
                         f"{float(u[p])!r} must be less than {name}[n_control] = "
                         f"{name}[{n_control}] = {float(u[n_control])!r}")
    return u, n_control


def _weights(value, n_control, name="weights"):
    """Positive weights, one per control point."""
    w = as_array(value, name)
    if w.ndim != 1 or len(w) != n_control:
        raise ValueError(f"{name} must be a 1D array with one weight per control point "
                         f"({n_control}), got shape {w.shape}")
    if np.any(w <= 0):
        i = int(np.argmax(w <= 0))
        raise ValueError(f"{name} must be positive (a zero or negative weight breaks the convex "
                         f"hull property and can send the curve through infinity), got "
                         f"{name}[{i}] = {float(w[i])!r}")
    return w


def _parameters(value, lo, hi, name="t"):
    """Parameter values inside [lo, hi] (rounded onto it when within _ROUND of an end)."""
    t = as_array(value, name)
    slack = _ROUND * max(1.0, hi - lo)
    outside = (t < lo - slack) | (t > hi + slack)
    if np.any(outside):
        bad = t[outside].flat[0] if t.ndim else float(t)
        where = ""
        if t.ndim:
            index = tuple(int(i) for i in np.argwhere(outside)[0])
            where = f" at index {index[0] if len(index) == 1 else index}"
        raise ValueError(f"{name} must lie in the domain [{float(lo)!r}, {float(hi)!r}], "
                         f"got {float(bad)!r}{where}")
    return np.clip(t, lo, hi)


# ---------------------------------------------------------------------------------------------
# Bernstein polynomials and Bézier curves
# ---------------------------------------------------------------------------------------------

def _binomials(n):
    return np.array([math.comb(n, i) for i in range(n + 1)], dtype=float)


def _powers(x, n):
    """x^0, x^1, ..., x^n along a new last axis, by repeated multiplication (faster than **)."""
    out = np.empty(x.shape + (n + 1,))
    out[..., 0] = 1.0
    out[..., 1:] = x[..., None]
    return np.cumprod(out, axis=-1, out=out)


def _bernstein_matrix(n, t):
    """All Bernstein polynomials of degree n at t: shape t.shape + (n + 1,). No checks."""
    t = np.asarray(t, dtype=float)
    return _binomials(n) * _powers(t, n) * _powers(1.0 - t, n)[..., ::-1]


def bernstein(n, i, t):
    r"""Bernstein polynomial(s) :math:`B_i^n(t)`, the blending functions of Bézier curves.

    .. math:: B_i^n(t) = \binom{n}{i}\, t^i (1 - t)^{n - i}, \qquad i = 0, \dots, n

    On :math:`[0, 1]` they are non-negative and sum to one (expand :math:`(t + (1 - t))^n` with
    the binomial theorem), :math:`B_i^n(t) = B_{n-i}^n(1 - t)` (symmetry), and :math:`B_i^n` has
    its single maximum at :math:`t = i / n`. Outside :math:`[0, 1]` the polynomials are still
    evaluated (they are polynomials), but these properties no longer hold. The value
    :math:`0^0` counts as 1, so :math:`B_0^n(0) = B_n^n(1) = 1`.

    Parameters
    ----------
    n : int
        The degree, n >= 0.
    i : int, array_like of int, or None
        Which polynomial(s), 0 <= i <= n; broadcast against `t`. None gives all n + 1 of them.
    t : float or array_like
        Parameter values.

    Returns
    -------
    ndarray
        Shape ``broadcast(i, t).shape``; with ``i=None`` shape ``t.shape + (n + 1,)``, the
        polynomials along the last axis (a "Bernstein matrix": ``bernstein(n, None, t) @ P``
        is the Bézier curve of the control points ``P``).

    Raises
    ------
    ValueError
        If n is negative, i is outside 0..n or not a whole number, or t is not finite.

    Examples
    --------
    >>> float(bernstein(3, 1, 0.5))                # 3 * 0.5 * 0.5**2
    0.375
    >>> bernstein(2, None, [0.0, 0.5])
    array([[1.  , 0.  , 0.  ],
           [0.25, 0.5 , 0.25]])
    """
    n = _integer(n, "n", 0)
    t = as_array(t, "t")
    if i is None:
        return _bernstein_matrix(n, t)
    i = as_array(i, "i")
    if np.any(i != np.round(i)) or np.any((i < 0) | (i > n)):
        raise ValueError(f"i must be whole numbers from 0 to n = {n}, got "
                         f"{i.tolist() if i.ndim else float(i)!r}")
    i = i.astype(int)
    return _binomials(n)[i] * t ** i * (1.0 - t) ** (n - i)


def de_casteljau(control_points, t, triangle=False):
    r"""A point of the Bézier curve by de Casteljau's algorithm: repeated linear interpolation.

    .. math:: P_i^0 = P_i, \qquad
              P_i^r(t) = (1 - t)\, P_i^{r-1}(t) + t\, P_{i+1}^{r-1}(t), \qquad
              C(t) = P_0^n(t)

    (The NURBS Book, Sec. 1.4.) Each level interpolates between neighbours of
    the level before, so every intermediate point is a convex combination of the control points
    for :math:`t \in [0, 1]`: the geometric reason for the convex hull property. The triangle's
    two outer edges are the control polygons of the two halves, see :func:`bezier_subdivide`.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
    t : float or array_like
        Parameter values in [0, 1].
    triangle : bool, default False
        Also return every intermediate level of the scheme (for drawing the construction).

    Returns
    -------
    point : ndarray, shape t.shape + (d,)
    levels : list of n + 1 ndarrays, only with ``triangle=True``
        ``levels[r]`` has shape ``t.shape + (n + 1 - r, d)`` and holds the points
        :math:`P_0^r, \dots, P_{n-r}^r` in order: ``levels[0]`` is the control polygon, each
        level has one point less, ``levels[n]`` holds the curve point. To draw the construction
        for one t, plot every level as a polyline.

    Raises
    ------
    ValueError
        If there are fewer than two control points or a t lies outside [0, 1].

    Examples
    --------
    >>> P = [[0, 0], [1, 2], [2, 0]]
    >>> de_casteljau(P, 0.5)
    array([1., 1.])
    >>> point, levels = de_casteljau(P, 0.5, triangle=True)
    >>> [level.tolist() for level in levels]
    [[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], [[0.5, 1.0], [1.5, 1.0]], [[1.0, 1.0]]]
    """
    p = _control_points(control_points)
    t = _parameters(t, 0.0, 1.0)
    level = np.broadcast_to(p, t.shape + p.shape)
    tt = t[..., None, None]
    levels = [level]
    for _ in range(len(p) - 1):
        level = (1.0 - tt) * level[..., :-1, :] + tt * level[..., 1:, :]
        levels.append(level)
    point = level[..., 0, :]
    if triangle:
        return point, [np.array(lv) for lv in levels]
    return point


def bezier(control_points, t):
    r"""Points of the Bézier curve of the control points, for many parameter values at once.

    .. math:: C(t) = \sum_{i=0}^{n} B_i^n(t)\, P_i, \qquad t \in [0, 1]

    Computed as one matrix product, Bernstein matrix times control points (the same values as
    :func:`de_casteljau`, which is numerically more robust for very high degrees; both are fine
    for the degrees used in practice). Properties, each a consequence of the Bernstein
    polynomials' properties:

    * endpoint interpolation: :math:`C(0) = P_0`, :math:`C(1) = P_n`;
    * convex hull: every point is a convex combination of the control points;
    * affine invariance: applying an affine map to the control points applies it to the whole
      curve (it does *not* hold for a perspective projection: see :func:`rational_bezier`);
      likewise an affine change of the parameter, :math:`t = (s - a) / (b - a)`, only moves
      the points along the same curve;
    * symmetry: the reversed control points give the same curve, traversed backwards;
    * linear precision: control points on a line give a curve on that line (equally spaced
      ones even give the uniform parametrisation :math:`C(t) = (1 - t) P_0 + t P_n`);
    * variation diminishing: a line (plane in 3D) crosses the curve no more often than it
      crosses the control polygon;
    * pseudo-local control: moving :math:`P_i` by :math:`\delta` moves every point by
      :math:`B_i^n(t)\,\delta`, most near :math:`t = i / n` but (except at the ends) everywhere;
    * every polynomial curve of degree :math:`\le n` is a Bézier curve of degree n.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
    t : float or array_like
        Parameter values in [0, 1].

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Raises
    ------
    ValueError
        If there are fewer than two control points or a t lies outside [0, 1].

    Examples
    --------
    >>> bezier([[0, 0], [1, 2], [2, 0]], [0, 0.5, 1])
    array([[0., 0.],
           [1., 1.],
           [2., 0.]])
    """
    p = _control_points(control_points)
    t = _parameters(t, 0.0, 1.0)
    return _bernstein_matrix(len(p) - 1, t) @ p


def bezier_hodograph(control_points):
    r"""The control points of the derivative curve (the hodograph) of a Bézier curve.

    .. math:: C'(t) = \sum_{i=0}^{n-1} B_i^{n-1}(t)\, Q_i, \qquad Q_i = n\,(P_{i+1} - P_i)

    The derivative of a degree-n Bézier curve is a Bézier curve of degree n - 1 whose control
    points are the edges of the control polygon times n (The NURBS Book, Sec. 1.4).

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)

    Returns
    -------
    ndarray, shape (n, d)

    Examples
    --------
    >>> bezier_hodograph([[0, 0], [1, 2], [2, 0]])
    array([[ 2.,  4.],
           [ 2., -4.]])
    """
    p = _control_points(control_points)
    return (len(p) - 1) * np.diff(p, axis=0)


def _hodographs(p, order):
    """Control points of the `order`-th derivative (a single zero point beyond the degree)."""
    for _ in range(order):
        if len(p) == 1:
            return np.zeros_like(p)
        p = (len(p) - 1) * np.diff(p, axis=0)
    return p


def bezier_derivative(control_points, t, order=1):
    r"""The `order`-th derivative :math:`C^{(k)}(t)` of the Bézier curve, via the hodograph.

    Apply :func:`bezier_hodograph` k times (each time the degree drops by one) and evaluate the
    resulting Bézier curve. At the ends, :math:`C'(0) = n (P_1 - P_0)` and
    :math:`C'(1) = n (P_n - P_{n-1})`: the curve leaves along the first edge of the control
    polygon and arrives along the last one. Beyond the degree the derivative is zero.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
    t : float or array_like
        Parameter values in [0, 1].
    order : int, default 1
        k >= 0 (0 gives the curve itself).

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> bezier_derivative([[0, 0], [1, 2], [2, 0]], [0, 1])
    array([[ 2.,  4.],
           [ 2., -4.]])
    >>> bezier_derivative([[0, 0], [1, 2], [2, 0]], 0.3, order=2)
    array([ 0., -8.])
    """
    p = _control_points(control_points)
    order = _integer(order, "order", 0)
    t = _parameters(t, 0.0, 1.0)
    q = _hodographs(p, order)
    return _bernstein_matrix(len(q) - 1, t) @ q


def bezier_tangent(control_points, t):
    r"""Unit tangent vectors :math:`C'(t) / \lVert C'(t) \rVert` of the Bézier curve.

    Where the first derivative vanishes (an end with a repeated control point such as
    :math:`P_0 = P_1`, or a cusp) the curve still has a direction of travel: the tangent
    returned is the limit of :math:`C'(s) / \lVert C'(s) \rVert` as s approaches t from the
    right (from the left at t = 1). If :math:`C^{(k)}` is the first derivative that does not
    vanish at t, that limit is the direction of :math:`C^{(k)}(t)`, times :math:`(-1)^{k-1}` at
    t = 1 (Taylor: :math:`C'(t + h) \approx C^{(k)}(t)\, h^{k-1} / (k-1)!`). At an interior
    cusp the tangent flips there, so the limit from the left is the opposite vector.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
    t : float or array_like
        Parameter values in [0, 1].

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Raises
    ------
    ValueError
        If all control points coincide: the curve is a single point and has no tangent.

    Examples
    --------
    >>> bezier_tangent([[0, 0], [1, 0], [1, 1]], [0, 1])
    array([[1., 0.],
           [0., 1.]])
    >>> bezier_tangent([[0, 0], [0, 0], [2, 1], [3, 0]], 0)    # P0 = P1: along P2 - P0
    array([0.89442719, 0.4472136 ])
    """
    p = _control_points(control_points)
    t = _parameters(t, 0.0, 1.0)
    if np.ptp(p, axis=0).max() == 0:
        raise ValueError("control_points all coincide: the curve is a single point and has no "
                         "tangent")
    flat = t.reshape(-1)
    tangent = np.zeros((len(flat), p.shape[1]))
    todo = np.ones(len(flat), dtype=bool)
    q = p
    for k in range(1, len(p)):
        q = (len(q) - 1) * np.diff(q, axis=0)                      # k-th hodograph
        value = _bernstein_matrix(len(q) - 1, flat[todo]) @ q
        length = np.linalg.norm(value, axis=-1)
        ok = length > 1e-10 * np.linalg.norm(q, axis=-1).max()
        sign = np.where((flat[todo] == 1.0) & (k % 2 == 0), -1.0, 1.0)
        index = np.flatnonzero(todo)[ok]
        tangent[index] = sign[ok, None] * value[ok] / length[ok, None]
        todo[index] = False
        if not todo.any():
            break
    if todo.any():                                    # only through rounding: report it
        raise ValueError(f"t = {float(flat[todo][0])!r}: every derivative of the curve "
                         "vanishes there (within rounding), so it has no tangent")
    return tangent.reshape(t.shape + (p.shape[1],))


def bezier_subdivide(control_points, t=0.5):
    r"""Split a Bézier curve at `t` into two Bézier curves of the same degree.

    The left curve's control points are the first points of the levels of de Casteljau's
    triangle, :math:`P_0^0, P_0^1, \dots, P_0^n`, and the right curve's the last points,
    :math:`P_0^n, P_1^{n-1}, \dots, P_n^0` (The NURBS Book, Sec. 1.4; Farin, ch. 5). The left
    curve on [0, 1] is the original on [0, t] (``left(s) = C(t s)``), the right one the original
    on [t, 1] (``right(s) = C(t + (1 - t) s)``). Repeated subdivision makes the control polygons
    converge to the curve: a fast way to draw it.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
    t : float, default 0.5
        Where to split, in [0, 1].

    Returns
    -------
    left, right : ndarray, shape (n + 1, d) each

    Examples
    --------
    >>> left, right = bezier_subdivide([[0, 0], [1, 2], [2, 0]], 0.5)
    >>> left
    array([[0. , 0. ],
           [0.5, 1. ],
           [1. , 1. ]])
    >>> right
    array([[1. , 1. ],
           [1.5, 1. ],
           [2. , 0. ]])
    """
    p = _control_points(control_points)
    t = _parameters(as_scalar(t, "t"), 0.0, 1.0)
    _, levels = de_casteljau(p, t, triangle=True)
    left = np.array([level[0] for level in levels])
    right = np.array([level[-1] for level in reversed(levels)])
    return left, right


def bezier_elevate(control_points, times=1):
    r"""Degree elevation: the same curve as a Bézier curve of degree n + `times`.

    One step from degree n to n + 1 (The NURBS Book, Sec. 5.5; Farin, ch. 6):

    .. math:: Q_i = \frac{i}{n + 1}\, P_{i-1} + \Big(1 - \frac{i}{n + 1}\Big) P_i,
              \qquad i = 0, \dots, n + 1

    (multiply the curve by :math:`(1 - t) + t = 1` and collect terms). The new control polygon
    is obtained by cutting the corners of the old one; repeated elevation makes it converge to
    the curve.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
    times : int, default 1
        How many degrees to add (>= 0).

    Returns
    -------
    ndarray, shape (n + 1 + times, d)

    Examples
    --------
    >>> bezier_elevate([[0, 0], [3, 3]])          # a line as a quadratic: the midpoint added
    array([[0. , 0. ],
           [1.5, 1.5],
           [3. , 3. ]])
    """
    p = _control_points(control_points)
    times = _integer(times, "times", 0)
    for _ in range(times):
        n = len(p) - 1
        a = (np.arange(1, n + 1) / (n + 1))[:, None]
        p = np.concatenate([p[:1], a * p[:-1] + (1.0 - a) * p[1:], p[-1:]])
    return p


# ---------------------------------------------------------------------------------------------
# B-splines: knot vectors, basis functions, de Boor's algorithm
# ---------------------------------------------------------------------------------------------

def clamped_knots(n_control, degree):
    r"""The clamped (open uniform) knot vector on [0, 1]: a B-spline that ends in its end points.

    .. math:: \underbrace{0, \dots, 0}_{p + 1},\ \frac{1}{n - p}, \frac{2}{n - p}, \dots,
              \frac{n - p - 1}{n - p},\ \underbrace{1, \dots, 1}_{p + 1}

    with :math:`n` = `n_control` and :math:`p` = `degree`: the end knots repeated degree + 1
    times, the n - p - 1 interior knots equally spaced. The curve interpolates its first and
    last control points and is tangent to the control polygon there. With n_control =
    degree + 1 there are no interior knots and the B-spline is the Bézier curve.

    Parameters
    ----------
    n_control : int
        Number of control points (>= 2).
    degree : int
        1 <= degree <= n_control - 1.

    Returns
    -------
    ndarray, shape (n_control + degree + 1,)
        Its domain is [0, 1].

    Examples
    --------
    >>> clamped_knots(5, 2)
    array([0.        , 0.        , 0.        , 0.33333333, 0.66666667,
           1.        , 1.        , 1.        ])
    """
    n = _integer(n_control, "n_control", 2)
    p = _degree(degree, n)
    inner = np.arange(1, n - p) / (n - p)
    return np.concatenate([np.zeros(p + 1), inner, np.ones(p + 1)])


def uniform_knots(n_control, degree):
    r"""The uniform (unclamped, "periodic-style") knot vector whose domain is [0, 1].

    Equally spaced knots :math:`u_j = (j - p) / (n - p)`, :math:`j = 0, \dots, n + p`
    (n = `n_control`, p = `degree`), so that the domain
    :math:`[u_p, u_n] = [0, 1]`; the first and last p knots lie outside it. Every basis
    function is a shifted copy of the same bell-shaped piece; the curve starts and ends
    *near*, not at, the first and last control points.

    Parameters
    ----------
    n_control : int
        Number of control points (>= 2).
    degree : int
        1 <= degree <= n_control - 1.

    Returns
    -------
    ndarray, shape (n_control + degree + 1,)

    Examples
    --------
    >>> uniform_knots(4, 2)
    array([-1. , -0.5,  0. ,  0.5,  1. ,  1.5,  2. ])
    >>> domain(uniform_knots(4, 2), 2)
    (0.0, 1.0)
    """
    n = _integer(n_control, "n_control", 2)
    p = _degree(degree, n)
    return (np.arange(n + p + 1) - p) / (n - p)


def domain(knots, degree):
    r"""The parameter interval :math:`[u_p, u_{n}]` on which a B-spline curve is defined.

    With n = ``len(knots) - degree - 1`` control points, the basis functions sum to one exactly
    on :math:`[u_p, u_n]`: there p + 1 basis functions are active on every knot span.

    Parameters
    ----------
    knots : array_like, shape (n_control + degree + 1,)
    degree : int

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> domain([0, 0, 0, 0.5, 1, 1, 1], 2)
    (0.0, 1.0)
    >>> domain([0, 1, 2, 3, 4, 5, 6, 7], 3)
    (3.0, 4.0)
    """
    u, n = _knot_vector(knots, degree)
    p = int(degree)
    return float(u[p]), float(u[n])


def _spans(u, t, end):
    """Indices k with u[k] <= t < u[k+1]; a t equal to `end` gets the last non-empty span
    before it (the right-closed last span). No checks."""
    k = np.searchsorted(u, t, side="right") - 1
    last = np.searchsorted(u, end, side="left") - 1
    return np.where(t >= end, last, k)


def find_span(knots, degree, t):
    r"""The knot span index k of each t: :math:`u_k \le t < u_{k+1}`, p <= k < n_control.

    The span tells which basis functions are active at t: :math:`N_{k-p,p}, \dots, N_{k,p}`,
    so which control points :math:`P_{k-p}, \dots, P_k` shape the curve there (The NURBS Book,
    algorithm A2.1, done for all t at once with ``np.searchsorted``). The last span is closed:
    t at the end of the domain gets the last non-empty span, k <= n_control - 1.

    Parameters
    ----------
    knots : array_like, shape (n_control + degree + 1,)
    degree : int
    t : float or array_like
        Parameter values in the domain (see :func:`domain`).

    Returns
    -------
    int or ndarray of int, shape t.shape

    Examples
    --------
    >>> find_span([0, 0, 0, 0.5, 1, 1, 1], 2, [0, 0.25, 0.5, 1])
    array([2, 2, 3, 3])
    """
    u, n = _knot_vector(knots, degree)
    p = int(degree)
    t = _parameters(t, u[p], u[n])
    k = _spans(u, t, u[n])
    return int(k) if k.ndim == 0 else k


def _inverse(x):
    """1 / x, with 1 / 0 := 0 (the 0/0 = 0 convention of the Cox-de Boor formula)."""
    safe = np.where(x > 0, x, 1.0)
    return np.where(x > 0, 1.0 / safe, 0.0)


def _basis_up_to(u, spans, t, degree):
    """Cox-de Boor: all len(u) - 1 - degree basis functions of `degree` at t (1D), shape
    (len(t), len(u) - 1 - degree), starting from the degree-0 indicator of each t's span."""
    m = len(u) - 1
    n = np.zeros((len(t), m))
    n[np.arange(len(t)), spans] = 1.0
    tt = t[:, None]
    for r in range(1, degree + 1):
        left = (tt - u[:m - r]) * _inverse(u[r:m] - u[:m - r])
        right = (u[r + 1:] - tt) * _inverse(u[r + 1:] - u[1:m - r + 1])
        n = left * n[:, :-1] + right * n[:, 1:]
    return n


def _basis_input(knots, degree, t, full_range):
    u, n = _knot_vector(knots, degree)
    p = int(degree)
    if full_range:
        lo, hi = u[0], u[-1]
    else:
        lo, hi = u[p], u[n]
    t = _parameters(t, lo, hi)
    flat = t.reshape(-1)
    return u, n, p, t, flat, _spans(u, flat, hi)


def bspline_basis(knots, degree, t, full_range=False):
    r"""All B-spline basis functions :math:`N_{i,p}(t)` at once, by the Cox-de Boor recursion.

    .. math:: N_{i,0}(t) = \begin{cases} 1 & u_i \le t < u_{i+1} \\ 0 & \text{otherwise}
              \end{cases}

    .. math:: N_{i,p}(t) = \frac{t - u_i}{u_{i+p} - u_i}\, N_{i,p-1}(t)
              + \frac{u_{i+p+1} - t}{u_{i+p+1} - u_{i+1}}\, N_{i+1,p-1}(t)

    with the convention 0/0 = 0 for repeated knots (The NURBS Book, Sec. 2.2). :math:`N_{i,p}`
    is a piecewise polynomial of degree p, positive on :math:`(u_i, u_{i+p+1})` and zero
    elsewhere (local support), :math:`C^{p-m}` at a knot of multiplicity m. Inside the domain
    :math:`[u_p, u_{n_{control}}]` the functions are non-negative and sum to one.

    Parameters
    ----------
    knots : array_like, shape (n_control + degree + 1,)
        Non-decreasing knots, no value repeated more than degree + 1 times.
    degree : int
        p >= 1.
    t : float or array_like
        Parameter values in the domain (see :func:`domain`), or anywhere in
        ``[knots[0], knots[-1]]`` with ``full_range=True``.
    full_range : bool, default False
        Allow t over the whole knot vector, to draw every basis function's full support (for a
        uniform knot vector, the familiar row of identical bells). Outside the domain the
        functions do not sum to one. The last non-empty span is then closed at ``knots[-1]``
        (instead of at the end of the domain).

    Returns
    -------
    ndarray, shape t.shape + (n_control,)
        ``N[..., i]`` is :math:`N_{i,p}(t)`; ``bspline_basis(knots, p, t) @ P`` is the curve.

    Raises
    ------
    ValueError
        For an invalid knot vector or degree, or t outside the allowed interval.

    Examples
    --------
    >>> bspline_basis([0, 0, 0, 1, 2, 2, 2], 2, [0.0, 1.0, 1.5])
    array([[1.   , 0.   , 0.   , 0.   ],
           [0.   , 0.5  , 0.5  , 0.   ],
           [0.   , 0.125, 0.625, 0.25 ]])
    """
    u, n, p, t, flat, spans = _basis_input(knots, degree, t, full_range)
    return _basis_up_to(u, spans, flat, p).reshape(t.shape + (n,))


def bspline_basis_derivative(knots, degree, t, order=1, full_range=False):
    r"""Derivatives :math:`N^{(k)}_{i,p}(t)` of all B-spline basis functions.

    .. math:: N^{(k)}_{i,p} = p \left( \frac{N^{(k-1)}_{i,p-1}}{u_{i+p} - u_i}
              - \frac{N^{(k-1)}_{i+1,p-1}}{u_{i+p+1} - u_{i+1}} \right)

    (The NURBS Book, Sec. 2.3; 0/0 = 0 again). At a knot where the derivative jumps, the value
    from the right is returned (from the left at the end of the domain), as scipy does.

    Parameters
    ----------
    knots, degree, t, full_range
        As in :func:`bspline_basis`.
    order : int, default 1
        k >= 0; beyond the degree the derivatives are zero.

    Returns
    -------
    ndarray, shape t.shape + (n_control,)

    Examples
    --------
    >>> bspline_basis_derivative([0, 0, 0, 1, 1, 1], 2, [0.0, 0.5])   # Bernstein: 2(t-1), ...
    array([[-2.,  2.,  0.],
           [-1.,  0.,  1.]])
    """
    u, n, p, t, flat, spans = _basis_input(knots, degree, t, full_range)
    k = _integer(order, "order", 0)
    if k > p:
        return np.zeros(t.shape + (n,))
    m = len(u) - 1
    d = _basis_up_to(u, spans, flat, p - k)
    for j in range(p - k + 1, p + 1):
        d = j * (d[:, :-1] * _inverse(u[j:m] - u[:m - j])
                 - d[:, 1:] * _inverse(u[j + 1:] - u[1:m - j + 1]))
    return d.reshape(t.shape + (n,))


def _de_boor(p_ctrl, u, degree, t, end):
    """de Boor's triangle on arrays: t 1D, result (len(t), d). No checks."""
    # Stored coordinate-major, d[c, j, m] (coordinate, triangle entry, parameter value), so
    # that every numpy operation runs over long contiguous rows of parameter values.
    p = degree
    k = _spans(u, t, end)
    d = np.take(p_ctrl.T, k + np.arange(-p, 1)[:, None], axis=1)  # (d, p + 1, m): P_{k-p..k}
    window = np.take(u, k + np.arange(-p + 1, p + 1)[:, None])     # (2p, m): u_{k-p+1..k+p}
    for r in range(1, p + 1):
        # the points d_j, j = k-p+r .. k, blend with alpha = (t - u_j) / (u_{j+p+1-r} - u_j)
        lo = window[r - 1:p]
        alpha = (t - lo) / (window[p:2 * p - r + 1] - lo)
        d0 = d[:, :-1]
        d = d[:, 1:] - d0                                         # (1 - alpha) d0 + alpha d1,
        d *= alpha                                                # computed in place
        d += d0
    return d[:, 0].T


def bspline(control_points, knots, degree, t):
    r"""Points of the B-spline curve :math:`C(t) = \sum_i N_{i,p}(t)\, P_i` by de Boor's algorithm.

    For t in the span :math:`[u_k, u_{k+1})` only :math:`P_{k-p}, \dots, P_k` matter. Start with
    them, :math:`d_j^0 = P_j`, and blend neighbours p times:

    .. math:: d_j^r = (1 - \alpha_j^r)\, d_{j-1}^{r-1} + \alpha_j^r\, d_j^{r-1}, \qquad
              \alpha_j^r = \frac{t - u_j}{u_{j+p+1-r} - u_j}, \qquad j = k-p+r, \dots, k

    and :math:`C(t) = d_k^p` (C. de Boor 1972; The NURBS Book, Sec. 5.2, where it appears as
    inserting t until it has multiplicity p). All parameter values are done at once: the spans
    by ``np.searchsorted``, the triangle on arrays of shape ``(d, p + 1, len(t))``.

    Properties: local control (moving :math:`P_i` changes the curve only for
    :math:`t \in [u_i, u_{i+p+1})`), strong convex hull (for t in a span the point lies in the
    convex hull of that span's p + 1 active control points), affine invariance (for the control
    points, and for the parameter: scaling and shifting all knots and t alike gives the same
    points), variation diminishing, and a clamped knot vector (:func:`clamped_knots`) makes the
    curve start at :math:`P_0` and end at :math:`P_n`.

    Parameters
    ----------
    control_points : array_like, shape (n_control, d)
    knots : array_like, shape (n_control + degree + 1,)
        Non-decreasing, no value more than degree + 1 times, e.g. :func:`clamped_knots` or
        :func:`uniform_knots`.
    degree : int
        1 <= degree <= n_control - 1.
    t : float or array_like
        Parameter values in the domain ``[knots[degree], knots[n_control]]``.

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Raises
    ------
    ValueError
        If ``len(knots) != n_control + degree + 1``, the knots decrease, the degree is out of
        range, or a t lies outside the domain.

    Examples
    --------
    >>> P = [[0, 0], [1, 2], [3, 2], [4, 0]]
    >>> bspline(P, clamped_knots(4, 2), 2, [0, 0.25, 0.5, 1])   # knots 0, 0, 0, 0.5, 1, 1, 1
    array([[0. , 0. ],
           [1. , 1.5],
           [2. , 2. ],
           [4. , 0. ]])
    """
    p_ctrl = _control_points(control_points)
    u, n = _knot_vector(knots, degree, len(p_ctrl))
    p = int(degree)
    t = _parameters(t, u[p], u[n])
    return _de_boor(p_ctrl, u, p, t.reshape(-1), u[n]).reshape(t.shape + (p_ctrl.shape[1],))


def de_boor(control_points, knots, degree, t):
    r"""de Boor's triangle for one parameter value t, for drawing the construction.

    The same scheme as :func:`bspline` (see there for the formula), keeping every level.

    Parameters
    ----------
    control_points : array_like, shape (n_control, d)
    knots : array_like, shape (n_control + degree + 1,)
    degree : int
    t : float
        One parameter value in the domain.

    Returns
    -------
    point : ndarray, shape (d,)
    span : int
        k with :math:`u_k \le t < u_{k+1}`: the active control points are
        ``control_points[k - degree : k + 1]``.
    levels : list of degree + 1 ndarrays
        ``levels[r]`` has shape ``(degree + 1 - r, d)``: ``levels[0]`` are the active control
        points, each further level one point less, ``levels[degree]`` holds the curve point.

    Examples
    --------
    >>> point, span, levels = de_boor([[0, 0], [1, 2], [3, 2], [4, 0]], [0, 0, 0, 1, 2, 2, 2],
    ...                               2, 0.5)
    >>> point, span
    (array([1. , 1.5]), 2)
    >>> [level.tolist() for level in levels]
    [[[0.0, 0.0], [1.0, 2.0], [3.0, 2.0]], [[0.5, 1.0], [1.5, 2.0]], [[1.0, 1.5]]]
    """
    p_ctrl = _control_points(control_points)
    u, n = _knot_vector(knots, degree, len(p_ctrl))
    p = int(degree)
    t = _parameters(as_scalar(t, "t"), u[p], u[n])
    k = int(_spans(u, t, u[n]))
    d = p_ctrl[k - p:k + 1]
    levels = [d.copy()]
    for r in range(1, p + 1):
        i = np.arange(k - p + r, k + 1)
        alpha = ((t - u[i]) / (u[i + p + 1 - r] - u[i]))[:, None]
        d = (1.0 - alpha) * d[:-1] + alpha * d[1:]
        levels.append(d)
    return d[0].copy(), k, levels


def bspline_derivative(control_points, knots, degree, t, order=1):
    r"""The `order`-th derivative of the B-spline curve, :math:`\sum_i N^{(k)}_{i,p}(t)\, P_i`.

    (The derivative of a B-spline of degree p is a B-spline of degree p - 1 with control points
    :math:`p\,(P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1})`; here it is computed with the basis
    derivatives of :func:`bspline_basis_derivative`.) At a knot where the derivative jumps, the
    value from the right is returned (from the left at the end of the domain).

    Parameters
    ----------
    control_points, knots, degree, t
        As in :func:`bspline`.
    order : int, default 1

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> bspline_derivative([[0, 0], [1, 2], [3, 2], [4, 0]], [0, 0, 0, 1, 2, 2, 2], 2, [0, 2])
    array([[ 2.,  4.],
           [ 2., -4.]])
    """
    p_ctrl = _control_points(control_points)
    _knot_vector(knots, degree, len(p_ctrl))
    return bspline_basis_derivative(knots, degree, t, order) @ p_ctrl


def insert_knot(control_points, knots, degree, u, times=1):
    r"""Knot insertion (Boehm's algorithm): more control points, the very same curve.

    Inserting :math:`\bar u \in [u_k, u_{k+1})` once replaces the control points
    :math:`P_{k-p+1}, \dots, P_k` by p + 1 new ones on the edges of the control polygon:

    .. math:: Q_i = (1 - \alpha_i)\, P_{i-1} + \alpha_i\, P_i, \qquad
              \alpha_i = \frac{\bar u - u_i}{u_{i+p} - u_i}, \qquad i = k-p+1, \dots, k

    (:math:`Q_i = P_i` before and :math:`Q_i = P_{i-1}` after; The NURBS Book, Sec. 5.2).
    Insertion is repeated `times` times. Inserting a knot until its multiplicity is p makes
    the curve pass through a control point (split it there); it is also how a B-spline is
    converted to Bézier pieces.

    Parameters
    ----------
    control_points : array_like, shape (n_control, d)
    knots : array_like, shape (n_control + degree + 1,)
    degree : int
    u : float
        The new knot, in the domain.
    times : int, default 1
        How often to insert it; its multiplicity may not exceed degree + 1.

    Returns
    -------
    control_points : ndarray, shape (n_control + times, d)
    knots : ndarray, shape (n_control + times + degree + 1,)

    Examples
    --------
    >>> P, U = insert_knot([[0, 0], [1, 2], [2, 0]], [0, 0, 0, 1, 1, 1], 2, 0.5)
    >>> P
    array([[0. , 0. ],
           [0.5, 1. ],
           [1.5, 1. ],
           [2. , 0. ]])
    >>> U
    array([0. , 0. , 0. , 0.5, 1. , 1. , 1. ])
    """
    p_ctrl = _control_points(control_points)
    knots, n = _knot_vector(knots, degree, len(p_ctrl))
    p = int(degree)
    ubar = float(_parameters(as_scalar(u, "u"), knots[p], knots[n], name="u"))
    times = _integer(times, "times", 0)
    s = int(np.count_nonzero(knots == ubar))
    if s + times > p + 1:
        raise ValueError(f"times = {times} is too many: u = {ubar!r} already appears {s} times "
                         f"in knots, and a knot may appear at most degree + 1 = {p + 1} times")
    for _ in range(times):
        end = knots[len(p_ctrl)]
        k = int(_spans(knots, np.array(ubar), end))
        i = np.arange(k - p + 1, k + 1)
        alpha = ((ubar - knots[i]) / (knots[i + p] - knots[i]))[:, None]
        p_ctrl = np.concatenate([p_ctrl[:k - p + 1],
                                 (1.0 - alpha) * p_ctrl[i - 1] + alpha * p_ctrl[i],
                                 p_ctrl[k:]])
        knots = np.insert(knots, k + 1, ubar)
    return p_ctrl, knots


# ---------------------------------------------------------------------------------------------
# Rational curves: rational Bézier, NURBS, conics and the circle
# ---------------------------------------------------------------------------------------------

def _homogeneous(p, w):
    return np.concatenate([p * w[:, None], w[:, None]], axis=1)


def rational_bezier(control_points, weights, t):
    r"""Points of the rational Bézier curve with positive `weights`.

    .. math:: C(t) = \frac{\sum_i B_i^n(t)\, w_i P_i}{\sum_i B_i^n(t)\, w_i}

    Computed in homogeneous coordinates: the Bézier curve of the points :math:`(w_i P_i, w_i)`
    one dimension up, followed by the division by the last coordinate (The NURBS Book,
    Sec. 1.5). A larger weight pulls the curve towards its control point; equal weights give
    the ordinary Bézier curve. With positive weights the blending functions are still
    non-negative and sum to one, so the convex hull property, endpoint interpolation, symmetry
    and variation diminishing carry over. Besides affine maps, the curve is also invariant
    under **projective** transformations (perspective): transform the homogeneous points
    :math:`(w_i P_i, w_i)` by the 4x4 (3x3 in 2D) matrix and the new last coordinates are the
    new weights. (A non-rational curve is only affinely invariant.) Rational curves represent
    conics exactly, see :func:`rational_quadratic_conic`.

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
    weights : array_like, shape (n + 1,)
        Positive.
    t : float or array_like
        Parameter values in [0, 1].

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Raises
    ------
    ValueError
        For a non-positive weight, a wrong number of weights, or t outside [0, 1].

    Examples
    --------
    >>> import numpy as np
    >>> quarter = rational_bezier([[1, 0], [1, 1], [0, 1]], [1, np.sqrt(0.5), 1], 0.5)
    >>> quarter, float(np.hypot(*quarter))        # on the unit circle
    (array([0.70710678, 0.70710678]), 1.0)
    """
    p = _control_points(control_points)
    w = _weights(weights, len(p))
    t = _parameters(t, 0.0, 1.0)
    h = _bernstein_matrix(len(p) - 1, t) @ _homogeneous(p, w)
    return h[..., :-1] / h[..., -1:]


def nurbs(control_points, weights, knots, degree, t):
    r"""Points of the NURBS curve (non-uniform rational B-spline) with positive `weights`.

    .. math:: C(t) = \frac{\sum_i N_{i,p}(t)\, w_i P_i}{\sum_i N_{i,p}(t)\, w_i}

    Computed in homogeneous coordinates: :func:`bspline` of the points :math:`(w_i P_i, w_i)`,
    then the division by the last coordinate (The NURBS Book, Sec. 4.2). NURBS combine the
    properties of the other curves: local control, strong convex hull and variation
    diminishing (positive weights), affine and projective invariance, exact conics and circles
    (:func:`nurbs_circle`). Equal weights give the non-rational B-spline.

    Parameters
    ----------
    control_points : array_like, shape (n_control, d)
    weights : array_like, shape (n_control,)
        Positive.
    knots : array_like, shape (n_control + degree + 1,)
    degree : int
    t : float or array_like
        Parameter values in the domain.

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> import numpy as np
    >>> circle = nurbs_circle()
    >>> points = nurbs(*circle, np.linspace(0, 1, 5))
    >>> np.round(points, 12) + 0.0
    array([[ 1.,  0.],
           [ 0.,  1.],
           [-1.,  0.],
           [ 0., -1.],
           [ 1.,  0.]])
    """
    p_ctrl = _control_points(control_points)
    w = _weights(weights, len(p_ctrl))
    u, n = _knot_vector(knots, degree, len(p_ctrl))
    p = int(degree)
    t = _parameters(t, u[p], u[n])
    h = _de_boor(_homogeneous(p_ctrl, w), u, p, t.reshape(-1), u[n])
    return (h[:, :-1] / h[:, -1:]).reshape(t.shape + (p_ctrl.shape[1],))


def nurbs_circle(radius=1.0, center=(0.0, 0.0)):
    r"""An exact full circle as a quadratic NURBS curve: 9 control points on a square.

    Four quarter circles, each a rational quadratic Bézier arc whose middle control point is a
    corner of the circumscribed square, with weight :math:`\cos 45° = \sqrt2 / 2` (The NURBS
    Book, Sec. 7.5). The knots :math:`0,0,0,\frac14,\frac14,\frac12,\frac12,\frac34,\frac34,
    1,1,1` make each quarter its own piece. Every point is at distance `radius` from the centre
    (up to rounding); the speed is not constant, so equal steps in t are not equal angles
    (t = 1/8 is at 45°, but t = 1/16 is not at 22.5°). Starts and ends at angle 0, turning
    counter-clockwise.

    Parameters
    ----------
    radius : float, default 1
        Positive.
    center : array_like, shape (2,)

    Returns
    -------
    NurbsCurve
        ``(control_points (9, 2), weights (9,), knots (12,), degree 2)``; unpack it into
        :func:`nurbs`: ``nurbs(*nurbs_circle(), t)``.

    Examples
    --------
    >>> import numpy as np
    >>> P, w, U, p = nurbs_circle(2.0, (1, 1))
    >>> points = nurbs(P, w, U, p, np.linspace(0, 1, 1001))
    >>> bool(np.allclose(np.linalg.norm(points - (1, 1), axis=1), 2.0, rtol=0, atol=1e-12))
    True
    """
    r = as_scalar(radius, "radius")
    if r <= 0:
        raise ValueError(f"radius must be positive, got {r!r}")
    c = as_vector(center, "center", 2)
    square = np.array([[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1],
                       [1, 0]], dtype=float)
    s = np.sqrt(0.5)
    weights = np.array([1, s, 1, s, 1, s, 1, s, 1])
    knots = np.array([0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1])
    return NurbsCurve(c + r * square, weights, knots, 2)


def conic_type(w):
    r"""Which conic the rational quadratic Bézier arc with weights (1, w, 1) lies on.

    With the end weights 1 (any positive arc can be brought to this standard form by
    reparametrising), the middle weight alone decides:
    w < 1 ellipse, w = 1 parabola (the non-rational quadratic), w > 1 hyperbola
    (The NURBS Book, Sec. 7.3; Farin, ch. 12). The test is exact: a weight that is only
    close to 1 gives an ellipse or a hyperbola.

    Parameters
    ----------
    w : float
        Positive.

    Returns
    -------
    {"ellipse", "parabola", "hyperbola"}

    Examples
    --------
    >>> conic_type(0.5), conic_type(1), conic_type(3)
    ('ellipse', 'parabola', 'hyperbola')
    """
    w = as_scalar(w, "w")
    if w <= 0:
        raise ValueError(f"w must be positive, got {w!r}")
    return "ellipse" if w < 1 else "parabola" if w == 1 else "hyperbola"


def rational_quadratic_conic(p0, p1, p2, w, t):
    r"""Points of the conic arc from `p0` to `p2`, controlled by `p1` with middle weight `w`.

    .. math:: C(t) = \frac{(1 - t)^2 P_0 + 2 w\, t (1 - t)\, P_1 + t^2 P_2}
                          {(1 - t)^2 + 2 w\, t (1 - t) + t^2}

    the rational quadratic Bézier curve with weights (1, w, 1). It starts at P0 tangent to
    P0P1 and ends at P2 tangent to P1P2, and is an arc of an ellipse for w < 1, of a parabola
    for w = 1 and of a hyperbola for w > 1 (see :func:`conic_type`). In barycentric
    coordinates :math:`(\tau_0, \tau_1, \tau_2)` of the triangle P0 P1 P2 its points satisfy
    :math:`\tau_1^2 = 4 w^2\, \tau_0 \tau_2`. With P1 at the corner of the isosceles triangle
    over a circular arc of opening angle :math:`2\theta`, :math:`w = \cos\theta` gives an arc
    of a circle (:func:`nurbs_circle` uses four of them).

    Parameters
    ----------
    p0, p1, p2 : array_like, shape (d,)
        Start point, control point, end point.
    w : float
        The middle weight, positive.
    t : float or array_like
        Parameter values in [0, 1].

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> rational_quadratic_conic([0, 0], [1, 1], [2, 0], 1.0, 0.5)    # parabola: w = 1
    array([1. , 0.5])
    >>> rational_quadratic_conic([0, 0], [1, 1], [2, 0], 3.0, 0.5)    # pulled towards p1
    array([1.  , 0.75])
    """
    a = as_array(p0, "p0")
    if a.ndim != 1 or len(a) < 1:
        raise ValueError(f"p0 must be a point (a vector of d >= 1 numbers), got shape {a.shape}")
    points = np.stack([a, as_vector(p1, "p1", len(a)), as_vector(p2, "p2", len(a))])
    w = as_scalar(w, "w")
    if w <= 0:
        raise ValueError(f"w must be positive, got {w!r}")
    return rational_bezier(points, [1.0, w, 1.0], t)
