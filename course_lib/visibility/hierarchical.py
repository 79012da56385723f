r"""Chapter 5, hierarchical occlusion culling: the z-pyramid, occlusion queries, occlusion maps.

Occlusion culling asks, before an object is drawn, whether its bounding box would be hidden by
what is already in the depth buffer. Testing every pixel of the box's screen rectangle costs as
much as drawing it; the three techniques here make the test cheap:

* the **hierarchical z-buffer** (Greene, Kass and Miller 1993): :func:`z_pyramid` builds a
  pyramid whose level :math:`k+1` holds the **maximum** (farthest) depth of 2 x 2 texels of level
  :math:`k`; :func:`hzb_test` reads at most 2 x 2 texels at the level where the box's rectangle
  is that small, and rejects the box when its nearest depth is farther than all of them.
  Conservative: it never rejects a box that the full depth buffer shows (:func:`full_test`,
  :func:`full_cull` are the per-pixel reference; :func:`hzb_cull` tests many boxes at once);
* **occlusion queries**: :func:`occlusion_query` counts the samples of a proxy that pass the
  depth test, as the GPU does; :func:`draw_if_visible` is the loop that draws an object only when
  its box's query reports more than a threshold of samples (front-to-back order matters);
* **hierarchical occlusion maps** (Zhang, Manocha, Hudson and Hoff 1997):
  :func:`occlusion_map_pyramid` **averages** the occluders' coverage (opacity) 2 x 2 at a time,
  :func:`depth_estimation_buffer` keeps the farthest occluder depth per coarse tile, and
  :func:`hom_test` culls when the covering texels are opaque enough (a threshold below 1 makes
  the test approximate) and the box is behind the depth estimate.

Conventions (those of :mod:`course_lib.visibility.z_buffer`): buffers have shape (height, width),
pixel ``(row j, column i)``, row 0 at the bottom; depth in [0, 1] grows away from the viewer,
``+inf`` where nothing was drawn. A screen rectangle is ``(i0, j0, i1, j1)``: the pixel columns
``i0..i1`` and rows ``j0..j1``, **inclusive**. Rectangles reaching past the screen are clamped to
it; one entirely off the screen, or with ``i1 < i0`` or ``j1 < j0``, is refused (ValueError).
Boxes are given in screen space (a rectangle and the nearest depth); :func:`screen_rect` gets
both from the corners of a 3D box already in viewport coordinates, :func:`box_screen_rect` from a
world box and the camera's view and projection matrices.

**Padding.** A level with an odd size is padded by repeating its last row or column before the
2 x 2 reduction. For the max pyramid that is conservative: a padded texel is a copy of a real one,
so every coarse texel is the maximum of real pixels only, and rectangles never reach the padding
(they are clamped to the screen). The opacity pyramid pads with 0 (no occluder off the screen):
averages there can only be lower, so fewer boxes are culled.
"""

from typing import NamedTuple

import numpy as np

from .. import transforms, viewing
from .._validate import as_scalar, as_vector, as_whole
from ._common import _camera
from .z_buffer import zbuffer

__all__ = ["HZBCull", "HOMTest", "Pyramid", "QueryLoop", "depth_estimation_buffer",
           "box_screen_rect", "draw_if_visible", "full_cull", "full_test", "hom_test", "hzb_cull", "hzb_level",
           "hzb_test", "occlusion_map_pyramid", "occlusion_query", "screen_rect", "z_pyramid"]


class Pyramid(NamedTuple):
    """A z-pyramid (:func:`z_pyramid`) or an occlusion-map pyramid (:func:`occlusion_map_pyramid`).

    Attributes
    ----------
    levels : list of ndarray
        ``levels[0]`` is the buffer itself (shape (height, width)); ``levels[k]`` has shape
        ``(ceil(height / 2**k), ceil(width / 2**k))``; the last level is 1 x 1.
    reduce : str
        ``"max"`` (z-pyramid) or ``"mean"`` (occlusion map).

    Examples
    --------
    >>> p = z_pyramid(np.arange(16.0).reshape(4, 4) / 16)
    >>> [lv.shape for lv in p.levels], p.reduce
    ([(4, 4), (2, 2), (1, 1)], 'max')
    """
    levels: list
    reduce: str

    @property
    def shape(self):
        """The shape (height, width) of level 0."""
        return self.levels[0].shape


class HZBCull(NamedTuple):
    """The result of :func:`hzb_cull` (or :func:`full_cull`) for n boxes.

    Attributes
    ----------
    rejected : ndarray of bool, shape (n,)
        Boxes certainly hidden.
    level : ndarray of int, shape (n,)
        The pyramid level each test read (0 for the full test).
    texels : ndarray of int, shape (n,)
        Texels (or pixels) read per box.

    Examples
    --------
    >>> r = hzb_cull(z_pyramid(np.full((4, 4), 0.5)), [(0, 0, 3, 3)], [0.7])
    >>> r.rejected.tolist(), r.level.tolist(), r.texels.tolist()
    ([True], [1], [4])
    """
    rejected: np.ndarray
    level: np.ndarray
    texels: np.ndarray


class HOMTest(NamedTuple):
    """The result of :func:`hom_test` for one box.

    Attributes
    ----------
    culled : bool
        Both tests passed: the box is (approximately) hidden.
    opaque : bool
        Every covering texel of the occlusion map has opacity >= the threshold.
    behind : bool
        The box's nearest depth is farther than the depth estimate of every tile it covers.
    level : int
        The occlusion-map level read.
    opacities : ndarray
        The covering texels' opacities (rows bottom to top).
    reads : int
        Texels read by the overlap test (with the descent into partly covered texels).

    Examples
    --------
    >>> cov = np.ones((4, 4))
    >>> t = hom_test(occlusion_map_pyramid(cov), (0, 0, 1, 1), 0.9, np.full((1, 1), 0.5))
    >>> t.culled, t.level
    (True, 0)
    """
    culled: bool
    opaque: bool
    behind: bool
    level: int
    opacities: np.ndarray
    reads: int


class QueryLoop(NamedTuple):
    """The result of :func:`draw_if_visible`.

    Attributes
    ----------
    drawn : ndarray of bool, shape (n,)
        Objects drawn (their query passed more than `threshold` samples).
    samples : ndarray of int, shape (n,)
        Each object's query result when it was tested.
    order : ndarray of int
        The order the objects were tested in.
    depth : ndarray
        The depth buffer at the end.

    Examples
    --------
    >>> r = draw_if_visible([(0, 0, 3, 3), (1, 1, 2, 2)], [0.2, 0.6], 4, 4)
    >>> r.drawn.tolist(), r.samples.tolist()
    ([True, False], [16, 0])
    """
    drawn: np.ndarray
    samples: np.ndarray
    order: np.ndarray
    depth: np.ndarray


# ---------------------------------------------------------------------------------------------
# Input checks
# ---------------------------------------------------------------------------------------------

def _buffer2d(value, name, allow_inf=True):
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name} must be a 2D array of numbers, got {type(value).__name__}")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a 2D array of numbers") from None
    if arr.ndim != 2 or arr.shape[0] < 1 or arr.shape[1] < 1:
        raise ValueError(f"{name} must be a non-empty 2D array (height, width), got shape "
                         f"{arr.shape}")
    bad = np.isnan(arr) | (np.isneginf(arr) if allow_inf else ~np.isfinite(arr))
    if bad.any():
        what = "NaN or -inf" if allow_inf else "NaN or infinite"
        raise ValueError(f"{name} must not hold {what} values")
    return arr


def _rects(rects, shape, name="rects"):
    """Rectangles as an int array (n, 4), clamped to the screen; refuse empty ones."""
    try:
        r = np.asarray(rects, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be rectangles (i0, j0, i1, j1) of whole numbers") from None
    if r.ndim == 1:
        r = r[None]
    if r.ndim != 2 or r.shape[1] != 4:
        raise ValueError(f"{name} must have shape (n, 4) (i0, j0, i1, j1), got {r.shape}")
    if not np.isfinite(r).all() or (r != np.round(r)).any():
        raise ValueError(f"{name} must hold whole pixel indices")
    r = r.astype(np.int64)
    h, w = shape
    if ((r[:, 2] < r[:, 0]) | (r[:, 3] < r[:, 1])).any():
        raise ValueError(f"{name}: i1 < i0 or j1 < j0 (a rectangle of negative size)")
    off = (r[:, 2] < 0) | (r[:, 0] >= w) | (r[:, 3] < 0) | (r[:, 1] >= h)
    if off.any():
        raise ValueError(f"{name}: {int(off.sum())} rectangle(s) entirely off the "
                         f"{w} x {h} screen")
    r[:, [0, 2]] = np.clip(r[:, [0, 2]], 0, w - 1)
    r[:, [1, 3]] = np.clip(r[:, [1, 3]], 0, h - 1)
    return r


def _nears(z, n, name="z_nears"):
    if isinstance(z, (str, bytes)) or z is None:
        raise TypeError(f"{name} must be numbers, got {type(z).__name__}")
    try:
        z = np.asarray(z, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be numbers") from None
    z = np.broadcast_to(z, (n,)) if z.ndim == 0 else z
    if z.shape != (n,) or not np.isfinite(z).all():
        raise ValueError(f"{name} must be {n} finite depths, got shape {z.shape}")
    return z


def _pyramid(buffer, reduce, pad_value=None):
    levels = [buffer]
    op = np.max if reduce == "max" else np.mean
    while levels[-1].shape != (1, 1):
        a = levels[-1]
        h, w = a.shape
        ph, pw = h % 2, w % 2
        if ph or pw:
            if pad_value is None:
                a = np.pad(a, ((0, ph), (0, pw)), mode="edge")
            else:
                a = np.pad(a, ((0, ph), (0, pw)), constant_values=pad_value)
        h2, w2 = a.shape[0] // 2, a.shape[1] // 2
        levels.append(op(a.reshape(h2, 2, w2, 2), axis=(1, 3)))
    return Pyramid(levels, reduce)


# ---------------------------------------------------------------------------------------------
# The hierarchical z-buffer
# ---------------------------------------------------------------------------------------------

def z_pyramid(depth):
    r"""Greene's z-pyramid: level 0 the depth buffer, each coarser level the max of 2 x 2 texels.

    .. math:: Z_{k+1}[r, c] = \max(Z_k[2r, 2c], Z_k[2r, 2c+1], Z_k[2r+1, 2c], Z_k[2r+1, 2c+1])

    so a texel of level :math:`k` holds the farthest depth of the :math:`2^k \times 2^k` pixels
    below it. Odd sizes are padded by repeating the last row/column (conservative, see the
    module). Empty pixels (``+inf``) stay ``+inf`` upwards: nothing is hidden behind them.

    Parameters
    ----------
    depth : array_like, shape (height, width)
        A depth buffer (``+inf`` = nothing drawn).

    Returns
    -------
    Pyramid

    Examples
    --------
    >>> d = np.array([[.1, .2, .5, .5], [.3, .4, .5, .6], [.9, .9, .2, .2], [.9, .9, .2, .3]])
    >>> z_pyramid(d).levels[1]
    array([[0.4, 0.6],
           [0.9, 0.3]])
    """
    return _pyramid(_buffer2d(depth, "depth"), "max")


def hzb_level(rect, max_span=2):
    """The finest level at which `rect` spans at most `max_span` texels in each direction.

    At level k pixel column i falls in texel column ``i >> k``; the level is the smallest k with
    ``(i1 >> k) - (i0 >> k) + 1 <= max_span`` and the same for the rows.

    Parameters
    ----------
    rect : sequence of 4 ints or array (n, 4)
        ``(i0, j0, i1, j1)``, inclusive.
    max_span : int
        Texels per direction allowed (2: at most 2 x 2 texels are read).

    Returns
    -------
    int or ndarray of int

    Examples
    --------
    >>> hzb_level((1, 1, 2, 2)), hzb_level((3, 0, 5, 0)), hzb_level((1, 1, 4, 4)), hzb_level((3, 0, 8, 0))
    (0, 1, 2, 3)
    """
    max_span = as_whole(max_span, "max_span", 1)
    r = np.asarray(rect, dtype=np.int64)
    single = r.ndim == 1
    r = np.atleast_2d(r)
    lo, hi = r[:, :2], r[:, 2:]
    if (hi < lo).any() or (lo < 0).any():
        raise ValueError("rect must have 0 <= i0 <= i1 and 0 <= j0 <= j1")
    level = np.zeros(len(r), dtype=np.int64)
    k = 0
    todo = np.ones(len(r), dtype=bool)
    while todo.any():
        span = ((hi >> k) - (lo >> k) + 1).max(axis=1)
        done = todo & (span <= max_span)
        level[done] = k
        todo &= ~done
        k += 1
    return int(level[0]) if single else level


def _covering(levels, r, max_span, fixed=None):
    """Per box: its level (capped at the top, or `fixed`), the texels read, and their max."""
    if fixed is None:
        level = np.minimum(hzb_level(r, max_span), len(levels) - 1)
    else:
        level = np.full(len(r), fixed, dtype=np.int64)
        max_span = 0                  # any number of texels: gather them one box at a time
    out = np.empty(len(r))
    texels = np.empty(len(r), dtype=np.int64)
    for k in np.unique(level):
        sel = np.flatnonzero(level == k)
        lv = levels[k]
        c0, r0, c1, r1 = (r[sel] >> k).T
        if max_span == 2:             # vectorized gather of the (at most) 2 x 2 texels
            m = np.maximum(np.maximum(lv[r0, c0], lv[r0, c1]),
                           np.maximum(lv[r1, c0], lv[r1, c1]))
        else:
            m = np.array([lv[a:b + 1, c:d + 1].max() for a, b, c, d in zip(r0, r1, c0, c1)])
        out[sel] = m
        texels[sel] = (c1 - c0 + 1) * (r1 - r0 + 1)
    return level, out, texels


def _level_arg(level, pyramid):
    if level is None:
        return None
    level = as_whole(level, "level", 0)
    if level >= len(pyramid.levels):
        raise ValueError(f"level must be at most {len(pyramid.levels) - 1} (the 1 x 1 top), "
                         f"got {level}")
    return level


def hzb_test(pyramid, rect, z_near, max_span=2, level=None):
    r"""Whether the hierarchical z-buffer rejects a box: its nearest depth is behind every texel.

    The level is :func:`hzb_level` (at most ``max_span`` x ``max_span`` texels cover the
    rectangle). Each covering texel holds the farthest depth of its pixels, so if
    :math:`z_{near} > \max` of those texels, every pixel of the rectangle already holds something
    nearer than any point of the box: the box is hidden. The converse fails (the texels also
    cover pixels outside the rectangle), so the test is **conservative**: it may keep a hidden
    box, never rejects a visible one.

    Parameters
    ----------
    pyramid : Pyramid
        From :func:`z_pyramid`.
    rect : sequence of 4 ints
        ``(i0, j0, i1, j1)`` inclusive, clamped to the screen.
    z_near : float
        The box's nearest depth.
    max_span : int
    level : int, optional
        Read this level instead (all its texels that cover the rectangle, however many):
        finer levels read more texels, coarser ones reject less.

    Returns
    -------
    (bool, int, int)
        Rejected, the level read, the number of texels read.

    Examples
    --------
    >>> d = np.array([[.1, .2, .5, .5], [.3, .4, .5, .6], [.9, .9, .2, .2], [.9, .9, .2, .3]])
    >>> p = z_pyramid(d)
    >>> hzb_test(p, (0, 0, 1, 1), 0.45)
    (True, 0, 4)

    Conservative: at level 1 the texel 0.6 also covers pixel (3, 1), outside the rectangle, so
    the box at 0.55 is kept although every one of its 6 pixels is nearer:

    >>> hzb_test(p, (0, 0, 2, 1), 0.55), full_test(d, (0, 0, 2, 1), 0.55)
    ((False, 1, 2), (True, 6))
    >>> hzb_test(p, (0, 0, 2, 1), 0.55, level=0)
    (True, 0, 6)
    """
    r = hzb_cull(pyramid, [rect], [as_scalar(z_near, "z_near")], max_span, level)
    return bool(r.rejected[0]), int(r.level[0]), int(r.texels[0])


def hzb_cull(pyramid, rects, z_nears, max_span=2, level=None):
    """:func:`hzb_test` for many boxes at once, vectorized per level.

    Parameters
    ----------
    pyramid : Pyramid
        From :func:`z_pyramid`.
    rects : array_like, shape (n, 4)
    z_nears : array_like, shape (n,) or a number
    max_span : int
    level : int, optional
        One level for every box (see :func:`hzb_test`).

    Returns
    -------
    HZBCull

    Examples
    --------
    >>> p = z_pyramid(np.full((8, 8), 0.5))
    >>> hzb_cull(p, [(0, 0, 7, 7), (2, 2, 3, 3)], [0.6, 0.4]).rejected.tolist()
    [True, False]
    """
    if not isinstance(pyramid, Pyramid):
        raise TypeError(f"pyramid must be a Pyramid (from z_pyramid), got "
                        f"{type(pyramid).__name__}")
    max_span = as_whole(max_span, "max_span", 1)
    r = _rects(rects, pyramid.shape)
    z = _nears(z_nears, len(r))
    level, far, texels = _covering(pyramid.levels, r, max_span, _level_arg(level, pyramid))
    return HZBCull(z > far, level, texels)


def full_test(depth, rect, z_near):
    """The exact per-pixel test: hidden when `z_near` is farther than every pixel of `rect`.

    Parameters
    ----------
    depth : array_like, shape (height, width)
    rect : sequence of 4 ints
    z_near : float

    Returns
    -------
    (bool, int)
        Rejected, and the pixels read.

    Examples
    --------
    >>> d = np.array([[.1, .2, .5, .5], [.3, .4, .5, .6], [.9, .9, .2, .2], [.9, .9, .2, .3]])
    >>> full_test(d, (1, 1, 2, 2), 0.45), full_test(d, (1, 1, 2, 2), 0.95)
    ((False, 4), (True, 4))
    """
    r = full_cull(depth, [rect], [as_scalar(z_near, "z_near")])
    return bool(r.rejected[0]), int(r.texels[0])


def full_cull(depth, rects, z_nears):
    """The per-pixel reference test for many boxes (one numpy max per box).

    Parameters
    ----------
    depth : array_like, shape (height, width)
    rects : array_like, shape (n, 4)
    z_nears : array_like, shape (n,)

    Returns
    -------
    HZBCull
        With ``level`` 0 and ``texels`` the pixels of each rectangle.

    Examples
    --------
    >>> full_cull(np.full((4, 4), 0.5), [(0, 0, 3, 3)], [0.7]).texels.tolist()
    [16]
    """
    d = _buffer2d(depth, "depth")
    r = _rects(rects, d.shape)
    z = _nears(z_nears, len(r))
    far = np.array([d[j0:j1 + 1, i0:i1 + 1].max() for i0, j0, i1, j1 in r])
    texels = (r[:, 2] - r[:, 0] + 1) * (r[:, 3] - r[:, 1] + 1)
    return HZBCull(z > far, np.zeros(len(r), dtype=np.int64), texels)


def screen_rect(points, width, height):
    """The screen rectangle and nearest depth of a box given by points in viewport coordinates.

    The rectangle holds every pixel whose square ``[i, i+1] x [j, j+1]`` meets the points' 2D
    bounding box (a conservative bound: a box may cover a pixel's square without its centre).

    Parameters
    ----------
    points : array_like, shape (m, 3)
        The box's corners (x, y in pixels, z depth), already projected (e.g. by
        :func:`course_lib.viewing.viewport` after the perspective divide).
    width, height : int

    Returns
    -------
    (tuple of 4 ints, float)
        ``(i0, j0, i1, j1)`` clamped to the screen, and the smallest z.

    Examples
    --------
    >>> screen_rect([[1.5, 2.2, 0.4], [3.2, 5.9, 0.7]], 8, 8)
    ((1, 2, 3, 5), 0.4)
    """
    p = np.asarray(points, dtype=float)
    if p.ndim != 2 or p.shape[1] != 3 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError(f"points must be finite rows (x, y, z), got shape {p.shape}")
    width, height = as_whole(width, "width", 1), as_whole(height, "height", 1)
    lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
    i0, j0 = np.floor(lo).astype(int)
    i1, j1 = np.ceil(hi).astype(int) - 1
    i1, j1 = max(i1, i0), max(j1, j0)
    rect = _rects([(i0, j0, i1, j1)], (height, width), "points")[0]
    return tuple(int(v) for v in rect), float(p[:, 2].min())


def box_screen_rect(lo, hi, view, projection, width, height):
    """The screen rectangle and nearest depth of an axis-aligned world box, through the camera.

    The 8 corners go through ``projection @ view``, the perspective divide and the viewport
    (depth to [0, 1]), as :func:`course_lib.visibility.render_depth` maps triangles; then
    :func:`screen_rect`. A box reaching behind the eye (some corner with clip :math:`w \\le 0`)
    cannot be bounded this way: it gets the whole screen and depth 0, i.e. it is never culled
    (conservative).

    Parameters
    ----------
    lo, hi : array_like, shape (3,)
        Opposite corners of the box (world coordinates).
    view, projection : array_like, shape (4, 4)
    width, height : int

    Returns
    -------
    (tuple of 4 ints, float)

    Examples
    --------
    >>> view = viewing.look_at([0, 0, 5], [0, 0, -1], [0, 1, 0])     # eye, gaze, up
    >>> proj = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    >>> rect, z = box_screen_rect([-0.5, -0.5, -0.5], [0.5, 0.5, 0.5], view, proj, 64, 64)
    >>> rect, round(z, 3)
    ((25, 25, 38, 38), 0.864)
    """
    lo, hi = as_vector(lo, "lo", 3), as_vector(hi, "hi", 3)
    if (hi < lo).any():
        raise ValueError("hi must be >= lo in every coordinate (a box of negative size)")
    view, projection = _camera(view, projection)
    width, height = as_whole(width, "width", 1), as_whole(height, "height", 1)
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                        for z in (lo[2], hi[2])])
    clip = transforms.to_homogeneous(corners) @ (projection @ view).T
    if (clip[:, 3] <= 1e-12).any():
        return (0, 0, width - 1, height - 1), 0.0
    screen = transforms.apply(viewing.viewport(0, 0, width, height),
                              transforms.from_homogeneous(clip))
    screen[:, 0] = np.clip(screen[:, 0], -1.0, width + 1.0)   # partly off screen: clamp
    screen[:, 1] = np.clip(screen[:, 1], -1.0, height + 1.0)
    return screen_rect(screen, width, height)


# ---------------------------------------------------------------------------------------------
# Occlusion queries
# ---------------------------------------------------------------------------------------------

def occlusion_query(depth, proxy, z=None):
    """The samples of a proxy that pass the depth test (``z < stored``), as a GPU query counts.

    Parameters
    ----------
    depth : array_like, shape (height, width)
        The depth buffer so far.
    proxy : rectangle or triangles
        With `z`: a rectangle ``(i0, j0, i1, j1)`` drawn at constant depth `z` (the front face
        of a screen-aligned box). Without: screen triangles (k, 3, 3) in viewport coordinates,
        rasterized by :func:`course_lib.visibility.zbuffer` (the proxy's own nearest depth per
        pixel is tested).
    z : float, optional

    Returns
    -------
    int

    Examples
    --------
    >>> d = np.array([[.2, .2, .9], [.2, .9, .9], [np.inf, .9, .9]])
    >>> occlusion_query(d, (0, 0, 2, 2), 0.5), occlusion_query(d, (0, 0, 2, 2), 0.9)
    (6, 1)
    """
    d = _buffer2d(depth, "depth")
    if z is None:
        zb = zbuffer(proxy, d.shape[1], d.shape[0])
        return int((zb.depth < d).sum())
    i0, j0, i1, j1 = _rects([proxy], d.shape, "proxy")[0]
    return int((as_scalar(z, "z") < d[j0:j1 + 1, i0:i1 + 1]).sum())


def draw_if_visible(rects, depths, width, height, threshold=0, order="front_to_back",
                    depth=None):
    """The draw-if-visible loop: query each object's box, draw it only if enough samples pass.

    Objects are screen rectangles at constant depth (their box stands in for them and drawing
    one writes its rectangle into the depth buffer). For each object in `order`: issue a query
    (:func:`occlusion_query`), wait for its result (a round trip: the CPU stalls or uses last
    frame's answer), draw when the count exceeds `threshold`. Front-to-back order lets near
    objects fill the buffer first, so later queries find them; back-to-front draws everything.

    Parameters
    ----------
    rects : array_like, shape (n, 4)
    depths : array_like, shape (n,)
    width, height : int
    threshold : int
        Draw only when more samples than this pass (0: any visible sample; larger: approximate,
        skips barely visible objects).
    order : {"front_to_back", "back_to_front", "given"}
    depth : array_like, optional
        The depth buffer to start from (default: empty, ``+inf``).

    Returns
    -------
    QueryLoop

    Examples
    --------
    >>> rects, z = [(0, 0, 3, 3), (1, 1, 2, 2)], [0.2, 0.6]
    >>> draw_if_visible(rects, z, 4, 4, order="given").drawn.tolist()
    [True, False]
    >>> draw_if_visible(rects, z, 4, 4, order="back_to_front").drawn.tolist()
    [True, True]
    """
    width, height = as_whole(width, "width", 1), as_whole(height, "height", 1)
    buf = (np.full((height, width), np.inf) if depth is None
           else _buffer2d(depth, "depth").copy())
    if buf.shape != (height, width):
        raise ValueError(f"depth must have shape ({height}, {width}), got {buf.shape}")
    r = _rects(rects, buf.shape)
    z = _nears(depths, len(r), "depths")
    threshold = as_whole(threshold, "threshold", 0)
    if order == "front_to_back":
        seq = np.argsort(z, kind="stable")
    elif order == "back_to_front":
        seq = np.argsort(-z, kind="stable")
    elif order == "given":
        seq = np.arange(len(r))
    else:
        raise ValueError(f"order must be 'front_to_back', 'back_to_front' or 'given', "
                         f"got {order!r}")
    drawn = np.zeros(len(r), dtype=bool)
    samples = np.zeros(len(r), dtype=np.int64)
    for k in seq:
        i0, j0, i1, j1 = r[k]
        block = buf[j0:j1 + 1, i0:i1 + 1]
        samples[k] = int((z[k] < block).sum())
        if samples[k] > threshold:
            drawn[k] = True
            np.minimum(block, z[k], out=block)
    return QueryLoop(drawn, samples, seq, buf)


# ---------------------------------------------------------------------------------------------
# Hierarchical occlusion maps
# ---------------------------------------------------------------------------------------------

def occlusion_map_pyramid(coverage):
    r"""Zhang's hierarchical occlusion map: opacities averaged 2 x 2 at a time.

    Level 0 is the occluders rendered white (1) on black (0), or their fractional coverage;
    level :math:`k+1` is the **mean** of 2 x 2 texels of level k, so a texel holds the fraction
    of its :math:`2^k \times 2^k` pixels covered by some occluder. Odd sizes are padded with 0.

    Parameters
    ----------
    coverage : array_like, shape (height, width), values in [0, 1]

    Returns
    -------
    Pyramid

    Examples
    --------
    >>> c = [[1, 1, 0, 0], [1, 0, 0, 0], [1, 1, 1, 1], [1, 1, 1, 1]]
    >>> occlusion_map_pyramid(c).levels[1]
    array([[0.75, 0.  ],
           [1.  , 1.  ]])
    """
    c = _buffer2d(coverage, "coverage", allow_inf=False)
    if (c < 0).any() or (c > 1).any():
        raise ValueError("coverage must lie in [0, 1] (opacity)")
    return _pyramid(c, "mean", pad_value=0.0)


def depth_estimation_buffer(occluder_depth, tile):
    """The farthest occluder depth in each `tile` x `tile` block (``+inf`` where none).

    Parameters
    ----------
    occluder_depth : array_like, shape (height, width)
        Depth of the occluders alone (``+inf`` where no occluder).
    tile : int
        Block size in pixels.

    Returns
    -------
    ndarray, shape (ceil(height / tile), ceil(width / tile))

    Examples
    --------
    >>> d = np.array([[.2, .3, np.inf, np.inf], [.4, np.inf, np.inf, np.inf]])
    >>> depth_estimation_buffer(d, 2)
    array([[0.4, inf]])
    """
    d = _buffer2d(occluder_depth, "occluder_depth")
    tile = as_whole(tile, "tile", 1)
    h, w = d.shape
    H, W = -(-h // tile), -(-w // tile)
    pad = np.pad(d, ((0, H * tile - h), (0, W * tile - w)), constant_values=np.inf)
    finite = np.where(np.isfinite(pad), pad, -np.inf).reshape(H, tile, W, tile).max(axis=(1, 3))
    return np.where(np.isneginf(finite), np.inf, finite)


def hom_test(pyramid, rect, z_near, deb, threshold=1.0, max_span=2, level=None, descend=True):
    """The hierarchical occlusion map test of one box: opaque enough and behind the occluders.

    Parameters
    ----------
    pyramid : Pyramid
        From :func:`occlusion_map_pyramid`.
    rect : sequence of 4 ints
        ``(i0, j0, i1, j1)``, clamped to the screen.
    z_near : float
        The box's nearest depth.
    deb : array_like, shape (H, W)
        The depth estimation buffer (:func:`depth_estimation_buffer`); its tile size is worked
        out from the screen size.
    threshold : float in (0, 1]
        Opacity that counts as opaque. 1: culled only behind fully covered texels (conservative
        up to the depth estimate); below 1: approximate, small gaps are ignored.
    max_span : int
    level : int, optional
        Read this level instead of the one where at most `max_span` texels cover the box.
    descend : bool
        As Zhang et al.: a covering texel below the threshold is not the end; its children that
        overlap the rectangle are tested, down to level 0 (the box may overlap only the covered
        part of a partly covered texel). False: decide on the covering texels alone.

    Returns
    -------
    HOMTest

    Examples
    --------
    >>> c = np.ones((4, 4)); c[0, 0] = 0
    >>> t = hom_test(occlusion_map_pyramid(c), (0, 0, 3, 3), 0.9, np.full((1, 1), 0.5), 0.75)
    >>> t.culled, t.level, t.opacities.tolist()
    (True, 1, [[0.75, 1.0], [1.0, 1.0]])
    >>> hom_test(occlusion_map_pyramid(c), (0, 0, 3, 3), 0.9, np.full((1, 1), 0.5)).culled
    False

    The box of the columns 1-3 overlaps the partly covered texel (0, 0) only where it is
    covered: the descent to level 0 finds that out (4 texels, then 2 children of the first):

    >>> t = hom_test(occlusion_map_pyramid(c), (1, 0, 3, 3), 0.9, np.full((1, 1), 0.5))
    >>> t.culled, t.reads
    (True, 6)
    >>> hom_test(occlusion_map_pyramid(c), (1, 0, 3, 3), 0.9, np.full((1, 1), 0.5),
    ...          descend=False).culled
    False
    """
    if not isinstance(pyramid, Pyramid) or pyramid.reduce != "mean":
        raise TypeError("pyramid must be an occlusion-map Pyramid (from occlusion_map_pyramid)")
    threshold = as_scalar(threshold, "threshold")
    if not 0 < threshold <= 1:
        raise ValueError(f"threshold must lie in (0, 1], got {threshold}")
    d = np.asarray(deb, dtype=float)
    if d.ndim != 2 or np.isnan(d).any():
        raise ValueError("deb must be a 2D array of depths")
    r = _rects([rect], pyramid.shape, "rect")[0]
    z = as_scalar(z_near, "z_near")
    level = _level_arg(level, pyramid)
    if level is None:
        level = min(hzb_level(r, as_whole(max_span, "max_span", 1)), len(pyramid.levels) - 1)
    i0, j0, i1, j1 = r >> level
    ops = pyramid.levels[level][j0:j1 + 1, i0:i1 + 1]
    h, w = pyramid.shape
    th, tw = -(-h // d.shape[0]), -(-w // d.shape[1])
    tiles = d[r[1] // th:r[3] // th + 1, r[0] // tw:r[2] // tw + 1]
    reads = [0]
    if descend:
        opaque = all(_opaque_texel(pyramid.levels, level, a, b, r, threshold, reads)
                     for a in range(j0, j1 + 1) for b in range(i0, i1 + 1))
    else:
        reads[0] = ops.size
        opaque = bool((ops >= threshold - 1e-12).all())
    behind = bool(z > tiles.max())
    return HOMTest(opaque and behind, opaque, behind, int(level), ops.copy(), reads[0])


def _opaque_texel(levels, k, row, col, rect, threshold, reads):
    """Zhang's overlap test of one texel: opaque enough, or all its children that overlap the
    rectangle are (down to level 0). Counts the texels read in ``reads[0]``."""
    reads[0] += 1
    if levels[k][row, col] >= threshold - 1e-12:
        return True
    if k == 0:
        return False
    i0, j0, i1, j1 = rect >> (k - 1)
    return all(_opaque_texel(levels, k - 1, a, b, rect, threshold, reads)
               for a in range(max(2 * row, j0), min(2 * row + 1, j1) + 1)
               for b in range(max(2 * col, i0), min(2 * col + 1, i1) + 1))
