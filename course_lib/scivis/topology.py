r"""Chapter 18 (lesson: vector-field topology): critical points, their classes, separatrices,
and streamlines integrated in a *gridded* field with bilinear interpolation of the velocity.

A 2D vector field sampled on a grid is a :class:`~course_lib.scivis.Field` whose ``values``
have shape (ny, nx, 2) (last array axis x, components (u, v)). Inside a cell the velocity is the
bilinear interpolant of the four corner vectors; with local coordinates
:math:`s, t \in [0, 1]`

.. math:: u(s, t) = a_0 + a_1 s + a_2 t + a_3 s t, \qquad v(s, t) = b_0 + b_1 s + b_2 t + b_3 s t.

A **critical point** is a zero of the velocity. :func:`critical_points` solves the two bilinear
equations of every cell *exactly*: eliminating :math:`s` leaves a quadratic in :math:`t`.
The **Jacobian** there comes analytically from the bilinear form, and the eigenvalues of the
Jacobian give the class (:func:`classify_critical_point`). From each saddle the four
**separatrices** start along the eigenvectors (:func:`separatrices`); together with the critical
points they form the topological skeleton of the field.
"""
from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_choice, as_positive, as_vector, as_whole
from ._common import _spacing
from .data import Field
from .grids import _lerp_grid

__all__ = ["CRITICAL_CLASSES", "FLOW_PRESETS", "Classification", "CriticalPoint",
           "bilinear_velocity", "classify_critical_point", "critical_points", "gridded_field",
           "integrate_gridded", "jacobian_at", "preset_field", "separatrices"]

#: The classes :func:`classify_critical_point` returns.
CRITICAL_CLASSES = ("saddle", "attracting node", "repelling node", "attracting focus",
                    "repelling focus", "centre", "degenerate")


# ---------------------------------------------------------------------------------------------
# Gridded fields and bilinear interpolation
# ---------------------------------------------------------------------------------------------

def gridded_field(u, v, spacing=1.0, origin=(0.0, 0.0)):
    """Pack the two velocity components sampled on a grid into a :class:`Field`.

    Parameters
    ----------
    u, v : array_like, shape (ny, nx)
        The x and y components at the grid nodes (row j is y = origin_y + j * spacing_y).
    spacing : float or (float, float)
        Distance between neighbouring nodes along x and y, > 0.
    origin : (float, float)
        Coordinates of node [0, 0].

    Returns
    -------
    Field
        ``values`` of shape (ny, nx, 2).

    Raises
    ------
    ValueError
        For grids of different shapes, fewer than 2 x 2 nodes, NaN or infinite values, or a
        spacing that is not positive.

    Examples
    --------
    >>> f = gridded_field([[1, 2], [3, 4]], [[0, 0], [1, 1]], spacing=0.5)
    >>> f.values.shape, f.spacing, f.origin
    ((2, 2, 2), (0.5, 0.5), (0.0, 0.0))
    """
    u = as_array(u, "u")
    v = as_array(v, "v")
    if u.ndim != 2 or min(u.shape) < 2:
        raise ValueError(f"u must be a grid of shape (ny, nx) with ny, nx >= 2, got shape "
                         f"{u.shape}")
    if v.shape != u.shape:
        raise ValueError(f"u and v must have the same shape, got {u.shape} and {v.shape}")
    sp = np.broadcast_to(np.asarray(spacing, dtype=float), (2,)) if np.ndim(spacing) == 0 \
        else spacing
    sp = _spacing(sp, 2)
    org = as_vector(origin, "origin", 2)
    return Field(np.stack([u, v], axis=-1), tuple(map(float, sp)), tuple(map(float, org)))


def _as_vector_field(field):
    """(values (ny, nx, 2), spacing (2,), origin (2,)) of a Field of 2D vectors, checked."""
    if not isinstance(field, Field):
        raise TypeError(f"field must be a Field (see gridded_field), got "
                        f"{type(field).__name__}")
    g = np.asarray(field.values, dtype=float)
    if g.ndim != 3 or g.shape[-1] != 2 or min(g.shape[:2]) < 2:
        raise ValueError(f"field.values must have shape (ny, nx, 2) with ny, nx >= 2, got "
                         f"shape {g.shape}")
    if not np.isfinite(g).all():
        raise ValueError("field.values must be finite: the field has NaN or infinite values")
    return g, _spacing(field.spacing, 2), as_vector(field.origin, "origin", 2)


def _cell_coords(shape, spacing, origin, x, y):
    """Cell indices (i, j) and local (s, t) of points, clamped into the grid."""
    ny, nx = shape
    gx = np.minimum(np.maximum((x - origin[0]) / spacing[0], 0.0), nx - 1)
    gy = np.minimum(np.maximum((y - origin[1]) / spacing[1], 0.0), ny - 1)
    i = np.minimum(gx.astype(int), nx - 2)
    j = np.minimum(gy.astype(int), ny - 2)
    return i, j, gx - i, gy - j


def _bilinear(g, spacing, origin, x, y):
    """The bilinear interpolation of g (ny, nx, 2) at points x, y (same shape): (..., 2).

    The grid package's one multilinear interpolation (clamped into the grid), on index
    coordinates."""
    shape = np.shape(x)
    idx = [(np.ravel(x) - origin[0]) / spacing[0], (np.ravel(y) - origin[1]) / spacing[1]]
    return _lerp_grid(g.reshape(-1, 2), g.shape[1::-1], idx).reshape(shape + (2,))


def bilinear_velocity(grid_u, grid_v, x, y, spacing=1.0, origin=(0.0, 0.0)):
    r"""The velocity at points (x, y) by bilinear interpolation of the grid's corner vectors.

    With the point in cell (i, j) at local coordinates :math:`s, t \in [0, 1]`:

    .. math:: \mathbf v = (1-s)(1-t)\,\mathbf v_{00} + s(1-t)\,\mathbf v_{10}
              + (1-s)\,t\,\mathbf v_{01} + s\,t\,\mathbf v_{11}

    (:math:`\mathbf v_{10}` is the corner one step along x). Points outside the grid take the
    value at the nearest point of the grid's border.

    Parameters
    ----------
    grid_u, grid_v : array_like, shape (ny, nx)
        The velocity components at the nodes (row j is y = origin_y + j * spacing_y).
    x, y : array_like
        Coordinates of the points (any equal shapes).
    spacing : float or (float, float)
    origin : (float, float)

    Returns
    -------
    ndarray, shape x.shape + (2,)

    Examples
    --------
    A quarter of the way along x and half-way up, in a single cell:

    >>> bilinear_velocity([[0, 4], [0, 4]], [[0, 0], [2, 2]], 0.25, 0.5)
    array([1., 1.])
    """
    f = gridded_field(grid_u, grid_v, spacing, origin)
    x = as_array(x, "x")
    y = as_array(y, "y")
    if x.shape != y.shape:
        raise ValueError(f"x and y must have the same shape, got {x.shape} and {y.shape}")
    return _bilinear(f.values, np.array(f.spacing), np.array(f.origin), x, y)


# ---------------------------------------------------------------------------------------------
# Integration in a gridded field
# ---------------------------------------------------------------------------------------------

def _advance(g, sp, org, lo, hi, seeds, h, n, method, min_speed, normalize=False):
    """Advance all seeds together; (k, n + 1, 2) with NaN after a line stopped."""
    def vel(p):
        v = _bilinear(g, sp, org, p[:, 0], p[:, 1])
        if normalize:
            v = v / np.maximum(np.hypot(v[:, 0], v[:, 1]), min_speed)[:, None]
        return v

    lines = np.full((len(seeds), n + 1, 2), np.nan)
    lines[:, 0] = seeds
    cur = seeds.copy()
    alive = ((seeds >= lo) & (seeds <= hi)).all(axis=1)
    for step in range(n):
        ids = np.flatnonzero(alive)
        if ids.size == 0:
            break
        p = cur[ids]
        k1 = _bilinear(g, sp, org, p[:, 0], p[:, 1])
        speed = np.hypot(k1[:, 0], k1[:, 1])
        if normalize:
            k1 = k1 / np.maximum(speed, min_speed)[:, None]
        if method == "euler":
            new = p + h * k1
        elif method == "rk2":
            new = p + h * vel(p + 0.5 * h * k1)
        else:
            k2 = vel(p + 0.5 * h * k1)
            k3 = vel(p + 0.5 * h * k2)
            k4 = vel(p + h * k3)
            new = p + (h / 6.0) * (k1 + 2 * k2 + 2 * k3 + k4)
        ok = (speed >= min_speed) & ((new >= lo) & (new <= hi)).all(1)
        alive[ids[~ok]] = False
        cur[ids[ok]] = new[ok]
        lines[ids[ok], step + 1] = new[ok]
    return lines


def integrate_gridded(field, seed, step, n, method="rk4", backward=False, min_speed=None,
                      normalize=False):
    r"""A streamline of a gridded 2D field, the velocity interpolated bilinearly at every stage.

    Euler :math:`x_{k+1} = x_k + h\,v(x_k)`; RK2 (midpoint)
    :math:`x_{k+1} = x_k + h\,v(x_k + \tfrac h2 v(x_k))`; RK4 the classic four-stage rule, as
    :func:`~course_lib.scivis.streamline`, with :math:`v` the bilinear interpolant
    (:func:`bilinear_velocity`). The line **stops** before a step that would leave the grid, or
    at a point where the speed is below `min_speed` (a critical point: the flow stands still).

    Parameters
    ----------
    field : Field
        Values (ny, nx, 2) (see :func:`gridded_field`).
    seed : array_like, shape (2,) or (k, 2)
        The start point(s).
    step : float
        The step h, > 0.
    n : int
        The number of steps, >= 1.
    method : {"euler", "rk2", "rk4"}
    backward : bool
        Integrate against the flow (:math:`\mathrm d x/\mathrm d t = -v`), as for the stable
        separatrices.
    min_speed : float, optional
        Default: 1e-6 times the largest speed on the grid.
    normalize : bool
        Integrate along the arc length, :math:`\mathrm d x/\mathrm d s = v/|v|`: the step is
        then a length, not a time (the same curve, traced at unit speed; slow regions no longer
        need many steps).

    Returns
    -------
    ndarray, shape (m, 2), m <= n + 1, or a list of them for several seeds
        The points reached, starting with the seed (a seed outside the grid gives just itself).

    Raises
    ------
    ValueError
        For a step <= 0, n < 1, an unknown method, or a field that is not a grid of 2D vectors.

    Examples
    --------
    The uniform flow (1, 0) on the unit square, two Euler steps of 0.25:

    >>> f = gridded_field([[1, 1], [1, 1]], [[0, 0], [0, 0]])
    >>> integrate_gridded(f, [0.0, 0.5], 0.25, 2, method="euler")
    array([[0.  , 0.5 ],
           [0.25, 0.5 ],
           [0.5 , 0.5 ]])
    """
    g, sp, org = _as_vector_field(field)
    as_choice(method, "method", ("euler", "rk2", "rk4"))
    h = as_positive(step, "step", "the integration step")
    n = as_whole(n, "n", 1)
    seeds = as_array(seed, "seed")
    single = seeds.shape == (2,)
    if not single and (seeds.ndim != 2 or seeds.shape[1] != 2):
        raise ValueError(f"seed must be a point (x, y) or points of shape (k, 2), got shape "
                         f"{seeds.shape}")
    seeds = seeds.reshape(-1, 2)
    if min_speed is None:
        min_speed = 1e-6 * float(np.hypot(g[..., 0], g[..., 1]).max())
    lo = org
    hi = org + sp * (np.array(g.shape[1::-1]) - 1)
    lines = _advance(-g if backward else g, sp, org, lo, hi, seeds, h, n, method, min_speed,
                     bool(normalize))
    out = [line[np.isfinite(line[:, 0])] for line in lines]
    return out[0] if single else out


# ---------------------------------------------------------------------------------------------
# Classification
# ---------------------------------------------------------------------------------------------

class Classification(NamedTuple):
    """The class of a critical point, its eigenvalues, and why.

    Examples
    --------
    >>> classify_critical_point([[1, 0], [0, -1]]).kind
    'saddle'
    """
    kind: str
    eigenvalues: np.ndarray
    reason: str


def classify_critical_point(jacobian, tol=1e-9):
    r"""Classify a critical point by the eigenvalues of its Jacobian J.

    With :math:`\tau = \operatorname{tr} J`, :math:`\Delta = \det J` the eigenvalues are
    :math:`\lambda = \tfrac12(\tau \pm \sqrt{\tau^2 - 4\Delta})`:

    * :math:`\Delta < 0`: real, opposite signs: **saddle**;
    * :math:`\Delta > 0`, :math:`\tau^2 - 4\Delta \ge 0`: real, same sign: **node**, attracting
      if :math:`\tau < 0`, repelling if :math:`\tau > 0`;
    * :math:`\tau^2 - 4\Delta < 0`: complex: **focus** (spiral), attracting if :math:`\tau < 0`,
      repelling if :math:`\tau > 0`, a **centre** if :math:`\tau = 0`;
    * :math:`\Delta = 0`: a zero eigenvalue, **degenerate** (the point is not isolated, or the
      linearisation does not decide).

    Parameters
    ----------
    jacobian : array_like, shape (2, 2)
        :math:`J = \begin{bmatrix} \partial u/\partial x & \partial u/\partial y \\
        \partial v/\partial x & \partial v/\partial y \end{bmatrix}`.
    tol : float
        Relative tolerance: :math:`|\Delta|`, :math:`|\tau|` and the discriminant count as zero
        below ``tol`` times the matching power of the largest entry.

    Returns
    -------
    Classification
        ``kind`` (one of :data:`CRITICAL_CLASSES`), ``eigenvalues`` (2 complex numbers, real part
        descending) and ``reason`` (a sentence).

    Raises
    ------
    ValueError
        For a matrix that is not 2 x 2 or has NaN or infinite entries.

    Examples
    --------
    >>> c = classify_critical_point([[-1, -2], [2, -1]])
    >>> c.kind, c.eigenvalues
    ('attracting focus', array([-1.+2.j, -1.-2.j]))
    """
    j = np.asarray(jacobian, dtype=float) if not isinstance(jacobian, (str, bytes)) else None
    if j is None or j.shape != (2, 2):
        raise ValueError(f"jacobian must be a 2 x 2 matrix, got "
                         f"{'a string' if j is None else f'shape {j.shape}'}")
    if not np.isfinite(j).all():
        raise ValueError("jacobian must be finite: the field has NaN or infinite values near "
                         "this point")
    tol = as_positive(tol, "tol")
    scale = float(np.abs(j).max())
    tr = float(j[0, 0] + j[1, 1])
    det = float(j[0, 0] * j[1, 1] - j[0, 1] * j[1, 0])
    disc = tr * tr - 4 * det
    root = np.sqrt(complex(disc))
    lam = np.array([(tr + root) / 2, (tr - root) / 2])
    numbers = f"trace {tr:.4g}, determinant {det:.4g}, discriminant {disc:.4g}"
    if scale == 0 or abs(det) <= tol * scale * scale:
        return Classification("degenerate", lam, f"{numbers}: an eigenvalue is zero, the "
                              "linearisation does not decide the class")
    if det < 0:
        return Classification("saddle", lam, f"{numbers}: the determinant is negative, so the "
                              "eigenvalues are real with opposite signs")
    way = "attracting" if tr < 0 else "repelling"
    sign = "negative" if tr < 0 else "positive"
    if disc >= -tol * scale * scale:
        return Classification(f"{way} node", lam, f"{numbers}: real eigenvalues of the same "
                              f"sign ({sign}, as the trace)")
    if abs(tr) <= tol * scale:
        return Classification("centre", lam, f"{numbers}: complex eigenvalues with zero real "
                              "part, the flow circles around the point")
    return Classification(f"{way} focus", lam, f"{numbers}: complex eigenvalues (negative "
                          f"discriminant) with {sign} real part {tr / 2:.4g}")


# ---------------------------------------------------------------------------------------------
# Critical points on a grid
# ---------------------------------------------------------------------------------------------

class CriticalPoint(NamedTuple):
    """A zero of a gridded field, with its Jacobian and class.

    Examples
    --------
    >>> f = preset_field("linear", 2.0, 1.0, n=5)        # trace 2, det 1: repelling node
    >>> critical_points(f)[0].kind
    'repelling node'
    """
    position: np.ndarray
    jacobian: np.ndarray
    kind: str
    eigenvalues: np.ndarray
    reason: str
    cell: tuple


def _cell_coefficients(g):
    """Bilinear coefficients a0..a3 (u) and b0..b3 (v) of every cell: (ny-1, nx-1, 4) each."""
    c00, c10 = g[:-1, :-1], g[:-1, 1:]
    c01, c11 = g[1:, :-1], g[1:, 1:]
    k = np.stack([c00, c10 - c00, c01 - c00, c11 - c10 - c01 + c00], axis=-2)
    return k[..., 0], k[..., 1]


def _cell_coefficients_at(g, j, i):
    """The bilinear coefficients (k, 4) of u and of v in the cells (j, i) only."""
    c00, c10, c01, c11 = g[j, i], g[j, i + 1], g[j + 1, i], g[j + 1, i + 1]
    k = np.stack([c00, c10 - c00, c01 - c00, c11 - c10 - c01 + c00], axis=-2)
    return k[..., 0], k[..., 1]


def _bilinear_jacobian(a, b, s, t, sp):
    """The Jacobian of the bilinear interpolant in world units at local (s, t): (..., 2, 2)."""
    j = np.empty(np.shape(s) + (2, 2))
    j[..., 0, 0] = (a[..., 1] + a[..., 3] * t) / sp[0]
    j[..., 0, 1] = (a[..., 2] + a[..., 3] * s) / sp[1]
    j[..., 1, 0] = (b[..., 1] + b[..., 3] * t) / sp[0]
    j[..., 1, 1] = (b[..., 2] + b[..., 3] * s) / sp[1]
    return j


def _cell_zeros(a, b):
    """All zeros (cell index, s, t) of the bilinear pair in candidate cells, solved exactly.

    u = 0 gives s = -(a0 + a2 t) / (a1 + a3 t); put into v = 0:
    (b0 + b2 t)(a1 + a3 t) - (b1 + b3 t)(a0 + a2 t) = 0, a quadratic in t.
    """
    c2 = b[:, 2] * a[:, 3] - b[:, 3] * a[:, 2]
    c1 = b[:, 0] * a[:, 3] + b[:, 2] * a[:, 1] - b[:, 1] * a[:, 2] - b[:, 3] * a[:, 0]
    c0 = b[:, 0] * a[:, 1] - b[:, 1] * a[:, 0]
    scale = np.maximum(np.abs(np.concatenate([a, b], axis=1)).max(axis=1), 1e-300) ** 2
    quad = np.abs(c2) > 1e-12 * scale
    disc = c1 * c1 - 4 * c2 * c0
    ts, idx = [], []
    cells = np.arange(len(a))
    # quadratic cells: both real roots
    q = quad & (disc >= -1e-12 * scale * scale)
    r = np.sqrt(np.maximum(disc[q], 0.0))
    for sign in (1.0, -1.0):
        # numerically stable form: t = 2 c0 / (-c1 -+ r) or (-c1 +- r) / (2 c2)
        ts.append((-c1[q] + sign * r) / (2 * c2[q]))
        idx.append(cells[q])
    # linear cells: c1 t + c0 = 0
    lin = ~quad & (np.abs(c1) > 1e-12 * scale)
    ts.append(-c0[lin] / c1[lin])
    idx.append(cells[lin])
    t = np.concatenate(ts)
    k = np.concatenate(idx)
    eps = 1e-9
    keep = (t >= -eps) & (t <= 1 + eps)
    t, k = np.clip(t[keep], 0, 1), k[keep]
    du = a[k, 1] + a[k, 3] * t
    dv = b[k, 1] + b[k, 3] * t
    use_u = np.abs(du) >= np.abs(dv)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(use_u, -(a[k, 0] + a[k, 2] * t) / du, -(b[k, 0] + b[k, 2] * t) / dv)
    keep = np.isfinite(s) & (s >= -eps) & (s <= 1 + eps)
    k, s, t = k[keep], np.clip(s[keep], 0, 1), t[keep]
    # both equations hold (a root of the quadratic can come from a zero denominator)
    res_u = a[k, 0] + a[k, 1] * s + a[k, 2] * t + a[k, 3] * s * t
    res_v = b[k, 0] + b[k, 1] * s + b[k, 2] * t + b[k, 3] * s * t
    size = np.sqrt(scale[k])
    ok = (np.abs(res_u) <= 1e-8 * size) & (np.abs(res_v) <= 1e-8 * size)
    return k[ok], s[ok], t[ok]


def critical_points(field, tol=1e-9):
    r"""The critical points (zeros of the velocity) of a gridded 2D field, classified.

    Only cells where **both** components change sign (or reach zero) at the corners can hold a
    zero. In such a cell the bilinear equations :math:`u(s, t) = 0`, :math:`v(s, t) = 0` are
    solved **exactly**: the first gives :math:`s = -(a_0 + a_2 t)/(a_1 + a_3 t)`; put into the
    second it leaves the quadratic

    .. math:: (b_2 a_3 - b_3 a_2)\,t^2 + (b_0 a_3 + b_2 a_1 - b_1 a_2 - b_3 a_0)\,t
              + (b_0 a_1 - b_1 a_0) = 0,

    whose roots in [0, 1] (with their :math:`s` in [0, 1]) are the zeros. The Jacobian is the
    derivative of the bilinear form at the zero (exact for that interpolant), and
    :func:`classify_critical_point` gives the class. A zero on an edge or node shared by
    several cells is reported once. Cells where a whole segment is zero (degenerate) give no
    isolated point and are skipped.

    Parameters
    ----------
    field : Field
        Values (ny, nx, 2).
    tol : float
        Passed to :func:`classify_critical_point`.

    Returns
    -------
    list of CriticalPoint
        Sorted by y, then x.

    Raises
    ------
    ValueError
        For a field with NaN or infinite values or not shaped (ny, nx, 2).

    Examples
    --------
    The saddle v = (y, x) (trace 0, determinant -1) sampled on [-1.5, 1.5]^2: its zero at the
    origin, inside a cell:

    >>> f = preset_field("linear", 0.0, -1.0, n=4)
    >>> [(p.kind, p.position.round(12) + 0.0) for p in critical_points(f)]
    [('saddle', array([0., 0.]))]
    """
    g, sp, org = _as_vector_field(field)
    nx1 = g.shape[1] - 1
    candidate = np.ones((g.shape[0] - 1, nx1), dtype=bool)
    for comp in (g[..., 0], g[..., 1]):        # a cell whose 4 corners share a strict sign
        for side in (comp > 0, comp < 0):       # cannot hold a zero of this component
            candidate &= ~(side[:-1, :-1] & side[:-1, 1:] & side[1:, :-1] & side[1:, 1:])
    jj, ii = np.nonzero(candidate)
    a, b = _cell_coefficients_at(g, jj, ii)
    k, s, t = _cell_zeros(a, b)
    j, i = jj[k], ii[k]
    pos = org + sp * np.stack([i + s, j + t], axis=1)
    jac = _bilinear_jacobian(a[k], b[k], s, t, sp)
    order = np.lexsort((pos[:, 0], pos[:, 1]))
    points, jac, i, j = pos[order], jac[order], i[order], j[order]
    out = []
    near = 1e-7 * float(sp.min())
    for m in range(len(points)):
        if any(np.abs(q.position - points[m]).max() <= near for q in out[-8:]):
            continue                              # the same zero seen from a neighbouring cell
        c = classify_critical_point(jac[m], tol)
        out.append(CriticalPoint(points[m], jac[m], c.kind, c.eigenvalues, c.reason,
                                 (int(j[m]), int(i[m]))))
    return out


def jacobian_at(field, point):
    r"""The Jacobian of the bilinear interpolant of a gridded field at a point.

    In the cell holding the point, :math:`\partial u/\partial x = (a_1 + a_3 t)/\Delta x`,
    :math:`\partial u/\partial y = (a_2 + a_3 s)/\Delta y`, and the same with b for v.

    Parameters
    ----------
    field : Field
    point : array_like, shape (2,)

    Returns
    -------
    ndarray, shape (2, 2)

    Raises
    ------
    ValueError
        For a field with NaN or infinite values (its Jacobian has no meaning).

    Examples
    --------
    >>> jacobian_at(preset_field("linear", 0.0, -1.0, n=5), [0.3, 0.2])
    array([[0., 1.],
           [1., 0.]])
    """
    g, sp, org = _as_vector_field(field)
    p = as_vector(point, "point", 2)
    i, j, s, t = _cell_coords(g.shape[:2], sp, org, p[0], p[1])
    a, b = _cell_coefficients(g[j:j + 2, i:i + 2])
    return _bilinear_jacobian(a[0, 0], b[0, 0], s, t, sp) + 0.0


# ---------------------------------------------------------------------------------------------
# Separatrices
# ---------------------------------------------------------------------------------------------

def separatrices(field, saddle, eps=None, step=None, n=400, method="rk4"):
    r"""The four separatrices of a saddle: streamlines that start along its eigenvectors.

    At a saddle the Jacobian has a positive eigenvalue (eigenvector :math:`e_u`, the
    **unstable** direction: the flow leaves along it) and a negative one (:math:`e_s`, stable:
    the flow arrives along it). Seeds at :math:`p \pm \varepsilon e_u` are integrated forward,
    seeds at :math:`p \pm \varepsilon e_s` backward. These four curves divide the plane into
    regions of different flow behaviour.

    Parameters
    ----------
    field : Field
    saddle : CriticalPoint or array_like, shape (2,)
        A saddle from :func:`critical_points`, or its position (the Jacobian then comes from
        :func:`jacobian_at`).
    eps : float, optional
        Offset of the seeds from the saddle. Default: a twentieth of the smaller grid spacing.
    step : float, optional
        Integration step, a length: the separatrices are integrated along the arc length
        (``normalize=True`` of :func:`integrate_gridded`), so that the slow flow next to the
        saddle costs no more steps than elsewhere. Default: half the smaller grid spacing.
    n : int
        Steps per separatrix.
    method : {"euler", "rk2", "rk4"}

    Returns
    -------
    dict
        ``unstable`` and ``stable``: two lines each, (m, 2) arrays beginning at the saddle;
        ``directions``: the unit eigenvectors (e_u, e_s).

    Raises
    ------
    ValueError
        If the point is not a saddle.

    Examples
    --------
    The saddle v = (y, x): the flow leaves along the diagonal y = x and arrives along y = -x:

    >>> f = preset_field("linear", 0.0, -1.0, n=9)
    >>> sep = separatrices(f, [0.0, 0.0], n=200)
    >>> [line[-1].round(2).tolist() for line in sep["unstable"]]
    [[1.5, 1.5], [-1.5, -1.5]]
    >>> [line[-1].round(2).tolist() for line in sep["stable"]]
    [[-1.5, 1.5], [1.5, -1.5]]
    """
    g, sp, org = _as_vector_field(field)
    if isinstance(saddle, CriticalPoint):
        p, jac = np.asarray(saddle.position, float), np.asarray(saddle.jacobian, float)
    else:
        p = as_vector(saddle, "saddle", 2)
        jac = jacobian_at(field, p)
    c = classify_critical_point(jac)
    if c.kind != "saddle":
        raise ValueError(f"saddle must be a saddle point, got a {c.kind} ({c.reason})")
    lam, vec = np.linalg.eig(jac)
    lam, vec = lam.real, vec.real
    unstable = vec[:, int(np.argmax(lam))]
    stable = vec[:, int(np.argmin(lam))]
    h_min = float(sp.min())
    eps = h_min / 20 if eps is None else as_positive(eps, "eps")
    speed = float(np.hypot(g[..., 0], g[..., 1]).max())
    step = h_min / 2 if step is None else as_positive(step, "step")
    out = {"directions": (unstable / np.linalg.norm(unstable), stable / np.linalg.norm(stable))}
    for name, e, back in (("unstable", unstable, False), ("stable", stable, True)):
        e = e / np.linalg.norm(e)
        seeds = np.array([p + eps * e, p - eps * e])
        lines = integrate_gridded(field, seeds, step, n, method, backward=back,
                                  min_speed=1e-9 * speed, normalize=True)
        out[name] = [np.vstack([p, line]) for line in lines]
    return out


# ---------------------------------------------------------------------------------------------
# Preset fields
# ---------------------------------------------------------------------------------------------

#: name -> (the two parameters' names, their defaults, their (low, high) ranges, the domain
#: ((x0, y0), (x1, y1))).
FLOW_PRESETS = {
    "linear": (("trace", "determinant"), (-1.0, 1.25), ((-3.0, 3.0), (-3.0, 3.0)),
               ((-1.5, -1.5), (1.5, 1.5))),
    "saddle and two foci": (("stiffness k", "damping δ"), (1.0, 0.5), ((-0.5, 1.5), (-1.0, 1.0)),
                            ((-2.0, -1.5), (2.0, 1.5))),
    "double gyre": (("time t", "amplitude ε"), (2.5, 0.25), ((0.0, 10.0), (0.0, 0.5)),
                    ((0.0, 0.0), (2.0, 1.0))),
}


def _preset_velocity(name, p, q, x, y):
    """The analytic velocity of a preset at points (x, y)."""
    if name == "linear":
        j = _linear_matrix(p, q)
        return j[0, 0] * x + j[0, 1] * y, j[1, 0] * x + j[1, 1] * y
    if name == "saddle and two foci":
        return y + 0.0 * x, p * x - x ** 3 - q * y
    a, omega = 0.1, 2 * np.pi / 10
    e = q * np.sin(omega * p)
    f = e * x * x + (1 - 2 * e) * x
    dfdx = 2 * e * x + (1 - 2 * e)
    return (-np.pi * a * np.sin(np.pi * f) * np.cos(np.pi * y),
            np.pi * a * np.cos(np.pi * f) * np.sin(np.pi * y) * dfdx)


def _linear_matrix(trace, det):
    """[[tau/2, 1], [tau^2/4 - det, tau/2]]: trace tau, determinant det."""
    return np.array([[trace / 2, 1.0], [trace * trace / 4 - det, trace / 2]])


def preset_field(name, p=None, q=None, n=33):
    r"""A gridded example field for the lesson and the explorer.

    * ``"linear"``: :math:`v = J x` with :math:`J = \begin{bmatrix} \tau/2 & 1 \\
      \tau^2/4 - \Delta & \tau/2 \end{bmatrix}` (p = trace :math:`\tau`, q = determinant
      :math:`\Delta`): one critical point at the origin, of any class; on [-1.5, 1.5]^2.
    * ``"saddle and two foci"``: the damped Duffing oscillator :math:`(y,\ k x - x^3 - \delta y)`
      (p = k, q = :math:`\delta`): for k > 0 a saddle at the origin and two attracting foci at
      :math:`(\pm\sqrt k, 0)`; on [-2, 2] x [-1.5, 1.5].
    * ``"double gyre"``: the double-gyre flow :math:`u = -\pi A \sin(\pi f)\cos(\pi y)`,
      :math:`v = \pi A \cos(\pi f)\sin(\pi y)\,\partial f/\partial x`,
      :math:`f = \epsilon \sin(\omega t) x^2 + (1 - 2\epsilon\sin(\omega t)) x` at the instant
      p = t (q = :math:`\epsilon`, A = 0.1, :math:`\omega = 2\pi/10`); on [0, 2] x [0, 1].

    Parameters
    ----------
    name : str
        A key of :data:`FLOW_PRESETS`.
    p, q : float, optional
        The two parameters (defaults in :data:`FLOW_PRESETS`).
    n : int
        Nodes along y (x gets about as many per unit length), >= 3. Values below 1e-12 of
        the largest are set to 0 (rounding noise would hide zeros on the border).

    Returns
    -------
    Field

    Examples
    --------
    >>> f = preset_field("linear", -1.0, 1.25, n=3)
    >>> f.values[1, 2]                      # v(1.5, 0) = (-0.75, -1.5 * 1)
    array([-0.75, -1.5 ])
    """
    as_choice(name, "name", tuple(FLOW_PRESETS))
    _, defaults, _, ((x0, y0), (x1, y1)) = FLOW_PRESETS[name]
    p = defaults[0] if p is None else float(p)
    q = defaults[1] if q is None else float(q)
    if not (np.isfinite(p) and np.isfinite(q)):
        raise ValueError(f"p and q must be finite, got {p} and {q}")
    n = as_whole(n, "n", 3)
    nx = int(round((x1 - x0) / (y1 - y0) * (n - 1))) + 1
    x, y = np.meshgrid(np.linspace(x0, x1, nx), np.linspace(y0, y1, n))
    u, v = _preset_velocity(name, p, q, x, y)
    small = 1e-12 * max(float(np.abs(u).max()), float(np.abs(v).max()))
    u, v = np.where(np.abs(u) < small, 0.0, u), np.where(np.abs(v) < small, 0.0, v)
    return gridded_field(u, v, ((x1 - x0) / (nx - 1), (y1 - y0) / (n - 1)), (x0, y0))
