"""Shared input checks and constants of :mod:`course_lib.curves`."""

from collections import namedtuple

import numpy as np

from .._validate import as_array, as_whole

__all__ = ["NurbsCurve"]


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
    p = as_whole(value, name, 0, at_least=True)
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
        p = as_whole(degree, "degree", 1, at_least=True)
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
    _knot_order(u, p, name)
    if not u[p] < u[n_control]:
        raise ValueError(f"{name} leave an empty domain: {name}[degree] = {name}[{p}] = "
                         f"{float(u[p])!r} must be less than {name}[n_control] = "
                         f"{name}[{n_control}] = {float(u[n_control])!r}")
    return u, n_control


def _knot_order(u, p, name="knots"):
    """Knots `u` of degree `p` non-decreasing, no value repeated more than p + 1 times (the
    checks every knot vector needs, with a curve's domain or without)."""
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


def _control_weights(value, n_control, name="weights"):
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
