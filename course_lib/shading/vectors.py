"""Chapter 12 (lesson section 2): the vectors of the model: normal, light, view, reflection,
halfway.
"""

import numpy as np

from .._validate import as_points, as_vector, broadcast_stacks
from ._common import _dot, _unit

__all__ = ["halfway", "reflect", "view_directions"]


# ---------------------------------------------------------------------------------------------
# Vectors of the model
# ---------------------------------------------------------------------------------------------

def reflect(l, n):
    r"""The mirror direction :math:`R = 2 (N \cdot L) N - L` of `l` about the normal `n`.

    Convention: :math:`L` points *away* from the surface, towards the light, and so does the
    result :math:`R` (towards where the mirrored light goes). With the other common convention,
    an *incoming* direction :math:`D = -L` travelling towards the surface (a ray's direction),
    the same reflected vector is :math:`R = D - 2 (N \cdot D) N` (``reflect(-d, n)``), which is
    :func:`course_lib.raytracing.reflect_direction` ``(d, n)``, computed by this function's
    formula. For unit :math:`L`, :math:`R` is a unit vector with :math:`N \cdot R = N \cdot L`.

    `n` is normalized here; `l` is used as given (so :math:`\lVert R \rVert = \lVert L
    \rVert`). Works on any stack of vectors, shape ``(..., 3)``, with broadcasting.

    Parameters
    ----------
    l : array_like, shape (..., 3)
        Direction(s) towards the light.
    n : array_like, shape (..., 3)
        Surface normal(s), not zero.

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For a zero normal, non-finite values or shapes that do not broadcast.

    Examples
    --------
    Light from 45 degrees on the left leaves at 45 degrees on the right:

    >>> reflect([-1, 1, 0], [0, 1, 0])
    array([1., 1., 0.])
    >>> d = [1, -1, 0]                      # a ray travelling down-right hits the floor
    >>> reflect(-np.asarray(d), [0, 2, 0])  # bounces up-right: D - 2 (N.D) N
    array([1., 1., 0.])
    """
    lv = as_points(l, "l", dims=3)
    nv = _unit(n, "n")
    broadcast_stacks(l=(lv, 1), n=(nv, 1))
    return _mirror(lv, nv)


def _mirror(l, n):
    """R = 2 (n . l) n - l for unit n (unvalidated): reflect, and raytracing.reflect_direction
    as _mirror(-d, n)."""
    return 2.0 * _dot(n, l)[..., None] * n - l


def halfway(l, v):
    r"""The halfway vector :math:`H = (L + V)/\lVert L + V \rVert` of Blinn-Phong.

    `l` and `v` are normalized first (both point away from the surface). :math:`H` is the
    normal a mirror would need to reflect the light into the eye, so :math:`N \cdot H = 1`
    exactly when :math:`R \cdot V = 1`.

    Parameters
    ----------
    l, v : array_like, shape (..., 3)
        Directions towards the light and towards the viewer.

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For zero vectors, or :math:`L = -V` (light exactly behind the viewer's line: no
        halfway direction).

    Examples
    --------
    >>> halfway([0, 0, 1], [1, 0, 0]) * np.sqrt(2)
    array([1., 0., 1.])
    """
    s = _unit(l, "l") + _unit(v, "v")
    length = np.sqrt(_dot(s, s))
    if np.any(length < 1e-12):
        raise ValueError("l and v must not be opposite: L + V = 0 has no halfway direction")
    return s / length[..., None]


def view_directions(points, eye):
    r"""Unit vectors from surface points towards the eye, :math:`V = (E - P)/\lVert E - P\rVert`.

    Parameters
    ----------
    points : array_like, shape (..., 3)
    eye : array_like, shape (3,)

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        If a point coincides with the eye.

    Examples
    --------
    >>> view_directions([[0, 0, 0], [3, 0, 4]], [0, 0, 4])
    array([[ 0.,  0.,  1.],
           [-1.,  0.,  0.]])
    """
    p = as_points(points, "points", dims=3)
    e = as_vector(eye, "eye", 3)
    d = e - p
    if np.any(_dot(d, d) == 0):
        raise ValueError("points must not coincide with the eye: the view direction is undefined")
    return d / np.sqrt(_dot(d, d))[..., None]
