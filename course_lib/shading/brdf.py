r"""Chapter 12 (lesson section 6): BRDFs: Lambert, Phong and Blinn-Phong lobes, Fresnel, energy.

The **bidirectional reflectance distribution function** of a surface point is the ratio of the
radiance reflected towards :math:`v` to the irradiance arriving from a small cone around
:math:`l`,

.. math:: f_r(l, v) = \frac{dL_r(v)}{dE_i(l)} = \frac{dL_r(v)}{L_i(l) \cos\theta_i\, d\omega_i}
          \qquad [\mathrm{sr}^{-1}],

so the **reflectance equation** reads
:math:`L_r(v) = \int_{\Omega} f_r(l, v)\, L_i(l) \cos\theta_i \, d\omega_i`, and for point lights
of intensity :math:`I_k` at distance :math:`d_k` (irradiance
:math:`E_k = I_k \cos\theta_k / d_k^2`) the integral becomes a sum,
:math:`L_r(v) = \sum_k f_r(l_k, v) E_k` (:func:`reflected_radiance`).

Directions follow the package's convention: unit vectors from the surface point outwards,
``l`` towards the light, ``v`` towards the viewer, ``n`` the normal; :math:`\theta_i, \theta_v`
are their angles to ``n``, :math:`\alpha` the angle between ``v`` and the mirror direction
:math:`R = 2 (n \cdot l) n - l`, :math:`\theta_h` the angle between ``n`` and the halfway vector.

A physically plausible BRDF is **non-negative**, **reciprocal** (:math:`f_r(l, v) = f_r(v,
l)`) and **energy conserving**: the directional-hemispherical reflectance
:math:`\rho(l) = \int_\Omega f_r(l, v) \cos\theta_v\, d\omega_v` (:func:`hemispherical_reflectance`)
is at most 1 for every :math:`l`. Most are also **isotropic** (unchanged when ``l`` and ``v``
turn together about ``n``). :func:`check_brdf` tests all three numerically.

**Normalisation constants** (derived in the lesson). Lambert: :math:`\int_\Omega \cos\theta\,
d\omega = \pi`, so :math:`f = \rho/\pi` reflects the fraction :math:`\rho`. Phong at normal
incidence (:math:`R = n`, :math:`\alpha = \theta_v`): :math:`\int_\Omega \cos^n\alpha
\cos\theta_v\, d\omega_v = 2\pi \int_0^1 u^{n+1} du = 2\pi/(n+2)`, so the normalised lobe is
:math:`k_s \frac{n+2}{2\pi}\cos^n\alpha`. Blinn-Phong at normal incidence (:math:`\theta_h =
\theta_v/2`): with :math:`u = \cos(\theta_v/2)`,
:math:`\int_\Omega \cos^n\theta_h \cos\theta_v\, d\omega_v = 8\pi\int_{1/\sqrt2}^1
u^{n+1}(2u^2 - 1)\, du = \frac{8\pi (n + 2^{-n/2})}{(n+2)(n+4)}`, so the **exact** constant is
:math:`\frac{(n+2)(n+4)}{8\pi(n + 2^{-n/2})}` (1/π at n = 0); the popular
:math:`(n+8)/(8\pi)` is an approximation of it (a few percent too large for small n).

**Link to the Phong lighting model** (:func:`course_lib.shading.phong`). Its diffuse term
:math:`k_d I_l (N \cdot L)` is a Lambertian BRDF :math:`f_r = k_d/\pi` (albedo :math:`\rho =
k_d`) lit by the irradiance :math:`E = \pi I_l \cos\theta_i`: the model's "light intensity"
:math:`I_l` is the irradiance of a surface facing the light divided by π (equivalently:
:math:`L_r = \pi f_r E` with :math:`E = I_l\cos\theta_i`, the real-time convention). With
:math:`E = I_l \cos\theta_i` instead, its specular term :math:`k_s I_l \cos^n\alpha` is exactly
the *original* Phong BRDF :math:`k_s \cos^n\alpha / \cos\theta_i` times :math:`E`, a BRDF that is
not reciprocal and whose reflectance grows towards grazing incidence. The *modified*
(reciprocal) lobe :math:`k_s\cos^n\alpha` reflects :math:`2\pi k_s/(n+2)` at normal incidence;
in the π convention the lighting model's lobe is :math:`(k_s/\pi)\cos^n\alpha`, reflecting
:math:`2k_s/(n+2)`: both lose energy as n grows, which the factor :math:`(n+2)/(2\pi)` repairs.
"""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_choice, as_points, as_rng, as_scalar, as_whole
from ._common import _dot, _unit
from .occlusion import _tangent_frame

__all__ = ["BRDFCheck", "blinn_phong_brdf", "blinn_phong_normalization", "check_brdf",
    "combined_brdf", "fresnel_dielectric", "fresnel_schlick", "hemispherical_reflectance",
    "lambert_brdf", "mirror_radiance", "phong_brdf", "phong_normalization",
    "reflected_radiance", "schlick_f0"]

_BELOW_TOL = 1e-12  # n.l or n.v this far below 0 still counts as "on the horizon" (rounding)


# ---------------------------------------------------------------------------------------------
# Input checks
# ---------------------------------------------------------------------------------------------

def _directions(l, v, n, below):
    """Unit l, v, n broadcast together, their cosines with n, and the mask of valid pairs."""
    below = as_choice(below, "below", ("raise", "zero"))
    l, v, n = _unit(l, "l"), _unit(v, "v"), _unit(n, "n")
    try:
        l, v, n = np.broadcast_arrays(l, v, n)
    except ValueError:
        raise ValueError(f"l, v and n must broadcast together, got shapes {l.shape}, "
                         f"{v.shape} and {n.shape}") from None
    cos_l, cos_v = _dot(n, l), _dot(n, v)
    for name, c in (("l", cos_l), ("v", cos_v)):
        if below == "raise" and np.any(c < -_BELOW_TOL):
            raise ValueError(f"{name} points below the surface (n.{name} = "
                             f"{float(np.min(c)):.3g} < 0): a BRDF is defined on the hemisphere "
                             "above n only; pass below='zero' to get 0 there instead")
    valid = (cos_l >= -_BELOW_TOL) & (cos_v >= -_BELOW_TOL)
    return l, v, n, np.clip(cos_l, 0, 1), np.clip(cos_v, 0, 1), valid


def _fraction(value, name, what):
    x = as_array(value, name)
    if np.any(x < 0):
        raise ValueError(f"{name} must be >= 0 ({what}), got {float(np.min(x)):g}: a BRDF is "
                         "never negative")
    if np.any(x > 1):
        raise ValueError(f"{name} must be <= 1 ({what}), got {float(np.max(x)):g}: a surface "
                         "cannot reflect more energy than it receives")
    return x


def _exponent(value):
    s = as_array(value, "shininess")
    if np.any(s < 0):
        raise ValueError(f"shininess must be >= 0 (the exponent n of the lobe), got "
                         f"{float(np.min(s)):g}")
    return s


# ---------------------------------------------------------------------------------------------
# BRDF models
# ---------------------------------------------------------------------------------------------

def lambert_brdf(l, v, n, albedo=1.0, below="raise"):
    r"""The Lambertian (ideal diffuse) BRDF :math:`f_r = \rho / \pi` in 1/sr.

    The same value for every pair of directions above the surface; the :math:`1/\pi` makes the
    reflected fraction :math:`\int_\Omega (\rho/\pi)\cos\theta\, d\omega` equal :math:`\rho`.

    Parameters
    ----------
    l, v, n : array_like, shape (..., 3)
        Towards the light, towards the viewer, the normal (normalized here; broadcast).
    albedo : float or array_like
        :math:`\rho \in [0, 1]`, the fraction of the incoming energy reflected.
    below : {'raise', 'zero'}
        What to do where ``l`` or ``v`` is below the surface: raise ValueError, or return 0.

    Returns
    -------
    ndarray, shape (...)

    Raises
    ------
    ValueError
        For an albedo outside [0, 1], zero or non-finite vectors, or directions below the
        surface with ``below='raise'``.

    Examples
    --------
    >>> round(float(lambert_brdf([0, 0, 1], [1, 0, 1], [0, 0, 1], albedo=0.5) * np.pi), 12)
    0.5
    """
    rho = _fraction(albedo, "albedo", "the fraction of the light reflected")
    l, v, n, cos_l, cos_v, valid = _directions(l, v, n, below)
    return np.where(valid, rho / np.pi, 0.0) * np.ones(cos_l.shape)


def phong_normalization(shininess):
    r"""The constant :math:`(n+2)/(2\pi)` that makes a Phong lobe reflect :math:`k_s` at normal
    incidence: :math:`\int_\Omega \cos^n\alpha \cos\theta_v\, d\omega_v = 2\pi/(n+2)` when
    :math:`R = n`.

    Examples
    --------
    >>> round(float(phong_normalization(2) * np.pi), 12)
    2.0
    """
    return (_exponent(shininess) + 2) / (2 * np.pi)


def blinn_phong_normalization(shininess, kind="exact"):
    r"""The constant of a normalised Blinn-Phong lobe :math:`C\,k_s\cos^n\theta_h`.

    ``kind='exact'``: :math:`C = \frac{(n+2)(n+4)}{8\pi(n + 2^{-n/2})}`, the value that makes the
    reflectance at normal incidence exactly :math:`k_s` (derived in the module docstring).
    ``kind='approx'``: the common approximation :math:`(n+8)/(8\pi)`.

    Examples
    --------
    >>> round(float(blinn_phong_normalization(0) * np.pi), 12)      # n = 0: the Lambert 1/pi
    1.0
    >>> round(float(blinn_phong_normalization(10, "approx") * 8 * np.pi), 12)
    18.0
    """
    s = _exponent(shininess)
    kind = as_choice(kind, "kind", ("exact", "approx"))
    if kind == "approx":
        return (s + 8) / (8 * np.pi)
    return (s + 2) * (s + 4) / (8 * np.pi * (s + 2.0 ** (-s / 2)))


def phong_brdf(l, v, n, ks=1.0, shininess=10.0, form="normalized", below="raise"):
    r"""Phong's specular lobe as a BRDF, in three forms (1/sr).

    * ``'original'``: :math:`k_s\cos^n\alpha / \cos\theta_i`, the lighting model
      :math:`k_s I_l \cos^n\alpha` divided by :math:`E = I_l\cos\theta_i`; not reciprocal
      (0 is returned at exactly grazing incidence, where :math:`E = 0` anyway).
    * ``'modified'``: :math:`k_s\cos^n\alpha`; reciprocal, but not normalised: it reflects
      :math:`2\pi k_s/(n+2)` at normal incidence, more than 1 for small n
      (:math:`n < 2\pi k_s - 2`) and almost nothing for large n. (Read with the π convention of
      the lighting model, its specular lobe is :math:`(k_s/\pi)\cos^n\alpha`, which reflects
      :math:`2k_s/(n+2)`.)
    * ``'normalized'``: :math:`k_s\frac{n+2}{2\pi}\cos^n\alpha`; reciprocal and reflecting
      :math:`k_s` at normal incidence, less elsewhere (the horizon cuts the lobe).

    :math:`\cos\alpha = \max(R \cdot v, 0)` with :math:`R` the mirror direction of ``l``.

    Parameters
    ----------
    l, v, n : array_like, shape (..., 3)
    ks : float or array_like
        Specular coefficient in [0, 1].
    shininess : float or array_like
        The exponent :math:`n \ge 0`.
    form : {'normalized', 'modified', 'original'}
    below : {'raise', 'zero'}

    Returns
    -------
    ndarray, shape (...)

    Raises
    ------
    ValueError
        For ks outside [0, 1], a negative exponent, an unknown form, zero or non-finite
        vectors, or directions below the surface with ``below='raise'``.

    Examples
    --------
    Viewer in the mirror direction of a light at 60 degrees:

    >>> l, v = [np.sin(np.pi / 3), 0, 0.5], [-np.sin(np.pi / 3), 0, 0.5]
    >>> [round(float(phong_brdf(l, v, [0, 0, 1], 0.5, 2, f)), 6)
    ...  for f in ("original", "modified")]
    [1.0, 0.5]
    """
    ks = _fraction(ks, "ks", "the specular coefficient")
    s = _exponent(shininess)
    form = as_choice(form, "form", ("normalized", "modified", "original"))
    l, v, n, cos_l, cos_v, valid = _directions(l, v, n, below)
    r = 2 * _dot(n, l)[..., None] * n - l
    lobe = ks * np.clip(_dot(r, v), 0, 1) ** s
    if form == "normalized":
        lobe = lobe * (s + 2) / (2 * np.pi)
    elif form == "original":
        lobe = np.divide(lobe, cos_l, out=np.zeros(np.broadcast(lobe, cos_l).shape),
                         where=cos_l > 0)
    return np.where(valid, lobe, 0.0)


def blinn_phong_brdf(l, v, n, ks=1.0, shininess=40.0, normalization="exact", below="raise"):
    r"""The Blinn-Phong lobe :math:`C\,k_s\cos^n\theta_h` as a BRDF (1/sr), reciprocal.

    :math:`\cos\theta_h = n \cdot h` with :math:`h = (l + v)/\lVert l + v\rVert`.
    ``normalization`` picks :math:`C`: ``'exact'`` (reflectance :math:`k_s` at normal
    incidence, :func:`blinn_phong_normalization`), ``'approx'`` (:math:`(n+8)/(8\pi)`) or
    ``'none'`` (:math:`C = 1`).

    Examples
    --------
    >>> float(blinn_phong_brdf([1, 0, 1], [-1, 0, 1], [0, 0, 1], 0.3, 5, "none"))  # h = n
    0.3
    """
    ks = _fraction(ks, "ks", "the specular coefficient")
    s = _exponent(shininess)
    normalization = as_choice(normalization, "normalization", ("exact", "approx", "none"))
    l, v, n, cos_l, cos_v, valid = _directions(l, v, n, below)
    h = l + v
    length = np.sqrt(_dot(h, h))
    cos_h = np.divide(_dot(n, h), length, out=np.zeros(length.shape), where=length > 0)
    lobe = ks * np.clip(cos_h, 0, 1) ** s
    if normalization != "none":
        lobe = lobe * blinn_phong_normalization(s, normalization)
    return np.where(valid, lobe, 0.0)


def combined_brdf(l, v, n, kd=0.5, ks=0.5, shininess=10.0, model="phong", normalized=True,
                  below="raise"):
    r"""Diffuse plus specular: :math:`f_r = k_d/\pi + f_{spec}` (1/sr).

    ``model='phong'`` uses :func:`phong_brdf` (form ``'normalized'`` or ``'modified'``),
    ``model='blinn-phong'`` uses :func:`blinn_phong_brdf` (``'exact'`` or ``'none'``). A
    normalised model reflects at most :math:`k_d + k_s`, so it is energy conserving exactly when
    :math:`k_d + k_s \le 1`; more is refused.

    Raises
    ------
    ValueError
        For coefficients outside [0, 1], :math:`k_d + k_s > 1` with ``normalized=True``, and
        the errors of the lobes.

    Examples
    --------
    >>> f = combined_brdf([0, 0, 1], [0, 0, 1], [0, 0, 1], kd=0.5, ks=0.5, shininess=0)
    >>> round(float(f * np.pi), 12)            # 0.5 + 0.5 * (0 + 2) / 2
    1.0
    >>> combined_brdf([0, 0, 1], [0, 0, 1], [0, 0, 1], kd=0.7, ks=0.5)
    Traceback (most recent call last):
    ...
    ValueError: kd + ks must be <= 1 for a normalised model, got 0.7 + 0.5 = 1.2: it would reflect more energy than it receives (at normal incidence rho = kd + ks)
    """
    kd = _fraction(kd, "kd", "the diffuse coefficient")
    ks = _fraction(ks, "ks", "the specular coefficient")
    model = as_choice(model, "model", ("phong", "blinn-phong"))
    if normalized and np.any(kd + ks > 1 + 1e-12):
        i = np.argmax(np.broadcast_to(kd + ks, np.broadcast(kd, ks).shape))
        a, b = np.broadcast_to(kd, np.broadcast(kd, ks).shape).flat[i], \
            np.broadcast_to(ks, np.broadcast(kd, ks).shape).flat[i]
        raise ValueError(f"kd + ks must be <= 1 for a normalised model, got {a:g} + {b:g} = "
                         f"{a + b:g}: it would reflect more energy than it receives (at normal "
                         "incidence rho = kd + ks)")
    diffuse = lambert_brdf(l, v, n, kd, below)
    if model == "phong":
        spec = phong_brdf(l, v, n, ks, shininess, "normalized" if normalized else "modified",
                          below)
    else:
        spec = blinn_phong_brdf(l, v, n, ks, shininess, "exact" if normalized else "none",
                                below)
    return diffuse + spec


# ---------------------------------------------------------------------------------------------
# Fresnel and the ideal mirror
# ---------------------------------------------------------------------------------------------

def _incidence_cosines(cos_theta):
    c = as_array(cos_theta, "cos_theta")
    if np.any((c < 0) | (c > 1)):
        raise ValueError("cos_theta must be in [0, 1] (the cosine of an angle of incidence "
                         f"between 0 and 90 degrees), got {float(c[(c < 0) | (c > 1)][0]):g}")
    return c


def _refractive_index(value, name):
    x = as_array(value, name)
    if np.any(x <= 0):
        raise ValueError(f"{name} must be a positive refractive index (1 for air, 1.5 for "
                         f"glass), got {float(np.min(x)):g}")
    return x


def fresnel_dielectric(cos_theta, n1=1.0, n2=1.5, polarization="unpolarized"):
    r"""Exact Fresnel reflectance of a smooth dielectric boundary, light coming from medium n1.

    With :math:`\sin\theta_t = (n_1/n_2)\sin\theta_i` (Snell; :math:`n_2/n_1` is the relative
    index),

    .. math:: r_s = \frac{n_1\cos\theta_i - n_2\cos\theta_t}{n_1\cos\theta_i + n_2\cos\theta_t},
              \quad r_p = \frac{n_2\cos\theta_i - n_1\cos\theta_t}{n_2\cos\theta_i +
              n_1\cos\theta_t}, \quad F = \tfrac12 (r_s^2 + r_p^2);

    :math:`F = 1` under total internal reflection (:math:`\sin\theta_t > 1`, only when
    :math:`n_1 > n_2`). The ray tracer's :func:`course_lib.raytracing.fresnel` computes the
    same unpolarised value with the same code (one implementation of Fresnel's equations);
    this one also gives each polarisation: ``polarization='s'`` or ``'p'`` returns :math:`r_s^2` or
    :math:`r_p^2` (:math:`r_p = 0` at Brewster's angle :math:`\tan\theta_B = n_2/n_1`).

    Examples
    --------
    >>> round(float(fresnel_dielectric(1.0, 1.0, 1.5)), 12)    # ((1 - 1.5) / (1 + 1.5))^2
    0.04
    >>> float(fresnel_dielectric(0.5, 1.5, 1.0))                # 60 deg inside glass: TIR
    1.0
    """
    from ..raytracing.optics import _fresnel_components    # here: raytracing imports shading

    c = _incidence_cosines(cos_theta)
    n1, n2 = _refractive_index(n1, "n1"), _refractive_index(n2, "n2")
    polarization = as_choice(polarization, "polarization", ("unpolarized", "s", "p"))
    c, n1, n2 = np.broadcast_arrays(c, n1, n2)
    rs2, rp2 = _fresnel_components(c, n1, n2)
    return {"s": rs2, "p": rp2, "unpolarized": 0.5 * (rs2 + rp2)}[polarization]


def schlick_f0(n1=1.0, n2=1.5):
    r"""Reflectance at normal incidence :math:`F_0 = ((n_1 - n_2)/(n_1 + n_2))^2`.

    Examples
    --------
    >>> round(float(schlick_f0(1.0, 1.5)), 12)
    0.04
    """
    n1, n2 = _refractive_index(n1, "n1"), _refractive_index(n2, "n2")
    return ((n1 - n2) / (n1 + n2)) ** 2


def fresnel_schlick(cos_theta, f0=0.04):
    r"""Schlick's approximation :math:`F \approx F_0 + (1 - F_0)(1 - \cos\theta)^5`.

    Good from the optically thinner side (air into glass); for light inside the denser medium
    use the cosine of the transmitted angle instead (it misses total internal reflection).

    Examples
    --------
    >>> float(fresnel_schlick(0.5, 0.04))                 # 0.04 + 0.96 / 32
    0.07
    """
    c = _incidence_cosines(cos_theta)
    f0 = _fraction(f0, "f0", "the reflectance at normal incidence")
    return f0 + (1 - f0) * (1 - c) ** 5


def mirror_radiance(incoming, v, n, reflectance=1.0, ior=None):
    r"""The ideal mirror: :math:`L_r(v) = F\,L_i(R_v)` with :math:`R_v = 2(n\cdot v)n - v`.

    Its BRDF is a delta, :math:`f_r = F\,\delta(l - R_v)/\cos\theta_i`, which has no value to
    evaluate: the reflectance equation collapses to reading the incoming radiance from the one
    mirror direction. ``incoming`` is a function of unit directions ``(..., 3)`` returning
    radiance; :math:`F` is `reflectance`, or the exact Fresnel factor of a dielectric of index
    `ior` (seen from air) when given.

    Examples
    --------
    >>> sky = lambda d: 2.0 * d[..., 2]               # brighter towards the zenith
    >>> round(float(mirror_radiance(sky, [1, 0, 1], [0, 0, 1], 0.5)), 6)  # 0.5 * 2 cos 45
    0.707107
    """
    if not callable(incoming):
        raise TypeError("incoming must be a function of directions returning radiance "
                        f"(L_i(direction)), got {type(incoming).__name__}")
    v, n = _unit(v, "v"), _unit(n, "n")
    cos_v = _dot(n, v)
    if np.any(cos_v < -_BELOW_TOL):
        raise ValueError("v points below the surface (n.v < 0): the mirror reflects only "
                         "towards viewers above it")
    r = 2 * cos_v[..., None] * n - v
    if ior is None:
        f = _fraction(reflectance, "reflectance", "the mirror's reflectance F")
    else:
        f = fresnel_dielectric(np.clip(cos_v, 0, 1), 1.0, ior)
    return f * as_array(incoming(r), "incoming(direction)")


# ---------------------------------------------------------------------------------------------
# The reflectance equation
# ---------------------------------------------------------------------------------------------

def reflected_radiance(brdf, l, v, n, *, irradiance=None, intensity=None, distance=1.0):
    r"""Reflected radiance of point lights: :math:`L_r(v) = \sum_k f_r(l_k, v)\,E_k`.

    Either the irradiances :math:`E_k` are given, or the intensities :math:`I_k` (and
    distances), and :math:`E_k = I_k\max(\cos\theta_k, 0)/d_k^2`. Lights below the surface add
    nothing. This is the reflectance equation
    :math:`L_r = \int_\Omega f_r L_i\cos\theta_i\, d\omega_i` for an incoming radiance made of
    deltas.

    Parameters
    ----------
    brdf : callable
        ``brdf(l, v, n)`` returning 1/sr, e.g. ``lambda l, v, n: lambert_brdf(l, v, n, 0.5)``.
    l : array_like, shape (k, 3) or (..., k, 3)
        Directions towards the k lights.
    v, n : array_like, shape (3,) or (..., 3)
    irradiance, intensity, distance : array_like, shape (k,) or (..., k)
        Give `irradiance` or `intensity` (with `distance`, default 1).

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    A white Lambertian surface, a light of intensity 2 at distance 1 and 60 degrees:

    >>> f = lambda l, v, n: lambert_brdf(l, v, n, 1.0)
    >>> L = reflected_radiance(f, [[np.sin(np.pi / 3), 0, 0.5]], [0, 0, 1], [0, 0, 1],
    ...                        intensity=[2.0])
    >>> round(float(L * np.pi), 12)             # (1 / pi) * 2 * 0.5 / 1
    1.0
    """
    if not callable(brdf):
        raise TypeError(f"brdf must be a function brdf(l, v, n), got {type(brdf).__name__}")
    if (irradiance is None) == (intensity is None):
        raise ValueError("give exactly one of irradiance (E_k) or intensity (I_k, with "
                         "distance)")
    l = _unit(as_points(l, "l", dims=3), "l")
    if l.ndim < 2:
        l = l[None]
    v = _unit(v, "v")[..., None, :]
    n = _unit(n, "n")[..., None, :]
    cos_l = _dot(n, l)
    lit = cos_l > 0
    safe_l = np.where(lit[..., None], l, n)      # evaluate the BRDF only where it is defined
    if irradiance is not None:
        e = as_array(irradiance, "irradiance")
        if np.any(e < 0):
            raise ValueError("irradiance must be >= 0")
    else:
        i = as_array(intensity, "intensity")
        d = as_array(distance, "distance")
        if np.any(i < 0):
            raise ValueError("intensity must be >= 0")
        if np.any(d <= 0):
            raise ValueError("distance must be > 0 (a light at the surface point has no "
                             "direction)")
        e = i * np.clip(cos_l, 0, None) / d ** 2
    f = as_array(brdf(safe_l, v, n), "brdf(l, v, n)")
    return np.sum(np.where(lit, f * e, 0.0), axis=-1)


# ---------------------------------------------------------------------------------------------
# Reflectance and the physical checks
# ---------------------------------------------------------------------------------------------

def _gauss_pieces(breaks, order):
    """Gauss-Legendre nodes and weights on consecutive intervals between `breaks`."""
    x, w = np.polynomial.legendre.leggauss(order)
    nodes, weights = [], []
    for a, b in zip(breaks[:-1], breaks[1:]):
        if b > a:
            nodes.append(0.5 * (b - a) * x + 0.5 * (a + b))
            weights.append(0.5 * (b - a) * w)
    return np.concatenate(nodes), np.concatenate(weights)


def hemispherical_reflectance(brdf, l, n=(0.0, 0.0, 1.0), shininess=None, order=48):
    r"""Directional-hemispherical reflectance :math:`\rho(l) = \int_\Omega f_r(l, v)
    \cos\theta_v\, d\omega_v` by deterministic quadrature.

    In :math:`(\theta_v, \phi_v)` about ``n``, :math:`d\omega = \sin\theta\, d\theta\, d\phi`,
    so the hemisphere is exactly the rectangle :math:`[0, \pi/2] \times [-\pi, \pi]`.
    Gauss-Legendre rules of `order` points are used on pieces of it; when `shininess` is given,
    extra breakpoints concentrate the nodes within :math:`12/\sqrt{n}` of the mirror direction
    (a Phong lobe :math:`\cos^n\alpha \approx e^{-n\alpha^2/2}`, a Blinn-Phong one about twice
    as wide), which keeps the result accurate to about 1e-8 for exponents up to several
    thousand.

    Parameters
    ----------
    brdf : callable
        ``brdf(l, v, n)``, vectorized over ``v`` of shape ``(m, 3)``.
    l : array_like, shape (3,) or (k, 3)
        Incident direction(s), above the surface.
    n : array_like, shape (3,)
    shininess : float, optional
        The lobe's exponent, to place the nodes; None for smooth BRDFs.
    order : int
        Gauss-Legendre points per piece and axis.

    Returns
    -------
    float or ndarray, shape (k,)

    Examples
    --------
    >>> f = lambda l, v, n: phong_brdf(l, v, n, 0.8, 100, "normalized")
    >>> round(float(hemispherical_reflectance(f, [0, 0, 1], shininess=100)), 8)
    0.8
    """
    if not callable(brdf):
        raise TypeError(f"brdf must be a function brdf(l, v, n), got {type(brdf).__name__}")
    n = _unit(as_array(n, "n").reshape(-1), "n")
    if n.shape != (3,):
        raise ValueError(f"n must be one normal of 3 numbers, got shape {n.shape}")
    ls = _unit(l, "l")
    single = ls.ndim == 1
    ls = ls.reshape(-1, 3)
    if np.any(ls @ n < -_BELOW_TOL):
        raise ValueError("l must be above the surface (n.l >= 0) for a reflectance")
    order = as_whole(order, "order", minimum=2)
    width = None
    if shininess is not None:
        s = as_scalar(shininess, "shininess")
        if s < 0:
            raise ValueError(f"shininess must be >= 0, got {s:g}")
        width = min(np.pi, 12.0 / np.sqrt(s)) if s > 0 else None
    t1, t2 = _tangent_frame(n)
    out = np.empty(len(ls))
    for k, lk in enumerate(ls):
        ct = np.clip(lk @ n, -1, 1)
        theta_r = np.arccos(ct)                       # the mirror direction's polar angle
        phi_r = np.arctan2(-(lk @ t2), -(lk @ t1))    # and azimuth (opposite to l's)
        tb, pb = [0.0, np.pi / 2], [-np.pi, np.pi]
        if width is not None:
            tb = sorted({0.0, np.pi / 2, *np.clip([theta_r - width, theta_r - width / 4,
                         theta_r, theta_r + width / 4, theta_r + width], 0, np.pi / 2)})
            if np.sin(theta_r) > 1e-9:
                dphi = min(np.pi, width / np.sin(theta_r))
                pb = sorted({-np.pi, np.pi, *np.clip([-dphi, -dphi / 4, 0, dphi / 4, dphi],
                             -np.pi, np.pi)})
        th, wt = _gauss_pieces(np.array(tb), order)
        ph, wp = _gauss_pieces(np.array(pb), order)
        T, P = np.meshgrid(th, ph + phi_r, indexing="ij")
        dirs = (np.sin(T)[..., None] * (np.cos(P)[..., None] * t1 + np.sin(P)[..., None] * t2)
                + np.cos(T)[..., None] * n).reshape(-1, 3)
        f = np.asarray(brdf(lk, dirs, n), dtype=float).reshape(T.shape)
        out[k] = np.sum(f * (np.cos(T) * np.sin(T) * wt[:, None]) * wp[None, :])
    return float(out[0]) if single else out


class BRDFCheck(NamedTuple):
    """What :func:`check_brdf` found: the reflectances and the three verdicts with their errors.

    Examples
    --------
    >>> c = check_brdf(lambda l, v, n: lambert_brdf(l, v, n, 0.5), incidence_deg=[0, 45])
    >>> c.reflectance.round(12).tolist(), c.energy_conserving, c.reciprocal, c.isotropic
    ([0.5, 0.5], True, True, True)
    """
    incidence_deg: np.ndarray          # the incidence angles tried
    reflectance: np.ndarray            # rho(l) at each of them
    max_reflectance: float
    energy_conserving: bool            # max reflectance <= 1 (+ tolerance)
    reciprocity_error: float           # max relative |f(l, v) - f(v, l)| over the pairs
    reciprocal: bool
    isotropy_error: float              # max relative change under a common rotation about n
    isotropic: bool


def _relative(a, b):
    scale = np.maximum(np.maximum(np.abs(a), np.abs(b)), 1e-300)
    return float(np.max(np.abs(a - b) / scale))


def check_brdf(brdf, shininess=None, incidence_deg=None, pairs=400, seed=0, tol=1e-6):
    r"""Test a BRDF for energy conservation, reciprocity and isotropy (normal ``n = +z``).

    * energy: :math:`\max_l \rho(l) \le 1` over the incidence angles (default 0, 5, ..., 85
      and 89 degrees), by :func:`hemispherical_reflectance`;
    * reciprocity: :math:`f(l, v) = f(v, l)` on `pairs` seeded direction pairs (half uniform
      on the hemisphere, half near the mirror configuration where a lobe is not negligible);
    * isotropy: :math:`f(Ql, Qv) = f(l, v)` for random rotations :math:`Q` about the normal.

    Examples
    --------
    >>> c = check_brdf(lambda l, v, n: phong_brdf(l, v, n, 1.0, 2, "original"), 2)
    >>> c.reciprocal, c.isotropic, c.energy_conserving
    (False, True, False)
    """
    if not callable(brdf):
        raise TypeError(f"brdf must be a function brdf(l, v, n), got {type(brdf).__name__}")
    pairs = as_whole(pairs, "pairs", minimum=2)
    rng = as_rng(seed)
    z = np.array([0.0, 0.0, 1.0])
    if incidence_deg is None:
        incidence_deg = np.append(np.arange(0, 90, 5.0), 89.0)
    angles = np.radians(as_array(incidence_deg, "incidence_deg").reshape(-1))
    if np.any((angles < 0) | (angles > np.pi / 2)):
        raise ValueError("incidence_deg must be between 0 and 90 degrees")
    ls = np.stack([np.sin(angles), 0 * angles, np.cos(angles)], axis=-1)
    rho = np.atleast_1d(hemispherical_reflectance(brdf, ls, z, shininess))

    def direction(theta, phi):
        return np.stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi),
                         np.cos(theta)], axis=-1)

    half = pairs // 2
    t_l = np.arccos(rng.uniform(0.02, 1, pairs))
    p_l = rng.uniform(-np.pi, np.pi, pairs)
    t_v = np.concatenate([np.arccos(rng.uniform(0.02, 1, half)),
                          np.clip(t_l[half:] + rng.uniform(-0.05, 0.05, pairs - half),
                                  0.01, 1.55)])
    p_v = np.concatenate([rng.uniform(-np.pi, np.pi, half),
                          p_l[half:] + np.pi + rng.uniform(-0.05, 0.05, pairs - half)])
    l, v = direction(t_l, p_l), direction(t_v, p_v)
    f_lv = np.asarray(brdf(l, v, z), float)
    f_vl = np.asarray(brdf(v, l, z), float)
    turn = rng.uniform(0, 2 * np.pi, pairs)
    f_rot = np.asarray(brdf(direction(t_l, p_l + turn), direction(t_v, p_v + turn), z), float)
    rec, iso = _relative(f_lv, f_vl), _relative(f_lv, f_rot)
    best = float(np.max(rho))
    return BRDFCheck(np.degrees(angles), rho, best, bool(best <= 1 + tol), rec,
                     bool(rec <= tol), iso, bool(iso <= tol))
