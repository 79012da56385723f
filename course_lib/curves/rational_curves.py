"""Chapter 7 (lesson section 3): rational Bezier curves, NURBS, conics and the circle."""

import numpy as np

from .._validate import as_array, as_positive, as_vector
from ._common import _control_points, _control_weights, _knot_vector, NurbsCurve, _parameters
from .bezier_curves import _bernstein_matrix
from .bspline_curves import _de_boor

__all__ = ["conic_type", "nurbs", "nurbs_circle", "rational_bezier", "rational_quadratic_conic"]


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
    w = _control_weights(weights, len(p))
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
    w = _control_weights(weights, len(p_ctrl))
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
    r = as_positive(radius, "radius")
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
    w = as_positive(w, "w")
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
    w = as_positive(w, "w")
    return rational_bezier(points, [1.0, w, 1.0], t)
