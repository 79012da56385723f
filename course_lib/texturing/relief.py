r"""Chapter 14 (textbook 14.7.1, 14.7.2): relief: bump mapping, normal mapping, and
displacement mapping for contrast.

**Bump mapping** (Blinn 1978). A surface :math:`P(u, v)` with tangents :math:`P_u =
\partial P/\partial u`, :math:`P_v = \partial P/\partial v` and normal
:math:`N = P_u \times P_v` is pushed out along its unit normal :math:`n = N/|N|` by a height
map, :math:`P' = P + h(u, v)\, n`. Differentiating,
:math:`P'_u = P_u + h_u n + h\, n_u \approx P_u + h_u n` (for small :math:`h` the last term is
dropped), and likewise for :math:`v`. The new normal is

.. math:: N' = P'_u \times P'_v \approx N + h_u\,(n \times P_v) - h_v\,(n \times P_u)
          = N + \frac{h_u (N \times P_v) - h_v (N \times P_u)}{|N|}

(the :math:`h_u h_v\, n \times n` term is zero). **Sign convention**: heights are measured
along :math:`+N = P_u \times P_v` (positive heights are bumps towards the viewer of the front
side); only the *normal* changes, the points stay where they are.

For an orthonormal frame (:math:`P_u = T`, :math:`P_v = B`, :math:`N = T \times B`, unit
vectors) :math:`N \times B = -T` and :math:`N \times T = B`, so
:math:`N' = N - h_u T - h_v B`: the simplification used with tangent frames. With orthogonal
but not unit tangents it still holds with :math:`h_u/|P_u|`, :math:`h_v/|P_v|` (derivatives per
unit length on the surface) in place of :math:`h_u, h_v`.

**Normal maps** store the perturbed unit normal itself, encoded as a colour
:math:`c = (n + 1)/2` (8-bit: :math:`\operatorname{round}(255 c)`). In a *tangent-space* map
the components are in the (T, B, N) frame of the surface (mostly :math:`(0, 0, 1)`, colour
:math:`(0.5, 0.5, 1)`: light blue); an *object-space* map stores object coordinates directly.

**Displacement mapping** really moves the points: the silhouette and self-occlusion change,
which bump and normal maps cannot do.

Height maps use the texture conventions of :mod:`course_lib.texturing` (row 0 is
:math:`v = 0`, texel centres at :math:`((j+\tfrac12)/W, (i+\tfrac12)/H)`).
"""

import numpy as np

from .._validate import as_array, as_choice, as_points, as_positive, as_whole
from ._common import WRAP_MODES, _dot, _wrap
from .sampling import bilinear_sample, uv_grid

__all__ = ["bricks_height", "bump_normal", "bump_normal_tangent", "bumps_height",
    "decode_normals", "displace", "encode_normals", "height_gradient", "height_gradient_at",
    "noise_height", "normal_map_from_height", "object_to_tangent", "shade_normals",
    "tangent_to_object", "triangle_tangent_frame", "vertex_tangent_frames"]


# ---------------------------------------------------------------------------------------------
# Checks
# ---------------------------------------------------------------------------------------------

def _height(height, name="height"):
    h = as_array(height, name)
    if h.ndim != 2:
        raise ValueError(f"{name} must be a 2D height map (H, W), got shape {h.shape}")
    if min(h.shape) < 2:
        raise ValueError(f"{name} must have at least 2 rows and 2 columns, got shape {h.shape}")
    return h


def _vectors(value, name):
    return as_points(value, name, dims=3)


def _normalize(v, name):
    length = np.sqrt(_dot(v, v))
    if np.any(length < 1e-300):
        raise ValueError(f"{name} must not contain zero vectors: they have no direction")
    return v / length[..., None]


def _size(size):
    if np.ndim(size) == 0:
        n = as_whole(size, "size", 2)
        return n, n
    if len(size) != 2:
        raise ValueError(f"size must be an int or (H, W), got {size!r}")
    return as_whole(size[0], "size", 2), as_whole(size[1], "size", 2)


# ---------------------------------------------------------------------------------------------
# Height-field derivatives
# ---------------------------------------------------------------------------------------------

def height_gradient(height, wrap="repeat"):
    r"""The partial derivatives :math:`h_u, h_v` of a height map at its texel centres.

    Central differences in texture units: neighbouring texel centres are :math:`1/W` apart in
    :math:`u` and :math:`1/H` in :math:`v`, so

    .. math:: h_u[i, j] = \frac{h[i, j+1] - h[i, j-1]}{2/W}, \qquad
              h_v[i, j] = \frac{h[i+1, j] - h[i-1, j]}{2/H}

    with the neighbours' indices wrapped by `wrap` (as :func:`bilinear_sample`). With
    ``"clamp"`` an edge texel's missing neighbour is itself, and the difference is divided by
    the true distance :math:`1/W` (a one-sided difference); with ``"mirror"`` the edge is a
    mirror, so the slope across it is halved.

    Parameters
    ----------
    height : array_like, shape (H, W)
    wrap : {"repeat", "clamp", "mirror"}

    Returns
    -------
    h_u, h_v : ndarray, shape (H, W)
        Height per unit of u and per unit of v.

    Raises
    ------
    ValueError
        For a height map that is not 2D (at least 2 x 2), non-finite values or an unknown wrap.

    Examples
    --------
    A ramp h = u sampled at the texel centres of a 4-texel-wide map has slope 1:

    >>> h = np.tile((np.arange(4) + 0.5) / 4, (2, 1))
    >>> h_u, h_v = height_gradient(h, wrap="clamp")
    >>> h_u[0], h_v[0]
    (array([1., 1., 1., 1.]), array([0., 0., 0., 0.]))
    """
    h = _height(height)
    wrap = as_choice(wrap, "wrap", WRAP_MODES)
    rows, cols = h.shape
    j = np.arange(cols)
    i = np.arange(rows)
    jp, jm = _wrap(j + 1, cols, wrap), _wrap(j - 1, cols, wrap)
    ip, im = _wrap(i + 1, rows, wrap), _wrap(i - 1, rows, wrap)
    du = (jp - jm if wrap == "clamp" else np.full(cols, 2)) / cols
    dv = (ip - im if wrap == "clamp" else np.full(rows, 2)) / rows
    h_u = (h[:, jp] - h[:, jm]) / du
    h_v = (h[ip, :] - h[im, :]) / dv[:, None]
    return h_u, h_v


def height_gradient_at(height, u, v, wrap="repeat"):
    r"""The derivatives :math:`h_u, h_v` at texture coordinates (u, v): bilinear samples of
    :func:`height_gradient`.

    Parameters
    ----------
    height : array_like, shape (H, W)
    u, v : array_like
    wrap : {"repeat", "clamp", "mirror"}

    Returns
    -------
    h_u, h_v : ndarray, shape ``broadcast(u, v).shape``

    Examples
    --------
    >>> h = np.tile((np.arange(4) + 0.5) / 4, (2, 1))
    >>> height_gradient_at(h, [0.3, 0.6], [0.5, 0.5], wrap="clamp")
    (array([1., 1.]), array([0., 0.]))
    """
    h_u, h_v = height_gradient(height, wrap)
    return bilinear_sample(h_u, u, v, wrap), bilinear_sample(h_v, u, v, wrap)


# ---------------------------------------------------------------------------------------------
# Bump mapping
# ---------------------------------------------------------------------------------------------

def bump_normal(p_u, p_v, h_u, h_v, normalize=True):
    r"""Blinn's perturbed normal of a bump-mapped surface.

    .. math:: N = P_u \times P_v, \qquad
              N' = N + \frac{h_u (N \times P_v) - h_v (N \times P_u)}{|N|}

    (derived in the module docstring; heights along :math:`+N`). Vectorised over points.

    Parameters
    ----------
    p_u, p_v : array_like, shape (..., 3)
        The surface's tangents :math:`\partial P/\partial u`, :math:`\partial P/\partial v`.
    h_u, h_v : array_like, shape (...)
        The height map's derivatives (world height per unit of u and v), already scaled by
        the bump strength.
    normalize : bool
        Return :math:`N'/|N'|` (default) or the unnormalised :math:`N'` (its length is
        :math:`|P'_u \times P'_v|` to first order).

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For parallel (or zero) tangents, non-finite input, or shapes that do not broadcast.

    Examples
    --------
    A unit plane, slope 0.5 along u: the normal tilts back against the slope:

    >>> bump_normal([1, 0, 0], [0, 1, 0], 0.5, 0.0, normalize=False)
    array([-0.5,  0. ,  1. ])
    """
    pu, pv = _vectors(p_u, "p_u"), _vectors(p_v, "p_v")
    hu, hv = as_array(h_u, "h_u"), as_array(h_v, "h_v")
    try:
        pu, pv = np.broadcast_arrays(pu, pv)
        hu, hv = np.broadcast_arrays(hu, hv, np.empty(pu.shape[:-1]))[:2]
    except ValueError:
        raise ValueError(f"p_u, p_v (shapes {pu.shape}, {pv.shape}) and h_u, h_v (shapes "
                         f"{np.shape(h_u)}, {np.shape(h_v)}) must broadcast") from None
    n = np.cross(pu, pv)
    length = np.sqrt(_dot(n, n))
    scale = np.sqrt(_dot(pu, pu) * _dot(pv, pv))
    if np.any(length <= 1e-12 * np.maximum(scale, 1e-300)):
        raise ValueError("p_u and p_v must not be parallel or zero: the surface has no normal")
    bent = n + (hu[..., None] * np.cross(n, pv) - hv[..., None] * np.cross(n, pu)) \
        / length[..., None]
    return bent / np.sqrt(_dot(bent, bent))[..., None] if normalize else bent


def bump_normal_tangent(normal, tangent, bitangent, h_u, h_v, normalize=True):
    r"""The tangent-frame simplification of bump mapping: :math:`N' \propto N - h_u T - h_v B`.

    Equal to :func:`bump_normal` (normalised) when :math:`T = P_u`, :math:`B = P_v` are
    orthonormal and :math:`N = T \times B`; for orthogonal tangents of other lengths pass
    :math:`h_u/|P_u|`, :math:`h_v/|P_v|`. The frame is used as given (not normalised).

    Parameters
    ----------
    normal, tangent, bitangent : array_like, shape (..., 3)
    h_u, h_v : array_like, shape (...)
    normalize : bool

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> bump_normal_tangent([0, 0, 1], [1, 0, 0], [0, 1, 0], 0.5, 0.0, normalize=False)
    array([-0.5,  0. ,  1. ])
    """
    n, t, b = (_vectors(x, name) for x, name in
               ((normal, "normal"), (tangent, "tangent"), (bitangent, "bitangent")))
    hu, hv = as_array(h_u, "h_u"), as_array(h_v, "h_v")
    bent = n - hu[..., None] * t - hv[..., None] * b
    return _normalize(bent, "the perturbed normal") if normalize else bent


# ---------------------------------------------------------------------------------------------
# Tangent frames
# ---------------------------------------------------------------------------------------------

def triangle_tangent_frame(positions, uvs):
    r"""The tangent frame (T, B, N) of triangles from their corners and texture coordinates.

    With edges :math:`E_1 = P_1 - P_0`, :math:`E_2 = P_2 - P_0` and their texture-space
    differences :math:`(\Delta u_k, \Delta v_k)`, the linear map
    :math:`P = P_0 + (u - u_0) T + (v - v_0) B` on the triangle gives

    .. math:: \begin{bmatrix} E_1 \\ E_2 \end{bmatrix} =
              \begin{bmatrix} \Delta u_1 & \Delta v_1 \\ \Delta u_2 & \Delta v_2\end{bmatrix}
              \begin{bmatrix} T \\ B \end{bmatrix}
              \;\Rightarrow\;
              T = \frac{\Delta v_2 E_1 - \Delta v_1 E_2}{d}, \quad
              B = \frac{\Delta u_1 E_2 - \Delta u_2 E_1}{d}

    with :math:`d = \Delta u_1 \Delta v_2 - \Delta u_2 \Delta v_1` (twice the signed area of
    the triangle in texture space). T and B are :math:`\partial P/\partial u` and
    :math:`\partial P/\partial v` (not normalised, not necessarily orthogonal);
    :math:`N = E_1 \times E_2 / |E_1 \times E_2|`.

    Parameters
    ----------
    positions : array_like, shape (..., 3, 3)
        The corners :math:`P_0, P_1, P_2`.
    uvs : array_like, shape (..., 3, 2)
        Their texture coordinates.

    Returns
    -------
    T, B, N : ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For zero texture-space area (d = 0: the (u, v) of the corners are collinear, there is
        no inverse), zero area in space, or non-finite input.

    Examples
    --------
    >>> T, B, N = triangle_tangent_frame([[0, 0, 0], [2, 0, 0], [0, 3, 0]],
    ...                                  [[0, 0], [1, 0], [0, 1]])
    >>> T, B, N
    (array([2., 0., 0.]), array([0., 3., 0.]), array([0., 0., 1.]))
    """
    p = as_array(positions, "positions")
    t = as_array(uvs, "uvs")
    if p.ndim < 2 or p.shape[-2:] != (3, 3):
        raise ValueError(f"positions must be triangles' corners, shape (..., 3, 3), got {p.shape}")
    if t.ndim < 2 or t.shape[-2:] != (3, 2):
        raise ValueError(f"uvs must be the corners' (u, v), shape (..., 3, 2), got {t.shape}")
    e1, e2 = p[..., 1, :] - p[..., 0, :], p[..., 2, :] - p[..., 0, :]
    d1, d2 = t[..., 1, :] - t[..., 0, :], t[..., 2, :] - t[..., 0, :]
    det = d1[..., 0] * d2[..., 1] - d2[..., 0] * d1[..., 1]
    uv_scale = np.maximum(_dot(d1, d1), _dot(d2, d2))
    if np.any(np.abs(det) <= 1e-12 * uv_scale) or np.any(uv_scale == 0):
        raise ValueError("uvs must span a triangle of nonzero area in texture space: with "
                         "collinear (u, v) the 2x2 system for T and B has no solution")
    cross = np.cross(e1, e2)
    area = np.sqrt(_dot(cross, cross))
    if np.any(area <= 1e-12 * np.maximum(_dot(e1, e1) + _dot(e2, e2), 1e-300)):
        raise ValueError("positions must span a triangle of nonzero area (collinear corners "
                         "have no normal)")
    inv = 1.0 / det[..., None]
    tangent = (d2[..., 1:2] * e1 - d1[..., 1:2] * e2) * inv
    bitangent = (d1[..., 0:1] * e2 - d2[..., 0:1] * e1) * inv
    return tangent, bitangent, cross / area[..., None]


def vertex_tangent_frames(vertices, faces, uvs, normals=None):
    r"""Per-vertex orthonormal tangent frames with a handedness sign.

    1. Per triangle, :math:`T_f, B_f` from :func:`triangle_tangent_frame`; summed at each of
       its corners weighted by the triangle's area (:math:`A_f \hat T_f`).
    2. Gram-Schmidt against the vertex normal:
       :math:`T = \operatorname{normalize}(T_\Sigma - (N \cdot T_\Sigma) N)`.
    3. Handedness :math:`w = \operatorname{sign}((N \times T) \cdot B_\Sigma)` (-1 where the
       texture is mirrored) and :math:`B = w\, (N \times T)`.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    uvs : array_like, shape (n, 2)
    normals : array_like, shape (n, 3), optional
        Vertex normals (default: :func:`course_lib.shading.vertex_normals`).

    Returns
    -------
    T, B, N : ndarray, shape (n, 3)
        Orthonormal per vertex.
    w : ndarray, shape (n,)
        +1 or -1.

    Raises
    ------
    ValueError
        For a face with zero (u, v) area or zero area (naming the face), or bad shapes.

    Examples
    --------
    >>> T, B, N, w = vertex_tangent_frames([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]],
    ...                                    [[0, 0], [0, 1], [1, 0]])   # mirrored: u along y
    >>> T[0], B[0] + 0.0, float(w[0])
    (array([0., 1., 0.]), array([1., 0., 0.]), -1.0)
    """
    from .._validate import as_mesh
    from ..shading import vertex_normals

    v, f = as_mesh(vertices, faces)
    t = as_array(uvs, "uvs")
    if t.shape != (len(v), 2):
        raise ValueError(f"uvs must have one (u, v) per vertex, shape ({len(v)}, 2), got "
                         f"{t.shape}")
    try:
        tf, bf, nf = triangle_tangent_frame(v[f], t[f])
    except ValueError as error:
        bad = _first_bad_face(v[f], t[f])
        raise ValueError(f"faces[{bad}]: {error}") from None
    area = 0.5 * np.sqrt(_dot(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]),
                              np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])))
    tu = tf / np.sqrt(_dot(tf, tf))[:, None] * area[:, None]
    bu = bf / np.sqrt(_dot(bf, bf))[:, None] * area[:, None]
    corners = f.ravel()                         # every face's weight to each of its corners
    t_sum = np.stack([np.bincount(corners, np.repeat(tu[:, c], 3), len(v)) for c in range(3)], 1)
    b_sum = np.stack([np.bincount(corners, np.repeat(bu[:, c], 3), len(v)) for c in range(3)], 1)
    n = vertex_normals(v, f) if normals is None else _normalize(
        as_points(normals, "normals", dims=3), "normals")
    if n.shape != v.shape:
        raise ValueError(f"normals must be one per vertex, shape {v.shape}, got {n.shape}")
    tt = t_sum - _dot(n, t_sum)[:, None] * n
    tt = _normalize(tt, "the averaged tangents (a vertex in no face, or T parallel to N)")
    nxt = np.cross(n, tt)
    w = np.where(_dot(nxt, b_sum) < 0, -1.0, 1.0)
    return tt, w[:, None] * nxt, n, w


def _first_bad_face(p, t):
    for k in range(len(p)):
        try:
            triangle_tangent_frame(p[k], t[k])
        except ValueError:
            return k
    return -1  # pragma: no cover


# ---------------------------------------------------------------------------------------------
# Normal maps
# ---------------------------------------------------------------------------------------------

def encode_normals(normals, bits=None):
    r"""Normals to colours: :math:`c = (n + 1)/2` per channel (normals normalised first).

    Parameters
    ----------
    normals : array_like, shape (..., 3)
    bits : None or 8
        None: float colours in [0, 1]; 8: ``uint8`` texels :math:`\operatorname{round}(255 c)`.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> encode_normals([0, 0, 1])
    array([0.5, 0.5, 1. ])
    >>> encode_normals([0, 0, 1], bits=8)
    array([128, 128, 255], dtype=uint8)
    """
    n = _normalize(_vectors(normals, "normals"), "normals")
    if bits is not None and bits != 8:
        raise ValueError(f"bits must be None (float colours) or 8, got {bits!r}")
    c = 0.5 * n + 0.5
    return c if bits is None else np.round(255.0 * c).astype(np.uint8)


def decode_normals(colors):
    r"""Colours back to unit normals: :math:`n = \operatorname{normalize}(2c - 1)`.

    Integer arrays are read as 8-bit texels (:math:`c = \text{texel}/255`), float arrays as
    colours in [0, 1]. The renormalisation undoes the rounding error of 8-bit storage.

    Parameters
    ----------
    colors : array_like, shape (..., 3)

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For colours outside [0, 1] (0..255 for integers) or the colour (0.5, 0.5, 0.5),
        which decodes to the zero vector.

    Examples
    --------
    >>> decode_normals(np.array([128, 128, 255], dtype=np.uint8)).round(4)
    array([0.0039, 0.0039, 1.    ])
    """
    integer = np.issubdtype(np.asarray(colors).dtype, np.integer)
    c = _vectors(colors, "colors")
    top = 255.0 if integer else 1.0
    if np.any(c < 0) or np.any(c > top):
        raise ValueError(f"colors must lie in [0, {top:g}], got values from {c.min():g} to "
                         f"{c.max():g}")
    return _normalize(2.0 * c / top - 1.0, "the decoded colors (grey 0.5 has no direction)")


def tangent_to_object(n_tangent, tangent, bitangent, normal):
    r"""A tangent-space normal to object space: :math:`n = n_x T + n_y B + n_z N`, normalised.

    That is :math:`n = M\,n_t` with the TBN matrix :math:`M = [T\;B\;N]` (columns).

    Parameters
    ----------
    n_tangent, tangent, bitangent, normal : array_like, shape (..., 3)

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> tangent_to_object([0, 0, 1], [1, 0, 0], [0, 0, -1], [0, 1, 0])   # floor, N = +y
    array([0., 1., 0.])
    """
    nt = _vectors(n_tangent, "n_tangent")
    t, b, n = (_vectors(x, name) for x, name in
               ((tangent, "tangent"), (bitangent, "bitangent"), (normal, "normal")))
    out = nt[..., 0:1] * t + nt[..., 1:2] * b + nt[..., 2:3] * n
    return _normalize(out, "the transformed normal (T, B, N must not be degenerate)")


def object_to_tangent(n_object, tangent, bitangent, normal):
    r"""An object-space normal into the tangent frame: :math:`n_t = M^{-1} n`, normalised.

    For an orthonormal frame :math:`M^{-1} = M^T`, i.e. :math:`n_t = (n\cdot T, n \cdot B,
    n \cdot N)`; the general inverse is used so that any non-degenerate frame round-trips.

    Examples
    --------
    >>> object_to_tangent([0, 1, 0], [1, 0, 0], [0, 0, -1], [0, 1, 0]) + 0.0
    array([0., 0., 1.])
    """
    no = _vectors(n_object, "n_object")
    t, b, n = (_vectors(x, name) for x, name in
               ((tangent, "tangent"), (bitangent, "bitangent"), (normal, "normal")))
    t, b, n, no = np.broadcast_arrays(t, b, n, no)
    m = np.stack([t, b, n], axis=-1)
    det = np.linalg.det(m)
    if np.any(np.abs(det) < 1e-12):
        raise ValueError("tangent, bitangent and normal must be linearly independent (the TBN "
                         "matrix is singular)")
    return _normalize(np.linalg.solve(m, no[..., None])[..., 0], "the transformed normal")


def normal_map_from_height(height, strength=1.0, extent=(1.0, 1.0), wrap="repeat"):
    r"""A tangent-space normal map (float colours) from a height map.

    The bump normal of a surface whose texture square covers `extent` = :math:`(s_u, s_v)`
    world units along orthonormal T, B, with world height :math:`k\,h`:

    .. math:: n_t = \operatorname{normalize}\left(-\frac{k\,h_u}{s_u},\; -\frac{k\,h_v}{s_v},
              \; 1\right), \qquad c = \frac{n_t + 1}{2}

    Examples
    --------
    >>> normal_map_from_height(np.zeros((2, 2)))[0, 0]
    array([0.5, 0.5, 1. ])
    """
    k = as_array(strength, "strength")
    s = as_array(extent, "extent")
    if s.shape != (2,) or np.any(s <= 0):
        raise ValueError(f"extent must be two positive numbers (s_u, s_v), got {extent!r}")
    h_u, h_v = height_gradient(height, wrap)
    n = np.stack([-k * h_u / s[0], -k * h_v / s[1], np.ones_like(h_u)], axis=-1)
    return encode_normals(n)


# ---------------------------------------------------------------------------------------------
# Displacement
# ---------------------------------------------------------------------------------------------

def displace(points, normals, heights, strength=1.0):
    r"""Displacement mapping: move points along their unit normals, :math:`P' = P + k\,h\,n`.

    Unlike bump mapping the geometry changes: silhouettes and occlusion follow the relief.
    Recompute the normals of the moved points (e.g. from a displaced grid's differences).

    Parameters
    ----------
    points, normals : array_like, shape (..., 3)
    heights : array_like, shape (...)
    strength : float

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> displace([[1, 0, 0]], [[2, 0, 0]], [0.5], strength=0.2)
    array([[1.1, 0. , 0. ]])
    """
    p = _vectors(points, "points")
    n = _normalize(_vectors(normals, "normals"), "normals")
    h = as_array(heights, "heights")
    k = as_array(strength, "strength")
    try:
        return p + (k * h)[..., None] * n
    except ValueError:
        raise ValueError(f"points {p.shape}, normals {n.shape} and heights {h.shape} must "
                         "broadcast") from None


# ---------------------------------------------------------------------------------------------
# Shading per pixel
# ---------------------------------------------------------------------------------------------

def shade_normals(normals, light=(0.4, 0.5, 0.75), view=(0.0, 0.0, 1.0), model="lambert",
                  material=None, mask=None):
    r"""Shade an image of per-pixel normals with one directional light (via
    :func:`course_lib.shading.blinn_phong` / :func:`course_lib.shading.phong`).

    ``"lambert"`` uses :math:`k_s = 0` (ambient + diffuse only). Pixels outside `mask` are 1
    (white background).

    Parameters
    ----------
    normals : array_like, shape (H, W, 3)
    light, view : array_like, shape (3,)
        Towards the light and towards the viewer.
    model : {"lambert", "blinn-phong", "phong"}
    material : course_lib.shading.Material, optional
    mask : array_like of bool, shape (H, W), optional

    Returns
    -------
    ndarray, shape (H, W, 3), in [0, 1]

    Examples
    --------
    >>> shade_normals(np.array([[[0.0, 0.0, 1.0]]]), light=(0, 0, 1))[0, 0]
    array([0.8, 0.8, 0.8])
    """
    from .. import shading

    model = as_choice(model, "model", ("lambert", "blinn-phong", "phong"))
    n = _vectors(normals, "normals")
    if material is None:
        material = shading.Material(ka=0.1, kd=0.7, ks=0.0 if model == "lambert" else 0.3,
                                    shininess=40.0)
    elif model == "lambert":
        material = material._replace(ks=0.0)
    keep = np.ones(n.shape[:-1], bool) if mask is None else np.asarray(mask, bool)
    out = np.ones(n.shape[:-1] + (3,))
    f = shading.phong if model == "phong" else shading.blinn_phong
    lamp = shading.directional_light(light)
    if keep.any():
        out[keep] = np.clip(f(None, n[keep], np.broadcast_to(view, (int(keep.sum()), 3)),
                              lamp, material).total, 0.0, 1.0)
    return out


# ---------------------------------------------------------------------------------------------
# Height maps for demos
# ---------------------------------------------------------------------------------------------

def _texel_centres_uv(size):
    rows, cols = _size(size)
    grid = uv_grid(cols, rows)
    return grid[..., 0], grid[..., 1]


def bumps_height(size=128, count=4):
    r"""Round bumps on a grid, tiling seamlessly:
    :math:`h = \tfrac14 (1 - \cos 2\pi k u)(1 - \cos 2\pi k v) \in [0, 1]`.

    Examples
    --------
    >>> bumps_height(4, count=1).round(3)
    array([[0.021, 0.125, 0.125, 0.021],
           [0.125, 0.729, 0.729, 0.125],
           [0.125, 0.729, 0.729, 0.125],
           [0.021, 0.125, 0.125, 0.021]])
    """
    k = as_positive(count, "count")
    u, v = _texel_centres_uv(size)
    return 0.25 * (1 - np.cos(2 * np.pi * k * u)) * (1 - np.cos(2 * np.pi * k * v))


def bricks_height(size=128, rows=8, columns=4, mortar=0.08):
    r"""Bricks (height 1) in staggered rows with grooves of mortar (height 0) and bevelled
    edges (a smoothstep over the `mortar` width, in units of a brick's height).

    Examples
    --------
    >>> h = bricks_height(64, rows=2, columns=1)
    >>> float(h.max()), float(h.min())
    (1.0, 0.0)
    """
    nr, nc = as_whole(rows, "rows", 1), as_whole(columns, "columns", 1)
    m = as_positive(mortar, "mortar")
    u, v = _texel_centres_uv(size)
    y = v * nr
    row = np.floor(y)
    x = u * nc + 0.5 * (row % 2)
    fy, fx = y - row, x - np.floor(x)
    aspect = nr / nc                     # a brick's width in units of its height
    dist = np.minimum(np.minimum(fy, 1 - fy), np.minimum(fx, 1 - fx) * aspect)
    t = np.clip((dist - 0.5 * m) / m, 0, 1)
    return t * t * (3 - 2 * t)


def noise_height(size=128, frequency=6.0, octaves=3, seed=0):
    r"""Turbulent noise in [0, 1] (:func:`course_lib.texturing.turbulence`), periodic in u.

    Evaluated on the cylinder :math:`(R\cos 2\pi u, R\sin 2\pi u, f v)`,
    :math:`R = f/2\pi`, so it wraps around a sphere's seam without a jump (not in v).

    Examples
    --------
    >>> h = noise_height(32, seed=1)
    >>> h.shape, bool(0 <= h.min() < h.max() <= 1)
    ((32, 32), True)
    """
    from .procedural import turbulence

    f = as_positive(frequency, "frequency")
    u, v = _texel_centres_uv(size)
    r = f / (2 * np.pi)
    p = np.stack([r * np.cos(2 * np.pi * u), r * np.sin(2 * np.pi * u), f * v], axis=-1)
    t = turbulence(p, octaves=octaves, seed=seed)
    return (t - t.min()) / max(float(t.max() - t.min()), 1e-12)
