"""Two-part mapping against closed forms typed here: the sphere's spherical map, the intersection
points on the surfaces' implicit equations, the box's face planar maps, and trimesh's ray casting
for the reflected rays of a mesh object."""
import numpy as np
import pytest
import trimesh

from course_lib.texturing import two_part as tp


def _sphere_points(n, r=0.7, seed=0):
    rng = np.random.default_rng(seed)
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    return r * d, d


def _closed_form_spherical(d):
    r = np.linalg.norm(d, axis=-1)
    return (0.5 + np.arctan2(d[:, 0], d[:, 2]) / (2 * np.pi),
            0.5 + np.arcsin(d[:, 1] / r) / np.pi)


@pytest.mark.parametrize("method", ["normal", "centroid", "intermediate_normal"])
def test_sphere_object_on_the_sphere_is_the_spherical_map(method):
    p, n = _sphere_points(200)
    u, v = tp.two_part_map(p, n, "sphere", method, size=2.0, centroid=(0, 0, 0))
    uc, vc = _closed_form_spherical(p)
    assert np.allclose(u, uc) and np.allclose(v, vc)


@pytest.mark.parametrize("surface", tp.SURFACES)
@pytest.mark.parametrize("method", tp.METHODS)
def test_intersection_points_lie_on_the_surface(surface, method):
    rng = np.random.default_rng(5)
    p = rng.uniform(-0.5, 0.5, (300, 3))
    n = rng.normal(size=(300, 3))
    c, s = np.array([0.1, -0.2, 0.05]), 1.5
    q, hit = tp.intermediate_points(p, n, surface, method, center=c, size=s, eye=(0, 0, 5))
    assert hit.mean() > 0.99
    d = q[hit] - c
    if surface == "sphere":
        assert np.allclose(np.sum(d * d, axis=1), s * s)
    elif surface == "cylinder":
        assert np.allclose(d[:, 0] ** 2 + d[:, 2] ** 2, s * s)
    elif surface == "plane":
        assert np.allclose(d[:, 2], -s)              # the plane z = c_z - s
    else:
        assert np.allclose(np.abs(d).max(axis=1), s)
    if method in ("normal", "reflected", "centroid") and surface != "plane":
        # Q - P is along the ray direction, forwards (t >= 0)
        if method == "normal":
            w = n / np.linalg.norm(n, axis=1, keepdims=True)
        elif method == "centroid":
            w = p - p.mean(axis=0)
        else:
            view = p - [0, 0, 5]
            nn = n / np.linalg.norm(n, axis=1, keepdims=True)
            w = view - 2 * np.sum(view * nn, axis=1, keepdims=True) * nn
        qp = q[hit] - p[hit]
        assert np.allclose(np.cross(qp, w[hit]), 0, atol=1e-9)
        assert (np.sum(qp * w[hit], axis=1) >= 0).all()


def test_normal_method_on_a_box_is_the_planar_map_of_the_face():
    rng = np.random.default_rng(2)
    a, s = 0.4, 1.0                             # a small cube object inside the unit box
    uv = rng.uniform(-a, a, (40, 2))
    # face +z of the object: normal z, the box face +z: u = (x + s)/(2s), v = (y + s)/(2s)
    p = np.column_stack([uv, np.full(40, a)])
    u, v = tp.two_part_map(p, [0, 0, 1], "box", "normal", size=s)
    assert np.allclose(u, (p[:, 0] + s) / (2 * s)) and np.allclose(v, (p[:, 1] + s) / (2 * s))
    # face -x: seen from -x, u grows towards -z... with e_u = y x (-x) = +z: u = (z + s)/(2s)
    p = np.column_stack([np.full(40, -a), uv[:, 0], uv[:, 1]])
    u, v = tp.two_part_map(p, [-1, 0, 0], "box", "normal", size=s)
    assert np.allclose(u, (p[:, 2] + s) / (2 * s)) and np.allclose(v, (p[:, 1] + s) / (2 * s))
    # top face +y: e_u = x, e_v = y x x = -z: u = (x + s)/(2s), v = (s - z)/(2s)
    p = np.column_stack([uv[:, 0], np.full(40, a), uv[:, 1]])
    u, v = tp.two_part_map(p, [0, 1, 0], "box", "normal", size=s)
    assert np.allclose(u, (p[:, 0] + s) / (2 * s)) and np.allclose(v, (s - p[:, 2]) / (2 * s))


def test_cylinder_normal_method_closed_form():
    # a point (0.3, 0.2, 0) with normal along x hits the cylinder of radius 1 at (1, 0.2, 0):
    # u = 1/2 + atan2(1, 0)/(2 pi) = 3/4, v = (0.2 + 1)/2 = 0.6
    u, v = tp.two_part_map([[0.3, 0.2, 0]], [[1, 0, 0]], "cylinder", "normal")
    assert np.allclose([u[0], v[0]], [0.75, 0.6])
    # intermediate normal: radial projection keeps the height
    u, v = tp.two_part_map([[0.0, -0.5, -0.2]], None, "cylinder", "intermediate_normal")
    assert np.allclose([u[0], v[0]], [0.0, 0.25]) or np.allclose([u[0], v[0]], [1.0, 0.25])


def test_reflected_rays_against_trimesh_ray_casting():
    """The reflected O-mapping of a sphere's points onto the box, recomputed with trimesh's
    ray caster on a triangulated box (from inside, the first hit is where it leaves)."""
    p, n = _sphere_points(60, r=0.5, seed=4)
    eye = np.array([0.3, 0.4, 6.0])
    q, hit = tp.intermediate_points(p, n, "box", "reflected", size=1.0, eye=eye)
    view = (p - eye) / np.linalg.norm(p - eye, axis=1, keepdims=True)
    r = view - 2 * np.sum(view * n, axis=1, keepdims=True) * n
    box = trimesh.creation.box(extents=(2, 2, 2))
    loc, idx, _ = box.ray.intersects_location(p, r, multiple_hits=False)
    ref = np.empty_like(p)
    ref[idx] = loc
    assert hit.all() and len(idx) == len(p)
    assert np.allclose(q, ref, atol=1e-6)


def test_plane_accepts_both_directions_and_reflected_depends_on_the_eye():
    u, v = tp.two_part_map([[0.2, 0.4, 0.5]], [[0, 0, 1]], "plane", "normal")   # backwards
    assert np.allclose([u[0], v[0]], [0.6, 0.7])
    p, n = _sphere_points(20, seed=9)
    a = tp.two_part_map(p, n, "sphere", "reflected", size=3, eye=(0, 0, 5))
    b = tp.two_part_map(p, n, "sphere", "reflected", size=3, eye=(5, 0, 0))
    assert not np.allclose(a[0], b[0])
    c = tp.two_part_map(p, n, "sphere", "normal", size=3, eye=(5, 0, 0))
    d = tp.two_part_map(p, n, "sphere", "normal", size=3, eye=(0, 0, 5))
    assert np.allclose(c, d)


def test_misses_are_nan_and_flagged():
    q, hit = tp.intermediate_points([[0, 0, 0]], [[0, 1, 0]], "cylinder", "normal")
    assert not hit[0] and np.isnan(q).all()
    u, v = tp.two_part_map([[0, 0, 0]], [[1, 0, 0]], "plane", "normal")
    assert np.isnan(u[0]) and np.isnan(v[0])


def test_bad_input_is_named():
    with pytest.raises(ValueError, match="surface must be one of 'plane', 'cylinder', 'sphere', 'box'"):
        tp.two_part_map([[0, 0, 1]], [[0, 0, 1]], "cone")
    with pytest.raises(ValueError, match="method must be one of 'reflected', 'normal', 'centroid', "
                       "'intermediate_normal'"):
        tp.two_part_map([[0, 0, 1]], [[0, 0, 1]], "sphere", "view")
    with pytest.raises(ValueError, match="normals must not contain the zero vector"):
        tp.two_part_map([[0, 0, 1]], [[0, 0, 0]], "sphere", "normal")
    with pytest.raises(ValueError, match="normals are needed"):
        tp.two_part_map([[0, 0, 1]], None, "sphere", "normal")
    with pytest.raises(ValueError, match="eye is needed"):
        tp.two_part_map([[0, 0, 1]], [[0, 0, 1]], "sphere", "reflected")
    with pytest.raises(ValueError, match="points must be finite"):
        tp.two_part_map([[np.nan, 0, 1]], [[0, 0, 1]], "sphere", "normal")
    with pytest.raises(ValueError, match="normals must be finite"):
        tp.two_part_map([[0, 0, 1]], [[np.inf, 0, 1]], "sphere", "normal")
    with pytest.raises(ValueError, match="size must be positive"):
        tp.two_part_map([[0, 0, 1]], [[0, 0, 1]], "sphere", "normal", size=0)
    with pytest.raises(ValueError, match="points - centroid"):
        tp.two_part_map([[0, 0, 1]], None, "sphere", "centroid")
    with pytest.raises(ValueError, match="points must not be at the center"):
        tp.box_face([[0, 0, 0]])
