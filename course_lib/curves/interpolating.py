r"""Chapter 7 (textbook 7.5, without 7.5.3): curves that pass through given points.

An **approximating** curve (Bézier, B-spline) is pulled towards its control points; an
**interpolating** curve passes through its data points :math:`P_0, \dots, P_n` at parameter
values :math:`t_0 < t_1 < \dots < t_n` (the *parameterisation*, see :func:`parameterize`).

* :func:`polynomial_curve`: the one polynomial of degree ``n`` through ``n + 1`` points
  (Lagrange's form, evaluated in the barycentric form); it oscillates between the points when
  there are many of them (Runge's phenomenon).
* :func:`hermite_basis`, :func:`hermite_segment`, :func:`hermite_curve`: a cubic from its two end
  points and its two end tangents, and a chain of them.
* :func:`spline_system`, :func:`thomas_solve`, :func:`spline_tangents`, :func:`cubic_spline`:
  the C2 cubic spline through the points; the second derivatives solve a tridiagonal system whose
  first and last rows are the *end conditions* (natural: zero second derivative; clamped: given
  end tangents; not-a-knot: the first two and the last two segments are single cubics).
* :func:`cardinal_tangents`, :func:`catmull_rom`: the tangents are estimated locally from the
  neighbours (no system to solve); Catmull-Rom is the cardinal spline with ``tension = 0.5``.
* :func:`passes_through`: does a curve interpolate its points?

Conventions: points are the rows of an ``(n + 1, d)`` array; tangents are derivatives with
respect to the **global** parameter ``t`` (as ``scipy.interpolate.CubicHermiteSpline`` has them),
so on a segment of length :math:`h_i = t_{i+1} - t_i` the local Hermite form uses
:math:`h_i T_i` and :math:`h_i T_{i+1}`. With the uniform parameterisation (``t_i = i``,
:math:`h_i = 1`) the two coincide. A parameter outside :math:`[t_0, t_n]` raises ``ValueError``.

Examples
--------
>>> import numpy as np
>>> p = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
>>> bool(passes_through(lambda t: cubic_spline(p, t, "uniform"), p, parameterize(p, "uniform")).all())
True
"""
import numpy as np

from .._validate import as_array, as_choice, as_scalar
from ._common import _control_points, _parameters
from .matrix_form import basis_matrix, power_row

__all__ = [
    "cardinal_tangents",
    "catmull_rom",
    "cubic_spline",
    "hermite_basis",
    "hermite_curve",
    "hermite_segment",
    "lagrange_basis",
    "parameterize",
    "passes_through",
    "polynomial_curve",
    "spline_system",
    "spline_tangents",
    "thomas_solve",
]

PARAMETERIZATIONS = ("uniform", "chord", "centripetal")
_END_CONDITIONS = ("natural", "clamped", "not-a-knot")
_MINIMUM_POINTS = {"natural": 3, "clamped": 2, "not-a-knot": 4}
_EXPONENT = {"uniform": 0.0, "centripetal": 0.5, "chord": 1.0}


# ---------------------------------------------------------------------------------------------
# parameter values
# ---------------------------------------------------------------------------------------------

def parameterize(points, kind="chord", normalize=False):
    r"""Parameter values :math:`t_0 = 0 < t_1 < \dots < t_n` for interpolating `points`.

    .. math:: t_{i+1} - t_i = \lVert P_{i+1} - P_i \rVert^{\alpha}, \qquad
              \alpha = 0 \text{ (uniform)},\ \tfrac12 \text{ (centripetal)},\ 1 \text{ (chord)}

    Parameters
    ----------
    points : array_like, shape (n + 1, d)
    kind : {"uniform", "chord", "centripetal"}
    normalize : bool
        Divide by :math:`t_n` so that the values run from 0 to 1.

    Returns
    -------
    ndarray, shape (n + 1,)

    Raises
    ------
    ValueError
        For "chord" and "centripetal", when two consecutive points coincide (a zero step).

    Examples
    --------
    >>> parameterize([[0, 0], [3, 4], [3, 13]], "chord").tolist()
    [0.0, 5.0, 14.0]
    >>> parameterize([[0, 0], [3, 4], [3, 13]], "centripetal").tolist()
    [0.0, 2.23606797749979, 5.23606797749979]
    >>> parameterize([[0, 0], [3, 4], [3, 13]], "uniform", normalize=True).tolist()
    [0.0, 0.5, 1.0]
    """
    p = _control_points(points, "points")
    kind = as_choice(kind, "kind", PARAMETERIZATIONS)
    steps = np.linalg.norm(np.diff(p, axis=0), axis=1)
    if kind != "uniform" and np.any(steps == 0):
        i = int(np.argmax(steps == 0))
        raise ValueError(f"points must not repeat consecutively for the {kind} parameterisation "
                         f"(points[{i}] == points[{i + 1}] gives a step of length 0, so two "
                         "parameter values would be equal)")
    t = np.concatenate([[0.0], np.cumsum(steps ** _EXPONENT[kind])])
    return t / t[-1] if normalize else t


def _knots(params, p, name="params"):
    """Parameter values: a name of a parameterisation or an increasing array, one per point."""
    if isinstance(params, str):
        return parameterize(p, params)
    t = as_array(params, name)
    if t.shape != (len(p),):
        raise ValueError(f"{name} must be a 1D array with one parameter value per point "
                         f"({len(p)}), or one of {', '.join(map(repr, PARAMETERIZATIONS))}; got "
                         f"shape {t.shape}")
    step = np.diff(t)
    if np.any(step <= 0):
        i = int(np.argmax(step <= 0))
        raise ValueError(f"{name} must be strictly increasing, but {name}[{i}] = "
                         f"{float(t[i])!r} >= {name}[{i + 1}] = {float(t[i + 1])!r}")
    return t


# ---------------------------------------------------------------------------------------------
# polynomial interpolation
# ---------------------------------------------------------------------------------------------

def lagrange_basis(params, t):
    r"""The Lagrange basis polynomials of the nodes `params`, at `t`.

    .. math:: L_i(t) = \prod_{j \ne i} \frac{t - t_j}{t_i - t_j}, \qquad L_i(t_j) = \delta_{ij}

    Evaluated in the barycentric form :math:`L_i(t) = \frac{w_i / (t - t_i)}{\sum_j w_j / (t - t_j)}`
    with :math:`w_i = 1 / \prod_{j \ne i}(t_i - t_j)`, which is stable and costs O(n) per point.

    Parameters
    ----------
    params : array_like, shape (n + 1,)
        Strictly increasing nodes.
    t : float or array_like
        Where to evaluate (any value; no domain check: a polynomial extrapolates).

    Returns
    -------
    ndarray, shape t.shape + (n + 1,)
        The values sum to 1.

    Examples
    --------
    >>> lagrange_basis([0, 1, 2], 0.5).tolist()
    [0.375, 0.75, -0.125]
    """
    nodes = as_array(params, "params")
    if nodes.ndim != 1 or len(nodes) < 2:
        raise ValueError(f"params must be a 1D array of at least 2 nodes, got shape {nodes.shape}")
    _knots(nodes, nodes)
    t = as_array(t, "t")
    diff = nodes[:, None] - nodes[None, :]
    np.fill_diagonal(diff, 1.0)
    w = 1.0 / np.prod(diff, axis=1)
    d = t[..., None] - nodes
    exact = d == 0
    d[exact] = 1.0
    terms = w / d
    basis = terms / terms.sum(axis=-1, keepdims=True)
    hit = exact.any(axis=-1)
    basis[hit] = exact[hit].astype(float)          # at a node: exactly the unit vector
    return basis


def polynomial_curve(points, t, params="uniform"):
    r"""The polynomial curve of degree n through the n + 1 `points`: :math:`\sum_i L_i(t) P_i`.

    Parameters
    ----------
    points : array_like, shape (n + 1, d)
    t : float or array_like
        Parameters in :math:`[t_0, t_n]`.
    params : {"uniform", "chord", "centripetal"} or array_like, shape (n + 1,)

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> polynomial_curve([[0, 0], [1, 1], [2, 4]], 1.5).tolist()      # y = x**2 at x = 1.5
    [1.5, 2.25]
    """
    p = _control_points(points, "points")
    nodes = _knots(params, p)
    t = _parameters(t, nodes[0], nodes[-1])
    return lagrange_basis(nodes, t) @ p


# ---------------------------------------------------------------------------------------------
# Hermite cubics
# ---------------------------------------------------------------------------------------------

def hermite_basis(t, derivative=0):
    r"""The four cubic Hermite basis functions at local parameter(s) `t` in [0, 1].

    .. math:: H_0 = 2t^3 - 3t^2 + 1,\quad H_1 = -2t^3 + 3t^2,\quad
              H_2 = t^3 - 2t^2 + t,\quad H_3 = t^3 - t^2

    so that :math:`C(t) = H_0 P_0 + H_1 P_1 + H_2 T_0 + H_3 T_1` has :math:`C(0) = P_0`,
    :math:`C(1) = P_1`, :math:`C'(0) = T_0`, :math:`C'(1) = T_1`.

    Parameters
    ----------
    t : float or array_like
    derivative : {0, 1, 2}
        Return the basis functions' derivatives instead.

    Returns
    -------
    ndarray, shape t.shape + (4,)

    Examples
    --------
    >>> hermite_basis(0.5).tolist()
    [0.5, 0.5, 0.125, -0.125]
    """
    t = _parameters(t, 0.0, 1.0)
    derivative = int(as_choice(derivative, "derivative", (0, 1, 2)))
    return power_row(t, derivative) @ basis_matrix("hermite")     # T M: [H0, H1, H2, H3]


def hermite_segment(p0, p1, t0, t1, t):
    r"""A point (or points) of the Hermite cubic from `p0` to `p1` with end tangents `t0`, `t1`.

    .. math:: C(t) = H_0(t) P_0 + H_1(t) P_1 + H_2(t) T_0 + H_3(t) T_1, \qquad t \in [0, 1]

    Parameters
    ----------
    p0, p1, t0, t1 : array_like, shape (d,)
    t : float or array_like

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> hermite_segment([0, 0], [4, 0], [0, 4], [0, -4], 0.5).tolist()
    [2.0, 1.0]
    """
    g = _hermite_geometry(p0, p1, t0, t1)
    if g.ndim != 2:
        raise ValueError(f"p0, p1, t0 and t1 must each be a vector of coordinates, got shape "
                         f"{g.shape[1:]}")
    return hermite_basis(t) @ g


def _hermite_geometry(*vectors):
    """The Hermite geometry (P0, P1, T0, T1) stacked as rows, checked for equal shapes."""
    names = ("p0", "p1", "t0", "t1")
    arrays = [as_array(v, n) for v, n in zip(vectors, names)]
    for n, a in zip(names[1:], arrays[1:]):
        if a.shape != arrays[0].shape:
            raise ValueError(f"{n} must have the same shape as p0 {arrays[0].shape}, got "
                             f"{a.shape}")
    return np.stack(arrays)


def hermite_curve(points, tangents, t, params="uniform"):
    r"""The piecewise Hermite cubic through `points` with the derivatives `tangents` there.

    On :math:`[t_i, t_{i+1}]`, with :math:`h_i = t_{i+1} - t_i` and :math:`u = (t - t_i)/h_i`,

    .. math:: C(t) = H_0(u) P_i + H_1(u) P_{i+1} + h_i H_2(u) T_i + h_i H_3(u) T_{i+1}.

    The curve is C1: neighbouring segments share the point and the tangent.

    Parameters
    ----------
    points, tangents : array_like, shape (n + 1, d)
        Tangents are derivatives with respect to the global parameter t.
    t : float or array_like
        In :math:`[t_0, t_n]`.
    params : {"uniform", "chord", "centripetal"} or array_like, shape (n + 1,)

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> hermite_curve([[0, 0], [1, 1], [2, 0]], [[1, 1], [1, 0], [1, -1]], 1.0).tolist()
    [1.0, 1.0]
    """
    p = _control_points(points, "points")
    d = as_array(tangents, "tangents")
    if d.shape != p.shape:
        raise ValueError(f"tangents must have one tangent per point, shape {p.shape}, got "
                         f"shape {d.shape}")
    nodes = _knots(params, p)
    t = _parameters(t, nodes[0], nodes[-1])
    i = np.clip(np.searchsorted(nodes, t, side="right") - 1, 0, len(nodes) - 2)
    h = nodes[i + 1] - nodes[i]
    u = np.clip((t - nodes[i]) / h, 0.0, 1.0)
    b = hermite_basis(u)
    return (b[..., 0:1] * p[i] + b[..., 1:2] * p[i + 1]
            + (h[..., None] * b[..., 2:3]) * d[i] + (h[..., None] * b[..., 3:4]) * d[i + 1])


# ---------------------------------------------------------------------------------------------
# C2 cubic splines
# ---------------------------------------------------------------------------------------------

def _spline_diagonals(p, nodes, end, end_tangents):
    """The three diagonals and right-hand side of the system for the second derivatives M."""
    h = np.diff(nodes)
    slope = np.diff(p, axis=0) / h[:, None]
    n = len(p)
    sub, diag, sup = np.zeros(n), np.zeros(n), np.zeros(n)
    rhs = np.zeros_like(p)
    sub[1:-1], diag[1:-1], sup[1:-1] = h[:-1], 2.0 * (h[:-1] + h[1:]), h[1:]
    rhs[1:-1] = 6.0 * (slope[1:] - slope[:-1])
    if end != "clamped":                 # natural; not-a-knot's rows are not tridiagonal
        diag[0] = diag[-1] = 1.0
    else:
        d0, dn = end_tangents
        diag[0], sup[0], rhs[0] = 2.0 * h[0], h[0], 6.0 * (slope[0] - d0)
        sub[-1], diag[-1], rhs[-1] = h[-1], 2.0 * h[-1], 6.0 * (dn - slope[-1])
    return sub, diag, sup, rhs


def _not_a_knot_rows(nodes):
    """The end rows of not-a-knot (third derivative continuous at t_1 and t_{n-1})."""
    h = np.diff(nodes)
    n = len(nodes)
    first, last = np.zeros(n), np.zeros(n)
    first[:3] = h[1], -(h[0] + h[1]), h[0]
    last[-3:] = h[-1], -(h[-2] + h[-1]), h[-2]
    return first, last


def _not_a_knot_moments(p, nodes):
    """Second derivatives with not-a-knot ends: M_0 and M_n eliminated from rows 1 and n - 1
    (which stay diagonally dominant), the inner tridiagonal system solved by Thomas, the ends
    recovered from the not-a-knot rows."""
    h = np.diff(nodes)
    sub, diag, sup, rhs = _spline_diagonals(p, nodes, "natural", None)
    sub, diag, sup, rhs = sub[1:-1].copy(), diag[1:-1].copy(), sup[1:-1].copy(), rhs[1:-1]
    # row 0: M_0 = ((h0 + h1) M_1 - h0 M_2) / h1, substituted into row 1
    diag[0] += h[0] * (h[0] + h[1]) / h[1]
    sup[0] -= h[0] ** 2 / h[1]
    # row n: M_n = ((h_{n-2} + h_{n-1}) M_{n-1} - h_{n-1} M_{n-2}) / h_{n-2}, into row n - 1
    diag[-1] += h[-1] * (h[-2] + h[-1]) / h[-2]
    sub[-1] -= h[-1] ** 2 / h[-2]
    inner = thomas_solve(sub, diag, sup, rhs)
    m0 = ((h[0] + h[1]) * inner[0] - h[0] * inner[1]) / h[1]
    mn = ((h[-2] + h[-1]) * inner[-1] - h[-1] * inner[-2]) / h[-2]
    return np.vstack([m0, inner, mn])


def _spline_input(points, params, end, end_tangents):
    end = as_choice(end, "end", _END_CONDITIONS)
    p = _control_points(points, "points", minimum=_MINIMUM_POINTS[end])
    nodes = _knots(params, p)
    if end == "clamped":
        if end_tangents is None:
            raise ValueError("end_tangents must be given for end='clamped': a pair (T_0, T_n) "
                             "of vectors with the points' dimension")
        e = as_array(end_tangents, "end_tangents")
        if e.shape != (2, p.shape[1]):
            raise ValueError(f"end_tangents must be the two end tangents (T_0, T_n), shape "
                             f"(2, {p.shape[1]}), got shape {e.shape}")
        end_tangents = e
    elif end_tangents is not None:
        raise ValueError(f"end_tangents is only used with end='clamped' (a {end} spline "
                         "sets its ends by another condition)")
    return p, nodes, end, end_tangents


def spline_system(points, params="uniform", end="natural", end_tangents=None):
    r"""The tridiagonal system :math:`A M = b` for the second derivatives of the cubic spline.

    Interior rows (C2 continuity at :math:`t_i`, :math:`h_i = t_{i+1} - t_i`):

    .. math:: h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
              = 6 \left(\frac{P_{i+1} - P_i}{h_i} - \frac{P_i - P_{i-1}}{h_{i-1}}\right)

    End rows: natural :math:`M_0 = 0`, :math:`M_n = 0`; clamped with end tangents
    :math:`T_0, T_n`: :math:`2 h_0 M_0 + h_0 M_1 = 6 ((P_1 - P_0)/h_0 - T_0)` and
    :math:`h_{n-1} M_{n-1} + 2 h_{n-1} M_n = 6 (T_n - (P_n - P_{n-1})/h_{n-1})`;
    not-a-knot (the third derivative is continuous at :math:`t_1` and :math:`t_{n-1}`, so the
    first two and the last two segments are one cubic each):
    :math:`h_1 M_0 - (h_0 + h_1) M_1 + h_0 M_2 = 0` and the mirror row at the end. These two
    rows have three entries: that matrix is not tridiagonal (:func:`spline_tangents` eliminates
    :math:`M_0` and :math:`M_n` first and solves the tridiagonal rest).

    Parameters
    ----------
    points : array_like, shape (n + 1, d)
        At least 3 for a natural spline, 2 for a clamped one, 4 for not-a-knot.
    params : {"uniform", "chord", "centripetal"} or array_like, shape (n + 1,)
    end : {"natural", "clamped", "not-a-knot"}
    end_tangents : array_like, shape (2, d), optional
        :math:`T_0` and :math:`T_n`, only (and always) for ``end="clamped"``.

    Returns
    -------
    A : ndarray, shape (n + 1, n + 1)
        Dense, for display; :func:`cubic_spline` keeps only its three diagonals.
    b : ndarray, shape (n + 1, d)

    Examples
    --------
    >>> A, b = spline_system([[0], [1], [0]])
    >>> A.tolist(), b.tolist()
    ([[1.0, 0.0, 0.0], [1.0, 4.0, 1.0], [0.0, 0.0, 1.0]], [[0.0], [-12.0], [0.0]])
    """
    p, nodes, end, e = _spline_input(points, params, end, end_tangents)
    sub, diag, sup, rhs = _spline_diagonals(p, nodes, end, e)
    a = np.diag(diag) + np.diag(sub[1:], -1) + np.diag(sup[:-1], 1)
    if end == "not-a-knot":
        a[0], a[-1] = _not_a_knot_rows(nodes)
    return a, rhs


def thomas_solve(sub, diag, sup, rhs):
    r"""Solve a tridiagonal system by Gaussian elimination without pivoting (Thomas algorithm).

    Row i reads :math:`\text{sub}_i x_{i-1} + \text{diag}_i x_i + \text{sup}_i x_{i+1} = r_i`
    (``sub[0]`` and ``sup[-1]`` are ignored). O(n); safe for the diagonally dominant systems of
    splines.

    Parameters
    ----------
    sub, diag, sup : array_like, shape (n,)
    rhs : array_like, shape (n,) or (n, k)
        One or several right-hand sides (e.g. one per coordinate).

    Returns
    -------
    ndarray, the shape of `rhs`

    Examples
    --------
    >>> thomas_solve([0, 1, 1], [2, 2, 2], [1, 1, 0], [3, 4, 3]).tolist()
    [1.0, 1.0, 1.0]
    """
    a, b, c = (as_array(v, n) for v, n in ((sub, "sub"), (diag, "diag"), (sup, "sup")))
    r = as_array(rhs, "rhs")
    n = len(b)
    for v, name in ((a, "sub"), (b, "diag"), (c, "sup")):
        if v.shape != (n,):
            raise ValueError(f"{name} must be a 1D array of length {n} (the size of diag), got "
                             f"shape {v.shape}")
    if r.ndim not in (1, 2) or len(r) != n:
        raise ValueError(f"rhs must have {n} rows (one per equation), got shape {r.shape}")
    # the recurrences run on Python floats: indexing numpy scalars one by one is ~10x slower
    a, b, c = a.tolist(), b.tolist(), c.tolist()
    cp, pivots = [0.0] * n, [0.0] * n
    for i in range(n):
        pivot = b[i] - (a[i] * cp[i - 1] if i else 0.0)
        if pivot == 0:
            raise ValueError(f"the system is singular at row {i} (zero pivot): diag must "
                             "dominate sub and sup")
        pivots[i] = pivot
        cp[i] = c[i] / pivot
    columns = r.reshape(n, -1).T.tolist()
    for col in columns:                               # forward sweep, then back substitution
        previous = 0.0
        for i in range(n):
            previous = col[i] = (col[i] - a[i] * previous) / pivots[i] if i else \
                col[i] / pivots[i]
        for i in range(n - 2, -1, -1):
            col[i] -= cp[i] * col[i + 1]
    return np.array(columns).T.reshape(r.shape)


def spline_tangents(points, params="uniform", end="natural", end_tangents=None,
                    second=False):
    r"""The tangents (first derivatives) of the C2 cubic spline at its points.

    Solves :func:`spline_system` for the second derivatives :math:`M_i` (Thomas algorithm), then

    .. math:: T_i = \frac{P_{i+1} - P_i}{h_i} - \frac{h_i}{6}(2 M_i + M_{i+1}), \qquad
              T_n = \frac{P_n - P_{n-1}}{h_{n-1}} + \frac{h_{n-1}}{6}(M_{n-1} + 2 M_n).

    Parameters
    ----------
    points, params, end, end_tangents
        As for :func:`spline_system`.
    second : bool
        Return the second derivatives :math:`M_i` instead.

    Returns
    -------
    ndarray, shape (n + 1, d)

    Examples
    --------
    >>> spline_tangents([[0], [1], [0]]).ravel().tolist()
    [1.5, 0.0, -1.5]
    >>> spline_tangents([[0], [1], [0]], second=True).ravel().tolist()
    [0.0, -3.0, 0.0]
    """
    p, nodes, end, e = _spline_input(points, params, end, end_tangents)
    if end == "not-a-knot":
        m = _not_a_knot_moments(p, nodes)
    else:
        m = thomas_solve(*_spline_diagonals(p, nodes, end, e))
    if second:
        return m
    h = np.diff(nodes)[:, None]
    slope = np.diff(p, axis=0) / h
    t = np.empty_like(p)
    t[:-1] = slope - h / 6.0 * (2.0 * m[:-1] + m[1:])
    t[-1] = slope[-1] + h[-1] / 6.0 * (m[-2] + 2.0 * m[-1])
    return t


def cubic_spline(points, t, params="chord", end="natural", end_tangents=None):
    r"""The C2 cubic spline through `points`, at parameter(s) `t`.

    It is the piecewise Hermite curve (:func:`hermite_curve`) whose tangents are
    :func:`spline_tangents`: the tangents are chosen so that the second derivative is continuous.

    Parameters
    ----------
    points : array_like, shape (n + 1, d)
    t : float or array_like
        In :math:`[t_0, t_n]`.
    params, end, end_tangents
        As for :func:`spline_system`.

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> cubic_spline([[0, 0], [1, 1], [2, 0]], 0.5, params="uniform").tolist()
    [0.5, 0.6875]
    """
    p, nodes, end, e = _spline_input(points, params, end, end_tangents)
    return hermite_curve(p, spline_tangents(p, nodes, end, e), t, nodes)


# ---------------------------------------------------------------------------------------------
# cardinal and Catmull-Rom splines
# ---------------------------------------------------------------------------------------------

def cardinal_tangents(points, tension=0.5, params="uniform"):
    r"""Tangents of the cardinal spline: :math:`T_i = s\,(P_{i+1} - P_{i-1})` for uniform t.

    Convention: ``tension`` is the factor :math:`s`; :math:`s = 1/2` is Catmull-Rom,
    :math:`s = 0` gives zero tangents (the curve stops at each point: a polyline traced with
    corners), larger :math:`s` gives looser, rounder curves. (Another common convention writes
    :math:`T_i = \frac{1 - c}{2}(P_{i+1} - P_{i-1})`, i.e. :math:`c = 1 - 2s`.) For general
    parameter values the tangent is :math:`2s` times the derivative at :math:`t_i` of the
    parabola through :math:`P_{i-1}, P_i, P_{i+1}`:

    .. math:: T_i = 2s\left(\frac{P_i - P_{i-1}}{t_i - t_{i-1}}
              - \frac{P_{i+1} - P_{i-1}}{t_{i+1} - t_{i-1}} + \frac{P_{i+1} - P_i}{t_{i+1} - t_i}\right)

    (the Barry-Goldman form; with ``params="centripetal"`` this is centripetal Catmull-Rom). At
    the two ends the one-sided difference is used: :math:`T_0 = 2s (P_1 - P_0)/(t_1 - t_0)`.

    Parameters
    ----------
    points : array_like, shape (n + 1, d)
        At least 2.
    tension : float
        :math:`s \ge 0`.
    params : {"uniform", "chord", "centripetal"} or array_like, shape (n + 1,)

    Returns
    -------
    ndarray, shape (n + 1, d)

    Examples
    --------
    >>> cardinal_tangents([[0, 0], [1, 2], [4, 2]]).tolist()
    [[1.0, 2.0], [2.0, 1.0], [3.0, 0.0]]
    """
    p = _control_points(points, "points")
    s = as_scalar(tension, "tension")
    if s < 0:
        raise ValueError(f"tension must be >= 0 (0 = zero tangents, 0.5 = Catmull-Rom), got {s}")
    nodes = _knots(params, p)
    h = np.diff(nodes)[:, None]
    slope = np.diff(p, axis=0) / h
    t = np.empty_like(p)
    t[0], t[-1] = slope[0], slope[-1]
    if len(p) > 2:
        wide = (p[2:] - p[:-2]) / (nodes[2:] - nodes[:-2])[:, None]
        t[1:-1] = slope[:-1] - wide + slope[1:]
    return 2.0 * s * t


def catmull_rom(points, t, params="uniform", tension=0.5):
    r"""The Catmull-Rom (``tension=0.5``) or cardinal spline through `points`, at `t`.

    The piecewise Hermite curve with the :func:`cardinal_tangents`. Only C1, but local: moving
    one point changes only the two segments on each side of it.

    Parameters
    ----------
    points : array_like, shape (n + 1, d)
    t : float or array_like
        In :math:`[t_0, t_n]`.
    params : {"uniform", "chord", "centripetal"} or array_like
    tension : float
        :math:`s`, see :func:`cardinal_tangents`.

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> catmull_rom([[0, 0], [1, 2], [4, 2]], 0.5).tolist()
    [0.375, 1.125]
    """
    p = _control_points(points, "points")
    nodes = _knots(params, p)
    return hermite_curve(p, cardinal_tangents(p, tension, nodes), t, nodes)


# ---------------------------------------------------------------------------------------------
# interpolation or approximation?
# ---------------------------------------------------------------------------------------------

def passes_through(curve, points, params=None, atol=1e-9):
    """Which of `points` the curve passes through (interpolates).

    Parameters
    ----------
    curve : callable or array_like, shape (m, d)
        A function ``t -> points`` (then `params` gives where to evaluate it), or samples of
        the curve (then each point's distance to the polyline through the samples is used).
    points : array_like, shape (n + 1, d)
    params : array_like, shape (n + 1,), optional
        Required with a callable.
    atol : float
        Largest distance counted as "on the curve".

    Returns
    -------
    ndarray of bool, shape (n + 1,)

    Examples
    --------
    >>> from course_lib.curves import bezier
    >>> p = [[0, 0], [1, 2], [2, 0]]
    >>> passes_through(lambda t: bezier(p, t), p, [0, 0.5, 1]).tolist()   # approximates P1
    [True, False, True]
    """
    p = _control_points(points, "points", minimum=1)
    atol = as_scalar(atol, "atol")
    if callable(curve):
        if params is None:
            raise ValueError("params must be given with a callable curve: the parameter value "
                             "at which each point should be reached")
        t = as_array(params, "params")
        if t.shape != (len(p),):
            raise ValueError(f"params must have one value per point ({len(p)}), got shape "
                             f"{t.shape}")
        q = np.asarray(curve(t), dtype=float)
        if q.shape != p.shape:
            raise ValueError(f"curve(params) must return one point per parameter, shape "
                             f"{p.shape}, got shape {q.shape}")
        return np.linalg.norm(q - p, axis=1) <= atol
    s = _control_points(curve, "curve")
    if s.shape[1] != p.shape[1]:
        raise ValueError(f"curve samples must have the points' dimension {p.shape[1]}, got "
                         f"{s.shape[1]}")
    a, e = s[:-1], np.diff(s, axis=0)
    length2 = np.maximum((e * e).sum(axis=1), 1e-300)
    u = np.clip(((p[:, None] - a) * e).sum(axis=2) / length2, 0.0, 1.0)
    dist = np.linalg.norm(p[:, None] - (a + u[..., None] * e), axis=2).min(axis=1)
    return dist <= atol
