r"""Chapter 7: tensor-product Bézier, B-spline and NURBS surfaces.

A tensor-product surface blends a grid of control points :math:`P_{ij}` with products of the
curve blending functions of :mod:`course_lib.curves`, one family per parameter:

.. math:: S(u, v) = \sum_{i} \sum_{j} F_i(u)\, G_j(v)\, P_{ij}

Fix u and the surface is a curve in v whose control points are the blended columns
:math:`\sum_i F_i(u) P_{ij}` (and the other way round), so the surfaces inherit the curves'
properties: convex hull, affine (and, for NURBS, projective) invariance, corner and boundary
interpolation for Bézier and clamped B-spline patches, local control for B-splines. The
variation diminishing property has no counterpart for surfaces.

Conventions:

* The control grid has shape ``(nu, nv, d)``: ``grid[i, j]`` is :math:`P_{ij}`, the first index
  runs along u, the second along v; d >= 1 (usually 3).
* ``u`` and ``v`` are 1D arrays (or single numbers) and the surface is evaluated on the grid
  they span: the result has shape ``u.shape + v.shape + (d,)``, ``S[a, b]`` being
  :math:`S(u_a, v_b)`. So ``S[..., 0], S[..., 1], S[..., 2]`` are the X, Y, Z arrays that
  matplotlib's ``plot_surface`` and pyvista's ``StructuredGrid`` take.
* Parameters, knots, degrees and weights follow :mod:`course_lib.curves` (Bézier patches live on
  :math:`[0, 1]^2`, B-spline patches on the product of the two knot vectors' domains; values
  outside raise ``ValueError``).
* Evaluation is a product of basis matrices, :math:`S = B_u\, P\, B_v^T` coordinate by
  coordinate (``numpy.einsum``), which is fast for the dense grids used for drawing.

References: L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer 1997, Sec. 1.6, 3.4-3.5,
4.4-4.5 and 8.5; G. Farin, *Curves and Surfaces for CAGD*, 5th ed., Morgan Kaufmann 2002.
"""
from collections import namedtuple

import numpy as np

from . import curves
from ._validate import as_array, as_positive, as_scalar, as_vector, as_whole
from .curves import bspline_basis, bspline_basis_derivative
from .curves._common import _knot_vector, _parameters
from .curves.bezier_curves import _bernstein_matrix

__all__ = [
    "NurbsSurface",
    "bezier_surface",
    "bezier_surface_partials",
    "bspline_surface",
    "bspline_surface_partials",
    "hill_grid",
    "isoparametric_lines",
    "nurbs_sphere",
    "nurbs_surface",
    "nurbs_surface_partials",
    "surface_normals",
    "wave_grid",
]

NurbsSurface = namedtuple("NurbsSurface", ["control_grid", "weights", "knots_u", "knots_v",
                                           "degree_u", "degree_v"])
NurbsSurface.__doc__ = """A NURBS surface's data, in the argument order of :func:`nurbs_surface`.

Unpacks as ``control_grid, weights, knots_u, knots_v, degree_u, degree_v``.

Examples
--------
>>> NurbsSurface(*range(6)).degree_v
5
"""


# ---------------------------------------------------------------------------------------------
# input checks
# ---------------------------------------------------------------------------------------------

def _control_grid(value, name="control_grid"):
    """A control grid of shape (nu, nv, d) with nu, nv >= 2 and d >= 1."""
    g = as_array(value, name)
    if g.ndim != 3 or g.shape[0] < 2 or g.shape[1] < 2 or g.shape[2] < 1:
        raise ValueError(f"{name} must be a grid of points of shape (nu, nv, d) with nu >= 2 "
                         f"and nv >= 2 (grid[i, j] is the control point P_ij), got shape "
                         f"{g.shape}")
    return g


def _grid_weights(value, shape, name="weights"):
    w = as_array(value, name)
    if w.shape != shape:
        raise ValueError(f"{name} must have one weight per control point, shape {shape}, got "
                         f"shape {w.shape}")
    if np.any(w <= 0):
        index = tuple(int(i) for i in np.argwhere(w <= 0)[0])
        raise ValueError(f"{name} must be positive (a zero or negative weight breaks the convex "
                         f"hull property), got {name}[{index}] = {float(w[index])!r}")
    return w


def _axis(values, name, lo, hi):
    """Parameter values along one direction: a number or a 1D array inside [lo, hi]."""
    x = _parameters(values, lo, hi, name)
    if x.ndim > 1:
        raise ValueError(f"{name} must be a number or a 1D array (the surface is evaluated on "
                         f"the grid of u and v values), got shape {x.shape}")
    return x


def _bspline_direction(knots, degree, n_control, values, knots_name, degree_name, name):
    """Validated knots of one direction and the parameter values along it."""
    try:
        u, _ = _knot_vector(knots, degree, n_control, name=knots_name)
    except ValueError as error:
        message = str(error)
        if message.startswith("degree "):            # say which degree it is
            message = degree_name + message[len("degree"):]
        raise ValueError(message) from None
    p = int(degree)
    return u, p, _axis(values, name, u[p], u[n_control])


def _contract(bu, grid, bv):
    """S[a, b] = sum_ij bu[a, i] grid[i, j] bv[b, j] for 0-d or 1-d parameter axes."""
    su, sv = bu.shape[:-1], bv.shape[:-1]
    out = np.einsum("ai,ijd,bj->abd", bu.reshape(-1, bu.shape[-1]), grid,
                    bv.reshape(-1, bv.shape[-1]), optimize=True)
    return out.reshape(su + sv + grid.shape[-1:])


def _bernstein_derivative_matrix(n, t):
    """d/dt of all Bernstein polynomials of degree n: n (B_{i-1}^{n-1} - B_i^{n-1})."""
    b = _bernstein_matrix(n - 1, t)
    zero = np.zeros(b.shape[:-1] + (1,))
    return n * (np.concatenate([zero, b], axis=-1) - np.concatenate([b, zero], axis=-1))


# ---------------------------------------------------------------------------------------------
# evaluation
# ---------------------------------------------------------------------------------------------

def bezier_surface(control_grid, u, v):
    r"""Points of the tensor-product Bézier patch on the grid of `u` and `v` values.

    .. math:: S(u, v) = \sum_{i=0}^{m} \sum_{j=0}^{n} B_i^m(u)\, B_j^n(v)\, P_{ij},
              \qquad (u, v) \in [0, 1]^2

    The patch passes through its four corner control points, its boundary curves are the
    Bézier curves of the boundary rows and columns of the grid, and it lies in the convex hull
    of the control points.

    Parameters
    ----------
    control_grid : array_like, shape (m + 1, n + 1, d)
    u, v : float or 1D array_like
        Parameter values in [0, 1].

    Returns
    -------
    ndarray, shape u.shape + v.shape + (d,)

    Examples
    --------
    >>> grid = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]   # a bilinear patch
    >>> bezier_surface(grid, [0, 0.5], 0.5)
    array([[0.  , 0.5 , 0.  ],
           [0.5 , 0.5 , 0.25]])
    """
    g = _control_grid(control_grid)
    u = _axis(u, "u", 0.0, 1.0)
    v = _axis(v, "v", 0.0, 1.0)
    return _contract(_bernstein_matrix(g.shape[0] - 1, u), g,
                     _bernstein_matrix(g.shape[1] - 1, v))


def bspline_surface(control_grid, knots_u, knots_v, degree_u, degree_v, u, v):
    r"""Points of the tensor-product B-spline surface on the grid of `u` and `v` values.

    .. math:: S(u, v) = \sum_{i} \sum_{j} N_{i,p}(u)\, N_{j,q}(v)\, P_{ij}

    with the B-spline basis functions (:func:`course_lib.curves.bspline_basis`) of the knot
    vector and degree of each direction. Moving :math:`P_{ij}` changes the surface only on the
    rectangle :math:`[u_i, u_{i+p+1}) \times [v_j, v_{j+q+1})` (local control).

    Parameters
    ----------
    control_grid : array_like, shape (nu, nv, d)
    knots_u : array_like, shape (nu + degree_u + 1,)
    knots_v : array_like, shape (nv + degree_v + 1,)
    degree_u, degree_v : int
    u, v : float or 1D array_like
        Parameter values in the domains of the two knot vectors.

    Returns
    -------
    ndarray, shape u.shape + v.shape + (d,)

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib.curves import clamped_knots
    >>> grid = hill_grid(4, 4)
    >>> ku = kv = clamped_knots(4, 2)
    >>> S = bspline_surface(grid, ku, kv, 2, 2, np.linspace(0, 1, 5), [0, 1])
    >>> S.shape
    (5, 2, 3)
    >>> S[0, 0], S[-1, -1]                      # corners interpolated (clamped knots)
    (array([-1., -1.,  0.]), array([1., 1., 0.]))
    """
    g = _control_grid(control_grid)
    ku, p, u = _bspline_direction(knots_u, degree_u, g.shape[0], u, "knots_u", "degree_u", "u")
    kv, q, v = _bspline_direction(knots_v, degree_v, g.shape[1], v, "knots_v", "degree_v", "v")
    return _contract(bspline_basis(ku, p, u), g, bspline_basis(kv, q, v))


def nurbs_surface(control_grid, weights, knots_u, knots_v, degree_u, degree_v, u, v):
    r"""Points of the NURBS surface on the grid of `u` and `v` values.

    .. math:: S(u, v) = \frac{\sum_i \sum_j N_{i,p}(u)\, N_{j,q}(v)\, w_{ij} P_{ij}}
                             {\sum_i \sum_j N_{i,p}(u)\, N_{j,q}(v)\, w_{ij}}

    Evaluated in homogeneous coordinates: the B-spline surface of the points
    :math:`(w_{ij} P_{ij}, w_{ij})`, then divided by its last coordinate. (Unlike the
    non-rational case the blending functions :math:`N_i N_j w_{ij} / \sum` are in general not
    products of one function of u and one of v.) Represents quadrics exactly, e.g. the sphere
    of :func:`nurbs_sphere`.

    Parameters
    ----------
    control_grid : array_like, shape (nu, nv, d)
    weights : array_like, shape (nu, nv)
        Positive.
    knots_u, knots_v, degree_u, degree_v, u, v
        As in :func:`bspline_surface`.

    Returns
    -------
    ndarray, shape u.shape + v.shape + (d,)

    Examples
    --------
    >>> import numpy as np
    >>> S = nurbs_surface(*nurbs_sphere(2.0), np.linspace(0, 1, 7), np.linspace(0, 1, 5))
    >>> bool(np.allclose(np.linalg.norm(S, axis=-1), 2.0, rtol=0, atol=1e-12))
    True
    """
    g = _control_grid(control_grid)
    w = _grid_weights(weights, g.shape[:2])
    ku, p, u = _bspline_direction(knots_u, degree_u, g.shape[0], u, "knots_u", "degree_u", "u")
    kv, q, v = _bspline_direction(knots_v, degree_v, g.shape[1], v, "knots_v", "degree_v", "v")
    h = _contract(bspline_basis(ku, p, u), _homogeneous_grid(g, w), bspline_basis(kv, q, v))
    return h[..., :-1] / h[..., -1:]


def _homogeneous_grid(g, w):
    return np.concatenate([g * w[..., None], w[..., None]], axis=-1)


# ---------------------------------------------------------------------------------------------
# partial derivatives and normals
# ---------------------------------------------------------------------------------------------

def bezier_surface_partials(control_grid, u, v):
    r"""The Bézier patch and its partial derivatives :math:`S_u`, :math:`S_v` on the grid.

    .. math:: S_u(u, v) = \sum_i \sum_j \frac{d B_i^m}{du}(u)\, B_j^n(v)\, P_{ij}, \qquad
              \frac{d B_i^m}{du} = m\,(B_{i-1}^{m-1} - B_i^{m-1})

    and likewise for v (the surface version of the hodograph).

    Parameters
    ----------
    control_grid, u, v
        As in :func:`bezier_surface`.

    Returns
    -------
    S, S_u, S_v : ndarray, each of shape u.shape + v.shape + (d,)

    Examples
    --------
    >>> grid = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]   # z = u v
    >>> S, Su, Sv = bezier_surface_partials(grid, 0.5, 0.25)
    >>> Su, Sv
    (array([1.  , 0.  , 0.25]), array([0. , 1. , 0.5]))
    """
    g = _control_grid(control_grid)
    u = _axis(u, "u", 0.0, 1.0)
    v = _axis(v, "v", 0.0, 1.0)
    m, n = g.shape[0] - 1, g.shape[1] - 1
    bu, bv = _bernstein_matrix(m, u), _bernstein_matrix(n, v)
    du, dv = _bernstein_derivative_matrix(m, u), _bernstein_derivative_matrix(n, v)
    return _contract(bu, g, bv), _contract(du, g, bv), _contract(bu, g, dv)


def _bspline_matrices(g, knots_u, knots_v, degree_u, degree_v, u, v):
    ku, p, u = _bspline_direction(knots_u, degree_u, g.shape[0], u, "knots_u", "degree_u", "u")
    kv, q, v = _bspline_direction(knots_v, degree_v, g.shape[1], v, "knots_v", "degree_v", "v")
    return (bspline_basis(ku, p, u), bspline_basis_derivative(ku, p, u),
            bspline_basis(kv, q, v), bspline_basis_derivative(kv, q, v))


def bspline_surface_partials(control_grid, knots_u, knots_v, degree_u, degree_v, u, v):
    r"""The B-spline surface and its partial derivatives :math:`S_u`, :math:`S_v` on the grid.

    .. math:: S_u = \sum_i \sum_j N'_{i,p}(u)\, N_{j,q}(v)\, P_{ij}, \qquad
              S_v = \sum_i \sum_j N_{i,p}(u)\, N'_{j,q}(v)\, P_{ij}

    with the basis derivatives of :func:`course_lib.curves.bspline_basis_derivative` (the
    value from the right where a derivative jumps at a knot).

    Parameters
    ----------
    control_grid, knots_u, knots_v, degree_u, degree_v, u, v
        As in :func:`bspline_surface`.

    Returns
    -------
    S, S_u, S_v : ndarray, each of shape u.shape + v.shape + (d,)

    Examples
    --------
    >>> grid = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    >>> S, Su, Sv = bspline_surface_partials(grid, [0, 0, 1, 1], [0, 0, 1, 1], 1, 1, 0.5, 0.25)
    >>> S, Su
    (array([0.5  , 0.25 , 0.125]), array([1.  , 0.  , 0.25]))
    """
    g = _control_grid(control_grid)
    bu, du, bv, dv = _bspline_matrices(g, knots_u, knots_v, degree_u, degree_v, u, v)
    return _contract(bu, g, bv), _contract(du, g, bv), _contract(bu, g, dv)


def nurbs_surface_partials(control_grid, weights, knots_u, knots_v, degree_u, degree_v, u, v):
    r"""The NURBS surface and its partial derivatives :math:`S_u`, :math:`S_v` on the grid.

    With :math:`A(u, v)` the B-spline surface of the weighted points :math:`w_{ij} P_{ij}` and
    :math:`W(u, v)` that of the weights, :math:`S = A / W` and by the quotient rule

    .. math:: S_u = \frac{A_u - W_u\, S}{W}, \qquad S_v = \frac{A_v - W_v\, S}{W}

    (The NURBS Book, Sec. 4.5).

    Parameters
    ----------
    control_grid, weights, knots_u, knots_v, degree_u, degree_v, u, v
        As in :func:`nurbs_surface`.

    Returns
    -------
    S, S_u, S_v : ndarray, each of shape u.shape + v.shape + (d,)

    Examples
    --------
    >>> import numpy as np
    >>> S, Su, Sv = nurbs_surface_partials(*nurbs_sphere(), 0.0, 0.5)   # on the equator
    >>> np.round(S, 12) + 0.0, np.round(surface_normals(Su, Sv), 12) + 0.0   # outward normal
    (array([1., 0., 0.]), array([1., 0., 0.]))
    """
    g = _control_grid(control_grid)
    w = _grid_weights(weights, g.shape[:2])
    bu, du, bv, dv = _bspline_matrices(g, knots_u, knots_v, degree_u, degree_v, u, v)
    h = _homogeneous_grid(g, w)
    a, a_u, a_v = _contract(bu, h, bv), _contract(du, h, bv), _contract(bu, h, dv)
    weight = a[..., -1:]
    s = a[..., :-1] / weight
    s_u = (a_u[..., :-1] - a_u[..., -1:] * s) / weight
    s_v = (a_v[..., :-1] - a_v[..., -1:] * s) / weight
    return s, s_u, s_v


def surface_normals(partial_u, partial_v):
    r"""Unit normals :math:`(S_u \times S_v) / \lVert S_u \times S_v \rVert` of a 3D surface.

    The normal points to the side from which u turns to v counter-clockwise (swap the arguments
    or negate for the other side). Where the partial derivatives are parallel or zero, e.g. at
    the pole of :func:`nurbs_sphere` where a whole row of control points coincides, the
    surface has no normal from this formula: those entries are **zero vectors** (so they shade
    black and draw no arrow) rather than NaN; test ``np.linalg.norm(n, axis=-1) == 0`` to find
    them. Degenerate means :math:`\lVert S_u \times S_v \rVert \le 10^{-12}
    \max(\lVert S_u \rVert, \lVert S_v \rVert)^2`, which also catches a partial derivative
    that is zero only up to rounding (as at the sphere's poles).

    Parameters
    ----------
    partial_u, partial_v : array_like, shape (..., 3)
        :math:`S_u` and :math:`S_v`, e.g. from :func:`bspline_surface_partials`.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> surface_normals([[2, 0, 0], [1, 0, 0]], [[0, 3, 0], [2, 0, 0]])
    array([[0., 0., 1.],
           [0., 0., 0.]])
    """
    su = as_array(partial_u, "partial_u")
    sv = as_array(partial_v, "partial_v")
    for name, x in (("partial_u", su), ("partial_v", sv)):
        if x.ndim == 0 or x.shape[-1] != 3:
            raise ValueError(f"{name} must be 3D vectors, shape (..., 3), got shape {x.shape}")
    if su.shape != sv.shape:
        raise ValueError(f"partial_u and partial_v must have the same shape, got {su.shape} and "
                         f"{sv.shape}")
    n = np.cross(su, sv)
    length = np.linalg.norm(n, axis=-1, keepdims=True)
    scale = np.maximum(np.linalg.norm(su, axis=-1, keepdims=True),
                       np.linalg.norm(sv, axis=-1, keepdims=True)) ** 2
    ok = (length > 1e-12 * scale) & (length > 0)
    return np.where(ok, n / np.where(ok, length, 1.0), 0.0)


# ---------------------------------------------------------------------------------------------
# drawing helpers and example patches
# ---------------------------------------------------------------------------------------------

def isoparametric_lines(evaluate, u_lines=5, v_lines=5, samples=50, domain_u=(0.0, 1.0),
                        domain_v=(0.0, 1.0)):
    r"""The isoparametric curves of a surface, u = const and v = const, ready to draw.

    A wireframe of a parametric surface: the curves :math:`v \mapsto S(u_a, v)` for a few
    fixed :math:`u_a`, and :math:`u \mapsto S(u, v_b)` for a few fixed :math:`v_b`.

    Parameters
    ----------
    evaluate : callable
        ``evaluate(u, v)`` takes two 1D arrays and returns the surface on their grid, shape
        ``(len(u), len(v), d)``: e.g. ``lambda u, v: bspline_surface(grid, ku, kv, 3, 3, u, v)``.
    u_lines, v_lines : int or 1D array_like, default 5
        The fixed u values (v values) of the lines, or how many equally spaced ones (ends
        included).
    samples : int, default 50
        Points per line (>= 2).
    domain_u, domain_v : (float, float), default (0, 1)
        The parameter domain, e.g. :func:`course_lib.curves.domain` of the knots.

    Returns
    -------
    constant_u : ndarray, shape (number of u lines, samples, d)
        ``constant_u[a]`` is the polyline :math:`S(u_a, v)`, v running over the domain.
    constant_v : ndarray, shape (number of v lines, samples, d)
        ``constant_v[b]`` is the polyline :math:`S(u, v_b)`, u running over the domain.

    Examples
    --------
    >>> grid = hill_grid(3, 3)
    >>> along_v, along_u = isoparametric_lines(lambda u, v: bezier_surface(grid, u, v), 3, 2, 4)
    >>> along_v.shape, along_u.shape
    ((3, 4, 3), (2, 4, 3))
    >>> along_v[0]                               # the boundary u = 0: the first grid row's curve
    array([[-1.        , -1.        ,  0.        ],
           [-1.        , -0.33333333,  0.        ],
           [-1.        ,  0.33333333,  0.        ],
           [-1.        ,  1.        ,  0.        ]])
    """
    if not callable(evaluate):
        raise TypeError(f"evaluate must be a function evaluate(u, v), got a "
                        f"{type(evaluate).__name__}")
    samples = as_whole(samples, "samples", 2, at_least=True)
    (u0, u1), (v0, v1) = _interval(domain_u, "domain_u"), _interval(domain_v, "domain_v")
    us = _line_values(u_lines, "u_lines", u0, u1)
    vs = _line_values(v_lines, "v_lines", v0, v1)
    constant_u = np.asarray(evaluate(us, np.linspace(v0, v1, samples)))
    constant_v = np.swapaxes(np.asarray(evaluate(np.linspace(u0, u1, samples), vs)), 0, 1)
    return constant_u, constant_v


def _interval(value, name):
    lo, hi = as_vector(value, name, 2)
    if not lo < hi:
        raise ValueError(f"{name} must be an interval (lo, hi) with lo < hi, got "
                         f"({float(lo)!r}, {float(hi)!r})")
    return lo, hi


def _line_values(value, name, lo, hi):
    if np.ndim(value) == 0 and not isinstance(value, float):
        return np.linspace(lo, hi, as_whole(value, name, 1, at_least=True))
    return _axis(value, name, lo, hi).reshape(-1)


def hill_grid(nu=4, nv=4, height=1.0):
    r"""An example control grid: a smooth hill over the square :math:`[-1, 1]^2`.

    The control points lie on an even grid in x and y, with
    :math:`z_{ij} = h \sin(\pi i / (n_u - 1)) \sin(\pi j / (n_v - 1))`: zero on the border and
    highest in the middle, so any patch type through it looks like a hill with flat edges.

    Parameters
    ----------
    nu, nv : int, default 4
        Grid size, each >= 2.
    height : float, default 1

    Returns
    -------
    ndarray, shape (nu, nv, 3)

    Examples
    --------
    >>> hill_grid(3, 3)[:, :, 2]
    array([[0., 0., 0.],
           [0., 1., 0.],
           [0., 0., 0.]])
    """
    nu = as_whole(nu, "nu", 2, at_least=True)
    nv = as_whole(nv, "nv", 2, at_least=True)
    h = as_scalar(height, "height")
    x, y = np.meshgrid(np.linspace(-1, 1, nu), np.linspace(-1, 1, nv), indexing="ij")
    z = h * np.outer(np.sin(np.pi * np.arange(nu) / (nu - 1)),
                     np.sin(np.pi * np.arange(nv) / (nv - 1)))
    return np.round(np.stack([x, y, z], axis=-1), 15) + 0.0


def wave_grid(nu=7, nv=7, amplitude=0.3, waves=1.0):
    r"""An example control grid: a wave running along x over the square :math:`[-1, 1]^2`.

    :math:`z_{ij} = a \sin(2\pi\, k\, (x_i + 1) / 2) \cos(\pi y_j / 2)` with k = `waves`
    periods across the square; a good surface for showing local control (move one control
    point and only one crest changes with B-splines) and shading with normals.

    Parameters
    ----------
    nu, nv : int, default 7
        Grid size, each >= 2.
    amplitude : float, default 0.3
    waves : float, default 1
        Periods across the square.

    Returns
    -------
    ndarray, shape (nu, nv, 3)

    Examples
    --------
    >>> grid = wave_grid(5, 3, amplitude=1.0)
    >>> grid.shape, grid[:, 1, 2].round(12) + 0.0
    ((5, 3, 3), array([ 0.,  1.,  0., -1., -0.]))
    """
    nu = as_whole(nu, "nu", 2, at_least=True)
    nv = as_whole(nv, "nv", 2, at_least=True)
    a = as_scalar(amplitude, "amplitude")
    k = as_scalar(waves, "waves")
    x, y = np.meshgrid(np.linspace(-1, 1, nu), np.linspace(-1, 1, nv), indexing="ij")
    z = a * np.sin(np.pi * k * (x + 1)) * np.cos(np.pi * y / 2)
    return np.stack([x, y, z], axis=-1)


def nurbs_sphere(radius=1.0, center=(0.0, 0.0, 0.0)):
    r"""An exact sphere as a biquadratic NURBS surface (a surface of revolution).

    The tensor product of the 9-point NURBS circle (:func:`course_lib.curves.nurbs_circle`) in
    u, around the z axis, with a 5-point half circle from the south pole to the north pole in
    v: :math:`P_{ij} = (r_j\, c_i, z_j)` and :math:`w_{ij} = w_i w_j`, where :math:`c_i, w_i`
    are the circle's control points and weights and :math:`(r_j, z_j), w_j` those of the half
    circle (The NURBS Book, Sec. 8.5). Every point lies at distance `radius` from the centre.
    The whole first and last rows of control points (v = 0 and v = 1) sit at the poles, where
    :math:`S_u = 0` and :func:`surface_normals` returns zero vectors.

    Parameters
    ----------
    radius : float, default 1
        Positive.
    center : array_like, shape (3,)

    Returns
    -------
    NurbsSurface
        ``(control_grid (9, 5, 3), weights (9, 5), knots_u (12,), knots_v (8,), 2, 2)``: unpack
        it into :func:`nurbs_surface`.

    Examples
    --------
    >>> sphere = nurbs_sphere()
    >>> sphere.control_grid.shape, sphere.knots_v
    ((9, 5, 3), array([0. , 0. , 0. , 0.5, 0.5, 1. , 1. , 1. ]))
    """
    r = as_positive(radius, "radius")
    c = as_vector(center, "center", 3)
    circle, w_circle, knots_u, _ = curves.nurbs_circle()
    s = np.sqrt(0.5)
    profile = np.array([[0, -1], [1, -1], [1, 0], [1, 1], [0, 1]], dtype=float)   # (r, z)
    w_profile = np.array([1, s, 1, s, 1])
    knots_v = np.array([0, 0, 0, 0.5, 0.5, 1, 1, 1], dtype=float)
    grid = np.empty((9, 5, 3))
    grid[..., :2] = circle[:, None, :] * profile[None, :, 0, None]
    grid[..., 2] = np.broadcast_to(profile[:, 1], (9, 5))
    return NurbsSurface(c + r * grid, np.outer(w_circle, w_profile), knots_u, knots_v, 2, 2)
