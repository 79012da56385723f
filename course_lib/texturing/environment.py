r"""Chapter 14 (lesson section: environment mapping): cube, sphere and latitude-longitude maps.

A mirror-like object shows its surroundings. Instead of tracing the reflected ray into the
scene, **environment mapping** looks the colour up in a texture indexed by the *direction*
of the reflected ray only:

.. math:: R = I - 2 (N \cdot I) N \qquad\text{(I: the view ray's direction, towards the
          surface)}, \qquad C = E(R)

Three ways of storing the function :math:`E` of a direction:

* the **cube map** (six square faces, OpenGL's ``GL_TEXTURE_CUBE_MAP``): the face is the
  direction's *major axis* (largest :math:`|r_i|`), and the two other components divided by
  it give :math:`(s, t)`. Faces are numbered +X, -X, +Y, -Y, +Z, -Z = 0..5 and the table of
  :func:`cube_face_coordinates` is the OpenGL specification's. **Ties** (two components of
  equal largest magnitude: a cube edge or corner) go to the first axis in the order x, y, z;
  the specification leaves this to the implementation. Both faces agree on the direction
  there (their (s, t) are on the shared edge), so the choice only matters for filtering;
* the **sphere map** (``GL_SPHERE_MAP``): the picture of a tiny mirror ball seen from far
  away along :math:`-z`, indexed by the eye-space reflection vector
  (:func:`sphere_map_coordinates`); it holds the whole sphere of directions in one disc, but
  only for *one* viewing direction, and the direction straight behind the ball,
  :math:`r = (0, 0, -1)`, is smeared over the disc's rim (a singular point);
* the **latitude-longitude** (equirectangular) map: the spherical mapping
  :func:`course_lib.texturing.spherical_map` of the direction (azimuth, elevation), with the
  pole on y: a seam and squeezed poles.

Storage: a cube map is an array ``(6, N, N)`` or ``(6, N, N, C)``; face ``f``'s row ``i``,
column ``j`` covers :math:`s \in [j/N, (j+1)/N]`, :math:`t \in [i/N, (i+1)/N]` (row 0 is
t = 0, the package's convention). Each face is filtered on its own, clamped at its edges
(the classic, non-seamless cube map).

**Limitations** (made computable here): the map is the view from *one point* (its centre):
an object displaced by :math:`d` from it, with the environment at distance :math:`R`, looks
up the wrong direction by up to :math:`\arcsin(d/R)` (:func:`distant_environment_error`);
and an object cannot reflect itself or its neighbours (they are not in the map).
"""

import numpy as np

from .._validate import as_array, as_choice, as_points, as_positive, as_vector, as_whole
from ..shading.vectors import reflect as _phong_reflect
from ._common import _dot
from .mappings import inverse_spherical_map, spherical_map
from .sampling import _blend_corners, _texel_corners, bilinear_sample

__all__ = ["CUBE_FACES", "ENVIRONMENTS", "cube_face_coordinates", "cube_face_direction",
           "cube_map_from_function", "cube_cross", "cross_position", "sample_cube_map",
           "sphere_map_coordinates", "sphere_map_direction", "sphere_map_from_function",
           "sample_sphere_map", "latlong_coordinates", "latlong_direction",
           "latlong_map_from_function", "sample_latlong_map", "reflect_view",
           "environment_lookup", "mirror_sphere", "distant_environment_error",
           "sky_environment", "room_environment", "axes_environment"]

CUBE_FACES = ("+X", "-X", "+Y", "-Y", "+Z", "-Z")

# The OpenGL table: for each face, (index of ma, (sign, index) of sc, (sign, index) of tc).
#   +X: sc = -rz, tc = -ry   -X: sc = +rz, tc = -ry
#   +Y: sc = +rx, tc = +rz   -Y: sc = +rx, tc = -rz
#   +Z: sc = +rx, tc = -ry   -Z: sc = -rx, tc = -ry
_SC = np.array([[-1, 2], [1, 2], [1, 0], [1, 0], [1, 0], [-1, 0]])
_TC = np.array([[-1, 1], [-1, 1], [1, 2], [-1, 2], [-1, 1], [-1, 1]])


# ---------------------------------------------------------------------------------------------
# Input checks
# ---------------------------------------------------------------------------------------------

def _nonzero_directions(value, name):
    d = as_points(value, name, dims=3)
    n2 = _dot(d, d)
    if np.any(n2 == 0):
        raise ValueError(f"{name} must not contain zero vectors: a zero vector has no direction")
    return d


def _cube_array(cube, name="cube"):
    c = as_array(cube, name)
    if c.ndim not in (3, 4) or c.shape[0] != 6:
        raise ValueError(f"{name} must have 6 faces (+X, -X, +Y, -Y, +Z, -Z) in an array "
                         f"(6, N, N) or (6, N, N, C), got shape {c.shape}")
    if c.shape[1] != c.shape[2]:
        raise ValueError(f"{name}'s faces must be square (N x N), got {c.shape[1]} x "
                         f"{c.shape[2]}")
    if c.shape[1] == 0:
        raise ValueError(f"{name} must not be empty")
    return c


def _face_index(face):
    f = as_array(face, "face")
    if np.any(f != np.round(f)) or np.any((f < 0) | (f > 5)):
        raise ValueError("face must be whole numbers 0..5 (+X, -X, +Y, -Y, +Z, -Z)")
    return f.astype(np.int64)


# ---------------------------------------------------------------------------------------------
# Cube maps
# ---------------------------------------------------------------------------------------------

def cube_face_coordinates(directions):
    r"""The cube-map face and :math:`(s, t)` of directions (the OpenGL specification's table).

    The major axis is the component of largest magnitude (ties: x before y before z); with
    its value :math:`m_a` and the face's :math:`s_c, t_c`

    ====  ======  ======  =========
    face  s_c     t_c     m_a
    ====  ======  ======  =========
    +X    -r_z    -r_y    r_x
    -X    +r_z    -r_y    r_x
    +Y    +r_x    +r_z    r_y
    -Y    +r_x    -r_z    r_y
    +Z    +r_x    -r_y    r_z
    -Z    -r_x    -r_y    r_z
    ====  ======  ======  =========

    .. math:: s = \tfrac12\left(\frac{s_c}{|m_a|} + 1\right), \qquad
              t = \tfrac12\left(\frac{t_c}{|m_a|} + 1\right)

    Parameters
    ----------
    directions : array_like, shape (..., 3)
        Not zero; need not be unit vectors.

    Returns
    -------
    face : ndarray of int, shape (...)
        0..5 for +X, -X, +Y, -Y, +Z, -Z.
    s, t : ndarray, shape (...)
        In [0, 1].

    Raises
    ------
    ValueError
        For zero vectors, NaN or infinite values, or a last axis that is not 3.

    Examples
    --------
    >>> face, s, t = cube_face_coordinates([[1, 0.5, 0], [0, 0, -2]])
    >>> face, s, t
    (array([0, 5]), array([0.5, 0.5]), array([0.25, 0.5 ]))
    """
    d = _nonzero_directions(directions, "directions")
    a = np.abs(d)
    axis = np.where((a[..., 0] >= a[..., 1]) & (a[..., 0] >= a[..., 2]), 0,
                    np.where(a[..., 1] >= a[..., 2], 1, 2))
    ma = np.take_along_axis(d, axis[..., None], -1)[..., 0]
    face = 2 * axis + (ma < 0)
    sc = _SC[face, 0] * np.take_along_axis(d, _SC[face, 1][..., None], -1)[..., 0]
    tc = _TC[face, 0] * np.take_along_axis(d, _TC[face, 1][..., None], -1)[..., 0]
    am = np.abs(ma)
    return face, 0.5 * (sc / am + 1.0), 0.5 * (tc / am + 1.0)


def cube_face_direction(face, s, t):
    r"""The direction (on the cube :math:`|m_a| = 1`) of face `face` at :math:`(s, t)`.

    The inverse of :func:`cube_face_coordinates`: :math:`s_c = 2s - 1`, :math:`t_c = 2t - 1`,
    :math:`m_a = \pm 1`, and the table solved for :math:`r`. Normalize the result for a unit
    direction.

    Parameters
    ----------
    face : int or array_like of int
        0..5 (+X, -X, +Y, -Y, +Z, -Z).
    s, t : array_like
        Broadcast with `face`.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> cube_face_direction(0, 0.5, 0.25)
    array([ 1. ,  0.5, -0. ])
    >>> cube_face_direction([2, 5], [1.0, 0.5], [0.5, 0.5])
    array([[ 1.,  1.,  0.],
           [-0., -0., -1.]])
    """
    f = _face_index(face)
    s, t = as_array(s, "s"), as_array(t, "t")
    try:
        f, s, t = np.broadcast_arrays(f, s, t)
    except ValueError:
        raise ValueError(f"face, s and t must broadcast together, got shapes {f.shape}, "
                         f"{s.shape} and {t.shape}") from None
    sc, tc = 2 * s - 1, 2 * t - 1
    d = np.zeros(f.shape + (3,))
    axis, sign = f // 2, np.where(f % 2 == 0, 1.0, -1.0)
    np.put_along_axis(d, axis[..., None], sign[..., None], -1)
    np.put_along_axis(d, _SC[f, 1][..., None], (_SC[f, 0] * sc)[..., None], -1)
    np.put_along_axis(d, _TC[f, 1][..., None], (_TC[f, 0] * tc)[..., None], -1)
    return d


def _texel_centres(n):
    return (np.arange(n) + 0.5) / n


def cube_map_from_function(environment, size=32):
    """A cube map ``(6, N, N, C)`` of the environment function sampled at the texel centres.

    Parameters
    ----------
    environment : callable
        Unit directions ``(..., 3)`` -> colours ``(..., C)`` (e.g. :func:`sky_environment`).
    size : int
        N, the faces' side in texels.

    Returns
    -------
    ndarray, shape (6, N, N, C)

    Examples
    --------
    >>> cube = cube_map_from_function(axes_environment, 4)
    >>> cube.shape, cube[0, 2, 2].round(3)     # the +X face is reddish
    ((6, 4, 4, 3), array([0.924, 0.394, 0.394]))
    """
    if not callable(environment):
        raise TypeError(f"environment must be a function of directions, got "
                        f"{type(environment).__name__}")
    n = as_whole(size, "size", 1)
    c = _texel_centres(n)
    t, s = np.meshgrid(c, c, indexing="ij")                  # row i is t, column j is s
    f = np.arange(6)[:, None, None]
    d = cube_face_direction(f, s[None], t[None])
    d = d / np.sqrt(_dot(d, d))[..., None]
    return np.asarray(environment(d), dtype=float)


def sample_cube_map(cube, directions, filter="bilinear"):
    r"""Look a cube map up by direction: face and (s, t), then a nearest or bilinear sample.

    Bilinear filtering is done within the face, its texel indices clamped to the face
    (``GL_CLAMP_TO_EDGE``): near a cube edge the four texels come from one face only, not
    from the neighbouring one as a *seamless* cube map would blend.

    Parameters
    ----------
    cube : array_like, shape (6, N, N) or (6, N, N, C)
    directions : array_like, shape (..., 3)
    filter : {"bilinear", "nearest"}

    Returns
    -------
    ndarray, shape (...) or (..., C)

    Raises
    ------
    ValueError
        For a cube that has not six square faces, zero or non-finite directions, an unknown
        filter.

    Examples
    --------
    >>> cube = np.arange(6.0)[:, None, None] * np.ones((6, 2, 2))   # face f holds f
    >>> sample_cube_map(cube, [[1, 0, 0], [0, -1, 0], [0.1, 0.2, -1]])
    array([0., 3., 5.])
    """
    c = _cube_array(cube)
    filter = as_choice(filter, "filter", ("bilinear", "nearest"))
    face, s, t = cube_face_coordinates(directions)
    n = c.shape[1]
    flat = c.reshape((6 * n * n,) + c.shape[3:])
    base = face * (n * n)
    if filter == "nearest":
        j = np.minimum((s * n).astype(np.int64), n - 1)
        i = np.minimum((t * n).astype(np.int64), n - 1)
        return flat.take(base + i * n + j, axis=0)
    i0, i1, j0, j1, a, b = _texel_corners(s * n - 0.5, t * n - 0.5, n, n, "clamp")
    return _blend_corners(flat, base + i0 * n, base + i1 * n, j0, j1, a, b)


# The unfolded cross, seen from inside the cube looking at -Z with +Y up: each cell's
# (column, row from the bottom) of a 4 x 3 grid and the matrix taking (a, b, 1) (a to the
# right, b up, in [-1, 1]) to the direction.
_CROSS = {
    1: ((0, 1), np.array([[0, 0, -1], [0, 1, 0], [-1, 0, 0]])),    # -X, left
    5: ((1, 1), np.array([[1, 0, 0], [0, 1, 0], [0, 0, -1]])),     # -Z, front
    0: ((2, 1), np.array([[0, 0, 1], [0, 1, 0], [1, 0, 0]])),      # +X, right
    4: ((3, 1), np.array([[-1, 0, 0], [0, 1, 0], [0, 0, 1]])),     # +Z, back
    2: ((1, 2), np.array([[1, 0, 0], [0, 0, 1], [0, 1, 0]])),      # +Y, above the front
    3: ((1, 0), np.array([[1, 0, 0], [0, 0, -1], [0, -1, 0]])),    # -Y, below the front
}


def _cross_matrix(face):
    return _CROSS[face][1].astype(float).T                          # rows -> d = M (a, b, 1)


def cube_cross(cube, cell=None, background=1.0):
    """The cube map unfolded as a horizontal cross, for display (``origin="lower"``).

    The cells are the faces as seen from inside the cube looking along -Z with +Y up:
    -X, -Z, +X, +Z left to right in the middle row, +Y above and -Y below -Z, so that the
    picture is continuous across every fold. (The stored faces' (s, t) axes follow the
    OpenGL table, which mirrors some of them relative to this view.)

    Parameters
    ----------
    cube : array_like, shape (6, N, N) or (6, N, N, C)
    cell : int, optional
        Pixels per cell side (default N); the cells are resampled (nearest) by direction.
    background : float
        The value outside the cross.

    Returns
    -------
    ndarray, shape (3 cell, 4 cell) or (3 cell, 4 cell, C)
        Row 0 is the bottom.

    Examples
    --------
    >>> cube = np.arange(6.0)[:, None, None] * np.ones((6, 1, 1))
    >>> cube_cross(cube, background=-1)
    array([[-1.,  3., -1., -1.],
           [ 1.,  5.,  0.,  4.],
           [-1.,  2., -1., -1.]])
    """
    c = _cube_array(cube)
    n = c.shape[1] if cell is None else as_whole(cell, "cell", 1)
    g = 2 * _texel_centres(n) - 1
    b, a = np.meshgrid(g, g, indexing="ij")
    abc = np.stack([a, b, np.ones_like(a)], -1)
    out = np.full((3 * n, 4 * n) + c.shape[3:], float(background))
    for face, ((col, row), _) in _CROSS.items():
        d = abc @ _cross_matrix(face).T
        out[row * n:(row + 1) * n, col * n:(col + 1) * n] = sample_cube_map(c, d, "nearest")
    return out


def cross_position(directions):
    """Where directions land in :func:`cube_cross`'s picture, in cell units (x, y).

    The cross spans x in [0, 4], y in [0, 3]; multiply by the cell size for pixels.

    Examples
    --------
    >>> cross_position([[0, 0, -1], [1, 0, 0], [0, 1, 0]])
    array([[1.5, 1.5],
           [2.5, 1.5],
           [1.5, 2.5]])
    """
    d = _nonzero_directions(directions, "directions")
    face = cube_face_coordinates(d)[0]
    out = np.zeros(d.shape[:-1] + (2,))
    for f, ((col, row), _) in _CROSS.items():
        m = face == f
        if np.any(m):
            abk = d[m] @ np.linalg.inv(_cross_matrix(f)).T
            ab = abk[:, :2] / abk[:, 2:]
            out[m] = np.stack([col + (ab[:, 0] + 1) / 2, row + (ab[:, 1] + 1) / 2], -1)
    return out


# ---------------------------------------------------------------------------------------------
# Sphere maps
# ---------------------------------------------------------------------------------------------

def sphere_map_coordinates(reflection):
    r"""OpenGL's ``GL_SPHERE_MAP`` coordinates of eye-space reflection vectors.

    .. math:: m = 2\sqrt{r_x^2 + r_y^2 + (r_z + 1)^2}, \qquad s = \frac{r_x}{m} + \tfrac12,
              \qquad t = \frac{r_y}{m} + \tfrac12

    for a *unit* :math:`r` (normalized here). :math:`(s, t)` is where a mirror ball, seen
    orthographically along :math:`-z`, shows that direction: its normal there is the halfway
    vector of :math:`r` and the direction to the eye :math:`(0, 0, 1)`, i.e.
    :math:`(r + \hat z)/\lVert r + \hat z \rVert` and :math:`m = 2\lVert r + \hat z\rVert`.
    The singular direction :math:`r = (0, 0, -1)` (straight away from the viewer) has
    :math:`m = 0`: every point of the rim shows it; it is returned as the rim point
    :math:`(s, t) = (1, \tfrac12)` by convention.

    Parameters
    ----------
    reflection : array_like, shape (..., 3)
        Eye-space reflection vectors, not zero.

    Returns
    -------
    s, t : ndarray, shape (...)
        In [0, 1], inside the disc :math:`(s - \tfrac12)^2 + (t - \tfrac12)^2 \le \tfrac14`.

    Examples
    --------
    >>> s, t = sphere_map_coordinates([[0, 0, 1], [1, 0, 0], [0, 0, -1]])
    >>> s.round(4), t.round(4)
    (array([0.5   , 0.8536, 1.    ]), array([0.5, 0.5, 0.5]))
    """
    r = _nonzero_directions(reflection, "reflection")
    r = r / np.sqrt(_dot(r, r))[..., None]
    m = 2 * np.sqrt(r[..., 0] ** 2 + r[..., 1] ** 2 + (r[..., 2] + 1) ** 2)
    singular = m < 1e-12
    m = np.where(singular, 1.0, m)
    s = np.where(singular, 1.0, r[..., 0] / m + 0.5)
    t = np.where(singular, 0.5, r[..., 1] / m + 0.5)
    return s, t


def sphere_map_direction(s, t):
    r"""The eye-space direction shown at :math:`(s, t)` of a sphere map (the inverse).

    With :math:`x = 2s - 1`, :math:`y = 2t - 1` (inside the unit disc) the ball's normal is
    :math:`n = (x, y, \sqrt{1 - x^2 - y^2})` and the view ray :math:`(0, 0, -1)` reflects to

    .. math:: r = (2 n_z x,\ 2 n_z y,\ 2 n_z^2 - 1)

    Raises
    ------
    ValueError
        For (s, t) outside the disc (beyond a small tolerance) or non-finite values.

    Examples
    --------
    >>> sphere_map_direction([0.5, 1.0], [0.5, 0.5])
    array([[ 0.,  0.,  1.],
           [ 0.,  0., -1.]])
    """
    s, t = as_array(s, "s"), as_array(t, "t")
    try:
        s, t = np.broadcast_arrays(s, t)
    except ValueError:
        raise ValueError(f"s and t must broadcast together, got {s.shape} and {t.shape}") from None
    x, y = 2 * s - 1, 2 * t - 1
    rho2 = x * x + y * y
    if np.any(rho2 > 1 + 1e-9):
        raise ValueError("s and t must lie in the sphere map's disc (s - 1/2)^2 + (t - 1/2)^2 "
                         "<= 1/4")
    nz = np.sqrt(np.clip(1 - rho2, 0, 1))
    return np.stack([2 * nz * x, 2 * nz * y, 2 * nz * nz - 1], -1)


def sphere_map_from_function(environment, size=64, view=None, background=0.0):
    """A sphere map ``(N, N, C)`` of the environment (texels outside the disc = background).

    Parameters
    ----------
    environment : callable
        Unit directions -> colours.
    size : int
    view : array_like, shape (3, 3), optional
        The rotation from eye space to the environment's (world) space (default: identity,
        the viewer looks along the world's -z). A sphere map is only right for this view.
    background : float

    Examples
    --------
    >>> m = sphere_map_from_function(axes_environment, 8)
    >>> m.shape, m[0, 0]                    # a corner, outside the disc
    ((8, 8, 3), array([0., 0., 0.]))
    """
    if not callable(environment):
        raise TypeError(f"environment must be a function of directions, got "
                        f"{type(environment).__name__}")
    n = as_whole(size, "size", 1)
    c = _texel_centres(n)
    t, s = np.meshgrid(c, c, indexing="ij")
    inside = (2 * s - 1) ** 2 + (2 * t - 1) ** 2 <= 1
    d = sphere_map_direction(np.where(inside, s, 0.5), np.where(inside, t, 0.5))
    if view is not None:
        d = d @ _rotation(view).T
    col = np.asarray(environment(d), dtype=float)
    mask = inside.reshape(inside.shape + (1,) * (col.ndim - 2))
    return np.where(mask, col, float(background))


def _rotation(view):
    m = as_array(view, "view")
    if m.shape != (3, 3):
        raise ValueError(f"view must be a 3x3 rotation matrix, got shape {m.shape}")
    return m


def _image(tex, name):
    m = as_array(tex, name)
    if m.ndim not in (2, 3) or 0 in m.shape[:2]:
        raise ValueError(f"{name} must be an image (H, W) or (H, W, C), got shape {m.shape}")
    return m


def sample_sphere_map(sphere_map, reflection, view=None):
    """Bilinear look-up of a sphere map by world-space reflection vectors.

    `view` is the rotation the map was made with (:func:`sphere_map_from_function`); the
    directions are taken to its eye space first (:math:`r_{eye} = V^T r`).

    Examples
    --------
    >>> m = sphere_map_from_function(axes_environment, 64)
    >>> sample_sphere_map(m, [[0, 0, 1]]).round(2)      # +z (back at the eye) is bluish
    array([[0.5 , 0.5 , 0.95]])
    """
    m = _image(sphere_map, "sphere_map")
    r = _nonzero_directions(reflection, "reflection")
    if view is not None:
        r = r @ _rotation(view)
    s, t = sphere_map_coordinates(r)
    return bilinear_sample(m, s, t, "clamp")


# ---------------------------------------------------------------------------------------------
# Latitude-longitude maps
# ---------------------------------------------------------------------------------------------

def latlong_coordinates(directions):
    r"""The latitude-longitude (equirectangular) coordinates of directions.

    :func:`course_lib.texturing.spherical_map` of the direction: pole on +y, u from the azimuth
    :math:`\operatorname{atan2}(r_x, r_z)`, v from the elevation.

    Examples
    --------
    >>> latlong_coordinates([[0, 0, 1], [0, 1, 0]])
    (array([0.5, 0.5]), array([0.5, 1. ]))
    """
    return spherical_map(_nonzero_directions(directions, "directions"))


def latlong_direction(u, v):
    """The unit direction at (u, v) of a latitude-longitude map (the inverse).

    Examples
    --------
    >>> np.round(latlong_direction(0.75, 0.5), 12)
    array([1., 0., 0.])
    """
    return inverse_spherical_map(u, v)


def latlong_map_from_function(environment, height=32):
    """A latitude-longitude map ``(H, 2H, C)`` of the environment at its texel centres.

    Examples
    --------
    >>> latlong_map_from_function(axes_environment, 4).shape
    (4, 8, 3)
    """
    if not callable(environment):
        raise TypeError(f"environment must be a function of directions, got "
                        f"{type(environment).__name__}")
    h = as_whole(height, "height", 1)
    v, u = np.meshgrid(_texel_centres(h), _texel_centres(2 * h), indexing="ij")
    return np.asarray(environment(latlong_direction(u, v)), dtype=float)


def sample_latlong_map(latlong, directions):
    """Bilinear look-up of a latitude-longitude map: wrapped across the seam, clamped at the
    poles.

    Examples
    --------
    >>> m = latlong_map_from_function(axes_environment, 32)
    >>> sample_latlong_map(m, [[0, 1, 0]]).round(1)     # +y: the top row's average
    array([[0.5, 0.9, 0.5]])
    """
    m = _image(latlong, "latlong")
    u, v = latlong_coordinates(directions)
    w = m.shape[1]
    padded = np.concatenate([m[:, -1:], m, m[:, :1]], axis=1)    # the seam wraps
    return bilinear_sample(padded, (u * w + 1) / (w + 2), v, "clamp")   # the poles clamp


# ---------------------------------------------------------------------------------------------
# Reflection and the mirror object
# ---------------------------------------------------------------------------------------------

def reflect_view(incident, normals):
    r"""The reflection vector :math:`R = I - 2 (N \cdot I) N` of view rays `incident` (travelling
    towards the surface) at unit-normalized `normals`.

    This is :func:`course_lib.shading.reflect` ``(-I, N)`` (whose L points away from the
    surface); the result has the length of :math:`I`.

    Examples
    --------
    >>> reflect_view([0, 0, -1], [0, 1, 1]).round(12) + 0.0   # a 45-degree mirror: up
    array([0., 1., 0.])
    """
    i = _nonzero_directions(incident, "incident")
    return _phong_reflect(-i, normals)


def environment_lookup(kind, environment_map, directions, filter="bilinear", view=None):
    """Look a map of kind ``"cube"``, ``"sphere"`` or ``"latlong"`` up by direction.

    Examples
    --------
    >>> cube = cube_map_from_function(axes_environment, 8)
    >>> environment_lookup("cube", cube, [[-1, 0, 0]]).round(2)
    array([[0.05, 0.  , 0.  ]])
    """
    kind = as_choice(kind, "kind", ("cube", "sphere", "latlong"))
    if kind == "cube":
        return sample_cube_map(environment_map, directions, filter)
    if kind == "sphere":
        return sample_sphere_map(environment_map, directions, view)
    return sample_latlong_map(environment_map, directions)


def mirror_sphere(size=128, eye_direction=(0.0, 0.0, 1.0), up=(0.0, 1.0, 0.0)):
    """A unit mirror sphere seen orthographically: per pixel the normal and reflection vector.

    The camera looks along ``-eye_direction`` (eye_direction points from the sphere to the
    eye), `up` fixes the picture's vertical. Pixels off the sphere get a zero normal and the
    view direction as their "reflection" (the background is seen straight through).

    Returns
    -------
    dict with ``mask`` (size, size) bool, ``normals`` and ``reflections`` (size, size, 3),
    ``view`` (3,) the view direction, ``frame`` (3, 3) the camera's right, up, back axes (rows).
    Row 0 is the bottom of the picture.

    Examples
    --------
    >>> m = mirror_sphere(5)
    >>> int(m["mask"].sum()), m["reflections"][2, 2]   # the centre reflects back at the eye
    (21, array([0., 0., 1.]))
    """
    n = as_whole(size, "size", 1)
    back = as_vector(eye_direction, "eye_direction", 3)
    if not np.any(back):
        raise ValueError("eye_direction must not be the zero vector")
    back = back / np.linalg.norm(back)
    upv = as_vector(up, "up", 3)
    right = np.cross(upv, back)
    if np.linalg.norm(right) < 1e-9:
        raise ValueError("up must not be parallel to eye_direction")
    right /= np.linalg.norm(right)
    upv = np.cross(back, right)
    g = (2 * np.arange(n) + 1) / n - 1
    y, x = np.meshgrid(g, g, indexing="ij")
    rho2 = x * x + y * y
    mask = rho2 <= 1
    z = np.sqrt(np.clip(1 - rho2, 0, 1))
    local = np.stack([x, y, z], -1) * mask[..., None]
    frame = np.stack([right, upv, back])
    normals = local @ frame
    view = -back
    refl = np.where(mask[..., None], view - 2 * _dot(normals, view)[..., None] * normals, view)
    return {"mask": mask, "normals": normals, "reflections": refl, "view": view, "frame": frame}


def distant_environment_error(offset, direction, radius):
    r"""The angle by which a direction-only look-up misses, for an object off the map's centre.

    The environment is a sphere of radius :math:`R` around the map's centre; the reflected ray
    leaves from :math:`P` (the `offset` :math:`d` from the centre) in the unit direction
    :math:`r` and really hits :math:`Q = P + t r` with
    :math:`t = -P\cdot r + \sqrt{(P \cdot r)^2 - |P|^2 + R^2}`. The map is looked up at
    :math:`r`, but shows the point in direction :math:`Q/R`: the error is the angle between
    :math:`r` and :math:`Q`. By the sine rule in the triangle (centre, P, Q) it is at most
    :math:`\arcsin(|d|/R)` (for :math:`r \perp d`), and 0 along :math:`\pm d`.

    Parameters
    ----------
    offset : array_like, shape (..., 3)
        The object's displacement from the map's centre, inside the environment (|d| < R).
    direction : array_like, shape (..., 3)
        Reflection directions (not zero).
    radius : float
        R, the distance of the environment.

    Returns
    -------
    ndarray, shape (...)
        Angles in radians.

    Examples
    --------
    >>> float(np.degrees(distant_environment_error([0, 0.5, 0], [1, 0, 0], 1.0)).round(6))
    30.0
    """
    p = as_points(offset, "offset", dims=3)
    r = _nonzero_directions(direction, "direction")
    big_r = as_positive(radius, "radius")
    if np.any(_dot(p, p) >= big_r * big_r):
        raise ValueError("offset must lie inside the environment (|offset| < radius)")
    r = r / np.sqrt(_dot(r, r))[..., None]
    pr = _dot(p, r)
    tt = -pr + np.sqrt(pr * pr - _dot(p, p) + big_r * big_r)
    q = p + tt[..., None] * r
    cosang = _dot(q, r) / np.sqrt(_dot(q, q))
    return np.arccos(np.clip(cosang, -1, 1))


# ---------------------------------------------------------------------------------------------
# Procedural environments (direction -> RGB)
# ---------------------------------------------------------------------------------------------

def _unit_rows(d):
    d = np.asarray(d, dtype=float)
    return d / np.sqrt(_dot(d, d))[..., None]


SUN = np.array([0.5, 0.45, -0.74]) / np.linalg.norm([0.5, 0.45, -0.74])


def sky_environment(directions):
    """A sky (blue to pale at the horizon) with a sun, over a checkered ground (y < 0).

    Examples
    --------
    >>> sky_environment([[0, 1, 0], [0, -1, 0]]).round(2)
    array([[0.25, 0.45, 0.85],
           [0.45, 0.3 , 0.15]])
    """
    d = _unit_rows(directions)
    y = d[..., 1]
    h = np.clip(y, 0, 1)[..., None]
    sky = (1 - h) * np.array([0.85, 0.9, 1.0]) + h * np.array([0.25, 0.45, 0.85])
    sun = np.clip((_dot(d, SUN) - 0.985) / 0.01, 0, 1)[..., None]
    sky = sky + sun * (np.array([1.0, 0.95, 0.7]) - sky)
    # the ground plane y = -1 seen from the centre, checkered with 0.5-wide squares
    k = 1.0 / np.maximum(-y, 1e-6)
    gx, gz = d[..., 0] * k, d[..., 2] * k
    check = (np.floor(gx * 2) + np.floor(gz * 2)) % 2
    ground = np.where(check[..., None] == 0, [0.45, 0.3, 0.15], [0.2, 0.55, 0.25])
    fade = np.clip(-y * 8, 0, 1)[..., None]             # fades into haze at the horizon
    ground = fade * ground + (1 - fade) * np.array([0.7, 0.72, 0.7])
    return np.where((y < 0)[..., None], ground, sky)


_WALLS = np.array([[0.85, 0.3, 0.25], [0.25, 0.6, 0.85], [0.95, 0.95, 0.9],
                   [0.4, 0.3, 0.25], [0.9, 0.75, 0.3], [0.35, 0.7, 0.4]])


def room_environment(directions):
    """A checkered room: the cube |x|, |y|, |z| <= 1, each wall its own colour, 4 x 4 checks.

    Examples
    --------
    >>> room_environment([[1, 0.1, 0.1], [0.1, 0.1, -1]]).round(2)
    array([[0.85, 0.3 , 0.25],
           [0.35, 0.7 , 0.4 ]])
    """
    d = _unit_rows(directions)
    face, s, t = cube_face_coordinates(d)
    check = (np.floor(s * 4) + np.floor(t * 4)) % 2
    base = _WALLS[face]
    return np.where(check[..., None] == 0, base, 0.55 * base)


def axes_environment(directions):
    """Colour = the direction itself, :math:`0.5 + 0.45\\,d`: +x reddish, +y greenish, +z bluish.

    Examples
    --------
    >>> axes_environment([[1, 0, 0], [0, 0, -1]])
    array([[0.95, 0.5 , 0.5 ],
           [0.5 , 0.5 , 0.05]])
    """
    return 0.5 + 0.45 * _unit_rows(directions)


ENVIRONMENTS = {"sky": sky_environment, "room": room_environment, "axes": axes_environment}
