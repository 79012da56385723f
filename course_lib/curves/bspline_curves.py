"""Chapter 7 (lesson section 2): B-splines: knot vectors, basis functions, de Boor's algorithm."""

import numpy as np

from .._validate import as_array, as_scalar, as_whole
from ._common import _control_points, _degree, _knot_order, _knot_vector, _parameters

__all__ = ["bspline", "bspline_basis", "bspline_basis_derivative", "bspline_derivative",
    "clamped_knots", "de_boor", "domain", "find_span", "insert_knot", "uniform_knots"]


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
    n = as_whole(n_control, "n_control", 2, at_least=True)
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
    n = as_whole(n_control, "n_control", 2, at_least=True)
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


def _basis_knots(value, degree, name="knots"):
    """Knots for basis functions only: (u, n_functions, has_domain).

    A basis function :math:`N_{i,p}` needs only its p + 2 knots, so any non-decreasing vector of
    at least degree + 2 knots (no value more than degree + 1 times) defines
    ``len(knots) - degree - 1`` of them; only a *curve* needs the domain [u_p, u_n] to be
    non-empty. `has_domain` tells whether it is.
    """
    u = as_array(value, name)
    if u.ndim != 1:
        raise ValueError(f"{name} must be a 1D array of numbers, got shape {u.shape}")
    p = as_whole(degree, "degree", 0, at_least=True)
    if p < 1:
        raise ValueError(f"degree must be at least 1 (1 = linear, 2 = quadratic, 3 = cubic), "
                         f"got {p}")
    if len(u) < p + 2:
        raise ValueError(f"{name} must have at least degree + 2 = {p + 2} values (the knots of "
                         f"one basis function of degree {p}), got {len(u)}")
    n = len(u) - p - 1
    if n >= p + 1 and u[p] < u[n]:
        _knot_vector(u, p, name=name)           # the full curve checks (same messages as before)
        return u, n, True
    _knot_order(u, p, name)
    return u, n, False


def _basis_input(knots, degree, t, full_range):
    u, n, has_domain = _basis_knots(knots, degree)
    p = int(degree)
    if full_range or not has_domain:
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
        Non-decreasing knots, no value repeated more than degree + 1 times, at least
        degree + 2 of them (the knots of one basis function). A knot vector too short for a
        curve (fewer than 2 * degree + 2 knots, or an empty domain) still defines its
        ``len(knots) - degree - 1`` basis functions: t then ranges over the whole knot vector,
        as with ``full_range=True``.
    degree : int
        p >= 1.
    t : float or array_like
        Parameter values in the domain (see :func:`domain`), or anywhere in
        ``[knots[0], knots[-1]]`` with ``full_range=True`` (or a knot vector with no domain).
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

    The knots {0, 1, 2, 3, 4} are too few for a quadratic curve but define 5 - 2 - 1 = 2
    basis functions, the bells :math:`N_{0,2}` on [0, 3] and :math:`N_{1,2}` on [1, 4]:

    >>> bspline_basis([0, 1, 2, 3, 4], 2, [0.5, 1.5, 2.5])
    array([[0.125, 0.   ],
           [0.75 , 0.125],
           [0.125, 0.75 ]])
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
    k = as_whole(order, "order", 0, at_least=True)
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
    times = as_whole(times, "times", 0, at_least=True)
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
