"""Chapter 18 (lesson section 5): glyphs (arrows) for vector fields."""

import numpy as np

from .._validate import as_points, as_positive, as_scalar

__all__ = ["arrows", "hedgehog"]


# ---------------------------------------------------------------------------------------------
# Glyphs
# ---------------------------------------------------------------------------------------------

def _glyph_inputs(points, vectors, dims):
    p = as_points(points, "points", dims=dims)
    v = as_points(vectors, "vectors", dims=dims)
    if p.shape[-1] != v.shape[-1]:
        raise ValueError(f"points and vectors must have the same dimension, got {p.shape[-1]} "
                         f"and {v.shape[-1]}")
    shape = np.broadcast_shapes(p.shape, v.shape) if p.shape != v.shape else p.shape
    return np.broadcast_to(p, shape), np.broadcast_to(v, shape)


def hedgehog(points, vectors, scale=1.0, normalize=False):
    """Hedgehog glyphs: a line segment from each point along its vector, p -> p + scale v.

    Parameters
    ----------
    points, vectors : array_like, shape (..., d)
        Positions and vectors (2D or 3D), broadcast against each other.
    scale : float
        Length factor (choose it so that the longest segment is about one grid cell).
    normalize : bool
        If True, all segments have length `scale` (direction only; zero vectors stay points).

    Returns
    -------
    ndarray, shape (..., 2, d)
        (start, end) of each segment, ready for matplotlib's ``LineCollection``.

    Examples
    --------
    >>> hedgehog([[0, 0], [1, 1]], [[2, 0], [0, -1]], scale=0.5)
    array([[[0. , 0. ],
            [1. , 0. ]],
    <BLANKLINE>
           [[1. , 1. ],
            [1. , 0.5]]])
    """
    p, v = _glyph_inputs(points, vectors, (2, 3))
    s = as_scalar(scale, "scale")
    if normalize:
        length = np.linalg.norm(v, axis=-1, keepdims=True)
        v = np.where(length > 0, v / np.where(length > 0, length, 1.0), 0.0)
    return np.stack([p, p + s * v], axis=-2)


def arrows(points, vectors, scale=1.0, head_length=0.3, head_width=0.3, shaft_width=0.08):
    """2D arrow glyphs as closed outlines of 7 vertices, sized by the vector's length.

    An arrow of length L = scale |v| runs from the point p to the tip p + scale v: a shaft of
    width ``shaft_width * L`` and a triangular head of length ``head_length * L`` and width
    ``head_width * L`` (so arrow shapes stay similar: the size shows the magnitude).

    Parameters
    ----------
    points, vectors : array_like, shape (..., 2)
    scale : float
        Length factor.
    head_length, head_width, shaft_width : float
        Proportions of the arrow's length, positive; head_length at most 1.

    Returns
    -------
    ndarray, shape (..., 7, 2)
        Vertices counter-clockwise from the tail: tail right, shaft end right, head right,
        tip, head left, shaft end left, tail left (for ``PolyCollection``). A zero vector gives
        seven copies of its point.

    Examples
    --------
    >>> arrows([0, 0], [1, 0], head_length=0.25, head_width=0.5, shaft_width=0.1)
    array([[ 0.  , -0.05],
           [ 0.75, -0.05],
           [ 0.75, -0.25],
           [ 1.  ,  0.  ],
           [ 0.75,  0.25],
           [ 0.75,  0.05],
           [ 0.  ,  0.05]])
    """
    p, v = _glyph_inputs(points, vectors, 2)
    s = as_scalar(scale, "scale")
    hl = as_positive(head_length, "head_length")
    if hl > 1:
        raise ValueError(f"head_length must be at most 1 (a fraction of the arrow), got {hl:g}")
    hw, sw = as_positive(head_width, "head_width"), as_positive(shaft_width, "shaft_width")
    d = s * v                                     # along the arrow, length L
    n = np.stack([-d[..., 1], d[..., 0]], axis=-1)  # to the left, also length L
    neck = p + (1 - hl) * d
    outline = [p - 0.5 * sw * n, neck - 0.5 * sw * n, neck - 0.5 * hw * n, p + d,
               neck + 0.5 * hw * n, neck + 0.5 * sw * n, p + 0.5 * sw * n]
    return np.stack(outline, axis=-2)
