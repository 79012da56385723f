"""Radiometry (course_lib.shading.radiometry): solid angles and irradiance, checked against
closed forms typed here and against scipy.integrate over the directions or the light's area."""

import numpy as np
import pytest
from scipy import integrate

from course_lib.shading import radiometry as rad

PI = np.pi


def _square(center, half, normal_sign=-1.0):
    """A square of half-side `half` in the plane z = center[2], facing -z by default."""
    cx, cy, cz = center
    sq = np.array([[cx - half, cy - half, cz], [cx + half, cy - half, cz],
                   [cx + half, cy + half, cz], [cx - half, cy + half, cz]])
    return sq[::-1] if normal_sign < 0 else sq     # reversed: right-hand normal -z


def _rect_surface_integral(f, origin, u, v):
    """Integral of f(x) over the parallelogram origin + s u + t v, s, t in [0, 1]."""
    origin, u, v = (np.asarray(a, float) for a in (origin, u, v))
    jac = np.linalg.norm(np.cross(u, v))
    val, _ = integrate.dblquad(lambda t, s: f(origin + s * u + t * v), 0, 1, 0, 1,
                               epsabs=1e-11, epsrel=1e-10)
    return val * jac


# ---------------------------------------------------------------------------------------------
# Solid angles
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("alpha", [0.0, 0.1, 0.7, PI / 2, 2.5, PI])
def test_cone_solid_angle_closed_form_and_dblquad(alpha):
    ref, _ = integrate.dblquad(lambda t, p: np.sin(t), 0, 2 * PI, 0, alpha)
    assert rad.cone_solid_angle(alpha) == pytest.approx(2 * PI * (1 - np.cos(alpha)), abs=1e-12)
    assert rad.cone_solid_angle(alpha) == pytest.approx(ref, abs=1e-10)


def test_sphere_hemisphere_and_small_cone():
    assert rad.cone_solid_angle(PI) == pytest.approx(4 * PI)
    assert rad.cone_solid_angle(PI / 2) == pytest.approx(2 * PI)
    a = 1e-3
    assert rad.cone_solid_angle(a) == pytest.approx(PI * a * a, rel=1e-6)
    out = rad.cone_solid_angle([0, PI / 3])
    assert np.allclose(out, [0, PI])


@pytest.mark.parametrize("t1,t2,p1,p2", [(0, PI, 0, 2 * PI), (0.2, 1.1, 0.5, 2.0),
                                         (PI / 3, PI / 2, -1.0, 1.5), (1.0, 3.0, 0, 6.0)])
def test_spherical_region_against_dblquad(t1, t2, p1, p2):
    ref, _ = integrate.dblquad(lambda t, p: np.sin(t), p1, p2, t1, t2)
    assert rad.spherical_region_solid_angle(t1, t2, p1, p2) == pytest.approx(ref, abs=1e-10)


def test_cube_face_from_centre_and_the_six_faces_fill_the_sphere():
    face = np.array([[-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], float)
    assert rad.polygon_solid_angle(face, [0, 0, 0]) == pytest.approx(4 * PI / 6, rel=1e-12)
    # the six faces of the cube, seen from any interior point, add up to the whole sphere
    faces = []
    for axis in range(3):
        for sign in (-1, 1):
            f = np.roll(face, axis, axis=1) * np.where(np.arange(3) == (axis + 2) % 3, sign, 1)
            faces.append(f)
    p = np.array([[0.3, -0.5, 0.7], [0.0, 0.0, 0.0], [-0.9, 0.9, 0.1]])
    total = sum(rad.polygon_solid_angle(f, p) for f in faces)
    assert np.allclose(total, 4 * PI, rtol=1e-11)


@pytest.mark.parametrize("point", [[0.2, 0.1, 1.0], [2.0, -1.0, 0.5], [0.4, 0.3, 0.05],
                                   [0.5, 0.5, -0.3]])
def test_polygon_solid_angle_against_surface_integral(point):
    """Omega = integral over the polygon of |cos theta| / r^2 dA (a tilted parallelogram)."""
    origin, u, v = np.array([0.0, 0.0, 0.0]), np.array([1.0, 0.0, 0.2]), np.array([0.3, 1.0, 0.0])
    n = np.cross(u, v) / np.linalg.norm(np.cross(u, v))
    p = np.array(point)

    def f(x):
        d = x - p
        r = np.linalg.norm(d)
        return abs(d @ n) / r ** 3

    ref = _rect_surface_integral(f, origin, u, v)
    poly = np.array([origin, origin + u, origin + u + v, origin + v])
    assert rad.polygon_solid_angle(poly, p) == pytest.approx(ref, rel=1e-7)
    assert rad.polygon_solid_angle(poly[::-1], p) == pytest.approx(ref, rel=1e-7)


def test_solid_angle_above_pi_keeps_its_branch():
    """Close to a big square, the solid angle tends to 2 pi (> pi: atan2 branch)."""
    big = _square([0, 0, 1], 50.0)
    omega = rad.polygon_solid_angle(big, [0, 0, 0])
    # exact for a square of half-side a at height h, seen from above its centre
    a, h = 50.0, 1.0
    exact = 4 * np.arcsin(a * a / (a * a + h * h))
    assert omega > PI
    assert omega == pytest.approx(exact, rel=1e-10)


def test_additivity_when_a_polygon_is_split():
    rng = np.random.default_rng(3)
    quad = np.array([[0, 0, 0], [2, 0, 0], [2.5, 1.5, 0], [0.2, 1.0, 0]], float)
    points = rng.uniform(-1, 3, (20, 3))
    points[:, 2] = rng.uniform(0.1, 2.0, 20) * rng.choice([-1, 1], 20)
    whole = rad.polygon_solid_angle(quad, points)
    halves = (rad.polygon_solid_angle(quad[[0, 1, 2]], points)
              + rad.polygon_solid_angle(quad[[0, 2, 3]], points))
    assert np.allclose(whole, halves, rtol=1e-11)
    # a non-convex L shape = two rectangles
    ell = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]], float)
    r1 = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]], float)
    r2 = np.array([[0, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]], float)
    assert np.allclose(rad.polygon_solid_angle(ell, points),
                       rad.polygon_solid_angle(r1, points) + rad.polygon_solid_angle(r2, points),
                       rtol=1e-11)


def test_polygon_on_its_own_plane_outside_is_zero_and_inside_is_an_error():
    sq = _square([0, 0, 0], 1.0)
    assert rad.polygon_solid_angle(sq, [5, 0, 0]) == pytest.approx(0.0, abs=1e-14)
    with pytest.raises(ValueError, match="points"):
        rad.polygon_solid_angle(sq, [0.2, 0.3, 0.0])


def test_patch_approximation_error_falls_like_size_over_distance_squared():
    n = np.array([np.sin(0.6), 0.0, np.cos(0.6)])
    b1 = np.array([np.cos(0.6), 0.0, -np.sin(0.6)])
    b2 = np.array([0.0, 1.0, 0.0])
    c, p = np.array([0.3, 0.2, 2.0]), np.zeros(3)
    errors = []
    for s in (0.4, 0.2, 0.1, 0.05):
        poly = c + s / 2 * np.array([-b1 - b2, b1 - b2, b1 + b2, -b1 + b2])
        exact = rad.polygon_solid_angle(poly, p)
        approx = rad.patch_solid_angle(s * s, n, c, p)
        d = np.linalg.norm(c - p)
        cos = abs(n @ (c - p)) / d
        assert approx == pytest.approx(s * s * cos / d ** 2, rel=1e-12)
        errors.append(abs(approx - exact) / exact)
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratios > 3.5) & (ratios < 4.5))


# ---------------------------------------------------------------------------------------------
# Point light
# ---------------------------------------------------------------------------------------------

def test_point_light_numbers_and_factors():
    light = 5 * np.array([np.sin(PI / 3), 0, np.cos(PI / 3)])
    r = rad.point_light_irradiance([0, 0, 0], [0, 0, 1], light, 100.0)
    assert r.irradiance == pytest.approx(100 * 0.5 / 25)
    assert r.cos_theta == pytest.approx(0.5)
    assert r.inv_d2 == pytest.approx(1 / 25)
    assert r.distance == pytest.approx(5)


def test_inverse_square_law_property():
    rng = np.random.default_rng(0)
    p = rng.normal(size=(50, 3))
    n = rng.normal(size=(50, 3))
    s = np.array([0.5, -0.2, 3.0])
    for k in (2.0, 3.0, 0.5):
        near = rad.point_light_irradiance(p, n, s, 7.0)
        far = rad.point_light_irradiance(s + k * (p - s), n, s, 7.0)   # same directions
        assert np.allclose(far.irradiance, near.irradiance / k ** 2)


def test_cosine_law_property_and_below_horizon():
    thetas = np.linspace(0, PI, 19)
    normals = np.stack([np.sin(thetas), np.zeros_like(thetas), np.cos(thetas)], axis=-1)
    r = rad.point_light_irradiance(np.zeros(3), normals, [0, 0, 2], 12.0)
    assert np.allclose(r.irradiance, 12.0 * np.maximum(np.cos(thetas), 0) / 4, atol=1e-14)
    assert np.all(r.irradiance[thetas > PI / 2 + 1e-9] == 0)
    assert np.allclose(r.irradiance, 12.0 * r.cos_theta * r.inv_d2)


def test_irradiance_is_flux_per_area():
    """Integrate E over a big plane under an isotropic light: it gets half the flux."""
    h, phi = 1.3, 10.0
    i = rad.isotropic_intensity(phi)

    def e(r):
        return float(rad.point_light_irradiance([r, 0, 0], [0, 0, 1], [0, 0, h], i).irradiance)

    total, _ = integrate.quad(lambda r: 2 * PI * r * e(r), 0, np.inf, limit=200)
    assert total == pytest.approx(phi / 2, rel=1e-7)


# ---------------------------------------------------------------------------------------------
# Area lights
# ---------------------------------------------------------------------------------------------

def _area_light_reference(point, normal, origin, u, v, radiance):
    """E = integral of L cos(theta_s) cos(theta_l) / r^2 dA over the light (one-sided both)."""
    point, normal = np.asarray(point, float), np.asarray(normal, float)
    normal = normal / np.linalg.norm(normal)
    nl = np.cross(u, v) / np.linalg.norm(np.cross(u, v))

    def f(x):
        d = x - point
        r = np.linalg.norm(d)
        return radiance * max(d @ normal, 0) * max(-d @ nl, 0) / r ** 4

    return _rect_surface_integral(f, origin, u, v)


@pytest.mark.parametrize("point,normal", [
    ([0, 0, 0], [0, 0, 1]),
    ([0.7, -0.4, 0], [0.3, 0.1, 1]),
    ([0.2, 0.3, -0.5], [0, 0.6, 1]),
    ([0.0, 0.0, 0.5], [1, 0, 0.2]),     # the light straddles the receiver's horizon: clipped
    ([1.5, 0.2, 0.8], [-1, 0, 0.1]),
])
def test_polygon_light_irradiance_against_dblquad(point, normal):
    origin = np.array([-0.5, -0.5, 1.0])
    u, v = np.array([0.0, 0.8, -0.2]), np.array([1.0, 0.0, 0.1])
    nl = np.cross(u, v)
    assert nl[2] < 0            # the light faces down towards the receivers
    poly = np.array([origin, origin + u, origin + u + v, origin + v])
    ref = _area_light_reference(point, normal, origin, u, v, 3.0)
    got = rad.polygon_light_irradiance(point, normal, poly, 3.0)
    assert got == pytest.approx(ref, rel=1e-6, abs=1e-10)


def test_polygon_light_fully_below_or_behind_gives_zero():
    light = _square([0, 0, 1], 0.5)                         # faces down
    assert rad.polygon_light_irradiance([0, 0, 0], [0, 0, -1], light, 2.0) == 0
    assert rad.polygon_light_irradiance([0, 0, 2], [0, 0, -1], light, 2.0) == 0  # behind it
    up = _square([0, 0, 1], 0.5, normal_sign=+1)            # faces up, away from the point
    assert rad.polygon_light_irradiance([0, 0, 0], [0, 0, 1], up, 2.0) == 0


def test_polygon_light_filling_the_hemisphere_gives_pi_l():
    big = _square([0, 0, 1], 1e4)
    assert rad.polygon_light_irradiance([0, 0, 0], [0, 0, 1], big, 2.5) == pytest.approx(
        PI * 2.5, rel=1e-6)
    # the exitance of a Lambertian surface is the same pi L
    ref, _ = integrate.dblquad(lambda t, p: 2.5 * np.cos(t) * np.sin(t), 0, 2 * PI, 0, PI / 2)
    assert rad.lambertian_exitance(2.5) == pytest.approx(ref)
    assert rad.lambertian_radiance(rad.lambertian_exitance(2.5)) == pytest.approx(2.5)


def test_polygon_light_is_vectorized_and_matches_per_point():
    rng = np.random.default_rng(7)
    light = _square([0.2, 0.1, 1.5], 0.6)
    p = rng.uniform(-2, 2, (30, 3))
    p[:, 2] = rng.uniform(-0.5, 1.0, 30)
    n = rng.normal(size=(30, 3))
    many = rad.polygon_light_irradiance(p, n, light, 1.0)
    one = [rad.polygon_light_irradiance(p[i], n[i], light, 1.0) for i in range(30)]
    assert np.allclose(many, one)
    assert np.all(many >= 0)


def test_small_light_converges_to_exact_like_size_squared():
    point, normal = np.zeros(3), np.array([0.2, 0.0, 1.0])
    c = np.array([0.4, 0.3, 2.0])
    errors = []
    for half in (0.2, 0.1, 0.05, 0.025):
        light = _square(c, half)
        exact = rad.polygon_light_irradiance(point, normal, light, 10.0)
        approx = rad.small_light_irradiance(point, normal, c, [0, 0, -1], (2 * half) ** 2, 10.0)
        # the approximation typed out
        d = c - point
        r = np.linalg.norm(d)
        nn = normal / np.linalg.norm(normal)
        typed = 10.0 * (2 * half) ** 2 * (d @ nn / r) * (d[2] / r) / r ** 2
        assert approx == pytest.approx(typed, rel=1e-12)
        errors.append(abs(approx - exact) / exact)
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratios > 3.5) & (ratios < 4.5))


def test_small_light_error_grows_as_the_light_nears():
    light_half = 0.1
    errs = []
    for h in (4.0, 2.0, 1.0, 0.5):
        c = np.array([0.0, 0.0, h])
        exact = rad.polygon_light_irradiance(np.zeros(3), [0, 0, 1], _square(c, light_half), 1.0)
        approx = rad.small_light_irradiance(np.zeros(3), [0, 0, 1], c, [0, 0, -1],
                                            (2 * light_half) ** 2, 1.0)
        errs.append(abs(approx - exact) / exact)
    assert np.all(np.diff(errs) > 0)


# ---------------------------------------------------------------------------------------------
# Conversions
# ---------------------------------------------------------------------------------------------

def test_isotropic_intensity_integrates_back_to_the_flux():
    i = rad.isotropic_intensity(60.0)
    assert i == pytest.approx(60 / (4 * PI))
    total, _ = integrate.dblquad(lambda t, p: i * np.sin(t), 0, 2 * PI, 0, PI)
    assert total == pytest.approx(60.0)


def test_emitter_intensity_integrates_to_pi_l_a():
    L, A = 40.0, 0.05
    assert rad.emitter_intensity(L, A, PI / 3) == pytest.approx(L * A * 0.5)
    assert rad.emitter_intensity(L, A, 2.0) == 0.0
    total, _ = integrate.dblquad(lambda t, p: rad.emitter_intensity(L, A, t) * np.sin(t),
                                 0, 2 * PI, 0, PI)
    assert total == pytest.approx(PI * L * A)


def test_quantities_table():
    units = {q.symbol: q.unit for q in rad.QUANTITIES}
    assert units["Φ"] == "W" and units["E"] == "W/m²" and units["I"] == "W/sr"
    assert units["L"] == "W/(m² sr)" and units["Q"] == "J"


# ---------------------------------------------------------------------------------------------
# Bad input
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("call,name", [
    (lambda: rad.point_light_irradiance([0, 0, 0], [0, 0, 1], [0, 0, 1], -1), "intensity"),
    (lambda: rad.point_light_irradiance([0, 0, 0], [0, 0, 0], [0, 0, 1], 1), "normals"),
    (lambda: rad.point_light_irradiance([0, 0, 0], [0, 0, 1], [0, 0, 0], 1), "points"),
    (lambda: rad.point_light_irradiance([0, np.nan, 0], [0, 0, 1], [0, 0, 1], 1), "points"),
    (lambda: rad.point_light_irradiance(np.zeros((3, 3)), np.ones((2, 3)), [0, 0, 1], 1),
     "points"),
    (lambda: rad.small_light_irradiance([0, 0, 0], [0, 0, 1], [0, 0, 1], [0, 0, -1], -1, 1),
     "area"),
    (lambda: rad.small_light_irradiance([0, 0, 0], [0, 0, 1], [0, 0, 1], [0, 0, 0], 1, 1),
     "light_normal"),
    (lambda: rad.small_light_irradiance([0, 0, 0], [0, 0, 1], [0, 0, 1], [0, 0, -1], 1, -2),
     "radiance"),
    (lambda: rad.polygon_light_irradiance([0, 0, 0], [0, 0, 1], _square([0, 0, 1], 1), -1),
     "radiance"),
    (lambda: rad.polygon_light_irradiance([0.1, 0, 1], [0, 0, 1], _square([0, 0, 1], 1), 1),
     "points"),
    (lambda: rad.polygon_light_irradiance([0, 0, 0], [0, 0, 1], [[0, 0, 1], [1, 0, 1]], 1),
     "vertices"),
    (lambda: rad.polygon_light_irradiance([0, 0, 0], [0, 0, 1],
                                          [[0, 0, 1], [1, 0, 1], [1, 1, 1.5], [0, 1, 1]], 1),
     "planar"),
    (lambda: rad.polygon_solid_angle([[0, 0, 1], [1, 0, 1], [2, 0, 1]], [0, 0, 0]), "vertices"),
    (lambda: rad.isotropic_intensity(-3), "flux"),
    (lambda: rad.emitter_intensity(1, 1, 4.0), "theta"),
    (lambda: rad.cone_solid_angle(-0.1), "half_angle"),
    (lambda: rad.cone_solid_angle(np.nan), "half_angle"),
    (lambda: rad.spherical_region_solid_angle(1.0, 0.5, 0, 1), "theta2"),
    (lambda: rad.patch_solid_angle(1, [0, 0, 0], [0, 0, 1], [0, 0, 0]), "normal"),
    (lambda: rad.patch_solid_angle(1, [0, 0, 1], [0, 0, 1], [0, 0, 1]), "points"),
    (lambda: rad.lambertian_exitance(-1), "radiance"),
    (lambda: rad.lambertian_radiance(-1), "exitance"),
])
def test_bad_input_names_the_argument(call, name):
    with pytest.raises(ValueError, match=name):
        call()
