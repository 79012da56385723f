"""Chapter 7 (lesson section 1): Bernstein polynomials and Bezier curves, de Casteljau."""

import math

import numpy as np

from .._validate import as_array, as_scalar, as_whole
from ._common import _control_points, _parameters

__all__ = ["bernstein", "bezier", "bezier_derivative", "bezier_elevate", "bezier_hodograph",
    "bezier_subdivide", "bezier_tangent", "de_casteljau"]


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
    n = as_whole(n, "n", 0, at_least=True)
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
    order = as_whole(order, "order", 0, at_least=True)
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
    times = as_whole(times, "times", 0, at_least=True)
    for _ in range(times):
        n = len(p) - 1
        a = (np.arange(1, n + 1) / (n + 1))[:, None]
        p = np.concatenate([p[:1], a * p[:-1] + (1.0 - a) * p[1:], p[-1:]])
    return p
