r"""Chapter 14: texturing: sampling, barycentric weights, mappings, procedural textures, mipmaps.

A texture is an image glued onto a surface: every surface point gets texture coordinates
:math:`(u, v)` (from a *mapping*: :func:`planar_map`, :func:`spherical_map`,
:func:`cylindrical_map`, or from per-vertex coordinates interpolated with :func:`barycentric`
weights), and the texture is *sampled* there (:func:`nearest_sample`, :func:`bilinear_sample`,
:func:`trilinear_sample` with a :func:`mipmap`). Procedural textures (:func:`checkerboard`,
:func:`perlin_noise`, :func:`marble`, :func:`wood`, ...) compute the colour from the
coordinates instead of looking it up.

Conventions
-----------
**Textures** are arrays of shape ``(H, W)`` (grey) or ``(H, W, C)`` (C channels, e.g. RGB), of
any numeric type; results are float. **Texel** ``(i, j)`` (row i, column j) covers the square
:math:`u \in [j/W, (j+1)/W]`, :math:`v \in [i/H, (i+1)/H]` of texture space and its **centre**
is at :math:`((j + \tfrac12)/W, (i + \tfrac12)/H)`: texel centres are where a texture
reproduces its texels exactly. **Row 0 is v = 0**, the *bottom* of the picture, as in OpenGL and
as :mod:`course_lib.visibility` stores images: show a texture with
``plt.imshow(texture, origin="lower", extent=(0, 1, 0, 1))`` (without ``origin="lower"`` it is
upside down; image files store the top row first, so flip them with ``texture[::-1]``).
In array coordinates (continuous row :math:`y`, column :math:`x`, texel centres at integers):

.. math:: x = u W - \tfrac12, \qquad y = v H - \tfrac12

**Wrap modes**, for :math:`(u, v)` outside :math:`[0, 1]`: ``"repeat"`` tiles the texture
(only the fractional part counts; OpenGL's ``GL_REPEAT``), ``"clamp"`` uses the nearest edge
texel (``GL_CLAMP_TO_EDGE``), ``"mirror"`` tiles it with every other copy mirrored
(``GL_MIRRORED_REPEAT``). scipy's ``ndimage.map_coordinates`` calls them ``"grid-wrap"``,
``"nearest"`` and ``"reflect"``.

Mappings (the course compendium's spherical formulas, corrected)
----------------------------------------------------------------
With the textbook's axes, the pole of a sphere on :math:`y` and the azimuth measured in the
:math:`xz` plane from :math:`+z` towards :math:`+x`, for :math:`d = P - C`,
:math:`r = \lVert d \rVert`:

.. math:: \theta = \operatorname{atan2}(d_x, d_z) \in (-\pi, \pi], \qquad
          \varphi = \arcsin(d_y / r) = \operatorname{atan2}\!\left(d_y,
          \sqrt{d_x^2 + d_z^2}\right) \in [-\tfrac\pi2, \tfrac\pi2]

.. math:: u = \tfrac12 + \frac{\theta}{2\pi}, \qquad v = \tfrac12 + \frac{\varphi}{\pi}

The compendium writes :math:`\theta = \tan^{-1}(x/z)` and an elevation
:math:`\tan^{-1}\big(y/\sqrt{x^2 + y^2}\big)`. Two mistakes: the elevation's horizontal
distance must be :math:`\sqrt{x^2 + z^2}` (the azimuth lives in the :math:`xz` plane; with
:math:`x^2 + y^2`, :math:`y` appears on both sides and the pole is not at :math:`\pi/2`), and
:math:`\tan^{-1}(x/z)` only covers half the circle (:math:`x/z` is the same for :math:`P` and
:math:`-P`): the two-argument :math:`\operatorname{atan2}` is needed.

* The **seam**: :math:`u` jumps from 1 to 0 across the half-plane behind the sphere
  (:math:`d_x = 0, d_z < 0`). A triangle straddling it gets :math:`u` values like 0.97 and 0.02
  and interpolates through the *whole* texture, a visible smeared stripe; :func:`seam_unwrap`
  shifts such a triangle's small :math:`u` by 1 (sample with ``wrap="repeat"``).
* The **poles**: :math:`u` is undefined at :math:`d = \pm r\,\hat y` (set to 1/2 here), and the
  whole top (bottom) row of the texture is squeezed into one point. The area of the sphere per
  unit of texture area is :math:`2\pi^2 r^2 \cos\varphi`: texels near the poles shrink by
  :math:`\cos\varphi`, the equator is the least distorted.

:func:`cylindrical_map` uses the same azimuth for :math:`u` and the height along the axis
(divided by the cylinder's height) for :math:`v`; it has the same seam, no pole distortion
(area per texel is constant), and is undefined on the axis itself. :func:`planar_map` projects
along the plane's normal: no seam, but everything along the normal gets the same texel
(stretched stripes on surfaces nearly parallel to the normal).
"""
from typing import NamedTuple

import numpy as np

from ._validate import as_array, as_points, as_scalar, as_vector, broadcast_stacks

__all__ = [
    "AliasingDemo",
    "WRAP_MODES",
    "aliasing_demo",
    "barycentric",
    "bilinear_sample",
    "checkerboard",
    "cylindrical_map",
    "interpolate",
    "inverse_cylindrical_map",
    "inverse_planar_map",
    "inverse_spherical_map",
    "marble",
    "mip_level",
    "mipmap",
    "nearest_sample",
    "perlin_noise",
    "perspective_interpolate",
    "perspective_weights",
    "planar_map",
    "seam_unwrap",
    "spherical_map",
    "stripes",
    "texel_footprint",
    "trilinear_sample",
    "turbulence",
    "uv_grid",
    "value_noise",
    "wood",
]

WRAP_MODES = ("repeat", "clamp", "mirror")


def _dot(a, b):
    return np.einsum("...i,...i->...", a, b)


# ---------------------------------------------------------------------------------------------
# Input checks
# ---------------------------------------------------------------------------------------------

def _texture(texture, name="texture"):
    t = as_array(texture, name)
    if t.ndim not in (2, 3):
        raise ValueError(f"{name} must be a 2D array (H, W) of grey values or a 3D array "
                         f"(H, W, channels), got shape {t.shape}")
    if t.shape[0] == 0 or t.shape[1] == 0 or (t.ndim == 3 and t.shape[2] == 0):
        raise ValueError(f"{name} must not be empty, got shape {t.shape}")
    return t


def _uv(u, v):
    u = as_array(u, "u")
    v = as_array(v, "v")
    try:
        return np.broadcast_arrays(u, v)
    except ValueError:
        raise ValueError(f"u and v must have the same shape (or broadcast), got {u.shape} and "
                         f"{v.shape}") from None


def _wrap_mode(wrap):
    if wrap not in WRAP_MODES:
        raise ValueError(f"wrap must be one of {', '.join(map(repr, WRAP_MODES))}, got {wrap!r}")
    return wrap


def _wrap(index, n, wrap):
    """Integer texel indices wrapped into [0, n) by the wrap mode."""
    if wrap == "repeat":
        return index & (n - 1) if n & (n - 1) == 0 else np.mod(index, n)   # power of two: mask
    if wrap == "clamp":
        return np.clip(index, 0, n - 1)
    m = np.mod(index, 2 * n)
    return np.where(m < n, m, 2 * n - 1 - m)


def _rng(seed):
    return seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)


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
    wrap = _wrap_mode(wrap)
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
    wrap = _wrap_mode(wrap)
    h, w = t.shape[:2]
    x = u * w - 0.5
    y = v * h - 0.5
    j0f, i0f = np.floor(x), np.floor(y)
    a, b = x - j0f, y - i0f
    j0, i0 = j0f.astype(np.int64), i0f.astype(np.int64)
    j1, i1 = _wrap(j0 + 1, w, wrap), _wrap(i0 + 1, h, wrap)
    j0, i0 = _wrap(j0, w, wrap), _wrap(i0, h, wrap)
    flat = t.reshape((h * w,) + t.shape[2:])        # one gather per corner, by flat index
    row0, row1 = i0 * w, i1 * w
    t00, t01 = flat.take(row0 + j0, axis=0), flat.take(row0 + j1, axis=0)
    t10, t11 = flat.take(row1 + j0, axis=0), flat.take(row1 + j1, axis=0)
    if t.ndim == 3:
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
    w, h = _positive_int(width, "width"), _positive_int(height, "height")
    u = (np.arange(w) + 0.5) / w
    v = (np.arange(h) + 0.5) / h
    uu, vv = np.meshgrid(u, v)
    return np.stack([uu, vv], axis=-1)


def _positive_int(value, name):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got a bool")
    x = as_scalar(value, name)
    if x < 1 or x != int(x):
        raise ValueError(f"{name} must be a positive whole number, got {value!r}")
    return int(x)


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


def _weights(weights, name="weights"):
    w = as_array(weights, name)
    if w.ndim == 0 or w.shape[-1] != 3:
        raise ValueError(f"{name} must hold three barycentric weights in the last axis (shape "
                         f"(..., 3)), got shape {w.shape}")
    return w


def interpolate(values, weights, stacked=False):
    r"""Interpolate vertex attributes with barycentric weights, :math:`q = \sum_k \lambda_k q_k`.

    Colours, texture coordinates, normals, depths: any attribute given at the three vertices.

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
    >>> interpolate([10.0, 20.0, 30.0], w)
    array([17.5, 15. ])
    >>> interpolate([[1, 0, 0], [0, 1, 0], [0, 0, 1]], w)          # RGB at the vertices
    array([[0.5 , 0.25, 0.25],
           [0.5 , 0.5 , 0.  ]])
    >>> interpolate([[0, 1, 2], [3, 4, 5]], [[1, 0, 0], [0, 0, 1]], stacked=True)
    array([0., 5.])
    """
    w = _weights(weights)
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
    lam = _weights(weights)
    ww = _weights(w, "w")
    if np.any(ww <= 0):
        raise ValueError("w must be positive (the vertices must be in front of the eye)")
    broadcast_stacks(weights=(lam, 1), w=(ww, 1))
    scaled = lam / ww
    return scaled / scaled.sum(axis=-1, keepdims=True)


def perspective_interpolate(values, weights, w, stacked=False):
    r"""Perspective-correct interpolation: :math:`\sum \lambda_k q_k/w_k \,/\, \sum \lambda_k/w_k`.

    :func:`interpolate` with :func:`perspective_weights`.

    Parameters
    ----------
    values : array_like
        As :func:`interpolate`.
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
    return interpolate(values, perspective_weights(weights, w), stacked)


# ---------------------------------------------------------------------------------------------
# Mappings
# ---------------------------------------------------------------------------------------------

def _least_aligned_axis(n):
    return np.eye(3)[int(np.argmin(np.abs(n)))]


def _frame(axis, reference, axis_name, reference_name):
    """Unit axis a, unit e1 (reference made perpendicular to a), e2 = a x e1."""
    a = as_vector(axis, axis_name, 3)
    if not np.any(a):
        raise ValueError(f"{axis_name} must not be the zero vector")
    a = a / np.linalg.norm(a)
    if reference is None:
        r = np.array([0.0, 0.0, 1.0])
        if abs(r @ a) > 0.9:
            r = _least_aligned_axis(a)
    else:
        r = as_vector(reference, reference_name, 3)
    e1 = r - (r @ a) * a
    if np.linalg.norm(e1) < 1e-9 * max(np.linalg.norm(r), 1e-300):
        raise ValueError(f"{reference_name} must not be parallel to {axis_name}")
    e1 = e1 / np.linalg.norm(e1)
    return a, e1, np.cross(a, e1)


def _size2(size):
    s = as_array(size, "size")
    if s.ndim == 0:
        s = np.array([s, s])
    if s.shape != (2,) or np.any(s <= 0):
        raise ValueError(f"size must be a positive number or (size_u, size_v), got {size!r}")
    return s


def planar_map(points, origin=(0.0, 0.0, 0.0), normal=(0.0, 0.0, 1.0), u_axis=None, size=1.0):
    r"""Planar mapping: project points along the plane's normal, measure them in plane axes.

    .. math:: u = \frac{(P - O) \cdot e_u}{s_u}, \qquad v = \frac{(P - O) \cdot e_v}{s_v}

    with :math:`e_u` the `u_axis` made perpendicular to the normal :math:`n`, and
    :math:`e_v = n \times e_u` (so :math:`(e_u, e_v, n)` is right-handed and the texture is
    not mirrored seen from the side :math:`n` points to). The unit square of texture space
    covers an :math:`s_u \times s_v` rectangle of the plane with its corner at :math:`O`;
    outside it, the sampler's wrap mode repeats or clamps. The component along :math:`n` is
    dropped: every point on a line along the normal gets the same :math:`(u, v)`.

    Parameters
    ----------
    points : array_like, shape (..., 3)
    origin : array_like, shape (3,)
        Where (u, v) = (0, 0).
    normal : array_like, shape (3,)
        The projection direction (not zero).
    u_axis : array_like, shape (3,), optional
        Direction of increasing u (default: the coordinate axis least aligned with the normal,
        x first; for the default normal z it is x, and then :math:`e_v = y`).
    size : float or (float, float)
        The plane's extent of one texture repeat.

    Returns
    -------
    u, v : ndarray, shape (...)

    Raises
    ------
    ValueError
        For a zero normal, a u axis parallel to it, or a non-positive size.

    Examples
    --------
    >>> u, v = planar_map([[0.5, 0.25, 7.0], [2.0, -1.0, 0.0]], size=2.0)
    >>> u, v
    (array([0.25, 1.  ]), array([ 0.125, -0.5  ]))
    """
    p = as_points(points, "points", dims=3)
    o = as_vector(origin, "origin", 3)
    n = as_vector(normal, "normal", 3)
    if not np.any(n):
        raise ValueError("normal must not be the zero vector")
    n = n / np.linalg.norm(n)
    ref = _least_aligned_axis(n) if u_axis is None else u_axis
    _, e_u, e_v = _frame(n, ref, "normal", "u_axis")
    s = _size2(size)
    d = p - o
    return d @ e_u / s[0], d @ e_v / s[1]


def inverse_planar_map(u, v, origin=(0.0, 0.0, 0.0), normal=(0.0, 0.0, 1.0), u_axis=None,
                       size=1.0):
    r"""The point of the plane with texture coordinates (u, v): :math:`O + u s_u e_u + v s_v e_v`.

    Parameters
    ----------
    u, v : array_like
    origin, normal, u_axis, size
        As :func:`planar_map`.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> inverse_planar_map(0.25, 0.5, size=2.0)
    array([0.5, 1. , 0. ])
    """
    u, v = _uv(u, v)
    o = as_vector(origin, "origin", 3)
    n = as_vector(normal, "normal", 3)
    if not np.any(n):
        raise ValueError("normal must not be the zero vector")
    n = n / np.linalg.norm(n)
    ref = _least_aligned_axis(n) if u_axis is None else u_axis
    _, e_u, e_v = _frame(n, ref, "normal", "u_axis")
    s = _size2(size)
    return o + (u * s[0])[..., None] * e_u + (v * s[1])[..., None] * e_v


def _azimuth_u(d, e1, e2):
    return 0.5 + np.arctan2(d @ e2, d @ e1) / (2 * np.pi)


def spherical_map(points, center=(0.0, 0.0, 0.0), axis=(0.0, 1.0, 0.0), reference=None):
    r"""Spherical (longitude-latitude) mapping of points around `center`.

    .. math:: u = \tfrac12 + \frac{\operatorname{atan2}(d \cdot e_2,\ d \cdot e_1)}{2\pi},
              \qquad v = \tfrac12 + \frac{\arcsin(d \cdot a / \lVert d \rVert)}{\pi},
              \qquad d = P - C

    with :math:`a` the pole `axis`, :math:`e_1` the `reference` direction (made perpendicular
    to :math:`a`) where :math:`u = 1/2`, and :math:`e_2 = a \times e_1`. With the defaults
    (:math:`a = y`, :math:`e_1 = z`, :math:`e_2 = x`) this is
    :math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`,
    :math:`v = \tfrac12 + \arcsin(y/r)/\pi`: the textbook's angles, corrected (see the module
    docstring). u grows from +z towards +x (unmirrored seen from outside), v from the south
    pole (0) to the north pole (1). The seam, :math:`u = 0 \equiv 1`, is the half-plane
    opposite :math:`e_1`; at the poles :math:`u = 1/2` by convention. Only the direction of
    :math:`d` matters (any radius).

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Not at the centre.
    center : array_like, shape (3,)
    axis : array_like, shape (3,)
        The pole direction (default y).
    reference : array_like, shape (3,), optional
        The direction of u = 1/2 (default z, or the least aligned axis if `axis` is near z).

    Returns
    -------
    u, v : ndarray, shape (...)
        :math:`u \in [0, 1]`, :math:`v \in [0, 1]`.

    Raises
    ------
    ValueError
        For a point at the centre, a zero axis or a reference parallel to the axis.

    Examples
    --------
    >>> u, v = spherical_map([[0, 0, 1], [1, 0, 0], [0, 1, 0], [-1, 0, 0]])
    >>> u, v
    (array([0.5 , 0.75, 0.5 , 0.25]), array([0.5, 0.5, 1. , 0.5]))
    """
    p = as_points(points, "points", dims=3)
    c = as_vector(center, "center", 3)
    a, e1, e2 = _frame(axis, reference, "axis", "reference")
    d = p - c
    r = np.sqrt(_dot(d, d))
    if np.any(r == 0):
        raise ValueError("points must not be at the center: the direction is undefined there")
    return _azimuth_u(d, e1, e2), 0.5 + np.arcsin(np.clip(d @ a / r, -1.0, 1.0)) / np.pi


def inverse_spherical_map(u, v, center=(0.0, 0.0, 0.0), radius=1.0, axis=(0.0, 1.0, 0.0),
                          reference=None):
    r"""The point of the sphere with texture coordinates (u, v) (inverse of :func:`spherical_map`).

    .. math:: \theta = 2\pi(u - \tfrac12), \quad \varphi = \pi(v - \tfrac12), \quad
              P = C + r\left[\cos\varphi(\cos\theta\, e_1 + \sin\theta\, e_2) + \sin\varphi\,
              a\right]

    Parameters
    ----------
    u, v : array_like
    center : array_like, shape (3,)
    radius : float
    axis, reference
        As :func:`spherical_map`.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> np.round(inverse_spherical_map([0.5, 0.75], [0.5, 0.5]), 12)
    array([[0., 0., 1.],
           [1., 0., 0.]])
    """
    u, v = _uv(u, v)
    c = as_vector(center, "center", 3)
    r = as_scalar(radius, "radius")
    if r <= 0:
        raise ValueError(f"radius must be positive, got {r}")
    a, e1, e2 = _frame(axis, reference, "axis", "reference")
    theta, phi = 2 * np.pi * (u - 0.5), np.pi * (v - 0.5)
    d = (np.cos(phi) * np.cos(theta))[..., None] * e1 + (np.cos(phi) * np.sin(theta))[
        ..., None] * e2 + np.sin(phi)[..., None] * a
    return c + r * d


def cylindrical_map(points, center=(0.0, 0.0, 0.0), axis=(0.0, 1.0, 0.0), height=1.0,
                    reference=None):
    r"""Cylindrical mapping: the angle around the axis and the height along it.

    .. math:: u = \tfrac12 + \frac{\operatorname{atan2}(d \cdot e_2,\ d \cdot e_1)}{2\pi},
              \qquad v = \frac{d \cdot a}{h}, \qquad d = P - C

    (same azimuth as :func:`spherical_map`: with the defaults
    :math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`, :math:`v = y / h`). The cylinder
    from :math:`C` to :math:`C + h a` covers :math:`v \in [0, 1]` once; beyond, the wrap mode
    decides. The seam is the half-plane opposite :math:`e_1`; on the axis u is undefined (1/2
    here). The distance from the axis does not matter.

    Parameters
    ----------
    points : array_like, shape (..., 3)
    center : array_like, shape (3,)
        The centre of the cylinder's base.
    axis : array_like, shape (3,)
        Direction of the axis (default y).
    height : float
        Height of one texture repeat along the axis.
    reference : array_like, shape (3,), optional
        Direction of u = 1/2 (default z).

    Returns
    -------
    u, v : ndarray, shape (...)

    Raises
    ------
    ValueError
        For a zero axis, a reference parallel to it or a non-positive height.

    Examples
    --------
    >>> cylindrical_map([[0, 0.5, 2], [-3, 2.0, 0]], height=2.0)
    (array([0.5 , 0.25]), array([0.25, 1.  ]))
    """
    p = as_points(points, "points", dims=3)
    c = as_vector(center, "center", 3)
    h = as_scalar(height, "height")
    if h <= 0:
        raise ValueError(f"height must be positive, got {h}")
    a, e1, e2 = _frame(axis, reference, "axis", "reference")
    d = p - c
    return _azimuth_u(d, e1, e2), d @ a / h


def inverse_cylindrical_map(u, v, center=(0.0, 0.0, 0.0), radius=1.0, axis=(0.0, 1.0, 0.0),
                            height=1.0, reference=None):
    r"""The point of the cylinder with texture coordinates (u, v).

    .. math:: P = C + r(\cos\theta\, e_1 + \sin\theta\, e_2) + v h\, a, \qquad
              \theta = 2\pi(u - \tfrac12)

    Parameters
    ----------
    u, v : array_like
    center : array_like, shape (3,)
    radius, height : float
    axis, reference
        As :func:`cylindrical_map`.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> np.round(inverse_cylindrical_map(0.25, 0.5, radius=2.0, height=4.0), 12)
    array([-2.,  2.,  0.])
    """
    u, v = _uv(u, v)
    c = as_vector(center, "center", 3)
    r, h = as_scalar(radius, "radius"), as_scalar(height, "height")
    if r <= 0 or h <= 0:
        raise ValueError(f"radius and height must be positive, got {r} and {h}")
    a, e1, e2 = _frame(axis, reference, "axis", "reference")
    theta = 2 * np.pi * (u - 0.5)
    return (c + r * (np.cos(theta)[..., None] * e1 + np.sin(theta)[..., None] * e2)
            + (v * h)[..., None] * a)


def seam_unwrap(u):
    r"""Fix triangles that straddle the u seam of a spherical or cylindrical mapping.

    For each triangle (last axis: its three vertices' u), if the u values span more than 1/2,
    the triangle crosses the seam (it cannot really cover half the circle): the small values
    get +1, so that interpolation runs the short way, through 1 (and ``wrap="repeat"`` brings
    1.02 back to 0.02).

    Parameters
    ----------
    u : array_like, shape (..., 3)

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> seam_unwrap([[0.97, 0.02, 0.99], [0.2, 0.3, 0.25]])
    array([[0.97, 1.02, 0.99],
           [0.2 , 0.3 , 0.25]])
    """
    uu = _weights(u, "u")
    crosses = (uu.max(axis=-1) - uu.min(axis=-1)) > 0.5
    return np.where(crosses[..., None] & (uu < 0.5), uu + 1.0, uu)


# ---------------------------------------------------------------------------------------------
# Procedural textures
# ---------------------------------------------------------------------------------------------

def _coords(points):
    p = as_points(points, "points", dims=(2, 3))
    return p


def checkerboard(points, squares=8):
    r"""A checkerboard: 0 or 1 by the parity of the square the point falls in.

    .. math:: T(P) = \left(\sum_k \lfloor s\, p_k \rfloor\right) \bmod 2

    In 2D (points (u, v)) an :math:`s \times s` board covers the unit square (it tiles
    seamlessly with ``wrap="repeat"`` when :math:`s` is even); in 3D it is a *solid* texture,
    a 3D grid of cubes that any surface can be cut out of, with no mapping and no seams.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    squares : float
        Squares per unit length, :math:`s > 0`.

    Returns
    -------
    ndarray, shape (...)
        0.0 or 1.0.

    Examples
    --------
    >>> checkerboard(uv_grid(4, 2), squares=2)
    array([[0., 0., 1., 1.],
           [1., 1., 0., 0.]])
    """
    p = _coords(points)
    s = as_scalar(squares, "squares")
    if s <= 0:
        raise ValueError(f"squares must be positive, got {s}")
    return np.mod(np.floor(s * p).sum(axis=-1), 2.0)


def stripes(points, count=8, width=0.5, direction=None):
    r"""Parallel stripes: 1 on a fraction `width` of each period, 0 elsewhere.

    .. math:: s = P \cdot \hat d, \qquad T(P) = [\operatorname{fract}(n s) < w]

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    count : float
        Stripes per unit length along `direction`, :math:`n > 0`.
    width : float
        Duty cycle :math:`w` in [0, 1].
    direction : array_like, optional
        Across the stripes (default the first axis, u or x); normalized.

    Returns
    -------
    ndarray, shape (...)
        0.0 or 1.0.

    Examples
    --------
    >>> stripes([[0.05, 0.0], [0.1, 0.3], [0.2, 0.9]], count=4, width=0.5)
    array([1., 0., 1.])
    """
    p = _coords(points)
    n = as_scalar(count, "count")
    w = as_scalar(width, "width")
    if n <= 0 or not 0 <= w <= 1:
        raise ValueError(f"count must be positive and width in [0, 1], got {n} and {w}")
    if direction is None:
        s = p[..., 0]
    else:
        d = as_vector(direction, "direction", p.shape[-1])
        if not np.any(d):
            raise ValueError("direction must not be the zero vector")
        s = p @ (d / np.linalg.norm(d))
    frac = n * s - np.floor(n * s)
    return (frac < w).astype(float)


_PERIOD = 256


class _Lattice:
    """The seeded random tables of a lattice noise: a permutation, values and gradients."""

    def __init__(self, seed, dim):
        rng = _rng(seed)
        self.perm = np.concatenate([rng.permutation(_PERIOD)] * 2)
        self.values = rng.uniform(-1.0, 1.0, _PERIOD)
        if dim == 2:
            angle = rng.uniform(0, 2 * np.pi, _PERIOD)
            self.gradients = np.stack([np.cos(angle), np.sin(angle)], axis=-1)
        else:
            g = rng.normal(size=(_PERIOD, 3))
            self.gradients = g / np.linalg.norm(g, axis=-1, keepdims=True)

    def hash(self, cells):
        """A pseudo-random index in [0, 256) for each integer lattice point (..., d)."""
        h = np.zeros(cells.shape[:-1], dtype=np.intp)
        for k in range(cells.shape[-1]):
            h = self.perm[(h + (cells[..., k] & (_PERIOD - 1))) & (_PERIOD - 1)]
        return h


def _fade(t):
    """Perlin's quintic 6t^5 - 15t^4 + 10t^3: 0 and 1 at the ends, zero slope and curvature."""
    return t * t * t * (t * (t * 6 - 15) + 10)


def _lattice_noise(points, seed, gradient):
    p = _coords(points)
    dim = p.shape[-1]
    lattice = _Lattice(seed, dim)
    base = np.floor(p)
    frac = p - base
    cell = base.astype(np.int64)
    fade = _fade(frac)
    result = np.zeros(p.shape[:-1])
    for corner in np.ndindex(*(2,) * dim):
        offset = np.array(corner)
        idx = lattice.hash(cell + offset)
        if gradient:
            contribution = _dot(lattice.gradients[idx], frac - offset)
        else:
            contribution = lattice.values[idx]
        weight = np.prod(np.where(offset == 1, fade, 1 - fade), axis=-1)
        result = result + weight * contribution
    return result


def value_noise(points, seed=0):
    r"""Value noise: random values at the integer lattice points, smoothly interpolated.

    Each lattice point gets a pseudo-random value in [-1, 1] (a seeded permutation table hashes
    its integer coordinates), and the values of the cell's :math:`2^d` corners are blended with
    the weights :math:`f(t) = 6t^5 - 15t^4 + 10t^3` per axis (smooth: no creases at the cell
    borders). Band-limited to about one feature per cell, but the lattice shows as blobs;
    :func:`perlin_noise` looks less grid-like. Periodic with period 256 in every coordinate.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    seed : int or numpy.random.Generator
        The same seed gives the same noise.

    Returns
    -------
    ndarray, shape (...)
        In [-1, 1]; equal to the lattice value at integer points.

    Examples
    --------
    >>> n = value_noise(np.random.default_rng(0).uniform(0, 50, (10_000, 2)), seed=1)
    >>> bool(n.min() >= -1 and n.max() <= 1)
    True
    >>> bool(np.allclose(value_noise([3.2, 4.7], seed=1), value_noise([3.2 + 256, 4.7], seed=1)))
    True
    """
    return _lattice_noise(points, seed, gradient=False)


def perlin_noise(points, seed=0):
    r"""Perlin (gradient) noise in 2D or 3D.

    Each integer lattice point :math:`c` gets a pseudo-random unit gradient :math:`g_c`; a point
    :math:`P` in a cell blends the corners' linear ramps :math:`g_c \cdot (P - c)` with the
    weights :math:`f(t) = 6t^5 - 15t^4 + 10t^3` per axis (Perlin's improved fade):

    .. math:: N(P) = \sum_{c \in \text{corners}} \Big(\prod_k w_k(c)\Big)\, g_c \cdot (P - c)

    So the noise is **zero at every lattice point** (all ramps vanish there) and has the
    gradient :math:`g_c` there: its features are about one cell apart, without the blobby grid
    of :func:`value_noise`. :math:`|N| \le \sqrt{d}/2` (0.71 in 2D, 0.87 in 3D): the ramps are
    at most the distance to the corner, and the weighted distance is largest at the cell
    centre. Periodic with period 256.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    seed : int or numpy.random.Generator

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> perlin_noise([[0, 0], [3, 7], [-2, 5]], seed=4)
    array([0., 0., 0.])
    >>> float(perlin_noise([0.5, 0.5], seed=4)) != 0
    True
    """
    return _lattice_noise(points, seed, gradient=True)


def turbulence(points, octaves=4, seed=0, lacunarity=2.0, gain=0.5, noise="perlin"):
    r"""Turbulence: a sum of octaves of the absolute value of noise.

    .. math:: T(P) = \sum_{o=0}^{O-1} g^o \, \lvert N(\ell^o P) \rvert

    Each octave doubles the frequency (lacunarity :math:`\ell = 2`) and halves the amplitude
    (gain :math:`g = 1/2`), a fractal (1/f) spectrum; the absolute value creates the sharp
    creases that look like turbulent flow, veins or flames.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    octaves : int
    seed : int or numpy.random.Generator
    lacunarity, gain : float
    noise : {"perlin", "value"}

    Returns
    -------
    ndarray, shape (...)
        Non-negative; at most :math:`\max|N| \sum_o g^o`.

    Examples
    --------
    >>> t = turbulence(uv_grid(32, 32) * 4, octaves=3)
    >>> t.shape, bool(t.min() >= 0)
    ((32, 32), True)
    """
    p = _coords(points)
    o = _positive_int(octaves, "octaves")
    lac, g = as_scalar(lacunarity, "lacunarity"), as_scalar(gain, "gain")
    if lac <= 0 or g <= 0:
        raise ValueError(f"lacunarity and gain must be positive, got {lac} and {g}")
    if noise not in ("perlin", "value"):
        raise ValueError(f"noise must be 'perlin' or 'value', got {noise!r}")
    # one lattice for every octave: the same as perlin_noise(points, seed) for an integer seed
    lattice_seed = seed if isinstance(seed, (int, np.integer)) else _rng(seed).integers(2**63)
    total = np.zeros(p.shape[:-1])
    for k in range(o):
        total = total + g**k * np.abs(_lattice_noise(p * lac**k, lattice_seed,
                                                     gradient=noise == "perlin"))
    return total


def marble(points, frequency=2.0, strength=4.0, octaves=4, seed=0):
    r"""Marble: sine stripes along the first coordinate, bent by turbulence.

    .. math:: T(P) = \tfrac12\left[1 + \sin\big(2\pi f\, p_0 + a\, \mathrm{turbulence}(P)\big)
              \right] \in [0, 1]

    Without turbulence (:math:`a = 0`) these are straight soft stripes; the turbulence
    displaces them into veins. Use as a grey value or to blend two colours.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    frequency : float
        Stripes per unit length :math:`f`.
    strength : float
        Turbulence amplitude :math:`a`.
    octaves : int
    seed : int or numpy.random.Generator

    Returns
    -------
    ndarray, shape (...)
        In [0, 1].

    Examples
    --------
    >>> m = marble(uv_grid(16, 16), seed=2)
    >>> bool(m.min() >= 0 and m.max() <= 1)
    True
    >>> bool(np.allclose(marble([[0.125, 0.3]], frequency=2, strength=0), 1.0))   # a crest
    True
    """
    p = _coords(points)
    f, a = as_scalar(frequency, "frequency"), as_scalar(strength, "strength")
    t = turbulence(p, octaves, seed) if a != 0 else 0.0
    return 0.5 * (1 + np.sin(2 * np.pi * f * p[..., 0] + a * t))


def wood(points, rings=8.0, strength=0.3, octaves=2, seed=0, center=(0.0, 0.0)):
    r"""Wood: concentric rings around an axis, wobbled by turbulence.

    .. math:: r = \lVert (p_0, p_1) - c \rVert, \qquad
              T(P) = \operatorname{fract}\big(k\, r + a\,\mathrm{turbulence}(P)\big) \in [0, 1)

    In 2D the rings are around the point `center`; in 3D around the line through it parallel
    to the third axis (the trunk), so a solid block of "wood" can be cut by any surface.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    rings : float
        Rings per unit radius :math:`k`.
    strength : float
        Turbulence amplitude :math:`a`.
    octaves : int
    seed : int or numpy.random.Generator
    center : array_like, shape (2,)

    Returns
    -------
    ndarray, shape (...)
        In [0, 1).

    Examples
    --------
    >>> wood([[0.3, 0.4], [0.0, 0.5]], rings=3, strength=0)     # r = 0.5: fract(1.5)
    array([0.5, 0.5])
    """
    p = _coords(points)
    k, a = as_scalar(rings, "rings"), as_scalar(strength, "strength")
    c = as_vector(center, "center", 2)
    r = np.hypot(p[..., 0] - c[0], p[..., 1] - c[1])
    x = k * r + (a * turbulence(p, octaves, seed) if a != 0 else 0.0)
    return x - np.floor(x)


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
        lam = np.minimum(lam, _positive_int(levels, "levels") - 1)
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
    wrap = _wrap_mode(wrap)
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
    w, h = _positive_int(width, "width"), _positive_int(height, "height")
    size = _positive_int(texture_size, "texture_size")
    n_sq = _positive_int(squares, "squares")
    ss = _positive_int(supersample, "supersample")
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
