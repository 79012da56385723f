"""Chapter 14 (lesson sections 1, 2): texture space, wrap modes, nearest and bilinear sampling."""

import numpy as np

from .._validate import as_choice, as_whole
from ._common import WRAP_MODES, _texture, _uv, _wrap

__all__ = ["bilinear_sample", "nearest_sample", "uv_grid"]


# ---------------------------------------------------------------------------------------------
# Sampling
# ---------------------------------------------------------------------------------------------

def nearest_sample(texture, u, v, wrap="repeat"):
    r"""Nearest-texel lookup: the texel whose square contains :math:`(u, v)`.

    .. math:: j = \lfloor u W \rfloor, \qquad i = \lfloor v H \rfloor

    then wrapped into range by `wrap` (see the module's conventions: texel (i, j) covers
    :math:`[j/W, (j+1)/W] \times [i/H, (i+1)/H]`, row 0 at v = 0). Under magnification texels
    show as blocks; under minification the lookup skips texels and aliases (moiré).

    Parameters
    ----------
    texture : array_like, shape (H, W) or (H, W, C)
    u, v : array_like
        Texture coordinates (broadcast together).
    wrap : {"repeat", "clamp", "mirror"}

    Returns
    -------
    ndarray, shape ``broadcast(u, v).shape`` (+ ``(C,)`` for a 3D texture)

    Raises
    ------
    ValueError
        For a texture that is not 2D or 3D, NaN or infinite coordinates, or an unknown wrap.

    Examples
    --------
    >>> tex = np.array([[0, 1], [2, 3]])          # row 0 (v < 1/2) holds 0 and 1
    >>> nearest_sample(tex, [0.1, 0.9, 0.9, 1.1], [0.1, 0.1, 0.9, 0.1])
    array([0., 1., 3., 0.])
    >>> nearest_sample(tex, [1.1], [0.1], wrap="clamp")
    array([1.])
    """
    t = _texture(texture)
    u, v = _uv(u, v)
    wrap = as_choice(wrap, "wrap", WRAP_MODES)
    h, w = t.shape[:2]
    j = _wrap(np.floor(u * w).astype(np.int64), w, wrap)
    i = _wrap(np.floor(v * h).astype(np.int64), h, wrap)
    return t[i, j]


def bilinear_sample(texture, u, v, wrap="repeat"):
    r"""Bilinear texture filtering: blend the four texels whose centres surround :math:`(u, v)`.

    With array coordinates :math:`x = uW - \tfrac12`, :math:`y = vH - \tfrac12` (texel centres
    at integers), :math:`j = \lfloor x \rfloor`, :math:`i = \lfloor y \rfloor`,
    :math:`\alpha = x - j`, :math:`\beta = y - i`:

    .. math:: T(u, v) = (1-\beta)\big[(1-\alpha) t_{i,j} + \alpha\, t_{i,j+1}\big]
              + \beta\big[(1-\alpha) t_{i+1,j} + \alpha\, t_{i+1,j+1}\big]

    (linear in :math:`u`, then in :math:`v`; the order does not matter). The neighbours'
    indices are wrapped by `wrap`, so with ``"repeat"`` the texture blends across its border
    into the opposite edge (seamless tiling) and with ``"clamp"`` the edge texels extend
    outwards. At a texel centre the result is that texel exactly.

    Parameters
    ----------
    texture : array_like, shape (H, W) or (H, W, C)
    u, v : array_like
    wrap : {"repeat", "clamp", "mirror"}

    Returns
    -------
    ndarray, shape ``broadcast(u, v).shape`` (+ ``(C,)``)

    Raises
    ------
    ValueError
        As :func:`nearest_sample`.

    Examples
    --------
    >>> tex = np.array([[0.0, 1.0], [2.0, 3.0]])
    >>> bilinear_sample(tex, [0.25, 0.5, 0.75], [0.25, 0.5, 0.25])   # centre, middle, centre
    array([0. , 1.5, 1. ])
    >>> bilinear_sample(tex, [0.0], [0.25])        # the border: half way to the wrapped column
    array([0.5])
    >>> bilinear_sample(tex, [0.0], [0.25], wrap="clamp")
    array([0.])
    """
    t = _texture(texture)
    u, v = _uv(u, v)
    wrap = as_choice(wrap, "wrap", WRAP_MODES)
    h, w = t.shape[:2]
    i0, i1, j0, j1, a, b = _texel_corners(u * w - 0.5, v * h - 0.5, h, w, wrap)
    flat = t.reshape((h * w,) + t.shape[2:])        # one gather per corner, by flat index
    return _blend_corners(flat, i0 * w, i1 * w, j0, j1, a, b)


def _texel_corners(x, y, h, w, wrap):
    """The rows i0, i1 and columns j0, j1 of the four texel centres around the array
    coordinates (x, y) (centres at whole numbers), wrapped into an h x w texture, and the
    fractions a, b of the way from column j0 to j1 and from row i0 to i1."""
    j0f, i0f = np.floor(x), np.floor(y)
    a, b = x - j0f, y - i0f
    j0, i0 = j0f.astype(np.int64), i0f.astype(np.int64)
    j1, i1 = _wrap(j0 + 1, w, wrap), _wrap(i0 + 1, h, wrap)
    return _wrap(i0, h, wrap), i1, _wrap(j0, w, wrap), j1, a, b


def _blend_corners(flat, row0, row1, j0, j1, a, b):
    """Bilinear blend of the texels of `flat` (one texel per row, channels after) at the flat
    indices row0 + j0, row0 + j1, row1 + j0, row1 + j1: first along a row by `a`, then
    between the rows by `b`."""
    t00, t01 = flat.take(row0 + j0, axis=0), flat.take(row0 + j1, axis=0)
    t10, t11 = flat.take(row1 + j0, axis=0), flat.take(row1 + j1, axis=0)
    if flat.ndim == 2:
        a, b = a[..., None], b[..., None]
    top = t00 + a * (t01 - t00)
    bottom = t10 + a * (t11 - t10)
    return top + b * (bottom - top)


def uv_grid(width, height):
    r"""The texel centres of a ``height x width`` texture as (u, v) points, shape (H, W, 2).

    ``grid[i, j] = ((j + 0.5)/W, (i + 0.5)/H)``: evaluate a procedural texture on it to turn
    it into an image texture.

    Parameters
    ----------
    width, height : int

    Returns
    -------
    ndarray, shape (height, width, 2)

    Examples
    --------
    >>> uv_grid(2, 1)
    array([[[0.25, 0.5 ],
            [0.75, 0.5 ]]])
    """
    w, h = as_whole(width, "width", 1), as_whole(height, "height", 1)
    u = (np.arange(w) + 0.5) / w
    v = (np.arange(h) + 0.5) / h
    uu, vv = np.meshgrid(u, v)
    return np.stack([uu, vv], axis=-1)
