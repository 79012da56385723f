"""Tests of course_lib.raytracing.quadrics against closed forms typed here, trimesh's ray-mesh
intersector, numerical gradients and numpy.roots (the torus quartic)."""
import numpy as np
import pytest
import trimesh
from trimesh.ray.ray_triangle import RayMeshIntersector

from course_lib.raytracing import (intersect_cylinder, intersect_disk, intersect_implicit,
                                   intersect_quadric, quadric_matrix, quadric_value,
                                   ray_quadratic, torus_function, transform_quadric)

RNG = np.random.default_rng(15)


def unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def test_matrices_against_the_implicit_equations_typed_here():
    p = RNG.normal(size=(50, 3))
    x, y, z = p.T
    forms = [
        ("sphere", dict(radius=2), x**2 + y**2 + z**2 - 4),
        ("ellipsoid", dict(radii=(1, 2, 3)), x**2 + y**2 / 4 + z**2 / 9 - 1),
        ("cylinder", dict(radius=0.5), x**2 + y**2 - 0.25),
        ("cone", dict(slope=2), x**2 + y**2 - 4 * z**2),
        ("paraboloid", dict(slope=3), 3 * (x**2 + y**2) - z),
        ("hyperboloid1", dict(radius=1, slope=0.5), x**2 + y**2 - 0.25 * z**2 - 1),
        ("hyperboloid2", dict(radius=1, slope=0.5), x**2 + y**2 - 0.25 * z**2 + 1),
    ]
    for kind, kw, want in forms:
        assert np.allclose(quadric_value(quadric_matrix(kind, **kw), p), want), kind
    moved = quadric_value(quadric_matrix("sphere", radius=1, center=(1, 2, 3)), p)
    assert np.allclose(moved, (x - 1)**2 + (y - 2)**2 + (z - 3)**2 - 1)


def test_ray_quadratic_matches_substitution_by_hand():
    o, d = np.array([3.0, 1.0, 2.0]), np.array([-1.0, 0.5, 0.25])
    a, b, c = ray_quadratic(o, d, quadric_matrix("cylinder", radius=2))
    assert np.isclose(a, d[0]**2 + d[1]**2)
    assert np.isclose(b, 2 * (o[0] * d[0] + o[1] * d[1]))
    assert np.isclose(c, o[0]**2 + o[1]**2 - 4)


def test_cylinder_from_outside_along_x_closed_form():
    r = 1.5
    ys = np.linspace(-2, 2, 41)
    o = np.stack([np.full_like(ys, 5.0), ys, np.zeros_like(ys)], axis=1)
    hits = intersect_quadric(o, [-1, 0, 0], quadric_matrix("cylinder", radius=r))
    inside = np.abs(ys) <= r
    want = np.where(inside, 5 - np.sqrt(np.clip(r * r - ys**2, 0, None)), np.inf)
    assert np.allclose(hits.t[inside], want[inside]) and np.all(np.isinf(hits.t[~inside]))
    x = 5 - hits.t[inside]
    assert np.allclose(hits.normals[inside], np.stack([x, ys[inside], 0 * x], 1) / r)


def test_cone_and_paraboloid_closed_forms():
    # cone x^2 + y^2 = z^2 (slope 1), ray from (2, 0, 1) along -x: x^2 = 1 -> x = 1, t = 1
    hits = intersect_quadric([2, 0, 1], [-1, 0, 0], quadric_matrix("cone"))
    assert np.isclose(hits.t, 1.0)
    assert np.allclose(hits.normals, unit([1, 0, -1]))
    # paraboloid z = x^2 + y^2, ray straight down from (0.5, 0, 5): z = 0.25, t = 4.75
    hits = intersect_quadric([0.5, 0, 5], [0, 0, -1], quadric_matrix("paraboloid"))
    assert np.isclose(hits.t, 4.75)
    assert np.allclose(hits.normals, unit([2 * 0.5, 0, -1]))


def test_linear_case_ray_parallel_to_the_cone_generator():
    # direction (1, 0, 1) lies on the cone x^2 = z^2 (a = 0); from (0, 0, 1): x^2 = (1+t)^2 - ...
    # f(t) = t^2 - (1 + t)^2 = -1 - 2t: no positive root; from (0, 0, -1): 1 - (t - 1)^2... by
    # hand: f = t^2 - (t - 1)^2 = 2t - 1 -> t = 1/2
    hits = intersect_quadric([0, 0, -1], [1, 0, 1], quadric_matrix("cone"))
    assert np.isclose(hits.t, 0.5)
    assert np.isinf(intersect_quadric([0, 0, 1], [1, 0, 1], quadric_matrix("cone")).t)
    # a ray along the cylinder's axis never meets it
    assert np.isinf(intersect_quadric([0.5, 0, 0], [0, 0, 1], quadric_matrix("cylinder")).t)


def test_hyperboloids_closed_forms():
    # one sheet x^2 + y^2 - z^2 = 1 at height z = 1: radius sqrt(2)
    hits = intersect_quadric([3, 0, 1], [-1, 0, 0], quadric_matrix("hyperboloid1"))
    assert np.isclose(hits.t, 3 - np.sqrt(2))
    # two sheets z^2 = x^2 + y^2 + 1 along the axis from z = 5: hits z = 1
    hits = intersect_quadric([0, 0, 5], [0, 0, -1], quadric_matrix("hyperboloid2"))
    assert np.isclose(hits.t, 4.0)
    # from between the sheets, sideways: never hits
    assert np.isinf(intersect_quadric([3, 0, 0], [-1, 0, 0], quadric_matrix("hyperboloid2")).t)


def test_starting_inside_takes_the_far_root_and_t_min():
    Q = quadric_matrix("sphere", radius=1)
    assert np.isclose(intersect_quadric([0, 0, 0], [1, 0, 0], Q).t, 1.0)
    assert np.isclose(intersect_quadric([-3, 0, 0], [1, 0, 0], Q, t_min=2.5).t, 4.0)


def test_clipping_sees_the_inside_through_the_open_end():
    Q = quadric_matrix("cylinder", radius=1)
    # from above, slanted: the near root is above z = 1, the far root inside the tube
    o, d = np.array([-2.0, 0, 3.0]), unit([1, 0, -1])
    t_all = intersect_quadric(o, d, Q).t
    hits = intersect_quadric(o, d, Q, clip=(0, 1))
    z = o[2] + hits.t * d[2]
    assert hits.t > t_all and 0 <= z <= 1
    # the point is on the far wall x = +1 and the normal (outward) is +x
    assert np.isclose(o[0] + hits.t * d[0], 1.0)
    assert np.allclose(hits.normals, [1, 0, 0])
    flipped = intersect_quadric(o, d, Q, clip=(0, 1), face_ray=True)
    assert np.allclose(flipped.normals, [-1, 0, 0])


def test_normals_against_numerical_gradient():
    Q = quadric_matrix("ellipsoid", radii=(1, 2, 0.5), center=(0.3, -0.2, 0.1))
    o = RNG.normal(size=(200, 3)) * 0.1 + [0, 0, 6]
    d = unit(RNG.normal(size=(200, 3)) * 0.15 + [0, 0, -1])
    hits = intersect_quadric(o, d, Q)
    ok = np.isfinite(hits.t)
    assert ok.sum() > 50
    p = hits.points[ok]
    h = 1e-6
    g = np.stack([(quadric_value(Q, p + e) - quadric_value(Q, p - e)) / (2 * h)
                  for e in np.eye(3) * h], axis=1)
    assert np.allclose(hits.normals[ok], unit(g), atol=1e-6)
    assert np.allclose(quadric_value(Q, p), 0, atol=1e-9)


def _trimesh_first(mesh, o, d):
    loc, ray_idx, _ = RayMeshIntersector(mesh).intersects_location(o, d, multiple_hits=True)
    t = np.full(len(o), np.inf)
    for k, q in zip(ray_idx, loc):
        t[k] = min(t[k], float(np.dot(q - o[k], d[k])))
    return t


def test_finite_cylinder_against_trimesh():
    r, h = 1.0, 2.0
    mesh = trimesh.creation.cylinder(radius=r, height=h, sections=256)   # z in [-1, 1]
    o = np.column_stack([RNG.uniform(-0.7, 0.7, 300), RNG.uniform(-0.7, 0.7, 300),
                         np.full(300, 6.0)])
    o[150:] = np.column_stack([np.full(150, 5.0), RNG.uniform(-0.7, 0.7, 150),
                               RNG.uniform(-0.8, 0.8, 150)])
    d = unit(np.where(np.arange(300)[:, None] < 150, [0, 0, -1], [-1, 0, 0])
             + RNG.normal(size=(300, 3)) * 0.05)
    ours = intersect_cylinder(o, d, radius=r, z_range=(-1, 1)).t
    theirs = _trimesh_first(mesh, o, d)
    assert np.array_equal(np.isfinite(ours), np.isfinite(theirs))
    both = np.isfinite(ours)
    # the 256-gon sits inside the circle by r (1 - cos(pi / 256)) ~ 7.5e-5
    assert np.allclose(ours[both], theirs[both], atol=2e-3)


def test_cone_and_ellipsoid_against_trimesh():
    # trimesh's cone: base radius 1 at z = 0, apex at z = 2: x^2 + y^2 = (z - 2)^2 / 4
    mesh = trimesh.creation.cone(radius=1.0, height=2.0, sections=256)
    Q = quadric_matrix("cone", slope=0.5, center=(0, 0, 2))
    o = np.column_stack([np.full(100, 4.0), RNG.uniform(-0.3, 0.3, 100),
                         RNG.uniform(0.2, 1.6, 100)])
    d = np.tile([-1.0, 0, 0], (100, 1))
    ours = intersect_quadric(o, d, Q, clip=(0, 2)).t
    assert np.allclose(ours, _trimesh_first(mesh, o, d), atol=2e-3)
    # ellipsoid: an icosphere scaled by (1, 2, 0.5)
    mesh = trimesh.creation.icosphere(subdivisions=6)
    mesh.apply_scale([1.0, 2.0, 0.5])
    Q = transform_quadric(quadric_matrix("sphere"), np.diag([1.0, 2.0, 0.5, 1.0]))
    o = np.column_stack([RNG.uniform(-0.6, 0.6, 100), RNG.uniform(-1.2, 1.2, 100),
                         np.full(100, 3.0)])
    d = np.tile([0, 0, -1.0], (100, 1))
    ours = intersect_quadric(o, d, Q).t
    assert np.allclose(ours, _trimesh_first(mesh, o, d), atol=2e-3)


def test_disk_against_plane_and_radius_typed_here():
    c, n, r = np.array([1.0, 2.0, 0.5]), unit([0.2, -0.3, 1.0]), 0.8
    o = RNG.uniform(-1, 3, size=(400, 3)) + [0, 0, 3]
    d = unit(RNG.normal(size=(400, 3)) * 0.4 + [0, 0, -1])
    hits = intersect_disk(o, d, c, n * 3, r)
    t = ((c - o) @ n) / (d @ n)
    p = o + t[:, None] * d
    want = np.where((t >= 0) & (np.linalg.norm(p - c, axis=1) <= r), t, np.inf)
    assert np.isfinite(want).sum() > 10
    assert np.allclose(hits.t[np.isfinite(want)], want[np.isfinite(want)])
    assert np.array_equal(np.isfinite(hits.t), np.isfinite(want))
    assert np.allclose(hits.normals[np.isfinite(want)], n)
    # behind the origin does not count
    assert np.isinf(intersect_disk([0, 0, -1], [0, 0, -1], [0, 0, 0], [0, 0, 1], 1).t)


def test_implicit_solver_matches_sphere_closed_form():
    f = lambda p: np.sum(p * p, axis=-1) - 4.0       # noqa: E731
    o = RNG.uniform(-1.5, 1.5, size=(100, 3)) + [0, 0, 6]
    d = np.tile([0, 0, -1.0], (100, 1))
    hits = intersect_implicit(o, d, f, t_max=12)
    rho2 = o[:, 0]**2 + o[:, 1]**2
    want = np.where(rho2 <= 4, o[:, 2] - np.sqrt(np.clip(4 - rho2, 0, None)), np.inf)
    assert np.allclose(hits.t, want, atol=1e-9)
    p = o + hits.t[:, None] * d
    assert np.allclose(hits.normals, p / 2, atol=1e-5)


def test_implicit_solver_matches_torus_quartic_roots():
    big, small = 2.0, 0.5
    f = torus_function(big, small)
    o = np.column_stack([np.full(60, -5.0), RNG.uniform(-2.4, 2.4, 60), RNG.uniform(-0.4, 0.4, 60)])
    d = unit(np.column_stack([np.ones(60), RNG.normal(size=60) * 0.1, RNG.normal(size=60) * 0.05]))
    hits = intersect_implicit(o, d, f, t_max=12, steps=400)
    for k in range(60):
        # (|o + t d|^2 + R^2 - r^2)^2 - 4 R^2 ((ox + t dx)^2 + (oy + t dy)^2), |d| = 1
        od, oo = o[k] @ d[k], o[k] @ o[k]
        s = np.array([1.0, 2 * od, oo + big**2 - small**2])      # |.|^2 + R^2 - r^2 in t
        q = np.array([d[k, 0]**2 + d[k, 1]**2, 2 * (o[k, 0] * d[k, 0] + o[k, 1] * d[k, 1]),
                      o[k, 0]**2 + o[k, 1]**2])
        quartic = np.polysub(np.polymul(s, s), 4 * big**2 * np.r_[0, 0, q])
        roots = np.roots(quartic)
        real = np.sort(roots[np.abs(roots.imag) < 1e-9].real)
        real = real[real >= 0]
        if len(real):
            assert np.isclose(hits.t[k], real[0], atol=1e-8), k
        else:
            assert np.isinf(hits.t[k]), k


def test_implicit_solver_normals_with_and_without_gradient():
    f = torus_function(2.0, 0.5)

    def grad(p):
        s = np.sum(p * p, axis=-1) + 4 - 0.25
        g = 4 * s[:, None] * p
        g[:, :2] -= 8 * 4 * p[:, :2]
        return g
    o, d = [[-5, 0.1, 0.2]], [[1, 0, 0]]
    a = intersect_implicit(o, d, f)
    b = intersect_implicit(o, d, f, grad=grad)
    assert np.allclose(a.t, b.t) and np.allclose(a.normals, b.normals, atol=1e-6)


def test_coarse_sampling_misses_a_thin_part():
    f = torus_function(2.0, 0.05)                      # a tube 0.1 thick
    o, d = [[-5, 0, 0]], [[1, 0, 0]]
    assert np.isfinite(intersect_implicit(o, d, f, steps=400).t).all()
    assert np.isinf(intersect_implicit(o, d, f, steps=4).t).all()      # samples at t=0,2.5,..


def test_closed_cylinder_caps():
    hits = intersect_cylinder([[0.2, 0.1, 5], [0.2, 0.1, -5]], [[0, 0, -1], [0, 0, 1]],
                              radius=1, z_range=(0, 2))
    assert np.allclose(hits.t, [3, 5]) and np.allclose(hits.normals, [[0, 0, 1], [0, 0, -1]])
    open_tube = intersect_cylinder([0.2, 0.1, 5], [0, 0, -1], radius=1, z_range=(0, 2),
                                   caps=False)
    assert np.isinf(open_tube.t)


@pytest.mark.parametrize("Q, msg", [
    (np.zeros((4, 4)), "all zero"),
    (np.triu(np.ones((4, 4))), "symmetric"),
    (np.eye(3), "4x4"),
    (np.diag([1, 1, np.nan, 1]), "finite"),
    (np.diag([0, 0, 0, 1.0]), "no x, y, z"),
])
def test_degenerate_quadrics_are_rejected(Q, msg):
    with pytest.raises(ValueError, match=msg):
        intersect_quadric([0, 0, 5], [0, 0, -1], Q)


def test_other_errors():
    with pytest.raises(ValueError, match="kind"):
        quadric_matrix("torus")
    with pytest.raises(ValueError, match="radius"):
        quadric_matrix("sphere", radius=0)
    with pytest.raises(ValueError, match="radii"):
        quadric_matrix("ellipsoid", radii=(1, -1, 1))
    with pytest.raises(ValueError, match="clip"):
        intersect_quadric([0, 0, 5], [0, 0, -1], np.eye(4), clip=(2, 1))
    with pytest.raises(ValueError, match="directions"):
        intersect_quadric([0, 0, 5], [0, 0, 0], quadric_matrix("sphere"))
    with pytest.raises(ValueError, match="radius"):
        intersect_disk([0, 0, 5], [0, 0, -1], [0, 0, 0], [0, 0, 1], -1)
    with pytest.raises(ValueError, match="normal"):
        intersect_disk([0, 0, 5], [0, 0, -1], [0, 0, 0], [0, 0, 0], 1)
    with pytest.raises(TypeError, match="f must be"):
        intersect_implicit([0, 0, 5], [0, 0, -1], "x^2")
    with pytest.raises(ValueError, match="shape"):
        intersect_implicit([0, 0, 5], [0, 0, -1], lambda p: p)
    with pytest.raises(ValueError, match="t_max"):
        intersect_implicit([0, 0, 5], [0, 0, -1], lambda p: p[:, 0], t_max=np.inf)
    with pytest.raises(ValueError, match="steps"):
        intersect_implicit([0, 0, 5], [0, 0, -1], lambda p: p[:, 0], steps=0)
    with pytest.raises(ValueError, match="minor"):
        torus_function(1.0, 2.0)
    with pytest.raises(ValueError, match="invertible"):
        transform_quadric(np.eye(4), np.diag([1.0, 0, 1, 1]))
