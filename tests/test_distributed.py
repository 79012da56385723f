"""Distributed ray tracing (course_lib.raytracing.distributed) against closed forms.

Every effect is an integral; each test computes the integral in closed form (typed here: the
circle-circle overlap area, the circle of confusion, the mean cosine of a Phong lobe, the time a
moving sphere covers a ray, the area of a pixel on one side of an edge, the latter also with
shapely) and checks that the Monte Carlo estimate converges to it.
"""

import numpy as np
import pytest

from course_lib import shading
from course_lib.raytracing import (Camera, Mesh, Scene, Sphere, WhittedMaterial, example_scene,
                                   lens_rays, progressive, render, render_distributed,
                                   sample_disk, sample_lobe, soft_shadow, stratified,
                                   trace_distributed)

WHITE = WhittedMaterial(shading.colored_material((1.0, 1.0, 1.0), ka=1.0, kd=0.0, ks=0.0))


def circle_overlap(r1, r2, dist):
    """Area of the intersection of two disks (radii r1, r2, centres dist apart)."""
    if dist >= r1 + r2:
        return 0.0
    if dist <= abs(r1 - r2):
        return np.pi * min(r1, r2) ** 2
    a1 = np.arccos((dist ** 2 + r1 ** 2 - r2 ** 2) / (2 * dist * r1))
    a2 = np.arccos((dist ** 2 + r2 ** 2 - r1 ** 2) / (2 * dist * r2))
    kite = 0.5 * np.sqrt((-dist + r1 + r2) * (dist + r1 - r2) * (dist - r1 + r2)
                         * (dist + r1 + r2))
    return r1 ** 2 * a1 + r2 ** 2 * a2 - kite


def disk_mesh(center, radius, sides=512):
    """A horizontal regular polygon (triangle fan) standing in for a disk occluder."""
    phi = 2 * np.pi * np.arange(sides) / sides
    ring = np.column_stack([radius * np.cos(phi), np.zeros(sides), radius * np.sin(phi)])
    v = np.vstack([[0.0, 0.0, 0.0], ring]) + center
    f = np.column_stack([np.zeros(sides, int), 1 + np.arange(sides),
                         1 + (np.arange(sides) + 1) % sides])
    return Mesh(v, f)


# light: disk of radius R at height H facing down; occluder: disk of radius rho at height h
R, H, RHO, HO = 1.0, 4.0, 0.6, 2.0


def penumbra_scene():
    return Scene([disk_mesh([0.0, HO, 0.0], RHO)], shading.point_light([0.0, H, 0.0]))


def exact_visible(x):
    """Seen from (x, 0, 0), the occluder projects (centrally) onto the light's plane as a disk
    of radius rho H / h centred at x + (0 - x) H / h."""
    centre = x + (0.0 - x) * H / HO
    shadow = circle_overlap(R, RHO * H / HO, abs(centre))
    return 1.0 - shadow / (np.pi * R ** 2)


def test_soft_shadow_matches_circle_overlap_across_the_penumbra():
    xs = np.linspace(0.0, 2.2, 12)
    expected = np.array([exact_visible(x) for x in xs])
    assert expected[0] == 0.0 and expected[-1] == 1.0 and 0.2 < expected[6] < 0.95
    points = np.column_stack([xs, np.zeros_like(xs), np.zeros_like(xs)])
    got = soft_shadow(penumbra_scene(), points, light_radius=R, light_normal=[0, 1, 0],
                      samples=4096, seed=3)
    assert np.allclose(got, expected, atol=0.01)


def test_soft_shadow_matches_shapely_overlap():
    shapely = pytest.importorskip("shapely")
    from shapely.geometry import Point
    x = 1.1
    light = Point(0.0, 0.0).buffer(R, quad_segs=512)
    shadow = Point(x + (0.0 - x) * H / HO, 0.0).buffer(RHO * H / HO, quad_segs=512)
    expected = 1.0 - light.intersection(shadow).area / light.area
    assert shapely.__version__
    got = soft_shadow(penumbra_scene(), [x, 0.0, 0.0], light_radius=R, light_normal=[0, 1, 0],
                      samples=4096, seed=5)
    assert abs(float(got) - expected) < 0.01


def test_soft_shadow_error_falls_with_samples():
    x = 1.0
    exact = exact_visible(x)
    scene = penumbra_scene()
    errors = []
    for n in (16, 256):
        est = np.array([soft_shadow(scene, [x, 0, 0], light_radius=R, light_normal=[0, 1, 0],
                                    samples=n, seed=s) for s in range(30)])
        errors.append(np.sqrt(np.mean((est - exact) ** 2)))
    # 16 times the samples: at least the 1/sqrt(N) factor of 4 (stratification does better)
    assert errors[1] < errors[0] / 4
    assert errors[0] < 0.2


def test_point_light_gives_hard_shadow():
    scene = penumbra_scene()
    got = soft_shadow(scene, [[0.5, 0, 0], [1.5, 0, 0]], light_radius=0.0, samples=8)
    # centre projection: x (1 - H/h) = -x; hidden if |x| < rho H / h ... |x| <= 1.2
    assert got.tolist() == [0.0, 1.0]


def test_circle_of_confusion_of_the_thin_lens():
    cam = Camera([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0], np.radians(60), 5, 5)
    a, f = 0.3, 4.0
    rays = lens_rays(cam, samples=4096, aperture=a, focal_distance=f, seed=2, antialias=False)
    o, d = rays.origins[2, 2], rays.directions[2, 2]        # the centre pixel: along -z
    for z in (1.5, 4.0, 9.0):
        hit = o + ((-z - o[:, 2]) / d[:, 2])[:, None] * d
        spread = np.hypot(hit[:, 0], hit[:, 1])                # from the pinhole ray's point
        radius = a * abs(z - f) / f
        assert spread.max() == pytest.approx(radius, rel=0.02, abs=1e-12)
        # uniform over a disk of radius rho: mean squared distance rho^2 / 2
        assert np.mean(spread ** 2) == pytest.approx(radius ** 2 / 2, rel=0.02, abs=1e-12)
    # all lens points lie in the aperture disk
    assert np.all(np.hypot(o[:, 0], o[:, 1]) <= a + 1e-12)


def test_rendered_blur_of_a_point_matches_the_circle_of_confusion():
    w = 41
    fov = np.radians(40)
    cam = Camera([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0], fov, w, w)
    z, f, a = 2.0, 4.0, 0.4
    scene = Scene([Sphere([0.0, 0.0, -z], 0.01, WHITE)], ambient=1.0, background=0.0)
    image = render_distributed(scene, cam, samples=400, aperture=a, focal_distance=f,
                               max_depth=0, seed=1)[..., 0]
    coc = 2 * a * abs(z - f) / (f * z) * (w / 2) / np.tan(fov / 2)      # diameter in pixels
    yy, xx = np.mgrid[0:w, 0:w] - (w - 1) / 2
    second_moment = np.sum(image * (xx ** 2 + yy ** 2)) / image.sum()
    # a uniform disk of radius c/2 has E[r^2] = (c/2)^2 / 2 (plus 2/12 from the pixel size)
    assert second_moment == pytest.approx((coc / 2) ** 2 / 2 + 1 / 6, rel=0.1)
    pinhole = render_distributed(scene, cam, samples=400, max_depth=0, seed=1)[..., 0]
    assert np.count_nonzero(pinhole) < 5 < np.count_nonzero(image)


@pytest.mark.parametrize("n", [0.0, 3.0, 40.0])
def test_phong_lobe_mean_cosine_and_distribution(n):
    uv = stratified(4096, seed=4)
    axis = np.array([1.0, 2.0, 2.0]) / 3.0
    dirs = sample_lobe(axis, n, uv)
    assert np.allclose(np.linalg.norm(dirs, axis=-1), 1.0)
    cos = dirs @ axis
    assert cos.min() >= -1e-12
    assert cos.mean() == pytest.approx((n + 1) / (n + 2), abs=2e-3)
    # P(cos > c) = 1 - c^(n+1)
    for c in (0.5, 0.9):
        assert np.mean(cos > c) == pytest.approx(1 - c ** (n + 1), abs=0.01)
    # isotropic around the axis: the perpendicular part averages to zero
    perp = dirs - cos[:, None] * axis
    assert np.allclose(perp.mean(axis=0), 0.0, atol=0.02)


def test_sample_disk_is_uniform_by_area():
    p = sample_disk(stratified(4096, seed=0), radius=2.0)
    r = np.hypot(p[:, 0], p[:, 1])
    assert r.max() <= 2.0 + 1e-12
    for rr in (0.5, 1.0, 1.5):
        assert np.mean(r < rr) == pytest.approx((rr / 2.0) ** 2, abs=0.01)
    quadrant = np.mean((p[:, 0] > 0) & (p[:, 1] > 0))
    assert quadrant == pytest.approx(0.25, abs=0.01)


def test_stratified_has_one_point_per_cell():
    p = stratified(9, seed=1, sets=5)
    assert p.shape == (5, 9, 2)
    for s in p:
        cells = sorted(map(tuple, np.floor(s * 3).astype(int).tolist()))
        assert cells == [(i, j) for i in range(3) for j in range(3)]
    q = stratified(5, seed=1)                     # N-rooks: one per row, one per column
    for axis in (0, 1):
        assert sorted(np.floor(q[:, axis] * 5).astype(int).tolist()) == [0, 1, 2, 3, 4]


def moving_coverage(o, d, c0, v, r, shutter):
    """Fraction of [0, shutter] during which the line o + t d passes within r of c0 + v tau."""
    d = d / np.linalg.norm(d)
    w0 = (c0 - o) - np.dot(c0 - o, d) * d          # perpendicular parts
    wv = v - np.dot(v, d) * d
    A, B, C = wv @ wv, 2 * w0 @ wv, w0 @ w0 - r * r
    disc = B * B - 4 * A * C
    if disc <= 0:
        return 0.0
    t1, t2 = (-B - np.sqrt(disc)) / (2 * A), (-B + np.sqrt(disc)) / (2 * A)
    return max(0.0, min(t2, shutter) - max(t1, 0.0)) / shutter


def test_motion_blur_is_the_time_average_of_a_moving_edge():
    cam = Camera([0.0, 0.0, 6.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0], np.radians(40), 16, 4)
    c0, v, r, shutter = np.array([-0.8, 0.0, 0.0]), np.array([1.6, 0.0, 0.0]), 1.0, 1.0
    scene = Scene([Sphere(c0, r, WHITE)], ambient=1.0, background=0.0)
    image = render_distributed(scene, cam, samples=64, shutter=shutter, motion={0: v},
                               antialias=False, max_depth=0, seed=7)[..., 0]
    rays = cam.rays()
    expected = np.array([[moving_coverage(rays.origins[j, i, 0], rays.directions[j, i, 0], c0, v,
                                          r, shutter) for i in range(16)] for j in range(4)])
    assert 0 < expected[2, 9] < 1                 # a blurred edge is inside the picture
    assert np.abs(image - expected).max() < 1 / 64 + 1e-9
    still = render_distributed(scene, cam, samples=4, antialias=False, max_depth=0, seed=7)
    assert set(np.unique(still).tolist()) <= {0.0, 1.0}


def test_antialiasing_gives_the_covered_area_of_each_pixel():
    pytest.importorskip("shapely")
    from shapely.geometry import Polygon, box
    # camera at z = 5 looking down -z, 90 degrees: (X, Y, 0) projects to canonical (X/5, Y/5)
    w = 8
    cam = Camera([0.0, 0.0, 5.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0], np.radians(90), w, w)
    tri = np.array([[-20.0, -30.0, 0.0], [3.0, 2.0, 0.0], [-30.0, 40.0, 0.0]])
    scene = Scene([Mesh(tri, [[0, 1, 2]], WHITE)], ambient=1.0, background=0.0)
    image = render_distributed(scene, cam, samples=256, max_depth=0, seed=2)[..., 0]
    pixels = (tri[:, :2] / 5.0 + 1.0) * w / 2          # viewport coordinates
    shape = Polygon(pixels)
    exact = np.array([[box(i, j, i + 1, j + 1).intersection(shape).area for i in range(w)]
                      for j in range(w)])
    partial = (exact > 0.05) & (exact < 0.95)
    assert partial.sum() >= 4
    assert np.abs(image - exact).max() < 0.03
    aliased = render_distributed(scene, cam, samples=1, antialias=False, max_depth=0)[..., 0]
    assert set(np.unique(aliased).tolist()) <= {0.0, 1.0}


def test_same_seed_same_image_and_reduction_to_whitted():
    scene = example_scene("spheres", 12, 9)
    opts = dict(samples=4, light_radius=0.6, aperture=0.1, gloss=30.0, shutter=1.0,
                motion={1: [0.5, 0, 0]})
    a = render_distributed(scene, seed=11, **opts)
    assert np.array_equal(a, render_distributed(scene, seed=11, **opts))
    assert not np.array_equal(a, render_distributed(scene, seed=12, **opts))
    assert np.allclose(render_distributed(scene, samples=3, antialias=False), render(scene))


def test_render_converges_to_a_reference():
    scene = example_scene("spheres", 10, 8)
    opts = dict(light_radius=0.8, gloss=20.0)
    reference = render_distributed(scene, samples=1024, seed=99, **opts)
    err = [np.sqrt(np.mean((render_distributed(scene, samples=n, seed=1, **opts)
                            - reference) ** 2)) for n in (4, 64)]
    assert err[1] < err[0] / 2


def test_progressive_accumulates_batches():
    scene = example_scene("spheres", 8, 6)
    images = list(progressive(scene, batch=2, batches=4, seed=3, light_radius=0.5))
    assert len(images) == 4 and images[0].shape == (6, 8, 3)
    reference = render_distributed(scene, samples=256, seed=5, light_radius=0.5)
    errs = [np.abs(im - reference).mean() for im in images]
    assert errs[-1] < errs[0]
    with pytest.raises(TypeError, match="unknown options"):
        list(progressive(scene, lights=3))


def test_trace_distributed_time_average():
    scene = Scene([Sphere([0, 0, 0], 1.0, WHITE)], ambient=1.0)
    n = 400
    times = (np.arange(n) + 0.5) / n
    col = trace_distributed(scene, np.tile([0.5, 0, 5], (n, 1)), np.tile([0, 0, -1], (n, 1)),
                            times=times, motion={0: [3.0, 0, 0]})
    # hit while |0.5 - 3 t| <= 1: t in [0, 0.5]
    assert col[:, 0].mean() == pytest.approx(0.5, abs=1 / n)


@pytest.mark.parametrize("kwargs, error, match", [
    (dict(samples=0), ValueError, "samples"),
    (dict(light_radius=-1), ValueError, "light_radius"),
    (dict(aperture=-0.1), ValueError, "aperture"),
    (dict(aperture=0.1, focal_distance=0), ValueError, "focal_distance"),
    (dict(focal_distance=-2), ValueError, "focal_distance"),
    (dict(gloss=-1), ValueError, "gloss"),
    (dict(shutter=-1), ValueError, "shutter"),
    (dict(seed=-3), ValueError, "seed"),
    (dict(seed=1.5), TypeError, "seed"),
    (dict(motion={0: [1, 0, 0]}), ValueError, "only spheres"),
    (dict(motion={9: [1, 0, 0]}), ValueError, "motion"),
    (dict(motion={1: [1, 0]}), ValueError, "motion"),
    (dict(motion=[1, 2]), TypeError, "motion"),
    (dict(camera="cam"), TypeError, "camera"),
])
def test_render_errors(kwargs, error, match):
    scene = example_scene("spheres", 4, 3)
    with pytest.raises(error, match=match):
        render_distributed(scene, **kwargs)


def test_helper_errors():
    with pytest.raises(ValueError, match="n must"):
        stratified(0)
    with pytest.raises(ValueError, match="uv"):
        sample_disk([0.2, 0.3, 0.4])
    with pytest.raises(ValueError, match="uv"):
        sample_disk([[1.5, 0.2]])
    with pytest.raises(ValueError, match="radius"):
        sample_disk([[0.5, 0.2]], radius=-1)
    with pytest.raises(ValueError, match="exponent"):
        sample_lobe([0, 0, 1], -2, [[0.1, 0.2]])
    with pytest.raises(ValueError, match="axis"):
        sample_lobe([0, 0, 0], 2, [[0.1, 0.2]])
    with pytest.raises(ValueError, match="axis"):
        sample_lobe([0, 1], 2, [[0.1, 0.2]])
    with pytest.raises(ValueError, match="light"):
        soft_shadow(penumbra_scene(), [0, 0, 0], light=2)
    with pytest.raises(ValueError, match="points"):
        soft_shadow(penumbra_scene(), [0, 0])
    with pytest.raises(ValueError, match="light_normal"):
        soft_shadow(penumbra_scene(), [0, 0, 0], light_normal=[0, 0, 0])
    with pytest.raises(TypeError, match="camera"):
        lens_rays("camera")
    with pytest.raises(ValueError, match="times"):
        trace_distributed(penumbra_scene(), [[0, 0, 5]], [[0, 0, -1]], times=[0, 1])
    with pytest.raises(ValueError, match="shape"):
        trace_distributed(penumbra_scene(), [[0, 0, 5]], [[0, 0, -1], [0, 0, 1]])


def test_infinite_gloss_is_a_perfect_mirror():
    scene = example_scene("spheres", 8, 6)
    assert np.array_equal(render_distributed(scene, samples=2, gloss=np.inf, seed=4),
                          render_distributed(scene, samples=2, gloss=None, seed=4))
    d = sample_lobe([0.0, 0.6, 0.8], np.inf, stratified(16, seed=1))
    assert np.allclose(d, [0.0, 0.6, 0.8])
