"""Tests of course_lib.raytracing (chapter 15).

References: trimesh's ray queries (``trimesh.ray.ray_triangle.RayMeshIntersector``: hit or miss,
distance, triangle id) on random rays; closed forms typed out below (the ray-sphere and ray-plane
distances by projection, the Fresnel equations in their sine/tangent form, Phong at a single hit
worked by hand); PyGLM's GLSL ``reflect`` and ``refract``; and ``course_lib.viewing.to_screen``
for the camera. Nothing is copied from the output of the code under test.
"""
import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from pyglm import glm
from trimesh.ray.ray_triangle import RayMeshIntersector

from course_lib import raytracing as rt
from course_lib import shading, viewing

FAST = settings(max_examples=40, deadline=None, database=None)


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def random_units(gen, n):
    return unit(gen.normal(size=(n, 3)))


def triangle_soup(gen, m, size=0.3):
    centres = gen.uniform(-1, 1, (m, 1, 3))
    return centres + size * gen.normal(size=(m, 3, 3))


def rays_towards_origin(gen, n, distance=3.0, spread=0.4):
    o = distance * random_units(gen, n)
    d = unit(-o / distance + spread * gen.normal(size=(n, 3)))
    return o, d


def trimesh_first_hits(tris, o, d):
    """Triangle id and distance of the first hit of each ray, by trimesh (-1, inf on a miss)."""
    mesh = trimesh.Trimesh(tris.reshape(-1, 3), np.arange(3 * len(tris)).reshape(-1, 3),
                           process=False)
    locations, ray_ids, tri_ids = RayMeshIntersector(mesh).intersects_location(
        o, d, multiple_hits=True)
    ids = np.full(len(o), -1)
    dist = np.full(len(o), np.inf)
    along = np.einsum("ij,ij->i", locations - o[ray_ids], d[ray_ids])
    for r, t, k in zip(ray_ids, along, tri_ids):
        if t < dist[r]:
            dist[r], ids[r] = t, k
    return ids, dist


# ---------------------------------------------------------------------------------------------
# Ray-triangle (Moller-Trumbore) against trimesh, and the BVH against brute force
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("accelerate", [False, True])
def test_triangles_match_trimesh_on_random_rays(accelerate):
    gen = np.random.default_rng(15)
    tris = triangle_soup(gen, 300)
    o, d = rays_towards_origin(gen, 1500)
    ids, dist = trimesh_first_hits(tris, o, d)
    hits = rt.intersect_triangles(o, d, tris, accelerate=accelerate)
    assert 0.2 < (ids >= 0).mean() < 0.95              # a real mix of hits and misses
    np.testing.assert_array_equal(hits.ids >= 0, ids >= 0)
    np.testing.assert_array_equal(hits.ids, ids)
    hit = ids >= 0
    np.testing.assert_allclose(hits.t[hit], dist[hit], rtol=1e-9, atol=1e-9)
    assert np.all(np.isinf(hits.t[~hit]))


def test_closed_mesh_from_inside_and_outside_matches_trimesh():
    gen = np.random.default_rng(3)
    sphere = trimesh.creation.icosphere(subdivisions=3)
    tris = sphere.vertices[sphere.faces]
    o = np.concatenate([0.5 * random_units(gen, 300), 2.5 * random_units(gen, 300)])
    d = random_units(gen, 600)
    ids = RayMeshIntersector(sphere).intersects_first(o, d)
    hits = rt.BVH(tris).intersect(o, d)
    np.testing.assert_array_equal(hits.ids, ids)
    assert np.all(hits.ids[:300] >= 0)                 # every ray from inside leaves the sphere
    # the hit point lies on the triangle at the barycentric coordinates returned
    hit = hits.ids >= 0
    v0, v1, v2 = (tris[hits.ids[hit], k] for k in range(3))
    u, v = hits.u[hit, None], hits.v[hit, None]
    np.testing.assert_allclose(o[hit] + hits.t[hit, None] * d[hit],
                               (1 - u - v) * v0 + u * v1 + v * v2, atol=1e-12)
    np.testing.assert_allclose(hits.normals[hit],
                               unit(np.cross(v1 - v0, v2 - v0)), atol=1e-12)


def test_triangle_by_hand():
    tri = [[[0, 0, 0], [2, 0, 0], [0, 2, 0]]]
    # the point (0.5, 0.5, 0) = 0.5 v0 + 0.25 v1 + 0.25 v2; from z = 3 straight down: t = 3
    hits = rt.intersect_triangles([0.5, 0.5, 3], [0, 0, -1], tri, accelerate=False)
    assert (float(hits.t), int(hits.ids), float(hits.u), float(hits.v)) == (3.0, 0, 0.25, 0.25)
    # behind the origin, outside the triangle, parallel to it: misses
    for o, d in (([0.5, 0.5, 3], [0, 0, 1]), ([1.5, 1.5, 3], [0, 0, -1]),
                 ([0.5, 0.5, 0.0], [1, 0, 0])):
        assert int(rt.intersect_triangles(o, d, tri).ids) == -1
    # t_max cuts the hit off
    assert np.isinf(rt.intersect_triangles([0.5, 0.5, 3], [0, 0, -1], tri, t_max=2.9).t)


@FAST
@given(st.integers(0, 10_000), st.integers(1, 8))
def test_bvh_gives_the_same_hits_as_brute_force(seed, leaf_size):
    gen = np.random.default_rng(seed)
    tris = triangle_soup(gen, int(gen.integers(1, 400)), size=float(gen.uniform(0.05, 0.5)))
    o, d = rays_towards_origin(gen, 200)
    t_min = float(gen.choice([0.0, 1.0]))
    slow = rt.intersect_triangles(o, d, tris, t_min=t_min, accelerate=False)
    fast = rt.BVH(tris, leaf_size=leaf_size).intersect(o, d, t_min=t_min)
    np.testing.assert_array_equal(fast.ids, slow.ids)
    np.testing.assert_array_equal(fast.t, slow.t)
    np.testing.assert_array_equal(fast.u, slow.u)
    np.testing.assert_array_equal(fast.v, slow.v)
    assert slow.triangle_tests == len(o) * len(tris) and slow.box_tests == 0


def test_bvh_saves_work_and_any_hit_finds_a_real_hit():
    gen = np.random.default_rng(7)
    tris = triangle_soup(gen, 5000, size=0.05)
    o, d = rays_towards_origin(gen, 400)
    bvh = rt.BVH(tris)
    nearest = bvh.intersect(o, d)
    assert nearest.triangle_tests < len(o) * len(tris) / 100
    assert bvh.depth == int(np.ceil(np.log2(5000 / 4)))       # median split: balanced
    leaves = [leaf for leaf in bvh.leaves if len(leaf)]
    assert sorted(np.concatenate(leaves).tolist()) == list(range(5000))
    # every leaf's triangles lie in its box
    for node, leaf in enumerate(bvh.leaves):
        if len(leaf):
            assert np.all(tris[leaf] >= bvh.lo[node]) and np.all(tris[leaf] <= bvh.hi[node])
    anyhit = bvh.intersect(o, d, any_hit=True)
    np.testing.assert_array_equal(anyhit.ids >= 0, nearest.ids >= 0)
    hit = anyhit.ids >= 0
    assert np.all(anyhit.t[hit] >= nearest.t[hit])
    # the triangle reported is really hit at that distance
    for r in np.nonzero(hit)[0][:50]:
        single = rt.intersect_triangles(o[r], d[r], tris[anyhit.ids[r]], accelerate=False)
        assert float(single.t) == anyhit.t[r]
    assert anyhit.triangle_tests <= nearest.triangle_tests


# ---------------------------------------------------------------------------------------------
# Spheres, planes, boxes
# ---------------------------------------------------------------------------------------------

def sphere_closed_form(o, d, c, r, t_min=0.0):
    """Nearest t >= t_min by projecting the centre onto the ray (unit d): t_c +- half chord."""
    tc = np.einsum("ij,ij->i", c - o, d)
    perp2 = np.einsum("ij,ij->i", c - o, c - o) - tc**2
    half = np.sqrt(np.maximum(r * r - perp2, 0.0))
    near, far = tc - half, tc + half
    t = np.where(near >= t_min, near, np.where(far >= t_min, far, np.inf))
    return np.where(perp2 <= r * r, t, np.inf)


def test_sphere_against_closed_form_and_trimesh():
    gen = np.random.default_rng(11)
    c, r = np.array([0.3, -0.2, 0.1]), 1.2
    o = np.concatenate([c + 4 * random_units(gen, 500), c + 0.5 * random_units(gen, 100)])
    d = unit(c - o + 0.8 * gen.normal(size=(600, 3)))
    d[500:] = random_units(gen, 100)
    hits = rt.intersect_sphere(o, d, c, r)
    expected = sphere_closed_form(o, d, c, r)
    assert 0.2 < np.isfinite(expected[:500]).mean() < 0.9
    np.testing.assert_array_equal(np.isfinite(hits.t), np.isfinite(expected))
    hit = np.isfinite(expected)
    np.testing.assert_allclose(hits.t[hit], expected[hit], rtol=1e-10)
    p = o[hit] + hits.t[hit, None] * d[hit]
    np.testing.assert_allclose(hits.normals[hit], (p - c) / r, atol=1e-10)
    # a fine triangulated sphere (trimesh) agrees up to the tessellation error
    mesh = trimesh.creation.icosphere(subdivisions=5, radius=r)
    mesh.apply_translation(c)
    ids = RayMeshIntersector(mesh).intersects_first(o[:200], d[:200])
    grazing = np.abs(np.sqrt(np.maximum(0, r * r - (np.einsum(
        "ij,ij->i", c - o[:200], c - o[:200]) - np.einsum("ij,ij->i", c - o[:200], d[:200]) ** 2)))
    ) < 0.05
    np.testing.assert_array_equal((ids >= 0)[~grazing], hit[:200][~grazing])
    # from inside: the far root; with t_min: the far root too
    np.testing.assert_allclose(rt.intersect_sphere(o, d, c, r, t_min=0.5).t,
                               sphere_closed_form(o, d, c, r, 0.5), rtol=1e-10)


def test_sphere_by_hand_and_far_away():
    # from (0, 0, 5) along -z: enters the unit sphere at t = 4; offset by 0.6: t = 5 - 0.8
    hits = rt.intersect_sphere([[0, 0, 5], [0.6, 0, 5], [1.01, 0, 5]], [0, 0, -1], [0, 0, 0], 1)
    np.testing.assert_allclose(hits.t, [4.0, 4.2, np.inf])
    np.testing.assert_allclose(hits.normals[1], [0.6, 0, 0.8])
    # far away (1e6) and tiny: no cancellation
    t = float(rt.intersect_sphere([0, 0, 1e6], [0, 0, -1], [0, 0, 0], 1e-3).t)
    assert abs(t - (1e6 - 1e-3)) < 1e-9
    # un-normalized direction: t in units of its length
    assert float(rt.intersect_sphere([0, 0, 5], [0, 0, -2], [0, 0, 0], 1).t) == 2.0


def test_plane_closed_form():
    gen = np.random.default_rng(5)
    q, n = np.array([1.0, 2.0, -1.0]), unit([1.0, 2.0, 2.0])
    o = gen.normal(size=(400, 3)) * 3
    d = random_units(gen, 400)
    hits = rt.intersect_plane(o, d, q, 3 * n)
    # signed distances: the ray covers (q - o).n along n at speed d.n
    s, v = (q - o) @ n, d @ n
    expected = np.where(s / v >= 0, s / v, np.inf)
    np.testing.assert_allclose(hits.t, expected, rtol=1e-12)
    p = o + np.where(np.isfinite(hits.t), hits.t, 0)[:, None] * d
    np.testing.assert_allclose(((p - q) @ n)[np.isfinite(hits.t)], 0, atol=1e-9)
    assert np.isinf(rt.intersect_plane([0, 1, 0], [1, 0, 0], [0, 0, 0], [0, 1, 0]).t)


def test_box_matches_a_trimesh_box():
    gen = np.random.default_rng(9)
    lo, hi = np.array([-1.0, -0.5, 0.0]), np.array([1.0, 0.5, 2.0])
    box = trimesh.creation.box(bounds=[lo, hi])
    o = np.concatenate([4 * random_units(gen, 400) + [0, 0, 1], gen.uniform(lo, hi, (100, 3))])
    d = unit(-o + [0, 0, 1] + 0.8 * gen.normal(size=(500, 3)))
    ids, dist = trimesh_first_hits(box.vertices[box.faces], o, d)
    hits = rt.intersect_box(o, d, lo, hi)
    np.testing.assert_array_equal(np.isfinite(hits.t), ids >= 0)
    hit = ids >= 0
    np.testing.assert_allclose(hits.t[hit], dist[hit], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(hits.normals[hit], box.face_normals[ids[hit]], atol=1e-12)
    assert np.all(hits.t[400:] > 0)                     # from inside: leaves the box


def test_box_parallel_rays_by_hand():
    hits = rt.intersect_box([[0.5, 0.5, 5], [0.5, 2, 5], [-1, 0.5, 0.5]],
                            [[0, 0, -1], [0, 0, -1], [1, 0, 0]], [0, 0, 0], [1, 1, 1])
    np.testing.assert_array_equal(hits.t, [4.0, np.inf, 1.0])
    np.testing.assert_array_equal(hits.normals[2], [-1, 0, 0])


# ---------------------------------------------------------------------------------------------
# Reflection, refraction, Fresnel
# ---------------------------------------------------------------------------------------------

def test_reflect_matches_glsl():
    gen = np.random.default_rng(2)
    d, n = random_units(gen, 300), random_units(gen, 300)
    r = rt.reflect_direction(d, n)
    for k in range(0, 300, 11):
        np.testing.assert_allclose(r[k], list(glm.reflect(glm.vec3(*d[k]), glm.vec3(*n[k]))),
                                   atol=1e-6)
    np.testing.assert_allclose(np.einsum("ij,ij->i", r, n), -np.einsum("ij,ij->i", d, n),
                               atol=1e-12)
    np.testing.assert_allclose(rt.reflect_direction(d, -4 * n), r, atol=1e-12)



def test_reflect_direction_is_phong_reflect_of_the_reversed_ray():
    # two conventions, one formula: a ray's d points towards the surface, Phong's L away from it
    gen = np.random.default_rng(7)
    d, n = 3 * random_units(gen, 200), random_units(gen, 200) * gen.uniform(0.5, 2, (200, 1))
    r = rt.reflect_direction(d, n)
    np.testing.assert_array_equal(r, shading.reflect(-d, n))          # r = 2 (n.L) n - L, L = -d
    unit_n = n / np.linalg.norm(n, axis=1, keepdims=True)
    np.testing.assert_allclose(r, d - 2 * np.einsum("ij,ij->i", d, unit_n)[:, None] * unit_n,
                               atol=1e-12)
    # Phong's R leaves on the side of L (away from the surface); the ray's r on the side -d
    l = -d
    np.testing.assert_allclose(np.einsum("ij,ij->i", shading.reflect(l, n), unit_n),
                               np.einsum("ij,ij->i", l, unit_n), atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(r, axis=1), np.linalg.norm(d, axis=1), rtol=1e-12)

def test_refract_matches_glsl_and_snell():
    gen = np.random.default_rng(4)
    n = random_units(gen, 300)
    d = random_units(gen, 300)
    d = np.where((np.einsum("ij,ij->i", d, n) > 0)[:, None], -d, d)      # d . n < 0
    for eta1, eta2 in ((1.0, 1.5), (1.5, 1.0), (1.33, 2.42)):
        t, tir = rt.refract_direction(d, n, eta1, eta2)
        for k in range(0, 300, 13):
            ref = np.array(glm.refract(glm.vec3(*d[k]), glm.vec3(*n[k]), eta1 / eta2))
            np.testing.assert_allclose(t[k], ref, atol=1e-5)
            assert tir[k] == (not ref.any())
        sin1 = np.linalg.norm(np.cross(d, n), axis=1)
        sin2 = np.linalg.norm(np.cross(t, n), axis=1)
        ok = ~tir
        np.testing.assert_allclose(eta1 * sin1[ok], eta2 * sin2[ok], atol=1e-12)
        # the refracted ray continues through the surface, in the plane of d and n
        assert np.all(np.einsum("ij,ij->i", t[ok], n[ok]) < 0)
        np.testing.assert_allclose(np.einsum("ij,ij->i", t[ok], np.cross(d[ok], n[ok])), 0,
                                   atol=1e-12)
        np.testing.assert_array_equal(tir, eta1 / eta2 * sin1 > 1)
    # the normal may point either way
    t1, _ = rt.refract_direction(d, n, 1.0, 1.5)
    t2, _ = rt.refract_direction(d, -n, 1.0, 1.5)
    np.testing.assert_allclose(t1, t2, atol=1e-12)


def test_total_internal_reflection_at_the_critical_angle():
    critical = np.arcsin(1 / 1.5)                       # 41.81 degrees
    for angle, expected in ((critical - 1e-6, False), (critical + 1e-6, True),
                            (np.radians(30), False), (np.radians(60), True)):
        d = [np.sin(angle), -np.cos(angle), 0]
        t, tir = rt.refract_direction(d, [0, 1, 0], 1.5, 1.0)
        assert bool(tir) == expected
        assert bool(tir) == (not np.any(t))
    # from air into glass there is never total internal reflection
    angles = np.radians(np.linspace(0, 89.9, 50))
    d = np.stack([np.sin(angles), -np.cos(angles), 0 * angles], axis=1)
    assert not rt.refract_direction(d, [0, 1, 0], 1.0, 1.5)[1].any()
    # head on: straight through
    np.testing.assert_allclose(rt.refract_direction([0, -1, 0], [0, 1, 0], 1.0, 1.5)[0],
                               [0, -1, 0])


def fresnel_reference(theta1, eta1, eta2):
    """The Fresnel equations in their sine / tangent form (another derivation than rt.fresnel)."""
    sin2 = eta1 / eta2 * np.sin(theta1)
    theta2 = np.arcsin(np.minimum(sin2, 1.0))
    rs = (np.sin(theta1 - theta2) / np.sin(theta1 + theta2)) ** 2
    rp = (np.tan(theta1 - theta2) / np.tan(theta1 + theta2)) ** 2
    return np.where(sin2 >= 1, 1.0, 0.5 * (rs + rp))


def test_fresnel_exact_and_schlick():
    theta = np.radians(np.linspace(1, 89, 89))
    for eta1, eta2, worst in ((1.0, 1.5, 0.04), (1.5, 1.0, 0.04), (1.0, 1.33, 0.065)):
        exact = rt.fresnel(np.cos(theta), eta1, eta2)
        np.testing.assert_allclose(exact, fresnel_reference(theta, eta1, eta2), atol=1e-12)
        approx = rt.schlick(np.cos(theta), eta1, eta2)
        assert np.max(np.abs(approx - exact)) < worst
        assert np.all((0 <= approx) & (approx <= 1))
        r0 = ((eta1 - eta2) / (eta1 + eta2)) ** 2
        assert float(rt.schlick(1.0, eta1, eta2)) == pytest.approx(r0, abs=1e-15)
        assert float(rt.fresnel(1.0, eta1, eta2)) == pytest.approx(r0, abs=1e-15)
        assert np.all(np.diff(approx) >= -1e-15)              # grows towards grazing
    # glass from outside: 4 % head on, everything at grazing incidence
    assert float(rt.schlick(0.0, 1.0, 1.5)) == 1.0
    assert float(rt.fresnel(0.0, 1.0, 1.5)) == pytest.approx(1.0)
    # beyond the critical angle, both say everything is reflected
    assert float(rt.schlick(np.cos(np.radians(50)), 1.5, 1.0)) == 1.0
    assert float(rt.fresnel(np.cos(np.radians(50)), 1.5, 1.0)) == 1.0
    assert float(rt.schlick(0.3, 1.2, 1.2)) == 0.0                # no interface


# ---------------------------------------------------------------------------------------------
# Camera
# ---------------------------------------------------------------------------------------------

def test_camera_rays_project_onto_their_samples():
    eye, gaze, up, fov, w, h = [1.0, 2.0, 5.0], [-0.2, -0.3, -1.0], [0, 1, 0], np.radians(50), 8, 6
    rays = rt.camera_rays(eye, gaze, up, fov, w, h, samples_per_pixel=4)
    view = viewing.look_at(eye, gaze, up)
    proj = viewing.perspective(fov, w / h, 0.5, 100.0)
    vp = viewing.viewport(0, 0, w, h)
    points = rays.origins + 7.0 * rays.directions
    screen = viewing.to_screen(points.reshape(-1, 3), view, proj, vp).reshape(h, w, 4, -1)
    j, i = np.mgrid[0:h, 0:w]
    for s, (a, b) in enumerate([(0, 0), (0, 1), (1, 0), (1, 1)]):
        np.testing.assert_allclose(screen[:, :, s, 0], i + (b + 0.5) / 2, atol=1e-9)
        np.testing.assert_allclose(screen[:, :, s, 1], j + (a + 0.5) / 2, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(rays.directions, axis=-1), 1.0)
    cam = rt.Camera(eye, gaze, up, fov, w, h)
    full = cam.rays()
    for row, column in ((0, 0), (5, 7), (2, 3)):
        origin, direction = cam.pixel_ray(row, column)
        np.testing.assert_allclose(origin, eye)
        np.testing.assert_allclose(direction, full.directions[row, column, 0], atol=1e-12)
    with pytest.raises(ValueError, match="outside the 8 x 6 image"):
        cam.pixel_ray(6, 0)
    # an odd image: the centre pixel looks along gaze
    centre = rt.camera_rays(eye, gaze, up, fov, 5, 5).directions[2, 2, 0]
    np.testing.assert_allclose(centre, unit(gaze), atol=1e-12)
    # jitter: reproducible, inside the sub-pixel
    a1 = rt.camera_rays(eye, gaze, up, fov, w, h, 4, seed=1, jitter=True)
    a2 = rt.camera_rays(eye, gaze, up, fov, w, h, 4, seed=1, jitter=True)
    np.testing.assert_array_equal(a1.directions, a2.directions)
    js = viewing.to_screen((a1.origins + a1.directions).reshape(-1, 3), view, proj,
                           vp).reshape(h, w, 4, -1)
    frac_x = (js[..., 0] - i[..., None]) * 2
    assert np.all((np.floor(frac_x) == [0, 1, 0, 1]))


# ---------------------------------------------------------------------------------------------
# Shading: analytic cases
# ---------------------------------------------------------------------------------------------

def emissive(colour):
    return rt.Material(shading.Material(ka=0.0, kd=0.0, ks=0.0, emission=colour))


def test_phong_at_the_front_of_a_sphere_by_hand():
    ka, kd, ks, n_exp = 0.1, 0.6, 0.3, 8
    alpha = np.radians(40)
    sphere = rt.Sphere([0, 0, 0], 1.0, rt.Material(shading.Material(ka, kd, ks, n_exp)))
    light = shading.directional_light([np.sin(alpha), 0, np.cos(alpha)])
    scene = rt.Scene([sphere], [light])
    # hit (0, 0, 1), N = V = z; R = 2 cos(a) N - L = (-sin a, 0, cos a), R.V = cos a
    expected = ka + kd * np.cos(alpha) + ks * np.cos(alpha) ** n_exp
    tree = rt.trace_tree(scene, [0, 0, 5], [0, 0, -1], max_depth=0)
    np.testing.assert_allclose(tree.total(), expected, rtol=1e-12)
    np.testing.assert_allclose(tree.hit, [0, 0, 1], atol=1e-12)
    camera = rt.Camera([0, 0, 5], [0, 0, -1], [0, 1, 0], np.radians(10), 1, 1)
    np.testing.assert_allclose(rt.render(scene, camera), np.full((1, 1, 3), expected),
                               rtol=1e-12)


def test_shadow_ray_leaves_only_the_ambient_term():
    floor = rt.Plane([0, 0, 0], [0, 1, 0], rt.Material(shading.Material(0.1, 0.6, 0.3, 10)))
    blocker = rt.Sphere([0, 2, 0], 0.5, emissive(0.0))
    scene = rt.Scene([floor, blocker], [shading.point_light([0, 5, 0])])
    # straight down onto (0, 0, 0): the sphere is between it and the light
    shadowed = rt.trace_tree(scene, [0.0, 1.0, 0.3], unit([0, -1, -0.3]), max_depth=0)
    np.testing.assert_allclose(shadowed.hit, [0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(shadowed.total(), 0.1, rtol=1e-12)
    assert shadowed.children[0].kind == "shadow" and shadowed.children[0].visibility == 0.0
    # without shadow rays: N.L = 1; the viewer at (0, 1, 0.3): R = (0, 1, 0), R.V = 1/|(0,1,.3)|
    unshadowed = rt.trace_tree(scene, [0.0, 1.0, 0.3], unit([0, -1, -0.3]), max_depth=0,
                               shadows=False)
    np.testing.assert_allclose(unshadowed.total(), 0.1 + 0.6 + 0.3 / np.sqrt(1.09) ** 10,
                               rtol=1e-12)
    # a point away from the sphere is lit: (3, 0, 0) sees the light at cos = 5 / sqrt(34)
    lit = rt.trace_tree(scene, [3.0, 1.0, 0.0], [0, -1, 0], max_depth=0)
    l_dir = unit([-3, 5, 0])
    r = 2 * l_dir[1] * np.array([0, 1, 0]) - l_dir
    np.testing.assert_allclose(lit.total(), 0.1 + 0.6 * l_dir[1] + 0.3 * max(r[1], 0) ** 10,
                               rtol=1e-12)


def test_directional_light_above_a_plane_lights_it_by_hand():
    """The issue's case: a plane under a directional light straight above. No object is in
    the way, so the pixel is k_a + k_d N.L + k_s (R.V)^n with N = L = (0, 1, 0)."""
    m = shading.Material()                              # k_a 0.1, k_d 0.7, k_s 0.2
    scene = rt.Scene([rt.Plane([0, 0, 0], [0, 1, 0])], [shading.directional_light([0, 1, 0])])
    camera = rt.Camera([0, 1, 3], [0, -1, -3], [0, 1, 0], 0.5, 4, 4)
    image = rt.render(scene, camera, max_depth=0)
    # pixel (2, 2): its primary ray, and the viewer direction at its hit point
    o, d = camera.rays().origins[2, 2, 0], camera.rays().directions[2, 2, 0]
    hit = o + (-o[1] / d[1]) * d
    v = unit(o - hit)
    r = np.array([0.0, 1.0, 0.0])                       # L reflected about N = N
    expected = m.ka + m.kd + m.ks * max(float(r @ v), 0.0) ** m.shininess
    np.testing.assert_allclose(image[2, 2], expected, rtol=1e-12)


def _side_by_side_scene():
    """A plane facing +z and three spheres in a row in front of it, lit along +z (from where
    the camera looks): every shadow ray leaves towards the light and passes nothing."""
    spheres = [rt.Sphere([x, 0.0, 0.0], 0.6) for x in (-1.5, 0.0, 1.5)]
    return rt.Scene(spheres, [shading.directional_light([0, 0, 1])])


@pytest.mark.parametrize("kind", ["plane", "spheres", "plane and point light"])
def test_an_unoccluded_directional_light_casts_no_shadow(kind):
    """With nothing between any visible point and the light, shadow rays change nothing:
    the image with shadow rays equals the image without (a missed object, t = inf, must never
    count as blocking a ray whose t_max is inf)."""
    camera = rt.Camera([0, 0.5, 6], [0, -0.08, -1], [0, 1, 0], np.radians(50), 48, 32)
    if kind == "plane":
        scene = rt.Scene([rt.Plane([0, -1, 0], [0, 1, 0])],
                         [shading.directional_light([0.3, 1, 0.2])])
    elif kind == "spheres":
        scene = _side_by_side_scene()
    else:       # a directional light and a point light above a plane with no object on it
        scene = rt.Scene([rt.Plane([0, -1, 0], [0, 1, 0])],
                         [shading.directional_light([0, 1, 1]), shading.point_light([0, 4, 2])])
    with_shadows = rt.render(scene, camera, max_depth=0, shadows=True)
    without = rt.render(scene, camera, max_depth=0, shadows=False)
    assert (with_shadows > 0.11).mean() > 0.05          # lit: more than the ambient term
    np.testing.assert_array_equal(with_shadows, without)


def test_spheres_in_a_row_have_no_shadowed_point_facing_the_light():
    """Every shadow ray of the side-by-side spheres, cast where N.L > 0, reaches the light."""
    scene = _side_by_side_scene()
    light = scene.lights[0].direction
    cast = 0
    for x in np.linspace(-2.0, 2.0, 17):
        for y in np.linspace(-0.5, 0.5, 5):
            tree = rt.trace_tree(scene, [x, y, 5.0], [0, 0, -1], max_depth=0)
            for node in tree.children:
                assert node.kind == "shadow"
                assert tree.normal @ light > 0          # only lights in front get a ray
                assert node.visibility == 1.0, (x, y)
                cast += 1
    assert cast > 20


def test_mirror_shows_the_object_in_the_mirror_direction():
    mirror = rt.Plane([0, 0, 0], [0, 0, 1],
                      rt.Material(shading.Material(0, 0, 0), reflectivity=1.0))
    glow = np.array([0.2, 0.5, 0.7])
    ball = rt.Sphere([2, 0, 2], 0.5, emissive(glow))
    scene = rt.Scene([mirror, ball])
    d = unit([1, 0, -1])
    tree = rt.trace_tree(scene, [-1, 0, 1], d, max_depth=1)
    np.testing.assert_allclose(tree.total(), glow, rtol=1e-12)
    reflected = tree.children[0]
    assert reflected.kind == "reflected" and reflected.weight == 1.0
    np.testing.assert_allclose(reflected.direction, unit([1, 0, 1]), atol=1e-12)
    assert reflected.object == 1
    np.testing.assert_allclose(rt.trace_tree(scene, [-1, 0, 1], d, max_depth=0).total(), 0)


def test_glass_sphere_head_on_transmits_one_minus_r0_twice():
    glass = rt.Material(shading.Material(0, 0, 0), transparency=1.0, ior=1.5)
    glow = np.array([0.8, 0.6, 0.4])
    wall = rt.Plane([0, 0, -5], [0, 0, 1], emissive(glow))
    scene = rt.Scene([rt.Sphere([0, 0, 0], 1.0, glass), wall])
    tree = rt.trace_tree(scene, [0, 0, 5], [0, 0, -1], max_depth=2)
    r0 = (0.5 / 2.5) ** 2                                   # 0.04
    # the straight path through both surfaces carries (1 - R0)^2; the reflected ones see black
    np.testing.assert_allclose(tree.total(), (1 - r0) ** 2 * glow, rtol=1e-12)
    refracted = [node for node in tree.walk() if node.kind == "refracted"]
    np.testing.assert_allclose(sorted(node.weight for node in refracted),
                               [(1 - r0) ** 2, 1 - r0], rtol=1e-12)
    through = [node for node in refracted if node.depth == 2][0]
    np.testing.assert_allclose(through.direction, [0, 0, -1], atol=1e-12)   # not bent
    np.testing.assert_allclose(through.origin[2], -1, atol=1e-3)


def test_total_internal_reflection_in_the_tracer():
    glass = rt.Material(shading.Material(0, 0, 0), transparency=0.9, ior=1.5)
    scene = rt.Scene([rt.Sphere([0, 0, 0], 1.0, glass)])
    # inside, hitting the surface at cos = sqrt(1 - 0.81) = 0.436 (64 degrees > 41.8)
    tree = rt.trace_tree(scene, [0, 0.9, 0], [1, 0, 0], max_depth=1)
    assert [node.kind for node in tree.children] == ["reflected"]
    assert tree.children[0].weight == pytest.approx(0.9)
    # at 30 degrees from inside: both, and the reflected share is Schlick's F
    angle = np.radians(30)
    tree = rt.trace_tree(scene, [0, np.sin(angle), 0], [1, 0, 0], max_depth=1)
    kinds = {node.kind: node.weight for node in tree.children}
    f = float(rt.schlick(np.cos(angle), 1.5, 1.0))
    assert kinds["reflected"] == pytest.approx(0.9 * f)
    assert kinds["refracted"] == pytest.approx(0.9 * (1 - f))
    # the refracted ray leaves bent away from the normal (GLSL refract, normal facing the ray)
    outward = np.array([np.cos(angle), np.sin(angle), 0.0])
    expected = np.array(glm.refract(glm.dvec3(1, 0, 0), glm.dvec3(*-outward), 1.5))
    refracted = [node for node in tree.children if node.kind == "refracted"][0]
    np.testing.assert_allclose(refracted.direction, expected, atol=1e-12)
    np.testing.assert_allclose(refracted.origin, outward, atol=1e-3)


def test_parallel_mirrors_ray_tree():
    scene = rt.example_scene("mirrors")
    for depth in range(5):
        tree = rt.trace_tree(scene, [0, 1.5, 0], [1, 0, 0], max_depth=depth)
        assert tree.count("reflected") == depth
        assert tree.count("refracted") == 0
        weights = [n.weight for n in tree.walk() if n.kind == "reflected"]
        np.testing.assert_allclose(weights, 0.9 ** np.arange(1, depth + 1))
    assert tree.count() == 1 + 4 + tree.count("shadow")


def test_render_sums_the_ray_tree_and_counts_rays():
    scene = rt.example_scene("spheres", 24, 18)
    image, counts = rt.render(scene, max_depth=2, return_counts=True)
    assert counts.primary == 24 * 18
    rays = scene.camera.rays()
    for j, i in ((5, 5), (9, 12), (3, 20), (12, 8)):
        tree = rt.trace_tree(scene, rays.origins[j, i, 0], rays.directions[j, i, 0], max_depth=2)
        np.testing.assert_allclose(image[j, i], np.clip(tree.total(), 0, 1), atol=1e-9)
    _, flat = rt.render(scene, max_depth=0, return_counts=True)
    assert flat.reflected == flat.refracted == 0 and flat.primary == 24 * 18


def test_supersampling_averages_the_finer_image():
    scene = rt.example_scene("spheres", 20, 16)
    sphere_only = rt.Scene(scene.objects[:2], scene.lights, 0.5, 0.2, scene.camera)
    coarse = rt.render(sphere_only, supersampling=4, max_depth=0)
    fine = rt.render(sphere_only, scene.camera.resized(40, 32), max_depth=0)
    assert fine.max() < 1                                # nothing clamped
    np.testing.assert_allclose(coarse, fine.reshape(16, 2, 20, 2, 3).mean(axis=(1, 3)),
                               atol=1e-12)


@pytest.mark.parametrize("rows", [1, 5, 18, 40])
def test_render_in_bands_traces_the_ray_tree_of_every_pixel(rows):
    """Band by band: each step adds the next `rows` rows (the rest still black), every pixel of
    the last step is its own ray tree's sum (trace_tree, one ray at a time) and the counts add
    up to the rays of the whole image; with jittered supersampling too."""
    scene = rt.example_scene("spheres", 24, 18)
    steps = list(rt.render_bands(scene, max_depth=2, rows=rows))
    assert [done for _, _, done in steps] == [min(k + rows, 18) for k in range(0, 18, rows)]
    before = 0
    for image, _, done in steps:
        assert not image[done:].any() and image[before:done].any()
        before = done
    image, counts, _ = steps[-1]
    rays = scene.camera.rays()
    for j, i in ((0, 0), (5, 5), (9, 12), (17, 20), (12, 8)):
        tree = rt.trace_tree(scene, rays.origins[j, i, 0], rays.directions[j, i, 0], max_depth=2)
        np.testing.assert_allclose(image[j, i], np.clip(tree.total(), 0, 1), atol=1e-9)
    _, whole = rt.render(scene, max_depth=2, return_counts=True)
    assert counts == whole and counts.primary == 24 * 18
    *_, (jittered, _, _) = rt.render_bands(scene, max_depth=1, rows=rows, supersampling=4,
                                           seed=3, jitter=True)
    np.testing.assert_allclose(jittered, rt.render(scene, max_depth=1, supersampling=4, seed=3,
                                                   jitter=True), atol=1e-12)
    with pytest.raises(ValueError, match="rows"):
        next(rt.render_bands(scene, rows=0))


def test_mesh_scene_renders_and_matches_brute_force_hits():
    scene = rt.example_scene("mesh", 16, 12)
    mesh = scene.objects[1]
    rays = scene.camera.rays()
    o, d = rays.origins.reshape(-1, 3), rays.directions.reshape(-1, 3)
    hits = rt.intersect_scene(scene, o, d)
    tri_hits = rt.intersect_triangles(o, d, mesh.vertices[mesh.faces], accelerate=False)
    plane_t = rt.intersect_plane(o, d, [0, 0, 0], [0, 1, 0]).t
    expected = np.where(tri_hits.t < plane_t, 1, np.where(np.isfinite(plane_t), 0, -1))
    np.testing.assert_array_equal(hits.objects, expected)
    image = rt.render(scene, max_depth=1)
    assert image.shape == (12, 16, 3) and np.all((image >= 0) & (image <= 1))


# ---------------------------------------------------------------------------------------------
# Bad input
# ---------------------------------------------------------------------------------------------

def test_bad_input_gets_clear_errors():
    scene = rt.example_scene("spheres", 8, 6)
    with pytest.raises(ValueError, match="directions must not contain the zero vector"):
        rt.intersect_sphere([[0, 0, 5], [0, 0, 5]], [[0, 0, -1], [0, 0, 0]], [0, 0, 0], 1)
    with pytest.raises(ValueError, match="directions must not contain the zero vector"):
        rt.intersect_triangles([0, 0, 5], [0, 0, 0], [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]])
    with pytest.raises(ValueError, match="direction must not contain the zero vector"):
        rt.trace_tree(scene, [0, 0, 5], [0, 0, 0])
    with pytest.raises(ValueError, match="d must not contain the zero vector"):
        rt.reflect_direction([0, 0, 0], [0, 1, 0])
    with pytest.raises(ValueError, match="radius must be positive"):
        rt.Sphere([0, 0, 0], -1.0)
    with pytest.raises(ValueError, match="radius must be positive"):
        rt.intersect_sphere([0, 0, 5], [0, 0, -1], [0, 0, 0], 0.0)
    with pytest.raises(ValueError, match="ior must be positive"):
        rt.Material(transparency=0.5, ior=0.0)
    with pytest.raises(ValueError, match="eta2 must be positive"):
        rt.refract_direction([1, -1, 0], [0, 1, 0], 1.0, -1.5)
    with pytest.raises(ValueError, match="eta1 must be positive"):
        rt.schlick(0.5, 0.0, 1.5)
    with pytest.raises(ValueError, match="max_depth must be a whole number >= 0"):
        rt.render(scene, max_depth=-1)
    with pytest.raises(ValueError, match="max_depth must be a whole number >= 0"):
        rt.trace_tree(scene, [0, 0, 5], [0, 0, -1], max_depth=-2)
    with pytest.raises(ValueError, match="samples_per_pixel must be a perfect square"):
        rt.render(scene, supersampling=3)
    with pytest.raises(ValueError, match="lo must not exceed hi"):
        rt.intersect_box([0, 0, 5], [0, 0, -1], [1, 1, 1], [0, 0, 0])
    with pytest.raises(ValueError, match="t_min must be >= 0"):
        rt.intersect_plane([0, 0, 5], [0, 0, -1], [0, 0, 0], [0, 0, 1], t_min=-1)
    with pytest.raises(ValueError, match="reflectivity \\+ transparency must not exceed 1"):
        rt.Material(reflectivity=0.6, transparency=0.6)
    with pytest.raises(ValueError, match="cos_theta must lie in"):
        rt.fresnel(1.5, 1.0, 1.5)
    with pytest.raises(ValueError, match="triangles must be an array of triangles"):
        rt.BVH(np.zeros((4, 3)))
    with pytest.raises(TypeError, match="objects\\[0\\] must be a Sphere, Plane or Mesh"):
        rt.Scene(["sphere"])
    with pytest.raises(TypeError, match="camera must be a Camera"):
        rt.render(scene, camera="front")
    with pytest.raises(ValueError, match="the scene has none"):
        rt.render(rt.Scene(scene.objects))
    with pytest.raises(TypeError, match="scene must be a Scene"):
        rt.render("scene")
    with pytest.raises(TypeError, match="directions must be numbers"):
        rt.intersect_plane([0, 0, 5], "down", [0, 0, 0], [0, 0, 1])
    with pytest.raises(ValueError, match="directions must be finite"):
        rt.intersect_plane([0, 0, 5], [0, np.nan, -1], [0, 0, 0], [0, 0, 1])
