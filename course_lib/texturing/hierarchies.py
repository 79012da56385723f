r"""Chapter 14 (textbook 14.9): texture hierarchies.

The mip pyramid of :mod:`.mipmaps` seen from four sides:

* **level selection from a rendered view**: the screen-space derivatives of :math:`(u, v)` by
  differences between neighbouring pixels (as a GPU's 2 x 2 pixel quads take them,
  :func:`uv_derivatives`), the per-pixel level of a surface (:func:`level_map`), and a textured
  floor seen in perspective with its analytic derivatives to compare (:func:`receding_plane`);
* **anisotropy**: the ratio of the footprint's axes (:func:`footprint_axes`) and the level and
  sample count of anisotropic filtering (:func:`anisotropic_level`), against the isotropic
  choice :math:`\lambda = \log_2 \rho` of :func:`~course_lib.texturing.mip_level`;
* **what a pyramid costs** (:func:`pyramid_memory`): the exact bytes for any size, with the
  floor-halving rule of OpenGL, and the geometric-series bounds 4/3 (2D) and 8/7 (3D);
* **textures larger than memory**: a *clipmap* (:func:`clipmap`, :func:`clipmap_window`,
  :func:`clipmap_level_used`) keeps only a fixed window of every fine level around a centre of
  interest; a *virtual texture* (:func:`tile_counts`, :func:`tiles_needed`,
  :class:`TileCache`) cuts every level into tiles, loads only the tiles a view needs into a
  fixed budget (least recently used out first) and falls back to the nearest coarser resident
  ancestor tile for a tile not (yet) loaded.

Levels are counted from 0 (the full texture); level :math:`l` has sides
:math:`\max(1, \lfloor s / 2^l \rfloor)` (exactly :math:`s / 2^l` for a power of two, as
:func:`~course_lib.texturing.mipmap` builds them).
"""

from collections import OrderedDict
from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_positive, as_scalar, as_whole
from ._common import _uv, _wrap
from .mipmaps import mip_level, texel_footprint

__all__ = ["ClipmapLayout", "PlaneView", "PyramidMemory", "TileCache", "anisotropic_level",
    "clipmap", "clipmap_level_used", "clipmap_window", "footprint_axes", "level_map",
    "level_shapes", "pyramid_memory", "receding_plane", "tile_counts", "tiles_needed",
    "uv_derivatives"]


# ---------------------------------------------------------------------------------------------
# Input checks
# ---------------------------------------------------------------------------------------------

def _shape(shape, name="shape", dims=(2,)):
    """A texture's size as a tuple of positive ints, (H, W) or, with 3 in dims, (D, H, W)."""
    if isinstance(shape, (str, bytes)) or not hasattr(shape, "__len__"):
        raise TypeError(f"{name} must be a tuple of {' or '.join(map(str, dims))} positive "
                        f"whole numbers (the texture's size in texels), got {shape!r}")
    if len(shape) not in dims:
        raise ValueError(f"{name} must have {' or '.join(map(str, dims))} entries (the texture's "
                         f"size in texels, {'(H, W)' if dims == (2,) else '(H, W) or (D, H, W)'}"
                         f"), got {shape!r}")
    return tuple(as_whole(s, name, 1) for s in shape)


def _power_of_two(value, name, what):
    n = as_whole(value, name, 1)
    if n & (n - 1):
        lower = 1 << (n.bit_length() - 1)
        raise ValueError(f"{name} must be a power of two ({what}), got {n} (try {lower} or "
                         f"{2 * lower})")
    return n


def _level(level, count, name="level"):
    """An integer level in [0, count - 1] (scalar)."""
    lv = as_whole(level, name)
    if lv > count - 1:
        raise ValueError(f"{name} must be in [0, {count - 1}] (the pyramid has {count} levels), "
                         f"got {lv}")
    return lv


def _levels_array(level, count, name="level"):
    """Levels as an int array: the finer level of a fractional one (floor), in [0, count-1]."""
    lam = as_array(level, name)
    if np.any(lam < 0) or np.any(lam > count - 1):
        raise ValueError(f"{name} must be in [0, {count - 1}] (the pyramid has {count} levels), "
                         f"got values in [{lam.min():g}, {lam.max():g}]")
    return np.floor(lam).astype(np.intp)


# ---------------------------------------------------------------------------------------------
# Level selection from a view
# ---------------------------------------------------------------------------------------------

def uv_derivatives(u, v):
    r"""Screen-space derivatives of per-pixel texture coordinates, as a GPU takes them.

    A GPU shades pixels in 2 x 2 *quads*; the derivative along x of any value is the difference
    between the two pixels of the quad's row, along y between the two of its column (the same
    for both pixels of a pair):

    .. math:: \frac{\partial u}{\partial x}\Big|_{(i, j)} \approx u_{i, j_1} - u_{i, j_0},
              \qquad j_0 = 2\lfloor j/2 \rfloor,\ j_1 = j_0 + 1

    and likewise :math:`\partial u / \partial y` with rows :math:`i_0 = 2\lfloor i/2 \rfloor`,
    :math:`i_1 = i_0 + 1` (row 0 at the bottom, so y grows with the row). A difference over
    one pixel is the derivative at the pair's midpoint, to second order. An odd last column
    (row) has no partner and uses the difference to its left (lower) neighbour.

    Parameters
    ----------
    u, v : array_like, shape (H, W)
        Texture coordinates per pixel (at least 2 x 2).

    Returns
    -------
    du_dx, dv_dx, du_dy, dv_dy : ndarray, shape (H, W)
        The order of :func:`~course_lib.texturing.texel_footprint`'s arguments.

    Raises
    ------
    ValueError
        For images that are not 2D, smaller than 2 x 2, of different shapes, or not finite.

    Examples
    --------
    >>> u = np.array([[0.0, 0.1, 0.3], [0.0, 0.1, 0.3]])     # 2 rows, 3 columns
    >>> du_dx, dv_dx, du_dy, dv_dy = uv_derivatives(u, np.zeros((2, 3)))
    >>> du_dx
    array([[0.1, 0.1, 0.2],
           [0.1, 0.1, 0.2]])
    """
    u, v = _uv(u, v)
    if u.ndim != 2 or u.shape[0] < 2 or u.shape[1] < 2:
        raise ValueError(f"u and v must be images of shape (H, W) with H, W >= 2, got shape "
                         f"{u.shape}")
    if not (np.isfinite(u).all() and np.isfinite(v).all()):
        raise ValueError("u and v must be finite (a pixel that sees no surface has no (u, v))")
    return (_pair_diff(u, 1), _pair_diff(v, 1), _pair_diff(u, 0), _pair_diff(v, 0))


def _pair_diff(a, axis):
    """Differences within pairs (0, 1), (2, 3), ... along `axis`, repeated for both members;
    an odd last member takes the difference to its neighbour."""
    a = np.moveaxis(a, axis, 0)
    n = a.shape[0]
    d = np.repeat(a[1:n - n % 2:2] - a[0:n - n % 2:2], 2, axis=0)
    if n % 2:
        d = np.concatenate([d, (a[-1] - a[-2])[None]], axis=0)
    return np.moveaxis(d, 0, axis)


def level_map(texture_shape, u, v, levels=None):
    r"""The isotropic mipmap level of every pixel of a view from its (u, v) image.

    :math:`\lambda = \log_2 \rho`, with the footprint :math:`\rho` of
    :func:`~course_lib.texturing.texel_footprint` computed from the quad differences of
    :func:`uv_derivatives` and clamped by :func:`~course_lib.texturing.mip_level` (level 0
    where the texture is magnified; a pixel whose (u, v) does not change at all is magnified).

    Parameters
    ----------
    texture_shape : tuple
        (H, W) of the texture's level 0.
    u, v : array_like, shape (H_img, W_img)
    levels : int, optional
        Number of levels of the pyramid (upper clamp), e.g. ``len(mipmap(texture))``.

    Returns
    -------
    ndarray, shape (H_img, W_img)

    Examples
    --------
    A view that steps 4 texels of a 64 x 64 texture per pixel in x and 1 in y is at level 2:

    >>> x, y = np.meshgrid(np.arange(4), np.arange(4))
    >>> level_map((64, 64), x * 4 / 64, y / 64)
    array([[2., 2., 2., 2.],
           [2., 2., 2., 2.],
           [2., 2., 2., 2.],
           [2., 2., 2., 2.]])
    """
    h, w = _shape(texture_shape[:2], "texture_shape")
    rho = texel_footprint((h, w), *uv_derivatives(u, v))
    return mip_level(np.maximum(rho, np.finfo(float).tiny), levels)


class PlaneView(NamedTuple):
    """A textured floor seen by a pinhole camera (:func:`receding_plane`); images (H, W), row 0
    at the bottom.

    Attributes
    ----------
    u, v : ndarray
        Texture coordinates at the pixel centres.
    du_dx, dv_dx, du_dy, dv_dy : ndarray
        Their exact derivatives along the screen's x and y (per pixel).
    distance : ndarray
        The distance along the floor from the point below the camera.

    Examples
    --------
    >>> view = receding_plane(8, 6)
    >>> view.u.shape, bool((view.dv_dx == 0).all())
    ((6, 8), True)
    """
    u: np.ndarray
    v: np.ndarray
    du_dx: np.ndarray
    dv_dx: np.ndarray
    du_dy: np.ndarray
    dv_dy: np.ndarray
    distance: np.ndarray


def receding_plane(width=256, height=256, tilt=np.radians(30.0), camera_height=1.0,
                   focal=None, texture_extent=8.0):
    r"""Texture coordinates of a floor seen in perspective, with their analytic derivatives.

    A pinhole camera at height :math:`h` above the floor looks along the floor, pitched down by
    the tilt :math:`\theta`; focal length :math:`f` in pixels, principal point at the image's
    centre, pixel centres at :math:`x = j + \tfrac12 - W/2`, :math:`y = i + \tfrac12 - H/2`
    (row 0 at the bottom). The ray of pixel :math:`(x, y)` reaches the floor at the lateral
    position :math:`X = h x / s` and the distance :math:`Z = h (y \sin\theta + f\cos\theta)/s`,
    with :math:`s = f \sin\theta - y \cos\theta` (positive below the horizon
    :math:`y = f \tan\theta`). One texture covers a square of side :math:`E` of floor:
    :math:`u = \tfrac12 + X/E`, :math:`v = Z/E`, and so

    .. math:: u_x = \frac{h}{E s}, \quad v_x = 0, \quad u_y = \frac{h x \cos\theta}{E s^2},
              \quad v_y = \frac{h f}{E s^2}

    Far rows (large :math:`y`, small :math:`s`) are minified most, and more along y than along
    x (:math:`v_y / u_x = f / s`): the floor's footprints are long ellipses, the case of
    anisotropic filtering.

    Parameters
    ----------
    width, height : int
        Image size in pixels.
    tilt : float
        :math:`\theta` in radians, in (0, pi/2); the horizon must lie above the image's top row.
    camera_height : float
        :math:`h > 0`.
    focal : float, optional
        :math:`f` in pixels (default: `height`).
    texture_extent : float
        :math:`E > 0`, the floor's side covered by one copy of the texture.

    Returns
    -------
    PlaneView

    Raises
    ------
    ValueError
        For a tilt that puts the horizon inside the image, and any non-positive size.

    Examples
    --------
    The centre column's u is 1/2; derivatives grow towards the top (far) rows:

    >>> view = receding_plane(4, 4, focal=4.0)
    >>> float(view.u[0, 2] + view.u[0, 1])
    1.0
    >>> bool(view.dv_dy[-1, 0] > view.dv_dy[0, 0])
    True
    """
    w, h_img = as_whole(width, "width", 1), as_whole(height, "height", 1)
    theta = as_scalar(tilt, "tilt")
    if not 0 < theta < np.pi / 2:
        raise ValueError(f"tilt must be in (0, pi/2) radians (the camera looks down at the "
                         f"floor), got {theta:g}")
    cam = as_positive(camera_height, "camera_height")
    f = float(h_img) if focal is None else as_positive(focal, "focal")
    extent = as_positive(texture_extent, "texture_extent")
    if f * np.tan(theta) <= h_img / 2:
        raise ValueError(f"tilt is too small: the horizon (y = f tan(tilt) = "
                         f"{f * np.tan(theta):.4g} pixels above the centre) must lie above the "
                         f"image's top edge ({h_img / 2:g}); tilt the camera down more")
    x, y = np.meshgrid(np.arange(w) + 0.5 - w / 2, np.arange(h_img) + 0.5 - h_img / 2)
    c, s_ = np.cos(theta), np.sin(theta)
    s = f * s_ - y * c
    lateral = cam * x / s
    distance = cam * (y * s_ + f * c) / s
    u = 0.5 + lateral / extent
    v = distance / extent
    du_dx = cam / (extent * s)
    du_dy = cam * x * c / (extent * s**2)
    dv_dy = cam * f / (extent * s**2)
    return PlaneView(u, v, du_dx, np.zeros_like(u), du_dy, dv_dy, distance)


# ---------------------------------------------------------------------------------------------
# Anisotropy
# ---------------------------------------------------------------------------------------------

def footprint_axes(shape, du_dx, dv_dx, du_dy, dv_dy, method="lengths"):
    r"""The major and minor axis of a pixel's footprint in the texture, in level-0 texels.

    A pixel step along x moves :math:`a = (W u_x, H v_x)` texels, one along y
    :math:`b = (W u_y, H v_y)`; the pixel's square maps to the parallelogram spanned by
    :math:`a` and :math:`b`.

    * ``"lengths"`` (what GPUs do, the ``EXT_texture_filter_anisotropic`` rule):
      major :math:`= \max(|a|, |b|)`, minor :math:`= \min(|a|, |b|)`;
    * ``"ellipse"``: the semi-axes of the ellipse that the unit circle of the screen maps to,
      the singular values :math:`\sigma_1 \ge \sigma_2` of the Jacobian :math:`J = [a\ b]`
      (exact for skewed footprints, where the lengths rule underestimates the major axis and
      overestimates the minor one: :math:`\sigma_2 \le |a|, |b| \le \sigma_1`).

    Both agree when :math:`a \perp b`. The ratio major/minor is the *anisotropy*: 1 for a
    surface facing the camera, large for a floor near the horizon.

    Parameters
    ----------
    shape : tuple
        (H, W, ...) of the texture's level 0.
    du_dx, dv_dx, du_dy, dv_dy : array_like
        Screen-space derivatives (broadcast together).
    method : {"lengths", "ellipse"}

    Returns
    -------
    major, minor : ndarray

    Examples
    --------
    >>> major, minor = footprint_axes((256, 256), 2 / 256, 0.0, 0.0, 8 / 256)
    >>> float(major), float(minor)
    (8.0, 2.0)
    """
    from .._validate import as_choice

    method = as_choice(method, "method", ("lengths", "ellipse"))
    if len(shape) < 2:
        raise ValueError(f"shape must be a texture's shape (H, W, ...), got {shape!r}")
    h, w = _shape(tuple(shape[:2]))
    ux, vx, uy, vy = np.broadcast_arrays(*(as_array(d, n) for d, n in (
        (du_dx, "du_dx"), (dv_dx, "dv_dx"), (du_dy, "du_dy"), (dv_dy, "dv_dy"))))
    ax, ay, bx, by = w * ux, h * vx, w * uy, h * vy
    if method == "lengths":
        la, lb = np.hypot(ax, ay), np.hypot(bx, by)
        return np.maximum(la, lb), np.minimum(la, lb)
    # singular values of [[ax, bx], [ay, by]] in closed form
    frob = ax**2 + ay**2 + bx**2 + by**2
    det = np.abs(ax * by - ay * bx)
    root = np.sqrt(np.maximum(frob**2 - 4 * det**2, 0.0))
    major = np.sqrt((frob + root) / 2)
    minor = np.divide(det, major, out=np.zeros_like(major), where=major > 0)
    return major, minor


def anisotropic_level(shape, du_dx, dv_dx, du_dy, dv_dy, max_anisotropy=16, levels=None,
                      method="lengths"):
    r"""The level and number of samples of anisotropic filtering, with the anisotropy.

    Isotropic mipmapping picks the level of the *major* axis, :math:`\log_2 P_{max}`: sharp
    enough along the short direction is given up to avoid aliasing along the long one, so a
    floor near the horizon blurs. Anisotropic filtering takes

    .. math:: N = \min\left(\lceil P_{max} / P_{min} \rceil, N_{max}\right), \qquad
              \lambda = \log_2 (P_{max} / N)

    and averages :math:`N` trilinear samples spread along the major axis: the level is that of
    the *minor* axis (:math:`\lambda = \log_2 P_{min}` when the ratio is a whole number up to
    :math:`N_{max}`; beyond :math:`N_{max}` it moves coarser, blurring rather than aliasing).

    Parameters
    ----------
    shape : tuple
        (H, W, ...) of the texture's level 0.
    du_dx, dv_dx, du_dy, dv_dy : array_like
    max_anisotropy : int
        :math:`N_{max} \ge 1` (GPUs offer 2, 4, 8, 16).
    levels : int, optional
        Pyramid levels, for the upper clamp of the level.
    method : {"lengths", "ellipse"}
        As :func:`footprint_axes`.

    Returns
    -------
    level : ndarray
        :math:`\lambda`, clamped to :math:`[0, L - 1]`.
    samples : ndarray of int
        :math:`N`.
    ratio : ndarray
        :math:`P_{max} / P_{min}` (inf for a footprint of zero width).

    Examples
    --------
    A footprint 8 texels long and 2 wide: 4 samples at level 1 (isotropic: level 3):

    >>> lam, n, ratio = anisotropic_level((256, 256), 2 / 256, 0.0, 0.0, 8 / 256)
    >>> float(lam), int(n), float(ratio)
    (1.0, 4, 4.0)
    """
    n_max = as_whole(max_anisotropy, "max_anisotropy", 1)
    major, minor = footprint_axes(shape, du_dx, dv_dx, du_dy, dv_dy, method)
    tiny = np.finfo(float).tiny
    ratio = np.divide(major, minor, out=np.full_like(major, np.inf), where=minor > 0)
    ratio = np.where(major > 0, ratio, 1.0)
    samples = np.minimum(np.ceil(np.minimum(ratio, n_max) - 1e-12), n_max).astype(int)
    samples = np.maximum(samples, 1)
    level = mip_level(np.maximum(major / samples, tiny), levels)
    return level, samples, ratio


# ---------------------------------------------------------------------------------------------
# What a pyramid costs
# ---------------------------------------------------------------------------------------------

def level_shapes(shape, levels=None):
    r"""The sizes of the levels of a mip pyramid, by the floor-halving rule.

    Level :math:`l + 1` has sides :math:`\max(1, \lfloor s_l / 2 \rfloor)` (OpenGL's rule for
    any size; for powers of two it is exact halving, the levels of
    :func:`~course_lib.texturing.mipmap`), down to all sides 1:
    :math:`\lfloor \log_2 \max s \rfloor + 1` levels.

    Parameters
    ----------
    shape : tuple of 2 or 3 ints
        (H, W) of a 2D texture or (D, H, W) of a volume texture.
    levels : int, optional
        Keep only the first `levels` (1 .. the full count).

    Returns
    -------
    list of tuple

    Examples
    --------
    >>> level_shapes((3, 5))
    [(3, 5), (1, 2), (1, 1)]
    """
    dims = _shape(shape, dims=(2, 3))
    out = [dims]
    while max(out[-1]) > 1:
        out.append(tuple(max(1, s // 2) for s in out[-1]))
    if levels is not None:
        n = as_whole(levels, "levels", 1)
        if n > len(out):
            raise ValueError(f"levels must be in [1, {len(out)}] for shape {dims} (its full "
                             f"pyramid has {len(out)} levels), got {n}")
        out = out[:n]
    return out


class PyramidMemory(NamedTuple):
    """The memory of a mip pyramid (:func:`pyramid_memory`).

    Attributes
    ----------
    shapes : list of tuple
        The size of every level.
    level_bytes : ndarray of int
        Bytes of every level.
    total : int
        Bytes of the whole pyramid (exact).
    base : int
        Bytes of level 0 alone.
    bound : float
        The geometric-series bound: base x 4/3 (2D) or x 8/7 (3D).
    ratio : float
        total / base.

    Examples
    --------
    >>> m = pyramid_memory((2, 2), channels=1)
    >>> m.total, m.base
    (5, 4)
    """
    shapes: list
    level_bytes: np.ndarray
    total: int
    base: int
    bound: float
    ratio: float


def pyramid_memory(shape, channels=4, bytes_per_channel=1, levels=None):
    r"""Exact bytes of a mip pyramid of any size, and the geometric-series bound.

    Each 2D level has a quarter of the texels of the one before, so the pyramid holds

    .. math:: N \left(1 + \tfrac14 + \tfrac1{16} + \dots\right) < N \sum_{k \ge 0} 4^{-k}
              = \tfrac43 N

    texels for :math:`N` in level 0 (exactly :math:`(4^{n+1} - 1)/3` for a
    :math:`2^n \times 2^n` texture); a volume texture's levels have an eighth each:
    :math:`\tfrac87 N`. The exact count sums the levels of :func:`level_shapes` (floor halving,
    so any size). A square power of two stays below the bound; a non-square texture's levels
    stop quartering once the short side is 1 and only halve from there (the 1D series
    :math:`1 + \tfrac12 + \dots`), which puts a 2:1 texture :math:`\tfrac13` texel above
    :math:`\tfrac43 N` and a :math:`1 \times W` strip at almost :math:`2 N`; floor halving of
    odd sides lowers the count.

    Parameters
    ----------
    shape : tuple of 2 or 3 ints
        (H, W), or (D, H, W) for a volume texture.
    channels : int
        Channels per texel (4 for RGBA).
    bytes_per_channel : int
        1 for 8-bit, 2 for half floats, 4 for floats.
    levels : int, optional
        Only the first `levels` levels.

    Returns
    -------
    PyramidMemory

    Examples
    --------
    A 1024 x 512 RGBA8 texture: 2 MiB at level 0, 2 796 204 bytes with its pyramid, a
    third of a texel (1.33 bytes) *above* the 4/3 bound (the last step, 1 x 2 to 1 x 1, only
    halves):

    >>> m = pyramid_memory((512, 1024))
    >>> m.base, m.total, round(m.bound, 2)
    (2097152, 2796204, 2796202.67)
    >>> round(pyramid_memory((64, 64, 64)).ratio, 4)
    1.1428
    """
    shapes = level_shapes(shape, levels)
    per_texel = as_whole(channels, "channels", 1) * as_whole(bytes_per_channel,
                                                             "bytes_per_channel", 1)
    level_bytes = np.array([int(np.prod(s)) * per_texel for s in shapes], dtype=np.int64)
    total, base = int(level_bytes.sum()), int(level_bytes[0])
    factor = 4 / 3 if len(shapes[0]) == 2 else 8 / 7
    return PyramidMemory(shapes, level_bytes, total, base, base * factor, total / base)


# ---------------------------------------------------------------------------------------------
# Clipmaps
# ---------------------------------------------------------------------------------------------

class ClipmapLayout(NamedTuple):
    """Which levels of a clipmap are clipped and what it keeps in memory (:func:`clipmap`).

    Attributes
    ----------
    shapes : list of tuple
        The full size (H, W) of every level.
    windows : list of tuple
        The size of the resident part of every level: ``min(side, clip_size)``.
    clipped : ndarray of bool
        True for the levels larger than the clip size (only a window is resident).
    resident_texels : int
        Texels kept: the sum of the windows.
    full_texels : int
        Texels of the whole pyramid.

    Examples
    --------
    >>> layout = clipmap((64, 64), 16)
    >>> layout.clipped.tolist(), layout.resident_texels, layout.full_texels
    ([True, True, False, False, False, False, False], 853, 5461)
    """
    shapes: list
    windows: list
    clipped: np.ndarray
    resident_texels: int
    full_texels: int


def clipmap(shape, clip_size):
    r"""The layout of a clipmap: a mip pyramid whose large levels are clipped to a window.

    A clipmap (Tanner, Migdal and Jones, 1998) serves a texture far larger than memory (a whole
    planet's imagery) by keeping, of every level, at most a :math:`c \times c` window of texels
    around a centre of interest (the viewer's position). Levels of side :math:`\le c` are kept
    whole (the pyramid's "tail"), larger ones are *clipped*. Because each level's texels are
    twice as wide as the finer level's, the windows cover twice the area of texture space per
    level: fine detail near the centre, coarser further out, exactly what a perspective view
    needs. For a :math:`2^n \times 2^n` texture and :math:`c = 2^m` the memory is
    :math:`(n - m)\,c^2` for the clipped levels plus under :math:`\tfrac43 c^2` for the tail,
    instead of :math:`\tfrac43 4^n`: it grows with the *logarithm* of the texture's size.

    Parameters
    ----------
    shape : tuple of 2 ints
        (H, W) of level 0.
    clip_size : int
        :math:`c`, a power of two (windows are moved in whole texels of every level, and a
        window halves with its level).

    Returns
    -------
    ClipmapLayout

    Raises
    ------
    ValueError
        For a shape that is not two positive whole numbers, or a clip size that is not a power
        of two.

    Examples
    --------
    A 16384 x 16384 texture with 512 x 512 windows: 5 clipped levels, 10 whole ones; about
    6.3 clip windows of memory instead of 1365:

    >>> layout = clipmap((16384, 16384), 512)
    >>> int(layout.clipped.sum()), round(layout.resident_texels / 512**2, 2)
    (5, 6.33)
    """
    shapes = level_shapes(_shape(shape))
    c = _power_of_two(clip_size, "clip_size", "the side of every level's window in texels")
    windows = [tuple(min(s, c) for s in sh) for sh in shapes]
    clipped = np.array([max(sh) > c for sh in shapes])
    resident = sum(int(np.prod(wd)) for wd in windows)
    full = sum(int(np.prod(sh)) for sh in shapes)
    return ClipmapLayout(shapes, windows, clipped, resident, full)


def clipmap_window(shape, clip_size, level, centre):
    r"""The texels of one level that a clipmap keeps around a centre (u, v).

    Along each axis of a level with :math:`n` texels, the centre is at :math:`p = u n` texel
    units; the window holds the :math:`c` texels whose centres lie in
    :math:`[p - c/2,\ p + c/2)`, moved inside the level where it would stick out (the centre
    clamped to :math:`[c/2, n - c/2]`). A level with :math:`n \le c` is kept whole.

    Parameters
    ----------
    shape : tuple of 2 ints
        (H, W) of level 0.
    clip_size : int
        A power of two.
    level : int
        In [0, number of levels - 1].
    centre : sequence of 2 floats
        (u, v) in [0, 1].

    Returns
    -------
    tuple of 4 ints
        ``(i0, i1, j0, j1)``: rows ``i0 <= i < i1``, columns ``j0 <= j < j1`` of the level.

    Examples
    --------
    >>> clipmap_window((64, 64), 16, 0, (0.5, 0.25))    # rows around v = 1/4, columns u = 1/2
    (8, 24, 24, 40)
    >>> clipmap_window((64, 64), 16, 2, (0.5, 0.25))    # level 2 is 16 x 16: whole
    (0, 16, 0, 16)
    """
    layout = clipmap(shape, clip_size)
    lv = _level(level, len(layout.shapes))
    centre = as_array(centre, "centre")
    if centre.shape != (2,) or np.any(centre < 0) or np.any(centre > 1):
        raise ValueError(f"centre must be (u, v) with both in [0, 1], got {centre.tolist()}")
    c = int(clip_size)
    out = []
    for n, t in zip(layout.shapes[lv], (centre[1], centre[0])):       # rows from v, cols from u
        if n <= c:
            out += [0, n]
            continue
        p = min(max(t * n, c / 2), n - c / 2)
        start = int(np.ceil(p - c / 2 - 0.5))
        out += [start, start + c]
    return tuple(out)


def clipmap_level_used(shape, clip_size, centre, u, v, level):
    r"""The level a clipmap actually samples: the requested one if resident, else coarser.

    A sample at :math:`(u, v)` wants level :math:`\lfloor\lambda\rfloor`; that level's texel
    under :math:`(u, v)` (the nearest texel, in the texel-centre convention, clamped to the
    level) is resident if it lies in the level's window (:func:`clipmap_window`), otherwise
    the next coarser level is tried. The whole tail is resident, so this always ends. Seen from
    the centre, the level used grows with distance: a view whose level rises with distance
    anyway (perspective) is served almost everywhere at its own level.

    Parameters
    ----------
    shape : tuple of 2 ints
        (H, W) of level 0.
    clip_size : int
        A power of two.
    centre : sequence of 2 floats
        (u, v) of the centre of interest, in [0, 1].
    u, v : array_like
        Sample positions in [0, 1] (broadcast with `level`).
    level : array_like
        Requested levels :math:`\lambda` in [0, L - 1] (the finer level of a fractional one).

    Returns
    -------
    ndarray of int

    Examples
    --------
    >>> clipmap_level_used((64, 64), 16, (0.5, 0.5), [0.5, 0.7, 0.99], 0.5, 0)
    array([0, 1, 2])
    """
    layout = clipmap(shape, clip_size)
    count = len(layout.shapes)
    u, v = _uv(u, v)
    if np.any(u < 0) or np.any(u > 1) or np.any(v < 0) or np.any(v > 1):
        raise ValueError("u and v must be in [0, 1] (a clipmap is not tiled)")
    lv = _levels_array(level, count)
    u, v, lv = np.broadcast_arrays(u, v, lv)
    used = lv.copy()
    pending = np.ones(u.shape, bool)
    for k in range(count):
        i0, i1, j0, j1 = clipmap_window(shape, clip_size, k, centre)
        h, w = layout.shapes[k]
        i = np.clip(np.floor(v * h).astype(np.intp), 0, h - 1)
        j = np.clip(np.floor(u * w).astype(np.intp), 0, w - 1)
        inside = (i >= i0) & (i < i1) & (j >= j0) & (j < j1)
        done = pending & (lv <= k) & inside
        used[done] = k
        pending &= ~done
    return used


# ---------------------------------------------------------------------------------------------
# Virtual textures
# ---------------------------------------------------------------------------------------------

def _vt_check(shape, tile):
    h, w = _shape(shape)
    for side, name in ((h, "height"), (w, "width")):
        if side & (side - 1):
            raise ValueError(f"shape must have power-of-two sides for a virtual texture (each "
                             f"tile's parent is the tile (i // 2, j // 2) one level up), got "
                             f"{name} {side}")
    return (h, w), _power_of_two(tile, "tile", "the side of a tile in texels")


def tile_counts(shape, tile):
    r"""How many tiles of :math:`T \times T` texels each level of a virtual texture has.

    Level :math:`l` of a :math:`W \times H` texture has
    :math:`\lceil (W/2^l) / T \rceil \times \lceil (H/2^l) / T \rceil` tiles (levels smaller
    than a tile fill part of one). The virtual texture's levels stop at the first level that is
    one tile (the rest of the pyramid lives inside that tile); that level is always resident.

    Parameters
    ----------
    shape : tuple of 2 ints
        (H, W) of level 0, powers of two.
    tile : int
        T, a power of two.

    Returns
    -------
    list of tuple
        (rows of tiles, columns of tiles) per level, the last (1, 1).

    Examples
    --------
    >>> tile_counts((512, 1024), 128)
    [(4, 8), (2, 4), (1, 2), (1, 1)]
    """
    (h, w), t = _vt_check(shape, tile)
    out = []
    for sh in level_shapes((h, w)):
        counts = tuple(-(-s // t) for s in sh)
        out.append(counts)
        if counts == (1, 1):
            break
    return out


def tiles_needed(shape, tile, u, v, level, wrap="repeat"):
    r"""The set of tiles a view needs: one tile per pixel's (u, v, level), without repeats.

    A pixel sampling level :math:`l = \lfloor\lambda\rfloor` (clamped to the virtual
    texture's last level) at :math:`(u, v)` reads the texel :math:`(i, j) =
    (\lfloor v H_l \rfloor, \lfloor u W_l \rfloor)` (wrapped into the level) of the tile
    :math:`(l, \lfloor i / T \rfloor, \lfloor j / T \rfloor)`. A renderer finds this set in a
    cheap first pass (the *feedback buffer*) and streams in the tiles it lacks.

    Parameters
    ----------
    shape : tuple of 2 ints
        (H, W) of level 0, powers of two.
    tile : int
        T, a power of two.
    u, v, level : array_like
        Per-pixel texture coordinates and levels (:math:`\lambda \ge 0`), broadcast together.
    wrap : {"repeat", "clamp", "mirror"}
        For coordinates outside [0, 1].

    Returns
    -------
    ndarray of int, shape (n, 3)
        The distinct tiles ``(level, tile_row, tile_col)``, sorted.

    Examples
    --------
    >>> tiles_needed((256, 256), 64, [0.1, 0.12, 0.9, 0.9], [0.1, 0.1, 0.1, 0.9], [0, 0, 1, 3])
    array([[0, 0, 0],
           [1, 0, 1],
           [2, 0, 0]])
    """
    from .._validate import as_choice
    from ._common import WRAP_MODES

    (h, w), t = _vt_check(shape, tile)
    counts = tile_counts((h, w), t)
    wrap = as_choice(wrap, "wrap", WRAP_MODES)
    u, v = _uv(u, v)
    lam = as_array(level, "level")
    if np.any(lam < 0):
        raise ValueError("level must be non-negative")
    u, v, lam = np.broadcast_arrays(u, v, lam)
    lv = np.minimum(np.floor(lam).astype(np.intp), len(counts) - 1).ravel()
    u, v = u.ravel(), v.ravel()
    rows = []
    for k in np.unique(lv):
        sel = lv == k
        hk, wk = max(1, h >> k), max(1, w >> k)
        i = _wrap(np.floor(v[sel] * hk).astype(np.intp), hk, wrap)
        j = _wrap(np.floor(u[sel] * wk).astype(np.intp), wk, wrap)
        rows.append(np.stack([np.full(i.shape, k), i // t, j // t], axis=1))
    if not rows:
        return np.zeros((0, 3), dtype=np.intp)
    return np.unique(np.concatenate(rows), axis=0)


class TileCache:
    r"""The resident tiles of a virtual texture: a fixed budget, least recently used out first.

    ``request(tiles)`` is one frame: each needed tile (in the given order) is a *hit* if
    resident (it becomes the most recently used) or a *miss*, loaded after evicting the least
    recently used tile when the budget is full. The single tile of the coarsest level is
    loaded at the start and never evicted (it does not count against the budget), so every
    lookup has a fallback: ``resolve(level, row, col)`` returns the nearest resident ancestor,
    walking up :math:`(l, i, j) \to (l + 1, \lfloor i/2 \rfloor, \lfloor j/2 \rfloor)`, the
    tile a renderer samples (blurrier) until the wanted one arrives. ``page_table(level)``
    gives, for every tile of a level, the level that would serve it: the GPU's page table
    (which stores where in the physical tile pool that tile lives).

    Parameters
    ----------
    shape : tuple of 2 ints
        (H, W) of level 0, powers of two.
    tile : int
        T, a power of two.
    budget : int
        Tiles that fit in the physical pool (>= 1).

    Examples
    --------
    >>> cache = TileCache((256, 256), 64, budget=2)
    >>> cache.request([(0, 0, 0), (0, 0, 1)])
    {'hits': 0, 'misses': 2, 'evicted': []}
    >>> cache.request([(0, 0, 0), (1, 1, 1)])       # (0, 0, 1) was the least recently used
    {'hits': 1, 'misses': 1, 'evicted': [(0, 0, 1)]}
    >>> cache.resolve(0, 3, 3)                       # its parent (1, 1, 1) is resident
    (1, 1, 1)
    """

    def __init__(self, shape, tile, budget):
        self.shape, self.tile = _vt_check(shape, tile)
        self.counts = tile_counts(self.shape, self.tile)
        self.budget = as_whole(budget, "budget", 1)
        self.root = (len(self.counts) - 1, 0, 0)
        self._lru = OrderedDict()

    @property
    def resident(self):
        """The resident tiles (without the pinned root), least recently used first."""
        return list(self._lru)

    def _tile(self, tile, name="tile"):
        try:
            lv, i, j = (int(x) for x in tile)
        except (TypeError, ValueError):
            raise ValueError(f"{name} must be (level, row, col), got {tile!r}") from None
        if not 0 <= lv < len(self.counts):
            raise ValueError(f"{name}'s level must be in [0, {len(self.counts) - 1}], got {lv}")
        rows, cols = self.counts[lv]
        if not (0 <= i < rows and 0 <= j < cols):
            raise ValueError(f"{name} {(lv, i, j)} is outside level {lv}'s {rows} x {cols} "
                             "tiles")
        return lv, i, j

    def request(self, tiles):
        """Use the tiles of one frame (an (n, 3) array or a list of triples); returns the hits,
        the misses and the evicted tiles (in eviction order)."""
        hits, misses, evicted = 0, 0, []
        for t in np.asarray(tiles, dtype=np.int64).reshape(-1, 3) if len(tiles) else []:
            key = self._tile(t)
            if key == self.root:
                hits += 1
            elif key in self._lru:
                self._lru.move_to_end(key)
                hits += 1
            else:
                misses += 1
                if len(self._lru) >= self.budget:
                    evicted.append(self._lru.popitem(last=False)[0])
                self._lru[key] = True
        return {"hits": hits, "misses": misses, "evicted": evicted}

    def resolve(self, level, row, col):
        """The nearest resident tile at or above (level, row, col): what the sample uses."""
        lv, i, j = self._tile((level, row, col))
        while (lv, i, j) != self.root and (lv, i, j) not in self._lru:
            lv, i, j = lv + 1, i // 2, j // 2
        return lv, i, j

    def page_table(self, level):
        """The level serving each tile of `level`: an int array (rows, cols) of tiles."""
        lv = _level(level, len(self.counts))
        rows, cols = self.counts[lv]
        table = np.empty((rows, cols), dtype=int)
        for i in range(rows):
            for j in range(cols):
                table[i, j] = self.resolve(lv, i, j)[0]
        return table
