r"""Chapter 12 (lesson section 1): radiometry: solid angles, irradiance, the inverse-square law.

How much light arrives at a surface point? Radiometry measures light as energy: the **radiant
energy** :math:`Q` [J], the **flux** :math:`\Phi = dQ/dt` [W] (power), the **irradiance**
:math:`E = d\Phi/dA` [W/m²] arriving at a surface (its twin leaving a surface is the radiant
exitance or radiosity :math:`M`), the **radiant intensity** :math:`I = d\Phi/d\omega` [W/sr] of
a point source in a direction, and the **radiance**
:math:`L = d^2\Phi / (dA \cos\theta \, d\omega)` [W/(m² sr)] travelling along a ray
(:data:`QUANTITIES`).

**Solid angles.** The solid angle of a set of directions is the area it covers on the unit
sphere [sr]. In spherical coordinates (polar angle :math:`\theta` from the axis, azimuth
:math:`\phi`) a small patch of the unit sphere is :math:`d\theta` high and
:math:`\sin\theta\, d\phi` wide, so :math:`d\omega = \sin\theta \, d\theta \, d\phi`
(:func:`spherical_region_solid_angle`). A cone of half-angle :math:`\alpha` covers
:math:`2\pi(1 - \cos\alpha)` (:func:`cone_solid_angle`): :math:`2\pi` for the hemisphere,
:math:`4\pi` for the sphere. A small flat patch of area :math:`A` at distance :math:`d`, tilted
by :math:`\theta` from the line of sight, covers about :math:`A\cos\theta/d^2`
(:func:`patch_solid_angle`); :func:`polygon_solid_angle` gives the exact value for a polygon.

**The inverse-square and cosine laws.** A point source of intensity :math:`I` sends the flux
:math:`I\,d\omega` into the small solid angle :math:`d\omega = dA\cos\theta/d^2` of a patch
:math:`dA`, hence the irradiance :math:`E = I\cos\theta/d^2` (:func:`point_light_irradiance`).
An area light of radiance :math:`L` gives :math:`E = \int L \cos\theta\, d\omega`: about
:math:`L A \cos\theta_s\cos\theta_l / d^2` when it is small (:func:`small_light_irradiance`),
exactly Lambert's contour formula for a polygon (:func:`polygon_light_irradiance`).
"""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_points, as_scalar, broadcast_stacks
from ._common import _dot, _unit

__all__ = ["PointIrradiance", "QUANTITIES", "Quantity", "cone_solid_angle",
    "isotropic_intensity", "lambertian_exitance", "lambertian_radiance",
    "emitter_intensity", "patch_solid_angle", "point_light_irradiance",
    "polygon_light_irradiance", "polygon_solid_angle", "small_light_irradiance",
    "spherical_region_solid_angle"]


# ---------------------------------------------------------------------------------------------
# The quantities
# ---------------------------------------------------------------------------------------------

class Quantity(NamedTuple):
    """One radiometric quantity: its name, symbol, defining formula, unit and meaning.

    Examples
    --------
    >>> Quantity("flux", "Φ", "dQ/dt", "W", "power").unit
    'W'
    """

    name: str
    symbol: str
    definition: str
    unit: str
    meaning: str


QUANTITIES = (
    Quantity("radiant energy", "Q", "Q", "J",
             "the energy carried by the light (a count of photons times h c / λ)"),
    Quantity("radiant flux (power)", "Φ", "dQ/dt", "W",
             "energy per unit time through a surface or out of a source"),
    Quantity("irradiance", "E", "dΦ/dA", "W/m²",
             "flux arriving per unit area of a surface, from all directions above it"),
    Quantity("radiant exitance (radiosity)", "M", "dΦ/dA", "W/m²",
             "flux leaving per unit area of a surface (emitted or reflected)"),
    Quantity("radiant intensity", "I", "dΦ/dω", "W/sr",
             "flux of a point source per unit solid angle, in one direction"),
    Quantity("radiance", "L", "d²Φ/(dA cos θ dω)", "W/(m² sr)",
             "flux per unit projected area and per unit solid angle: the light along one ray; "
             "constant along the ray in empty space, and what a camera pixel measures"),
)
"""The radiometric quantities, in the order the lesson introduces them (tuple of Quantity)."""


# ---------------------------------------------------------------------------------------------
# Input checks
# ---------------------------------------------------------------------------------------------

def _nonnegative(value, name, what):
    v = as_array(value, name)
    if np.any(v < 0):
        raise ValueError(f"{name} must be zero or positive ({what}), got {float(v[v < 0].flat[0]):g}")
    return v


def _angles(value, name, low, high, what):
    v = as_array(value, name)
    if np.any((v < low) | (v > high)):
        bad = float(v[(v < low) | (v > high)].flat[0])
        raise ValueError(f"{name} must lie in [{low:g}, {high:g}] radians ({what}), got {bad:g}")
    return v


def _planar_polygon(vertices, name="vertices"):
    """A planar polygon (n, 3), n >= 3, and its unit normal (right-hand rule) and area."""
    v = as_points(vertices, name, dims=3)
    if v.ndim != 2 or v.shape[0] < 3:
        raise ValueError(f"{name} must be an (n, 3) array of n >= 3 polygon corners, "
                         f"got shape {v.shape}")
    newell = 0.5 * np.cross(v, np.roll(v, -1, axis=0)).sum(axis=0)  # area vector
    area = float(np.linalg.norm(newell))
    size = float(np.ptp(v, axis=0).max())
    if area <= 1e-12 * max(size, 1e-300) ** 2:
        raise ValueError(f"{name} must span a polygon of non-zero area (the corners are "
                         "collinear or repeated)")
    n = newell / area
    off = np.abs((v - v[0]) @ n)
    if off.max() > 1e-9 * size:
        raise ValueError(f"{name} must be planar: a corner lies {off.max():.3g} off the "
                         "polygon's plane")
    return v, n, area


def _triangle_solid_angle(a, b, c):
    """Signed solid angle of triangle (a, b, c) seen from the origin (Van Oosterom-Strackee).

    a, b, c: (..., 3). Positive when a, b, c turn counter-clockwise seen from the origin
    (a . (b x c) > 0). The atan2 keeps the right branch when the angle exceeds pi.
    """
    la, lb, lc = (np.sqrt(_dot(x, x)) for x in (a, b, c))
    num = _dot(a, np.cross(b, c))
    den = la * lb * lc + _dot(a, b) * lc + _dot(a, c) * lb + _dot(b, c) * la
    return 2.0 * np.arctan2(num, den)


# ---------------------------------------------------------------------------------------------
# Solid angles
# ---------------------------------------------------------------------------------------------

def cone_solid_angle(half_angle):
    r"""Solid angle of a circular cone of half-angle :math:`\alpha`: :math:`2\pi(1-\cos\alpha)`.

    From :math:`d\omega = \sin\theta\,d\theta\,d\phi` integrated over
    :math:`0 \le \theta \le \alpha`, :math:`0 \le \phi < 2\pi`. For small :math:`\alpha` it is
    about :math:`\pi\alpha^2` (the area of a disc of radius :math:`\alpha`).

    Parameters
    ----------
    half_angle : float or array_like
        In radians, in :math:`[0, \pi]` (:math:`\pi/2` is the hemisphere, :math:`\pi` the
        whole sphere).

    Returns
    -------
    float or ndarray
        Steradians.

    Raises
    ------
    ValueError
        For an angle outside :math:`[0, \pi]` or NaN.

    Examples
    --------
    >>> import numpy as np
    >>> round(cone_solid_angle(np.pi / 2) / np.pi, 12), round(cone_solid_angle(np.pi) / np.pi, 12)
    (2.0, 4.0)
    """
    a = _angles(half_angle, "half_angle", 0.0, np.pi, "the cone's half-angle")
    out = 2.0 * np.pi * (1.0 - np.cos(a))
    return float(out) if out.ndim == 0 else out


def spherical_region_solid_angle(theta1, theta2, phi1, phi2):
    r"""Solid angle of the region :math:`\theta_1\le\theta\le\theta_2`, :math:`\phi_1\le\phi\le\phi_2`.

    .. math:: \Omega = \int_{\phi_1}^{\phi_2}\int_{\theta_1}^{\theta_2} \sin\theta\,d\theta\,
              d\phi = (\phi_2 - \phi_1)(\cos\theta_1 - \cos\theta_2)

    Parameters
    ----------
    theta1, theta2 : float or array_like
        Polar angles (from the axis) in radians, :math:`0 \le \theta_1 \le \theta_2 \le \pi`.
    phi1, phi2 : float or array_like
        Azimuths in radians, :math:`\phi_1 \le \phi_2 \le \phi_1 + 2\pi`.

    Returns
    -------
    float or ndarray

    Raises
    ------
    ValueError
        For angles out of range or in the wrong order.

    Examples
    --------
    The band 60°..90° all the way round, and one octant of the sphere (4π / 8):

    >>> import numpy as np
    >>> float(spherical_region_solid_angle(np.pi / 3, np.pi / 2, 0, 2 * np.pi) / np.pi)
    1.0
    >>> round(spherical_region_solid_angle(0, np.pi / 2, 0, np.pi / 2) / np.pi, 12)
    0.5
    """
    t1 = _angles(theta1, "theta1", 0.0, np.pi, "a polar angle")
    t2 = _angles(theta2, "theta2", 0.0, np.pi, "a polar angle")
    p1, p2 = as_array(phi1, "phi1"), as_array(phi2, "phi2")
    if np.any(t2 < t1):
        raise ValueError("theta2 must not be smaller than theta1")
    span = p2 - p1
    if np.any(span < 0) or np.any(span > 2 * np.pi * (1 + 1e-12)):
        raise ValueError("phi2 - phi1 must lie in [0, 2 pi] (an azimuth range)")
    out = span * (np.cos(t1) - np.cos(t2))
    return float(out) if out.ndim == 0 else out


def polygon_solid_angle(vertices, points):
    r"""Exact solid angle of a planar polygon seen from each point (unsigned, steradians).

    The polygon is split into a fan of triangles :math:`(v_0, v_i, v_{i+1})`; each triangle's
    signed solid angle seen from :math:`P` comes from the formula of Van Oosterom and Strackee
    (1983), with :math:`a, b, c` the corners relative to :math:`P`:

    .. math:: \tan\frac{\Omega}{2} = \frac{a\cdot(b\times c)}{|a||b||c| + (a\cdot b)|c|
              + (a\cdot c)|b| + (b\cdot c)|a|}

    evaluated with ``atan2`` so that angles above :math:`\pi` keep their branch. The signed
    parts add up like the signed areas of the shoelace formula, so the fan is right for any
    simple planar polygon (convex or not); the magnitude of the sum is returned, whichever
    way the corners turn.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        The corners in order, n >= 3, on one plane.
    points : array_like, shape (..., 3)
        Where the polygon is seen from.

    Returns
    -------
    ndarray, shape (...)
        Zero for points on the polygon's plane outside it.

    Raises
    ------
    ValueError
        For a degenerate or non-planar polygon, non-finite input, or a point lying on the
        polygon itself (the solid angle jumps there from 0 to 2 pi).

    Examples
    --------
    A face of a cube seen from the cube's centre is one sixth of the sphere:

    >>> import numpy as np
    >>> face = [[-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]]
    >>> round(float(polygon_solid_angle(face, [0, 0, 0]) / (4 * np.pi / 6)), 12)
    1.0
    """
    v, normal, _ = _planar_polygon(vertices)
    p = as_points(points, "points", dims=3)
    rel = v - p[..., None, :]                                 # (..., n, 3)
    _reject_points_on(rel, normal, v, "points")
    a = rel[..., :1, :]
    total = _triangle_solid_angle(a, rel[..., 1:-1, :], rel[..., 2:, :]).sum(axis=-1)
    return np.abs(total)


def _reject_points_on(rel, normal, v, name):
    """Raise if a point lies on the polygon (on its plane and inside it)."""
    size = float(np.ptp(v, axis=0).max())
    height = rel[..., 0, :] @ normal
    near = np.abs(height) <= 1e-12 * size
    if not np.any(near):
        return
    a, b = rel[near], np.roll(rel[near], -1, axis=-2)
    turn = np.arctan2(np.cross(a, b) @ normal, _dot(a, b)).sum(axis=-1)   # 2 pi x winding
    touching = np.min(np.sqrt(_dot(rel[near], rel[near])), axis=-1) <= 1e-12 * size
    if np.any((np.abs(turn) > np.pi) | touching):
        raise ValueError(f"{name} must not lie on the polygon itself (a point on the light "
                         "or on the patch sees it edge-on and half of all directions at once)")


def patch_solid_angle(area, normal, center, points):
    r"""Small-patch approximation of a flat patch's solid angle: :math:`A\cos\theta / d^2`.

    :math:`d` is the distance from the point to the patch's centre and :math:`\theta` the angle
    between the patch's normal and the line of sight. The patch is seen from either side, so
    :math:`|\cos\theta|` is used. The relative error against the exact value
    (:func:`polygon_solid_angle`) falls like :math:`(\text{size}/d)^2`.

    Parameters
    ----------
    area : float
        Patch area, >= 0.
    normal : array_like, shape (3,)
        Not zero.
    center : array_like, shape (3,)
    points : array_like, shape (..., 3)

    Returns
    -------
    ndarray, shape (...)

    Raises
    ------
    ValueError
        For a negative area, a zero normal, non-finite input or a point at the centre.

    Examples
    --------
    A 0.1 x 0.1 patch 2 units away, tilted by 60 degrees:

    >>> import numpy as np
    >>> n = [np.sin(np.pi / 3), 0, np.cos(np.pi / 3)]
    >>> round(float(patch_solid_angle(0.01, n, [0, 0, 2], [0, 0, 0])), 12)
    0.00125
    """
    a = _nonnegative(area, "area", "the patch's area")
    n = _unit(normal, "normal")
    c = as_points(center, "center", dims=3)
    p = as_points(points, "points", dims=3)
    d = c - p
    d2 = _dot(d, d)
    if np.any(d2 == 0):
        raise ValueError("points must not coincide with the patch's center (d = 0)")
    cos = np.abs(_dot(d, n)) / np.sqrt(d2)
    return a * cos / d2


# ---------------------------------------------------------------------------------------------
# Irradiance
# ---------------------------------------------------------------------------------------------

class PointIrradiance(NamedTuple):
    r"""Irradiance from a point light and its two factors: ``irradiance = I * cos_theta * inv_d2``.

    Examples
    --------
    >>> r = point_light_irradiance([0, 0, 0], [0, 0, 1], [0, 0, 2], 8.0)
    >>> float(r.irradiance), float(r.cos_theta), float(r.inv_d2), float(r.distance)
    (2.0, 1.0, 0.25, 2.0)
    """

    irradiance: np.ndarray   # E = I cos(theta) / d^2 [W/m^2], 0 where the light is below
    cos_theta: np.ndarray    # max(N . L, 0): the cosine law
    inv_d2: np.ndarray       # 1 / d^2: the inverse-square law
    distance: np.ndarray     # d


def point_light_irradiance(points, normals, light_position, intensity):
    r"""Irradiance at surface points from an isotropic point light: :math:`E = I\cos\theta/d^2`.

    The light sends the flux :math:`I\,d\omega` into the solid angle
    :math:`d\omega = dA\cos\theta/d^2` of a small patch :math:`dA` at distance :math:`d`
    whose normal makes the angle :math:`\theta` with the direction to the light; dividing by
    :math:`dA` gives :math:`E`. A light at or below the surface's horizon
    (:math:`\cos\theta \le 0`) lights the front side not at all: the cosine is clamped to 0
    (one-sided surfaces, as in the Phong model's :math:`\max(N\cdot L, 0)`).

    Parameters
    ----------
    points : array_like, shape (..., 3)
    normals : array_like, shape (..., 3)
        Not zero (normalized here); broadcast against `points`.
    light_position : array_like, shape (3,) or (..., 3)
    intensity : float or array_like
        Radiant intensity :math:`I` [W/sr], >= 0.

    Returns
    -------
    PointIrradiance
        ``irradiance``, ``cos_theta`` (clamped), ``inv_d2`` and ``distance``, each shape (...).

    Raises
    ------
    ValueError
        For a negative intensity, zero normals, non-finite input, mismatched stacks, or a
        point at the light (d = 0).

    Examples
    --------
    A 100 W/sr light 5 m away, 60 degrees off the normal: 100 * 0.5 / 25 = 2 W/m².

    >>> import numpy as np
    >>> light = 5 * np.array([np.sin(np.pi / 3), 0, np.cos(np.pi / 3)])
    >>> round(float(point_light_irradiance([0, 0, 0], [0, 0, 1], light, 100).irradiance), 12)
    2.0
    """
    p = as_points(points, "points", dims=3)
    n = _unit(normals, "normals")
    s = as_points(light_position, "light_position", dims=3)
    i = _nonnegative(intensity, "intensity", "the light's radiant intensity in W/sr")
    broadcast_stacks(points=(p, 1), normals=(n, 1), light_position=(s, 1), intensity=(i, 0))
    d = s - p
    d2 = _dot(d, d)
    if np.any(d2 == 0):
        raise ValueError("points must not coincide with light_position (d = 0: the irradiance "
                         "of a point light is infinite there)")
    dist = np.sqrt(d2)
    cos = np.maximum(_dot(d, n) / dist, 0.0)
    inv = 1.0 / d2
    return PointIrradiance(i * cos * inv, cos, inv, dist)


def small_light_irradiance(points, normals, light_center, light_normal, area, radiance):
    r"""Irradiance from a small uniform Lambertian area light: :math:`E \approx L A\cos\theta_s\cos\theta_l/d^2`.

    A flat emitter of radiance :math:`L` and area :math:`A` has the intensity
    :math:`I(\theta_l) = L A\cos\theta_l` towards a direction at :math:`\theta_l` from its
    normal (:func:`emitter_intensity`); treated as a point light at its centre this gives the
    formula. Good while the light is small against the distance (error about
    :math:`(\text{size}/d)^2`); :func:`polygon_light_irradiance` is exact. The light emits on
    the side of its normal only and the receiver is lit on the side of its normal only: both
    cosines are clamped at 0.

    Parameters
    ----------
    points, normals : array_like, shape (..., 3)
    light_center : array_like, shape (3,)
    light_normal : array_like, shape (3,)
        The side the light shines to; not zero.
    area : float
        >= 0, in m².
    radiance : float
        >= 0, in W/(m² sr).

    Returns
    -------
    ndarray, shape (...)
        W/m².

    Raises
    ------
    ValueError
        For negative area or radiance, zero normals, non-finite input or a point at the
        light's centre.

    Examples
    --------
    A 0.01 m² panel of radiance 100 facing straight down from 1 m: E = 100 * 0.01 = 1.

    >>> float(small_light_irradiance([0, 0, 0], [0, 0, 1], [0, 0, 1], [0, 0, -1], 0.01, 100))
    1.0
    """
    p = as_points(points, "points", dims=3)
    n = _unit(normals, "normals")
    c = as_points(light_center, "light_center", dims=3)
    nl = _unit(light_normal, "light_normal")
    a = _nonnegative(area, "area", "the light's area in m²")
    L = _nonnegative(radiance, "radiance", "the light's radiance in W/(m² sr)")
    broadcast_stacks(points=(p, 1), normals=(n, 1))
    d = c - p
    d2 = _dot(d, d)
    if np.any(d2 == 0):
        raise ValueError("points must not coincide with light_center (d = 0)")
    dist = np.sqrt(d2)
    cos_s = np.maximum(_dot(d, n) / dist, 0.0)
    cos_l = np.maximum(-_dot(d, nl) / dist, 0.0)
    return L * a * cos_s * cos_l / d2


def polygon_light_irradiance(points, normals, vertices, radiance):
    r"""Exact irradiance from a uniform Lambertian polygon light (Lambert's contour formula).

    For a light of constant radiance :math:`L`, :math:`E = \int L\cos\theta\,d\omega` over the
    directions in which the receiver sees the light. By Stokes' theorem the integral becomes a
    sum over the polygon's edges (Lambert 1760):

    .. math:: E = \frac{L}{2}\left|\sum_i \beta_i\, (N \cdot \Gamma_i)\right|, \qquad
              \Gamma_i = \frac{a_i \times a_{i+1}}{\lVert a_i \times a_{i+1}\rVert},\quad
              \beta_i = \angle(a_i, a_{i+1})

    with :math:`a_i = v_i - P` the corners relative to the receiver point :math:`P` and
    :math:`N` its unit normal. The formula holds only for the part of the light **above the
    receiver's plane** (where :math:`\cos\theta \ge 0`): the polygon is clipped against that
    plane per point first (one Sutherland-Hodgman step, vectorized), so lights that straddle
    the horizon are handled. The light is one-sided: it emits on the side of its right-hand
    normal (corners counter-clockwise seen from the lit side); points behind it or on its
    plane get 0.

    Parameters
    ----------
    points, normals : array_like, shape (..., 3)
    vertices : array_like, shape (n, 3)
        The light's corners, n >= 3, planar, simple (convex or not).
    radiance : float
        >= 0, in W/(m² sr).

    Returns
    -------
    ndarray, shape (...)
        W/m².

    Raises
    ------
    ValueError
        For a negative radiance, a degenerate or non-planar polygon, zero normals,
        non-finite input or a point on the light.

    Examples
    --------
    A huge light above the point fills its hemisphere: E tends to pi L:

    >>> import numpy as np
    >>> big = [[-1e4, -1e4, 1], [1e4, -1e4, 1], [1e4, 1e4, 1], [-1e4, 1e4, 1]][::-1]
    >>> round(float(polygon_light_irradiance([0, 0, 0], [0, 0, 1], big, 1) / np.pi), 6)
    1.0
    """
    p = as_points(points, "points", dims=3)
    n = _unit(normals, "normals")
    v, nl, _ = _planar_polygon(vertices)
    L = as_scalar(radiance, "radiance")
    if L < 0:
        raise ValueError(f"radiance must be zero or positive (the light's radiance in "
                         f"W/(m² sr)), got {L:g}")
    shape = broadcast_stacks(points=(p, 1), normals=(n, 1))
    p = np.broadcast_to(p, shape + (3,))
    n = np.broadcast_to(n, shape + (3,))
    rel = v - p[..., None, :]                                   # (..., k, 3)
    _reject_points_on(rel, nl, v, "points")
    k = v.shape[0]
    # clip against the receiver's plane: keep s = N . a >= 0
    s = _dot(rel, n[..., None, :])                               # (..., k)
    nxt, s_n = np.roll(rel, -1, axis=-2), np.roll(s, -1, axis=-1)
    cross = s * s_n < 0
    t = np.where(cross, s / np.where(cross, s - s_n, 1.0), 0.0)
    hit = rel + t[..., None] * (nxt - rel)
    cand = np.stack([rel, hit], axis=-2).reshape(shape + (2 * k, 3))
    keep = np.stack([s >= 0, cross], axis=-1).reshape(shape + (2 * k,))
    order = np.argsort(~keep, axis=-1, kind="stable")          # kept corners first, in order
    cand = np.take_along_axis(cand, order[..., None], axis=-2)
    count = keep.sum(axis=-1)
    first = cand[..., :1, :]
    slot = np.arange(2 * k)
    cand = np.where((slot < count[..., None])[..., None], cand, first)   # pad with corner 0
    b = np.roll(cand, -1, axis=-2)
    cr = np.cross(cand, b)
    crn = np.sqrt(_dot(cr, cr))
    beta = np.arctan2(crn, _dot(cand, b))
    term = np.where(crn > 0, beta * _dot(cr, n[..., None, :]) / np.where(crn > 0, crn, 1.0),
                    0.0)
    e = 0.5 * L * np.abs(term.sum(axis=-1))
    front = (-rel[..., 0, :] @ nl) > 0                          # receiver on the lit side
    return np.where(front & (count >= 3), e, 0.0)


# ---------------------------------------------------------------------------------------------
# Conversions
# ---------------------------------------------------------------------------------------------

def isotropic_intensity(flux):
    r"""Intensity of an isotropic point source of flux :math:`\Phi`: :math:`I = \Phi/(4\pi)`.

    The flux spreads evenly over the whole sphere of directions, :math:`4\pi` sr.

    Parameters
    ----------
    flux : float or array_like
        W, >= 0.

    Returns
    -------
    float or ndarray
        W/sr.

    Raises
    ------
    ValueError
        For a negative or non-finite flux.

    Examples
    --------
    >>> import numpy as np
    >>> float(isotropic_intensity(400 * np.pi))
    100.0
    """
    f = _nonnegative(flux, "flux", "the source's radiant flux in W")
    out = f / (4 * np.pi)
    return float(out) if out.ndim == 0 else out


def emitter_intensity(radiance, area, theta):
    r"""Intensity of a small flat Lambertian emitter in a direction: :math:`I(\theta) = L A\cos\theta`.

    From :math:`L = d^2\Phi/(dA\cos\theta\,d\omega)` and :math:`I = d\Phi/d\omega`: the emitter
    looks foreshortened to :math:`A\cos\theta` from an angle :math:`\theta` off its normal
    (Lambert's cosine law of emission). Behind it (:math:`\theta > \pi/2`) it sends nothing.

    Parameters
    ----------
    radiance : float or array_like
        W/(m² sr), >= 0.
    area : float or array_like
        m², >= 0.
    theta : float or array_like
        Radians from the emitter's normal, in :math:`[0, \pi]`.

    Returns
    -------
    float or ndarray
        W/sr.

    Raises
    ------
    ValueError
        For negative radiance or area, or theta out of range.

    Examples
    --------
    >>> import numpy as np
    >>> round(emitter_intensity(1000, 0.02, np.pi / 3), 12)
    10.0
    """
    L = _nonnegative(radiance, "radiance", "the emitter's radiance in W/(m² sr)")
    a = _nonnegative(area, "area", "the emitter's area in m²")
    t = _angles(theta, "theta", 0.0, np.pi, "the angle from the emitter's normal")
    out = L * a * np.maximum(np.cos(t), 0.0)
    return float(out) if out.ndim == 0 else out


def lambertian_exitance(radiance):
    r"""Radiant exitance of a Lambertian surface of radiance :math:`L`: :math:`M = \pi L`.

    :math:`M = \int_{\text{hemisphere}} L\cos\theta\,d\omega
    = L\int_0^{2\pi}\!\int_0^{\pi/2}\cos\theta\sin\theta\,d\theta\,d\phi = \pi L`
    (not :math:`2\pi L`: the cosine weights the hemisphere's :math:`2\pi` sr down to
    :math:`\pi`). The same :math:`\pi` links a Lambertian light's radiance to the irradiance
    it gives when it fills the whole hemisphere above a point.

    Parameters
    ----------
    radiance : float or array_like
        W/(m² sr), >= 0.

    Returns
    -------
    float or ndarray
        W/m².

    Raises
    ------
    ValueError
        For a negative or non-finite radiance.

    Examples
    --------
    >>> import numpy as np
    >>> float(lambertian_exitance(2 / np.pi))
    2.0
    """
    L = _nonnegative(radiance, "radiance", "the surface's radiance in W/(m² sr)")
    out = np.pi * L
    return float(out) if out.ndim == 0 else out


def lambertian_radiance(exitance):
    r"""Radiance of a Lambertian surface of radiant exitance :math:`M`: :math:`L = M/\pi`.

    The inverse of :func:`lambertian_exitance`.

    Parameters
    ----------
    exitance : float or array_like
        W/m², >= 0.

    Returns
    -------
    float or ndarray
        W/(m² sr).

    Raises
    ------
    ValueError
        For a negative or non-finite exitance.

    Examples
    --------
    >>> import numpy as np
    >>> float(lambertian_radiance(3 * np.pi))
    3.0
    """
    m = _nonnegative(exitance, "exitance", "the surface's radiant exitance in W/m²")
    out = m / np.pi
    return float(out) if out.ndim == 0 else out
