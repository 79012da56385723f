r"""Chapter 14: texture transformations, affine maps of texture coordinates (u, v).

A *texture matrix* :math:`M` (3x3, homogeneous, 2D) is applied to the texture coordinates of a
point before the texture is sampled: the sampler looks up :math:`(u', v', 1)^T = M (u, v, 1)^T`.
Tiling (repeat the texture k times: scale the coordinates by k), offset (translate), rotation
about a point (the texture's centre, a texel centre) and shear are the usual ones, composed
like any chapter 3 matrices (:func:`course_lib.transforms.compose`; the first to act stands
rightmost).

**The picture moves the opposite way.** :math:`M` maps *coordinates*, not the picture: the
feature that used to sit at :math:`(u_0, v_0)` now shows where :math:`M (u, v) = (u_0, v_0)`,
i.e. at :math:`M^{-1} (u_0, v_0)`. Offsetting the coordinates by +0.25 moves the picture by
-0.25; scaling them by 2 shrinks the picture to half (two repeats); rotating them by +30°
turns the picture by -30°. To move the picture by :math:`A`, use :math:`M = A^{-1}`.

In the pipeline (OpenGL's fixed-function ``GL_TEXTURE`` matrix, or a line in a vertex
shader), the texture matrix acts on the per-vertex coordinates after the mapping or the
stored (u, v) and before interpolation and sampling; since it is affine, transforming the
vertices and interpolating equals interpolating and transforming.

The 2D matrices are :mod:`course_lib.transforms`' (``translate``, ``scale``, ``rotate_about``,
``shear_x``, ``shear_y``); this module only names them for texture space and adds the
application to (u, v) arrays and to a whole texture.
"""

import numpy as np

from .. import transforms
from .._validate import as_array, as_choice, as_matrix, as_scalar, as_vector, as_whole
from ._common import WRAP_MODES, _texture, _uv
from .sampling import bilinear_sample, nearest_sample, uv_grid

__all__ = ["apply_texture_matrix", "texture_matrix", "tile", "transform_texture"]

FILTERS = ("bilinear", "nearest")


def _pair(value, name):
    a = as_array(value, name)
    if a.ndim == 0:
        a = np.array([a, a])
    if a.shape != (2,):
        raise ValueError(f"{name} must be a number or a pair (for u, v), got shape {a.shape}")
    return a


def tile(repeats_u, repeats_v=None):
    r"""The texture matrix that repeats the texture `repeats_u` x `repeats_v` times: a scaling.

    .. math:: S(k_u, k_v) = \operatorname{diag}(k_u, k_v, 1)

    Over :math:`u \in [0, 1]` the coordinate :math:`k_u u` runs through :math:`[0, k_u]`: with
    ``wrap="repeat"`` the texture appears :math:`k_u` times, each copy :math:`1/k_u` wide (the
    picture shrinks while the coordinates grow: the inverse relation).

    Parameters
    ----------
    repeats_u : float
        Non-zero (negative mirrors).
    repeats_v : float, optional
        Default: `repeats_u`.

    Returns
    -------
    ndarray, shape (3, 3)

    Raises
    ------
    ValueError
        For zero (a texture squeezed to one texel) or non-finite repeats.

    Examples
    --------
    >>> tile(2, 3) @ [0.5, 0.5, 1]
    array([1. , 1.5, 1. ])
    """
    ku = as_scalar(repeats_u, "repeats_u")
    kv = ku if repeats_v is None else as_scalar(repeats_v, "repeats_v")
    for k, name in ((ku, "repeats_u"), (kv, "repeats_v")):
        if k == 0:
            raise ValueError(f"{name} must not be 0: the whole surface would get one texel")
    return transforms.scale([ku, kv])


def texture_matrix(tiling=1.0, offset=(0.0, 0.0), rotation=0.0, center=(0.5, 0.5), shear=0.0):
    r"""The usual texture matrix: shear, rotate about `center`, tile, then offset.

    .. math:: M = T(o)\; S(k_u, k_v)\; T(c)\, R(\alpha)\, T(-c)\; SH_x(s)

    read right to left (the rightmost acts first on the coordinates): a shear of u by
    :math:`s v`, a rotation by :math:`\alpha` radians about :math:`c`, the tiling, the offset.
    Equivalent to ``transforms.compose(shear_x(s), rotate_about(alpha, c), scale(k), translate(o))``.
    The picture undergoes the inverse: it moves by :math:`-o` (in tiled units), shrinks by
    :math:`k`, turns by :math:`-\alpha`.

    Parameters
    ----------
    tiling : float or (float, float)
        Repeats in u and v (non-zero).
    offset : (float, float)
        Added to the coordinates last.
    rotation : float
        Radians, counter-clockwise for the coordinates.
    center : (float, float)
        The fixed point of the rotation (default: the texture's centre).
    shear : float
        u += shear * v, applied first.

    Returns
    -------
    ndarray, shape (3, 3)

    Examples
    --------
    >>> m = texture_matrix(tiling=2, offset=(0.25, 0))
    >>> m @ [0.5, 0.5, 1]
    array([1.25, 1.  , 1.  ])
    """
    k = _pair(tiling, "tiling")
    o = as_vector(offset, "offset", 2)
    c = as_vector(center, "center", 2)
    m = transforms.compose(transforms.shear_x(as_scalar(shear, "shear")),
                           transforms.rotate_about(as_scalar(rotation, "rotation"), c),
                           tile(k[0], k[1]), transforms.translate(o))
    return m


def apply_texture_matrix(matrix, u, v):
    r"""The transformed coordinates :math:`(u', v', 1)^T = M (u, v, 1)^T` of many points.

    Parameters
    ----------
    matrix : array_like, shape (3, 3)
        An affine texture matrix (last row 0 0 1).
    u, v : array_like
        Broadcast together.

    Returns
    -------
    u2, v2 : ndarray

    Raises
    ------
    ValueError
        For a matrix that is not 3x3 or not affine (a projective texture matrix needs the
        division by q, not done here), or non-finite coordinates.

    Examples
    --------
    >>> apply_texture_matrix(tile(2, 3), [0.5, 1.0], [0.5, 0.0])
    (array([1., 2.]), array([1.5, 0. ]))
    """
    m = as_matrix(matrix, "matrix", sizes=(3,))
    if not np.allclose(m[2], [0.0, 0.0, 1.0]):
        raise ValueError(f"matrix must be affine (last row 0 0 1), got last row {m[2].tolist()}")
    u, v = _uv(u, v)
    return m[0, 0] * u + m[0, 1] * v + m[0, 2], m[1, 0] * u + m[1, 1] * v + m[1, 2]


def transform_texture(texture, matrix, size=None, wrap="repeat", filter="bilinear"):
    r"""Resample a texture as it appears with the texture matrix: texel centre :math:`x` shows
    the texture at :math:`M x`.

    Every texel centre :math:`(u, v)` of the output (an ``size`` = (H, W) grid, default the
    texture's) is mapped by `matrix` and the input is sampled there with `wrap` and `filter`.
    This is what a surface with the unit square of texture coordinates shows.

    Parameters
    ----------
    texture : array_like, shape (H, W) or (H, W, C)
    matrix : array_like, shape (3, 3)
    size : (int, int), optional
        Output (H, W).
    wrap : {"repeat", "clamp", "mirror"}
    filter : {"bilinear", "nearest"}

    Returns
    -------
    ndarray, shape (H', W') or (H', W', C)

    Examples
    --------
    >>> tex = np.array([[0, 1], [2, 3]])
    >>> transform_texture(tex, transforms.translate([0.5, 0]), filter="nearest")   # u + 1/2
    array([[1., 0.],
           [3., 2.]])
    """
    t = _texture(texture)
    wrap = as_choice(wrap, "wrap", WRAP_MODES)
    filter = as_choice(filter, "filter", FILTERS)
    if size is None:
        h, w = t.shape[:2]
    else:
        s = np.asarray(size)
        if s.shape != (2,):
            raise ValueError(f"size must be (height, width), got {size!r}")
        h, w = as_whole(s[0], "size[0]", 1), as_whole(s[1], "size[1]", 1)
    g = uv_grid(w, h)
    u2, v2 = apply_texture_matrix(matrix, g[..., 0], g[..., 1])
    sample = bilinear_sample if filter == "bilinear" else nearest_sample
    return sample(t, u2, v2, wrap=wrap)
