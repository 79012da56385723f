"""Tests of course_lib.shading.brdf: BRDF models, Fresnel, reflectance, the physical checks.

Reflectances are cross-checked against scipy's ``dblquad`` over (theta_v, phi_v) and against
closed forms typed here (Lambert rho, normalised Phong k_s, unnormalised 2 pi k_s / (n + 2), the
exact Blinn-Phong constant integrated with ``quad``); Fresnel values are typed from optics.
"""
import math

import numpy as np
import pytest
from scipy.integrate import dblquad, quad

from course_lib import shading
from course_lib.shading import brdf as B

Z = np.array([0.0, 0.0, 1.0])


def direction(theta, phi=0.0):
    return np.array([math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi),
                     math.cos(theta)])


def dblquad_reflectance(f, l, centre=None, width=None):
    """rho(l) = int f(l, v) cos(theta) sin(theta) dtheta dphi by scipy, one v at a time."""
    def integrand(theta, phi):
        return float(f(l, direction(theta, phi), Z)) * math.cos(theta) * math.sin(theta)
    if centre is None:
        return dblquad(integrand, -math.pi, math.pi, 0, math.pi / 2, epsabs=1e-10,
                       epsrel=1e-10)[0]
    # a sharp lobe: tell scipy where it is (theta window; the integrand is 0 elsewhere)
    lo, hi = max(0.0, centre - width), min(math.pi / 2, centre + width)
    return dblquad(integrand, -math.pi, math.pi, lo, hi, epsabs=1e-10, epsrel=1e-10)[0]


def phong_f(ks, s, form):
    return lambda l, v, n: B.phong_brdf(l, v, n, ks, s, form)


# ---------------------------------------------------------------------------------------------
# Reflectance against scipy and closed forms
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("rho,theta", [(1.0, 0.0), (0.6, 0.7), (0.25, 1.5)])
def test_lambert_reflects_its_albedo(rho, theta):
    f = lambda l, v, n: B.lambert_brdf(l, v, n, rho)
    l = direction(theta)
    assert B.hemispherical_reflectance(f, l) == pytest.approx(rho, abs=1e-12)
    assert dblquad_reflectance(f, l) == pytest.approx(rho, abs=1e-9)
    assert float(f(l, Z, Z)) == pytest.approx(rho / math.pi)


@pytest.mark.parametrize("s", [1, 5, 30, 200, 1000])
def test_phong_at_normal_incidence(s):
    ks = 0.7
    norm = B.hemispherical_reflectance(phong_f(ks, s, "normalized"), Z, shininess=s)
    plain = B.hemispherical_reflectance(phong_f(ks, s, "modified"), Z, shininess=s)
    assert norm == pytest.approx(ks, rel=1e-7)
    assert plain == pytest.approx(2 * math.pi * ks / (s + 2), rel=1e-7)
    width = min(math.pi / 2, 10 / math.sqrt(s))
    ref = dblquad_reflectance(phong_f(ks, s, "modified"), Z, 0.0, width)
    assert plain == pytest.approx(ref, rel=1e-6)
    assert float(B.phong_normalization(s)) == pytest.approx((s + 2) / (2 * math.pi))


@pytest.mark.parametrize("s,theta", [(3, 0.5), (40, 1.0), (500, 1.2)])
def test_oblique_reflectance_against_dblquad(s, theta):
    l = direction(theta, 0.4)
    for f in (phong_f(0.9, s, "normalized"), phong_f(0.9, s, "original"),
              lambda l, v, n: B.blinn_phong_brdf(l, v, n, 0.9, s, "exact")):
        mine = B.hemispherical_reflectance(f, l, shininess=s)
        ref = dblquad_reflectance(f, l, theta, min(math.pi, 14 / math.sqrt(s)))
        assert mine == pytest.approx(ref, rel=2e-5, abs=1e-9)


def blinn_integral(s):
    """int cos^n(theta_h) cos(theta_v) d omega_v at normal incidence, theta_h = theta_v / 2."""
    return 2 * math.pi * quad(lambda t: math.cos(t / 2) ** s * math.cos(t) * math.sin(t),
                              0, math.pi / 2, epsabs=1e-13)[0]


@pytest.mark.parametrize("s", [0, 1, 4, 16, 100, 1000])
def test_blinn_phong_exact_constant(s):
    exact = (s + 2) * (s + 4) / (8 * math.pi * (s + 2 ** (-s / 2)))
    assert float(B.blinn_phong_normalization(s)) == pytest.approx(exact, rel=1e-12)
    assert exact * blinn_integral(s) == pytest.approx(1.0, rel=1e-9)
    f = lambda l, v, n: B.blinn_phong_brdf(l, v, n, 0.6, s, "exact")
    assert B.hemispherical_reflectance(f, Z, shininess=s or None) == pytest.approx(0.6, rel=1e-7)
    approx = (s + 8) / (8 * math.pi)
    assert float(B.blinn_phong_normalization(s, "approx")) == pytest.approx(approx)
    # the approximation overshoots for small n and converges (ratio -> 1) for large n
    if s >= 1:
        assert approx > exact
    assert abs(approx / exact - 1) < 3 / (s + 1) + 0.01


def test_original_phong_reflectance_grows_towards_grazing():
    f = phong_f(1.0, 50, "original")
    rho = [B.hemispherical_reflectance(f, direction(math.radians(t)), shininess=50)
           for t in (0, 60, 80, 89)]
    assert rho[0] == pytest.approx(2 * math.pi / 52, rel=1e-7)
    assert np.all(np.diff(rho) > 0)
    assert rho[-1] > 3 * rho[0]                 # the 1 / cos(theta_i) blows up near grazing
    big = B.check_brdf(phong_f(1.0, 2, "original"), 2)
    assert not big.energy_conserving and big.max_reflectance > 1


# ---------------------------------------------------------------------------------------------
# Reciprocity, isotropy, energy
# ---------------------------------------------------------------------------------------------

def test_reciprocity_by_swapping():
    rng = np.random.default_rng(3)
    for _ in range(50):
        l = direction(rng.uniform(0, 1.4), rng.uniform(-3, 3))
        v = direction(rng.uniform(0, 1.4), rng.uniform(-3, 3))
        for form in ("normalized", "modified"):
            assert float(B.phong_brdf(l, v, Z, 0.5, 3, form)) == pytest.approx(
                float(B.phong_brdf(v, l, Z, 0.5, 3, form)), rel=1e-12, abs=1e-300)
        assert float(B.blinn_phong_brdf(l, v, Z, 0.5, 3)) == pytest.approx(
            float(B.blinn_phong_brdf(v, l, Z, 0.5, 3)), rel=1e-12)
    # the original form: f(l, v) / f(v, l) = cos(theta_v) / cos(theta_l)
    l, v = direction(0.2), direction(1.0, math.pi)
    ratio = float(B.phong_brdf(l, v, Z, 0.5, 3, "original") / B.phong_brdf(v, l, Z, 0.5, 3,
                                                                              "original"))
    assert ratio == pytest.approx(math.cos(1.0) / math.cos(0.2), rel=1e-12)


def test_check_brdf_classifies_the_models():
    cases = {
        "lambert": (lambda l, v, n: B.lambert_brdf(l, v, n, 0.8), None, (True, True, True)),
        "modified": (phong_f(1.0, 10, "modified"), 10, (True, True, True)),
        "normalized": (phong_f(1.0, 10, "normalized"), 10, (True, True, True)),
        "original": (phong_f(1.0, 10, "original"), 10, (False, True, False)),
        "blinn": (lambda l, v, n: B.blinn_phong_brdf(l, v, n, 1.0, 10), 10, (True, True, True)),
    }
    for name, (f, s, (rec, iso, energy)) in cases.items():
        c = B.check_brdf(f, s)
        assert (c.reciprocal, c.isotropic, c.energy_conserving) == (rec, iso, energy), name
    # normalised Phong with ks = 1 reflects exactly 1 at normal incidence, cos(theta) later
    c = B.check_brdf(phong_f(1.0, 1000, "normalized"), 1000, incidence_deg=[0, 60])
    assert c.reflectance == pytest.approx([1.0, 0.5], abs=2e-3)


def test_anisotropic_brdf_is_detected():
    def aniso(l, v, n):
        return 0.2 + 0.1 * (l[..., 0] * v[..., 0]) ** 2     # prefers the x axis
    c = B.check_brdf(aniso)
    assert c.reciprocal and not c.isotropic


def test_combined_is_sum_and_refuses_too_much_energy():
    l, v = direction(0.5), direction(0.4, math.pi)
    f = B.combined_brdf(l, v, Z, 0.3, 0.6, 20)
    assert float(f) == pytest.approx(0.3 / math.pi + float(B.phong_brdf(l, v, Z, 0.6, 20)))
    rho = B.hemispherical_reflectance(lambda a, b, n: B.combined_brdf(a, b, n, 0.3, 0.6, 20),
                                      Z, shininess=20)
    assert rho == pytest.approx(0.9, rel=1e-7)
    with pytest.raises(ValueError, match="kd \\+ ks"):
        B.combined_brdf(l, v, Z, 0.6, 0.6)
    # the unnormalised model may have kd + ks > 1 (its lobe reflects only 2 ks / (n + 2))
    assert float(B.combined_brdf(l, v, Z, 0.6, 0.6, 20, normalized=False)) > 0


# ---------------------------------------------------------------------------------------------
# Link to the Phong lighting model
# ---------------------------------------------------------------------------------------------

def test_phong_model_terms_are_brdf_times_irradiance():
    theta, Il = 0.6, 1.7
    l, v = direction(theta, 0.3), direction(0.5, 0.3 + math.pi - 0.1)
    mat = shading.Material(ka=0.0, kd=0.4, ks=0.5, shininess=12)
    t = shading.phong(None, Z, v, shading.directional_light(l, Il), mat)
    E = Il * math.cos(theta)
    spec = float(B.phong_brdf(l, v, Z, 0.5, 12, "original")) * E
    assert float(t.specular[0]) == pytest.approx(spec, rel=1e-12)
    assert spec > 0
    # diffuse: Lambert with rho = kd and the irradiance pi * I_l cos(theta)
    diff = float(B.lambert_brdf(l, v, Z, 0.4)) * math.pi * E
    assert float(t.diffuse[0]) == pytest.approx(diff, rel=1e-12)
    L = B.reflected_radiance(lambda a, b, n: B.lambert_brdf(a, b, n, 0.4), [l], v, Z,
                             irradiance=[math.pi * E])
    assert float(L) == pytest.approx(0.4 * Il * math.cos(theta))


def test_reflected_radiance_point_lights():
    f = lambda l, v, n: B.lambert_brdf(l, v, n, 0.5)
    lights = [direction(0.0), direction(math.pi / 3), direction(2.0)]     # the last is below
    L = B.reflected_radiance(f, lights, Z, Z, intensity=[4.0, 2.0, 9.0],
                             distance=[2.0, 1.0, 1.0])
    assert float(L) == pytest.approx(0.5 / math.pi * (4 / 4 + 2 * 0.5))
    with pytest.raises(ValueError, match="exactly one"):
        B.reflected_radiance(f, lights, Z, Z)


def test_mirror_radiance():
    sky = lambda d: 1.0 + d[..., 0]
    v = direction(0.7)
    assert float(B.mirror_radiance(sky, v, Z, 0.9)) == pytest.approx(0.9 * (1 - math.sin(0.7)))
    glass = float(B.mirror_radiance(sky, Z, Z, ior=1.5))
    assert glass == pytest.approx(0.04)
    with pytest.raises(TypeError, match="incoming"):
        B.mirror_radiance(2.0, v, Z)


# ---------------------------------------------------------------------------------------------
# Fresnel
# ---------------------------------------------------------------------------------------------

def test_fresnel_glass():
    assert float(B.fresnel_dielectric(1.0, 1.0, 1.5)) == pytest.approx(0.04, abs=1e-12)
    assert float(B.schlick_f0(1.0, 1.5)) == pytest.approx(0.04)
    brewster = math.atan(1.5)                                   # 56.31 degrees
    assert float(B.fresnel_dielectric(math.cos(brewster), 1.0, 1.5, "p")) == pytest.approx(
        0, abs=1e-15)
    # s-polarised at Brewster: ((cos b - 1.5 cos t) / (cos b + 1.5 cos t))^2, t = 90 deg - b
    cb, ct = math.cos(brewster), math.sin(brewster)
    assert float(B.fresnel_dielectric(cb, 1.0, 1.5, "s")) == pytest.approx(
        ((cb - 1.5 * ct) / (cb + 1.5 * ct)) ** 2)
    # grazing: everything is reflected
    assert float(B.fresnel_dielectric(0.0, 1.0, 1.5)) == pytest.approx(1.0)
    # 45 degrees, air to glass: a textbook value 0.0503
    assert float(B.fresnel_dielectric(math.cos(math.pi / 4), 1.0, 1.5)) == pytest.approx(
        0.0503, abs=1e-4)


def test_total_internal_reflection():
    critical = math.asin(1 / 1.5)                               # 41.8 degrees
    inside = B.fresnel_dielectric(np.cos([critical + 0.01, 1.0, 1.4]), 1.5, 1.0)
    assert np.all(inside == 1.0)
    below = float(B.fresnel_dielectric(math.cos(critical - 0.05), 1.5, 1.0))
    assert 0.04 < below < 1
    assert float(B.fresnel_dielectric(1.0, 1.5, 1.0)) == pytest.approx(0.04)  # symmetric at 0


def test_schlick_close_to_exact_for_glass():
    c = np.linspace(0, 1, 91)
    exact = B.fresnel_dielectric(c, 1.0, 1.5)
    approx = B.fresnel_schlick(c, B.schlick_f0(1.0, 1.5))
    assert np.max(np.abs(exact - approx)) < 0.04          # worst near 85 degrees (0.036)
    assert np.max(np.abs(exact - approx)[c > 0.5]) < 0.02   # 0.019 at 60 degrees
    assert float(B.fresnel_schlick(0.0, 0.04)) == 1.0
    assert float(B.fresnel_schlick(1.0, 0.04)) == pytest.approx(0.04)


# ---------------------------------------------------------------------------------------------
# Bad input
# ---------------------------------------------------------------------------------------------

def test_errors():
    with pytest.raises(ValueError, match="albedo must be >= 0"):
        B.lambert_brdf(Z, Z, Z, -0.1)
    with pytest.raises(ValueError, match="albedo must be <= 1.*more energy"):
        B.lambert_brdf(Z, Z, Z, 1.2)
    with pytest.raises(ValueError, match="l points below the surface"):
        B.lambert_brdf([0, 0, -1], Z, Z)
    with pytest.raises(ValueError, match="v points below the surface"):
        B.phong_brdf(Z, [1, 0, -0.1], Z)
    assert float(B.phong_brdf(Z, [1, 0, -0.1], Z, below="zero")) == 0.0
    with pytest.raises(ValueError, match="below must be one of"):
        B.phong_brdf(Z, Z, Z, below="clamp")
    with pytest.raises(ValueError, match="n must not contain zero vectors"):
        B.blinn_phong_brdf(Z, Z, [0, 0, 0])
    with pytest.raises(ValueError, match="l must be finite"):
        B.lambert_brdf([0, np.nan, 1], Z, Z)
    with pytest.raises(ValueError, match="shininess must be >= 0"):
        B.phong_brdf(Z, Z, Z, 0.5, -1)
    with pytest.raises(ValueError, match="ks must be <= 1"):
        B.phong_brdf(Z, Z, Z, 1.5)
    with pytest.raises(ValueError, match="form must be one of"):
        B.phong_brdf(Z, Z, Z, form="blinn")
    with pytest.raises(ValueError, match="cos_theta must be in"):
        B.fresnel_dielectric(1.2)
    with pytest.raises(ValueError, match="n2 must be a positive refractive index"):
        B.fresnel_dielectric(0.5, 1.0, 0.0)
    with pytest.raises(ValueError, match="broadcast"):
        B.lambert_brdf(np.ones((2, 3)), np.ones((3, 3)), Z)
    with pytest.raises(TypeError, match="brdf must be a function"):
        B.hemispherical_reflectance(0.5, Z)
    with pytest.raises(ValueError, match="l must be above"):
        B.hemispherical_reflectance(lambda l, v, n: 0 * v[..., 0], [0, 0, -1])


def test_vectorized_shapes():
    l = np.stack([direction(t) for t in np.linspace(0, 1.4, 7)])
    f = B.phong_brdf(l, Z, Z, 0.5, 10)
    assert f.shape == (7,)
    for i in range(7):
        assert f[i] == pytest.approx(float(B.phong_brdf(l[i], Z, Z, 0.5, 10)))
    assert B.lambert_brdf(l, Z, Z, 0.5).shape == (7,)


def test_fresnel_agrees_with_the_ray_tracer_s_own():
    """The ray tracer (chapter 15) has its own Fresnel and Schlick: both sides agree."""
    from course_lib.raytracing import optics
    c = np.linspace(0, 1, 37)
    for n1, n2 in ((1.0, 1.5), (1.5, 1.0), (1.0, 2.4)):
        assert np.allclose(B.fresnel_dielectric(c, n1, n2), optics.fresnel(c, n1, n2),
                           atol=1e-12)
    assert np.allclose(B.fresnel_schlick(c, B.schlick_f0(1.0, 1.5)), optics.schlick(c, 1.0, 1.5),
                       atol=1e-12)
