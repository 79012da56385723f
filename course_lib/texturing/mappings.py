"""Chapter 14 (lesson section 4): mapping a surface to texture space."""

import numpy as np

from .._validate import as_array, as_points, as_positive, as_vector
from ._common import _dot, _uv
from .triangle_interpolation import _per_vertex

__all__ = ["cylindrical_map", "inverse_cylindrical_map", "inverse_planar_map",
    "inverse_spherical_map", "planar_map", "seam_unwrap", "spherical_map"]


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
    r = as_positive(radius, "radius")
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
    h = as_positive(height, "height")
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
    r, h = as_positive(radius, "radius"), as_positive(height, "height")
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
    uu = _per_vertex(u, "u")
    crosses = (uu.max(axis=-1) - uu.min(axis=-1)) > 0.5
    return np.where(crosses[..., None] & (uu < 0.5), uu + 1.0, uu)
