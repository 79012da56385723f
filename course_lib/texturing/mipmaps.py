"""Chapter 14 (lesson section 6): aliasing, mipmaps and trilinear filtering."""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_choice, as_whole
from ._common import WRAP_MODES, _texture, _uv
from .procedural import checkerboard
from .sampling import bilinear_sample, nearest_sample, uv_grid

__all__ = ["AliasingDemo", "aliasing_demo", "mip_level", "mipmap", "texel_footprint",
    "trilinear_sample"]


# ---------------------------------------------------------------------------------------------
# Mipmaps
# ---------------------------------------------------------------------------------------------

def mipmap(texture):
    r"""The mipmap pyramid of a texture: box-filtered halvings down to 1 x 1.

    Level :math:`l + 1` averages 2 x 2 blocks of level :math:`l`,
    :math:`t^{(l+1)}_{i,j} = \tfrac14 (t^{(l)}_{2i,2j} + t^{(l)}_{2i,2j+1} + t^{(l)}_{2i+1,2j}
    + t^{(l)}_{2i+1,2j+1})` (pairs only, once one side has reached 1), so every texel of level
    :math:`l` is the average of the :math:`2^l \times 2^l` level-0 texels it covers, and its
    centre lies at the centre of that block (the texel-centre convention holds on every level).
    The whole pyramid costs only 1/3 more memory than the texture
    (:math:`1 + \tfrac14 + \tfrac1{16} + \dots`).

    Parameters
    ----------
    texture : array_like, shape (H, W) or (H, W, C)
        H and W powers of two (not necessarily equal).

    Returns
    -------
    list of ndarray
        ``[level 0 (the texture, as float), level 1, ..., 1 x 1]``:
        :math:`\log_2 \max(H, W) + 1` levels.

    Raises
    ------
    ValueError
        For a texture that is not 2D or 3D, or sides that are not powers of two.

    Examples
    --------
    >>> levels = mipmap(np.arange(8.0).reshape(2, 4))
    >>> [lvl.shape for lvl in levels]
    [(2, 4), (1, 2), (1, 1)]
    >>> levels[1], levels[2]
    (array([[2.5, 4.5]]), array([[3.5]]))
    """
    t = _texture(texture)
    h, w = t.shape[:2]
    for side, name in ((h, "height"), (w, "width")):
        if side & (side - 1):
            raise ValueError(f"texture {name} must be a power of two for a mipmap, got {side} "
                             "(resize or pad the texture)")
    levels = [t]
    while max(t.shape[:2]) > 1:
        if t.shape[0] > 1:
            t = 0.5 * (t[0::2] + t[1::2])
        if t.shape[1] > 1:
            t = 0.5 * (t[:, 0::2] + t[:, 1::2])
        levels.append(t)
    return levels


def texel_footprint(shape, du_dx, dv_dx, du_dy, dv_dy):
    r"""How many level-0 texels one pixel spans: the scale factor :math:`\rho` of OpenGL.

    .. math:: \rho = \max\left(\sqrt{(W u_x)^2 + (H v_x)^2},\ \sqrt{(W u_y)^2 + (H v_y)^2}
              \right)

    from the screen-space derivatives of the texture coordinates (how fast u and v change from
    one pixel to the next along x and along y; from neighbouring pixels' differences, or
    analytically). :math:`\rho > 1`: minification (several texels per pixel, aliasing
    without filtering); :math:`\rho < 1`: magnification.

    Parameters
    ----------
    shape : tuple
        The texture's shape (level 0); the first two entries are H, W.
    du_dx, dv_dx, du_dy, dv_dy : array_like
        The derivatives (broadcast together).

    Returns
    -------
    ndarray

    Examples
    --------
    >>> float(texel_footprint((256, 256), 1 / 64, 0.0, 0.0, 1 / 128))  # 4 along x, 2 along y
    4.0
    """
    if len(shape) < 2:
        raise ValueError(f"shape must be a texture's shape (H, W, ...), got {shape!r}")
    h, w = shape[0], shape[1]
    ux, vx, uy, vy = (as_array(x, name) for x, name in ((du_dx, "du_dx"), (dv_dx, "dv_dx"),
                                                         (du_dy, "du_dy"), (dv_dy, "dv_dy")))
    return np.maximum(np.hypot(w * ux, h * vx), np.hypot(w * uy, h * vy))


def mip_level(footprint, levels=None):
    r"""The mipmap level for a footprint of :math:`\rho` texels per pixel:
    :math:`\lambda = \log_2 \rho`.

    Level :math:`\lambda` has texels :math:`2^\lambda` times as wide, so there one texel is
    about one pixel: the Nyquist limit is respected. Clamped to :math:`[0, L - 1]` (level 0
    when magnifying, the 1 x 1 level at most). The fractional part is what trilinear filtering
    blends between the two nearest levels.

    Parameters
    ----------
    footprint : array_like
        :math:`\rho > 0`, e.g. from :func:`texel_footprint`.
    levels : int, optional
        Number of levels L of the pyramid (no upper clamp if None).

    Returns
    -------
    ndarray

    Raises
    ------
    ValueError
        For a non-positive footprint.

    Examples
    --------
    >>> mip_level([0.5, 1.0, 2.0, 6.0, 1000.0], levels=9)
    array([0.       , 0.       , 1.       , 2.5849625, 8.       ])
    """
    rho = as_array(footprint, "footprint")
    if np.any(rho <= 0):
        raise ValueError("footprint must be positive (texels per pixel)")
    lam = np.maximum(np.log2(rho), 0.0)
    if levels is not None:
        lam = np.minimum(lam, as_whole(levels, "levels", 1) - 1)
    return lam


def trilinear_sample(pyramid, u, v, level, wrap="repeat"):
    r"""Trilinear (mipmap) filtering: bilinear in the two nearest levels, then linear between.

    .. math:: T(u, v, \lambda) = (1 - f)\, B_{\lfloor\lambda\rfloor}(u, v)
              + f\, B_{\lfloor\lambda\rfloor + 1}(u, v), \qquad f = \lambda - \lfloor \lambda
              \rfloor

    with :math:`B_l` the :func:`bilinear_sample` of level :math:`l` (each level uses its own
    size in the texel-centre convention) and :math:`\lambda` clamped to the pyramid. At an
    integer level it *is* bilinear sampling of that level; blending between levels avoids
    visible bands where the level changes.

    Parameters
    ----------
    pyramid : list of ndarray, or array_like
        From :func:`mipmap` (a plain texture is turned into one).
    u, v : array_like
    level : float or array_like
        :math:`\lambda`, broadcast with u and v (e.g. :func:`mip_level`).
    wrap : {"repeat", "clamp", "mirror"}

    Returns
    -------
    ndarray, shape ``broadcast(u, v, level).shape`` (+ ``(C,)``)

    Raises
    ------
    ValueError
        As :func:`bilinear_sample`, or for a negative level.

    Examples
    --------
    >>> tex = np.array([[0.0, 1.0], [1.0, 0.0]])     # a 2 x 2 checker; level 1 is its mean
    >>> pyr = mipmap(tex)
    >>> trilinear_sample(pyr, 0.25, 0.25, [0.0, 0.5, 1.0, 7.0])
    array([0.  , 0.25, 0.5 , 0.5 ])
    """
    if isinstance(pyramid, (list, tuple)):
        levels = [_texture(t, "pyramid level") for t in pyramid]
        if not levels:
            raise ValueError("pyramid must contain at least one level")
    else:
        levels = mipmap(pyramid)
    u, v = _uv(u, v)
    lam = as_array(level, "level")
    if np.any(lam < 0):
        raise ValueError("level must be non-negative")
    u, v, lam = np.broadcast_arrays(u, v, lam)
    wrap = as_choice(wrap, "wrap", WRAP_MODES)
    lam = np.minimum(lam, len(levels) - 1)
    low = np.floor(lam).astype(np.intp)
    frac = lam - low
    channels = levels[0].shape[2:]
    out = np.zeros(u.shape + channels)
    for lv in np.unique(low):
        sel = low == lv
        a = bilinear_sample(levels[lv], u[sel], v[sel], wrap)
        f = frac[sel]
        if lv + 1 < len(levels):
            b = bilinear_sample(levels[lv + 1], u[sel], v[sel], wrap)
            if channels:
                f = f[:, None]
            a = a + f * (b - a)
        out[sel] = a
    return out


class AliasingDemo(NamedTuple):
    """The result of :func:`aliasing_demo`: images of shape (height, width), row 0 at the bottom.

    Attributes
    ----------
    nearest : ndarray
        One nearest-texel lookup per pixel centre: moiré in the distance.
    trilinear : ndarray
        Mipmapped trilinear filtering at the level of each pixel's footprint.
    reference : ndarray
        The pixel's true average: many nearest lookups spread over the pixel (supersampling).
    level : ndarray
        The mipmap level used.
    u, v : ndarray
        Texture coordinates at the pixel centres.

    Examples
    --------
    >>> demo = aliasing_demo(40, 30, supersample=4)
    >>> demo.nearest.shape, demo.trilinear.shape
    ((30, 40), (30, 40))
    """
    nearest: np.ndarray
    trilinear: np.ndarray
    reference: np.ndarray
    level: np.ndarray
    u: np.ndarray
    v: np.ndarray


def aliasing_demo(width=160, height=120, texture_size=64, squares=8, supersample=8):
    r"""A checkerboard floor receding to the horizon: nearest sampling aliases, mipmaps do not.

    A pinhole camera at height 1 looks horizontally over an infinite floor tiled with a
    checkerboard texture (``texture_size`` texels, ``squares`` x ``squares`` squares per tile,
    one tile per unit of floor, ``wrap="repeat"``); the horizon is just above the top row. For
    the pixel at :math:`(x, y)` below the horizon (:math:`y < 0`, focal length :math:`f` =
    `height` pixels) the floor point is at distance :math:`z = f / (-y)` and
    :math:`x_{floor} = x / (-y)`, so :math:`(u, v) = (x_{floor}, z)`. Near the top a pixel spans
    many tiles: one nearest lookup per pixel picks an arbitrary texel (the moiré of
    undersampling), while trilinear filtering at :math:`\lambda = \log_2 \rho` (footprint from
    the differences of (u, v) between neighbouring pixels) returns the average grey 1/2.
    `reference` averages ``supersample`` x ``supersample`` nearest lookups per pixel (a box
    filter over the pixel), the answer both should approximate.

    Parameters
    ----------
    width, height : int
        Image size in pixels.
    texture_size : int
        The checker texture's side, a power of two.
    squares : int
        Squares per side of the texture (even, for seamless tiling).
    supersample : int
        Reference samples per pixel side.

    Returns
    -------
    AliasingDemo

    Examples
    --------
    In the far half of the picture the nearest-texel image is far from the true average,
    the trilinear one much closer:

    >>> d = aliasing_demo()
    >>> far = slice(d.nearest.shape[0] // 2, None)
    >>> err = lambda img: float(np.abs(img[far] - d.reference[far]).mean())
    >>> err(d.nearest) > 3 * err(d.trilinear)
    True
    """
    w, h = as_whole(width, "width", 1), as_whole(height, "height", 1)
    size = as_whole(texture_size, "texture_size", 1)
    n_sq = as_whole(squares, "squares", 1)
    ss = as_whole(supersample, "supersample", 1)
    texture = checkerboard(uv_grid(size, size), n_sq)
    pyramid = mipmap(texture)
    focal, horizon = float(h), h + 1.0

    def floor_uv(px, py):
        depth = -(py - horizon)                   # > 0 below the horizon
        return (px - w / 2) / depth, focal / depth

    cx, cy = np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)
    u, v = floor_uv(cx, cy)
    du_dy, du_dx = np.gradient(u)
    dv_dy, dv_dx = np.gradient(v)
    level = mip_level(texel_footprint(texture.shape, du_dx, dv_dx, du_dy, dv_dy), len(pyramid))
    nearest = nearest_sample(texture, u, v)
    trilinear = trilinear_sample(pyramid, u, v, level)
    offsets = (np.arange(ss) + 0.5) / ss - 0.5
    reference = np.zeros((h, w))
    for oy in offsets:
        for ox in offsets:
            reference += nearest_sample(texture, *floor_uv(cx + ox, cy + oy))
    return AliasingDemo(nearest, trilinear, reference / ss**2, level, u, v)
