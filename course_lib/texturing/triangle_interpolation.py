"""Chapter 14 (lesson section 3): barycentric coordinates, perspective-correct interpolation."""

import numpy as np

from .._validate import as_array, as_points, broadcast_stacks
from ._common import _dot

__all__ = ["barycentric", "barycentric_interpolate", "perspective_interpolate",
    "perspective_weights"]


# ---------------------------------------------------------------------------------------------
# Barycentric coordinates and interpolation
# ---------------------------------------------------------------------------------------------

def barycentric(p, a, b, c):
    r"""Barycentric coordinates of points in the triangle (a, b, c), by signed areas.

    .. math:: \lambda_a = \frac{A(P, B, C)}{A(A, B, C)}, \quad
              \lambda_b = \frac{A(A, P, C)}{A(A, B, C)}, \quad
              \lambda_c = \frac{A(A, B, P)}{A(A, B, C)}, \qquad
              P = \lambda_a A + \lambda_b B + \lambda_c C,\ \ \sum \lambda = 1

    Each sub-triangle replaces one vertex by :math:`P`. The areas are **signed** (positive when
    counter-clockwise), so the weights are all in [0, 1] exactly when :math:`P` is inside (or on
    the border) and one or two are negative outside: the sign tells on which side of which
    edge :math:`P` lies. In 2D, :math:`2A(A, B, C) = (B - A) \times (C - A)`. In 3D the signed
    area is measured along the triangle's normal :math:`n = (B - A) \times (C - A)`:
    :math:`\lambda_a = ((B - P) \times (C - P)) \cdot n / \lVert n \rVert^2`, etc., which gives
    the coordinates of the **orthogonal projection of P onto the triangle's plane** (the
    component of :math:`P` along :math:`n` drops out of every cross product dotted with
    :math:`n`).

    Parameters
    ----------
    p : array_like, shape (..., 2) or (..., 3)
        The points.
    a, b, c : array_like, shape (..., 2) or (..., 3)
        The triangle's vertices: one triangle for all points, or one per point (broadcast).

    Returns
    -------
    ndarray, shape (..., 3)
        :math:`(\lambda_a, \lambda_b, \lambda_c)`, summing to 1.

    Raises
    ------
    ValueError
        For a degenerate (zero-area) triangle, mixed dimensions, NaN or shapes that do not
        broadcast.

    Examples
    --------
    >>> barycentric([[1, 1], [0, 0], [4, 0]], [0, 0], [4, 0], [0, 4])
    array([[0.5 , 0.25, 0.25],
           [1.  , 0.  , 0.  ],
           [0.  , 1.  , 0.  ]])
    >>> barycentric([3, 3], [0, 0], [4, 0], [0, 4])       # outside, beyond the edge b-c
    array([-0.5 ,  0.75,  0.75])
    >>> barycentric([1, 1, 5], [0, 0, 0], [4, 0, 0], [0, 4, 0])   # projected onto z = 0
    array([0.5 , 0.25, 0.25])
    """
    pts = [as_points(x, name) for x, name in ((p, "p"), (a, "a"), (b, "b"), (c, "c"))]
    dims = {x.shape[-1] for x in pts}
    if len(dims) != 1:
        raise ValueError(f"p, a, b and c must all be 2D or all 3D, got dimensions "
                         f"{[x.shape[-1] for x in pts]}")
    broadcast_stacks(p=(pts[0], 1), a=(pts[1], 1), b=(pts[2], 1), c=(pts[3], 1))
    p, a, b, c = pts
    if p.shape[-1] == 2:
        def area2(q, r, s):
            return ((r[..., 0] - q[..., 0]) * (s[..., 1] - q[..., 1])
                    - (r[..., 1] - q[..., 1]) * (s[..., 0] - q[..., 0]))
        total = area2(a, b, c)
        scale = np.abs(total)
        weights = [area2(p, b, c), area2(a, p, c), area2(a, b, p)]
    else:
        n = np.cross(b - a, c - a)
        total = _dot(n, n)
        scale = np.sqrt(total)
        weights = [_dot(np.cross(b - p, c - p), n), _dot(np.cross(c - p, a - p), n),
                   _dot(np.cross(a - p, b - p), n)]
    edges = np.maximum(np.maximum(_dot(b - a, b - a), _dot(c - b, c - b)), _dot(a - c, a - c))
    degenerate = scale <= 1e-12 * edges
    degenerate = degenerate | (edges == 0)
    if np.any(degenerate):
        where = ""
        if np.ndim(degenerate):
            index = np.unravel_index(np.argmax(degenerate), np.shape(degenerate))
            where = f" (triangle at index {tuple(int(i) for i in index)})"
        raise ValueError(f"the triangle a, b, c is degenerate{where}: its area is zero, so "
                         "barycentric coordinates are undefined")
    return np.stack(np.broadcast_arrays(*weights), axis=-1) / np.asarray(total)[..., None]


def _per_vertex(weights, name="weights"):
    """Three values per point, one for each vertex of the triangle (last axis 3)."""
    w = as_array(weights, name)
    if w.ndim == 0 or w.shape[-1] != 3:
        raise ValueError(f"{name} must hold three barycentric weights in the last axis (shape "
                         f"(..., 3)), got shape {w.shape}")
    return w


def barycentric_interpolate(values, weights, stacked=False):
    r"""Interpolate vertex attributes with barycentric weights, :math:`q = \sum_k \lambda_k q_k`.

    Colours, texture coordinates, normals, depths: any attribute given at the three vertices.
    Linear in screen space; :func:`perspective_interpolate` is the perspective-correct one.
    ``texturing.interpolate`` is this function under its old name (not grid interpolation:
    that is :func:`course_lib.scivis.multilinear_interpolate`).

    Parameters
    ----------
    values : array_like
        With ``stacked=False`` (default): one triangle's attribute, shape ``(3,)`` (a number
        per vertex) or ``(3, k)`` (a k-vector per vertex, rows a, b, c), shared by all points.
        With ``stacked=True``: one triangle per point, shape ``(..., 3)`` or ``(..., 3, k)``,
        the leading axes broadcasting against those of `weights` (e.g. a ray tracer's hits on
        different triangles: ``uv[faces[ids]]``).
    weights : array_like, shape (..., 3)
        Barycentric weights, e.g. from :func:`barycentric`.
    stacked : bool

    Returns
    -------
    ndarray, shape (...) or (..., k)

    Raises
    ------
    ValueError
        For shapes that do not fit.

    Examples
    --------
    >>> w = barycentric([[1, 1], [2, 0]], [0, 0], [4, 0], [0, 4])
    >>> barycentric_interpolate([10.0, 20.0, 30.0], w)
    array([17.5, 15. ])
    >>> barycentric_interpolate([[1, 0, 0], [0, 1, 0], [0, 0, 1]], w)          # RGB at the vertices
    array([[0.5 , 0.25, 0.25],
           [0.5 , 0.5 , 0.  ]])
    >>> barycentric_interpolate([[0, 1, 2], [3, 4, 5]], [[1, 0, 0], [0, 0, 1]], stacked=True)
    array([0., 5.])
    """
    w = _per_vertex(weights)
    q = as_array(values, "values")
    if not stacked:
        if q.ndim not in (1, 2) or q.shape[0] != 3:
            raise ValueError(f"values must be one triangle's attribute, shape (3,) or (3, k) "
                             f"(use stacked=True for one triangle per point), got shape {q.shape}")
        return w @ q
    if q.ndim >= 1 and q.shape[-1] == 3 and (q.ndim < 2 or q.ndim <= w.ndim):
        broadcast_stacks(values=(q, 1), weights=(w, 1))
        return _dot(q, w)
    if q.ndim >= 2 and q.shape[-2] == 3:
        broadcast_stacks(values=(q, 2), weights=(w, 1))
        return np.einsum("...v,...vk->...k", w, q)
    raise ValueError(f"values must have shape (..., 3) or (..., 3, k) with stacked=True, got "
                     f"shape {q.shape}")


interpolate = barycentric_interpolate     # the old name (not in __all__): the same function


def perspective_weights(weights, w):
    r"""Perspective-correct barycentric weights from screen-space ones and the vertices' clip w.

    .. math:: \lambda'_k = \frac{\lambda_k / w_k}{\sum_j \lambda_j / w_j}

    **Why.** The perspective divide maps a triangle to the screen non-linearly: equal steps on
    the screen are unequal steps on the triangle (the far part is squeezed). So screen-space
    weights :math:`\lambda_k` interpolate correctly only quantities that are affine *on the
    screen*. An attribute :math:`q` that is affine on the 3D triangle (a texture coordinate) is
    not, but :math:`q / w` and :math:`1 / w` are (:math:`w` is the eye-space depth for a
    perspective camera): interpolate both linearly and divide,
    :math:`q = \frac{\sum \lambda_k q_k / w_k}{\sum \lambda_k / w_k}`, which is interpolation
    with these corrected weights. Interpolating :math:`q` itself with screen weights makes
    textures on receding floors bend and swim (the PlayStation-1 look).

    Parameters
    ----------
    weights : array_like, shape (..., 3)
        Screen-space barycentric weights.
    w : array_like, shape (3,) or (..., 3)
        The clip-space w of the three vertices (positive: in front of the eye).

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For non-positive w or shapes that do not fit.

    Examples
    --------
    Half way along the screen between a vertex at depth 1 and one at depth 3, the point on the
    3D edge is only a quarter of the way:

    >>> perspective_weights([0.5, 0.5, 0.0], [1.0, 3.0, 1.0])
    array([0.75, 0.25, 0.  ])
    """
    lam = _per_vertex(weights)
    ww = _per_vertex(w, "w")
    if np.any(ww <= 0):
        raise ValueError("w must be positive (the vertices must be in front of the eye)")
    broadcast_stacks(weights=(lam, 1), w=(ww, 1))
    scaled = lam / ww
    return scaled / scaled.sum(axis=-1, keepdims=True)


def perspective_interpolate(values, weights, w, stacked=False):
    r"""Perspective-correct interpolation: :math:`\sum \lambda_k q_k/w_k \,/\, \sum \lambda_k/w_k`.

    :func:`barycentric_interpolate` with :func:`perspective_weights`.

    Parameters
    ----------
    values : array_like
        As :func:`barycentric_interpolate`.
    weights : array_like, shape (..., 3)
        Screen-space barycentric weights.
    w : array_like, shape (3,) or (..., 3)
        Clip-space w of the vertices.
    stacked : bool

    Returns
    -------
    ndarray

    Examples
    --------
    >>> float(perspective_interpolate([0.0, 1.0, 0.0], [0.5, 0.5, 0.0], [1.0, 3.0, 1.0]))
    0.25
    """
    return barycentric_interpolate(values, perspective_weights(weights, w), stacked)
