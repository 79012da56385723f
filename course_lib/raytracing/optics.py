"""Chapter 15 (lesson section 15.4): reflected and refracted directions, Fresnel and Schlick."""

import numpy as np

from .._validate import as_array, as_points, broadcast_stacks
from ..shading.vectors import _mirror
from ._common import _dot, _indices, _nonzero_vectors, _unit_vectors

__all__ = ["fresnel", "reflect_direction", "refract_direction", "schlick"]


# ---------------------------------------------------------------------------------------------
# Reflection, refraction, Fresnel
# ---------------------------------------------------------------------------------------------

def reflect_direction(d, n):
    r"""The mirror direction of a ray travelling along `d` that hits a surface of normal `n`.

    .. math:: r = d - 2\,(d \cdot n)\, n

    `d` is the *incoming* direction (the way the ray travels, towards the surface), the
    convention of ray tracers and GLSL's ``reflect``; the Phong model's :math:`R = 2 (N \cdot
    L) N - L` (:func:`course_lib.shading.reflect`, whose :math:`L` points *away* from the
    surface) is the same formula for :math:`L = -d`, and this function computes it so:
    ``reflect_direction(d, n) == shading.reflect(-d, n)``. The
    side `n` points to does not matter (the formula is even in :math:`n`); `n` is normalized
    here and :math:`\lVert r \rVert = \lVert d \rVert`. The angle of reflection equals the angle
    of incidence: :math:`r \cdot n = -d \cdot n`.

    Parameters
    ----------
    d : array_like, shape (..., 3)
        Incoming directions (not zero).
    n : array_like, shape (..., 3)
        Surface normals (not zero); broadcasts against `d`.

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For zero vectors, NaN, or shapes that do not broadcast.

    Examples
    --------
    A ray going down and to the right bounces off the floor up and to the right:

    >>> reflect_direction([1, -1, 0], [0, 1, 0])
    array([1., 1., 0.])
    """
    dv = as_points(d, "d", dims=3)
    _nonzero_vectors(dv.reshape(-1, 3), "d", dv.shape[:-1])
    nv = _unit_vectors(n, "n")
    broadcast_stacks(d=(dv, 1), n=(nv, 1))
    return _mirror(-dv, nv)                  # shading.reflect's R = 2 (n . L) n - L, L = -d


def _refract(d, n, eta1, eta2):
    """Unit d, unit n facing d (d.n <= 0): (t, total internal reflection mask)."""
    eta = eta1 / eta2
    c1 = np.clip(-_dot(d, n), 0.0, 1.0)
    k = 1.0 - eta * eta * (1.0 - c1 * c1)
    tir = k < 0
    c2 = np.sqrt(np.maximum(k, 0.0))
    t = eta[..., None] * d + (eta * c1 - c2)[..., None] * n
    t = t / np.sqrt(_dot(t, t))[..., None]
    return np.where(tir[..., None], 0.0, t), tir


def refract_direction(d, n, eta1, eta2):
    r"""The refracted direction by Snell's law, and where there is total internal reflection.

    A ray travelling along `d` passes from a medium of refractive index :math:`\eta_1` into
    one of index :math:`\eta_2` (:math:`\eta_1 \sin\theta_1 = \eta_2 \sin\theta_2`). With
    :math:`n` turned to face the incoming ray, :math:`\eta = \eta_1 / \eta_2` and
    :math:`c_1 = -d \cdot n = \cos\theta_1`:

    .. math:: c_2 = \sqrt{1 - \eta^2 (1 - c_1^2)} = \cos\theta_2, \qquad
              t = \eta\, d + (\eta\, c_1 - c_2)\, n

    When :math:`1 - \eta^2 (1 - c_1^2) < 0`, i.e. :math:`\sin\theta_1 > \eta_2/\eta_1` (beyond
    the critical angle, possible only when :math:`\eta_1 > \eta_2`), there is no refracted ray:
    **total internal reflection**; the direction is then returned as the zero vector and the
    flag is True (all light goes along :func:`reflect_direction`).

    Parameters
    ----------
    d : array_like, shape (..., 3)
        Incoming directions (normalized here; not zero).
    n : array_like, shape (..., 3)
        Surface normals, on either side (normalized and turned towards the incoming ray here).
    eta1, eta2 : float or array_like, shape (...)
        Refractive indices of the media the ray leaves and enters (positive).

    Returns
    -------
    direction : ndarray, shape (..., 3)
        Unit refracted directions (zero where there is total internal reflection).
    total_internal : ndarray of bool, shape (...)
        True where the ray is totally internally reflected.

    Raises
    ------
    ValueError
        For zero vectors, NaN, non-positive refractive indices, or shapes that do not
        broadcast.

    Examples
    --------
    Into glass at 45 degrees: :math:`\sin\theta_2 = \sin 45^\circ / 1.5 = 0.4714`. Out of the
    glass at 45 degrees (beyond the critical angle of 41.8 degrees): reflected totally.

    >>> t, tir = refract_direction([1, -1, 0], [0, 1, 0], 1.0, 1.5)
    >>> t.round(4), tir
    (array([ 0.4714, -0.8819,  0.    ]), array(False))
    >>> refract_direction([1, -1, 0], [0, 1, 0], 1.5, 1.0)
    (array([0., 0., 0.]), array(True))
    """
    dv = _unit_vectors(d, "d")
    nv = _unit_vectors(n, "n")
    e1 = _indices(eta1, "eta1")
    e2 = _indices(eta2, "eta2")
    lead = broadcast_stacks(d=(dv, 1), n=(nv, 1), eta1=(e1, 0), eta2=(e2, 0))
    dv = np.broadcast_to(dv, lead + (3,))
    nv = np.broadcast_to(nv, lead + (3,))
    nv = np.where((_dot(dv, nv) > 0)[..., None], -nv, nv)
    t, tir = _refract(dv, nv, np.broadcast_to(e1, lead), np.broadcast_to(e2, lead))
    return t, np.asarray(tir)


def _cosines(cos_theta, eta1, eta2):
    c = as_array(cos_theta, "cos_theta")
    if np.any(c < -1e-12) or np.any(c > 1 + 1e-12):
        bad = c[(c < -1e-12) | (c > 1 + 1e-12)].flat[0]
        raise ValueError(f"cos_theta must lie in [0, 1] (the cosine of the angle between the ray "
                         f"and the normal facing it), got {bad:g}")
    e1 = _indices(eta1, "eta1")
    e2 = _indices(eta2, "eta2")
    lead = broadcast_stacks(cos_theta=(c, 0), eta1=(e1, 0), eta2=(e2, 0))
    return (np.broadcast_to(np.clip(c, 0.0, 1.0), lead), np.broadcast_to(e1, lead),
            np.broadcast_to(e2, lead))


def _transmitted_cosine(c1, eta1, eta2):
    """cos(theta_2) by Snell's law and the total-internal-reflection mask."""
    s2 = (eta1 / eta2) ** 2 * (1.0 - c1 * c1)
    return np.sqrt(np.maximum(1.0 - s2, 0.0)), s2 > 1.0


def _schlick(c1, eta1, eta2):
    r0 = ((eta1 - eta2) / (eta1 + eta2)) ** 2
    c2, tir = _transmitted_cosine(c1, eta1, eta2)
    c = np.where(eta1 > eta2, c2, c1)
    f = r0 + (1.0 - r0) * (1.0 - c) ** 5
    return np.where(tir, 1.0, np.where(eta1 == eta2, 0.0, f))


def schlick(cos_theta, eta1, eta2):
    r"""Schlick's approximation of the Fresnel reflectance of a dielectric interface.

    .. math:: F = R_0 + (1 - R_0)(1 - \cos\theta)^5, \qquad
              R_0 = \left(\frac{\eta_1 - \eta_2}{\eta_1 + \eta_2}\right)^2

    :math:`R_0` is the exact reflectance at normal incidence. For :math:`\eta_1 > \eta_2`
    (leaving the denser medium) :math:`\cos\theta` is the cosine of the *transmitted* angle,
    :math:`\sqrt{1 - (\eta_1/\eta_2)^2 \sin^2\theta_1}` (otherwise the approximation is poor
    near the critical angle), and :math:`F = 1` beyond the critical angle (total internal
    reflection). With :math:`\eta_1 = \eta_2` there is no interface and :math:`F = 0`. Compared
    with the exact :func:`fresnel`, the error is largest near grazing incidence (or, from
    inside, just below the critical angle): at most 0.036 for glass (:math:`\eta = 1.5`) and
    0.06 for water (1.33); the curve has the right shape: small and flat up to about 45°,
    rising steeply to 1 at grazing incidence.

    Parameters
    ----------
    cos_theta : float or array_like
        Cosine of the angle of incidence, in [0, 1] (:math:`-d \cdot n` for a unit ray
        direction and the normal facing the ray).
    eta1, eta2 : float or array_like
        Refractive indices of the medium the ray comes from and of the other one.

    Returns
    -------
    ndarray
        The fraction of light reflected, in [0, 1].

    Raises
    ------
    ValueError
        For a cosine outside [0, 1], non-positive indices or NaN.

    Examples
    --------
    Head-on, glass reflects 4 %; at grazing incidence everything; from inside beyond the
    critical angle everything:

    >>> schlick([1.0, 0.0], 1.0, 1.5).round(6)
    array([0.04, 1.  ])
    >>> float(schlick(np.cos(np.radians(60)), 1.5, 1.0))
    1.0
    """
    c, e1, e2 = _cosines(cos_theta, eta1, eta2)
    return _schlick(c, e1, e2)


def fresnel(cos_theta, eta1, eta2):
    r"""The exact Fresnel reflectance of unpolarized light (the average of both polarizations).

    With :math:`c_1 = \cos\theta_1` and :math:`c_2 = \cos\theta_2` from Snell's law,

    .. math:: r_s = \frac{\eta_1 c_1 - \eta_2 c_2}{\eta_1 c_1 + \eta_2 c_2}, \qquad
              r_p = \frac{\eta_2 c_1 - \eta_1 c_2}{\eta_2 c_1 + \eta_1 c_2}, \qquad
              F = \tfrac12 (r_s^2 + r_p^2)

    and :math:`F = 1` beyond the critical angle. The ray tracer uses the cheaper
    :func:`schlick`; this is the reference it approximates.

    Parameters
    ----------
    cos_theta : float or array_like
        Cosine of the angle of incidence, in [0, 1].
    eta1, eta2 : float or array_like
        Refractive indices of the medium the ray comes from and of the other one.

    Returns
    -------
    ndarray
        The reflected fraction, in [0, 1].

    Raises
    ------
    ValueError
        For a cosine outside [0, 1], non-positive indices or NaN.

    Examples
    --------
    >>> fresnel([1.0, np.cos(np.radians(60))], 1.0, 1.5).round(4)
    array([0.04  , 0.0892])
    """
    c1, e1, e2 = _cosines(cos_theta, eta1, eta2)
    rs2, rp2 = _fresnel_components(c1, e1, e2)
    return 0.5 * (rs2 + rp2)


def _fresnel_components(c1, e1, e2):
    """The reflectances r_s^2 and r_p^2 of the two polarisations (unvalidated), 1 under total
    internal reflection; :func:`fresnel` and :func:`course_lib.shading.fresnel_dielectric`."""
    c2, tir = _transmitted_cosine(c1, e1, e2)
    with np.errstate(invalid="ignore", divide="ignore"):
        rs = (e1 * c1 - e2 * c2) / (e1 * c1 + e2 * c2)
        rp = (e2 * c1 - e1 * c2) / (e2 * c1 + e1 * c2)
    # 0/0 only at grazing incidence with eta1 = eta2: no interface, nothing reflected
    rs2 = np.where(np.isfinite(rs), rs * rs, 0.0)
    rp2 = np.where(np.isfinite(rp), rp * rp, 0.0)
    return np.where(tir, 1.0, rs2), np.where(tir, 1.0, rp2)
