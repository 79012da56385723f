"""Environment mapping (ch 14): cube, sphere and latitude-longitude maps, cross-checked against
the OpenGL specification's table typed here, closed forms, scipy and the ray tracer."""
import numpy as np
import pytest
from scipy import ndimage

from course_lib import raytracing
from course_lib.texturing import environment as env

RNG = np.random.default_rng(1414)


def _spec_face(r):
    """OpenGL spec, cube map face selection, typed from its table (one direction, scalar)."""
    rx, ry, rz = (float(c) for c in r)
    ax, ay, az = abs(rx), abs(ry), abs(rz)
    if ax >= ay and ax >= az:
        face, sc, tc, ma = (0, -rz, -ry, rx) if rx > 0 else (1, rz, -ry, rx)
    elif ay >= az:
        face, sc, tc, ma = (2, rx, rz, ry) if ry > 0 else (3, rx, -rz, ry)
    else:
        face, sc, tc, ma = (4, rx, -ry, rz) if rz > 0 else (5, -rx, -ry, rz)
    return face, 0.5 * (sc / abs(ma) + 1), 0.5 * (tc / abs(ma) + 1)


def test_cube_face_matches_the_specification_table():
    d = RNG.normal(size=(2000, 3)) * RNG.uniform(0.1, 10, size=(2000, 1))
    face, s, t = env.cube_face_coordinates(d)
    expected = np.array([_spec_face(r) for r in d])
    assert np.array_equal(face, expected[:, 0].astype(int))
    assert np.allclose(s, expected[:, 1]) and np.allclose(t, expected[:, 2])
    assert set(face) == set(range(6))


@pytest.mark.parametrize("d, face, s, t", [
    ((1, 0, 0), 0, 0.5, 0.5), ((-1, 0, 0), 1, 0.5, 0.5), ((0, 1, 0), 2, 0.5, 0.5),
    ((0, -1, 0), 3, 0.5, 0.5), ((0, 0, 1), 4, 0.5, 0.5), ((0, 0, -1), 5, 0.5, 0.5),
    ((2, 1, 0), 0, 0.5, 0.25), ((2, 0, 1), 0, 0.25, 0.5),      # +X: sc = -rz, tc = -ry
    ((-2, 0, 1), 1, 0.75, 0.5), ((0, 2, 1), 2, 0.5, 0.75),     # -X: sc = +rz; +Y: tc = +rz
    ((0, -2, 1), 3, 0.5, 0.25), ((1, 0, 2), 4, 0.75, 0.5),     # -Y: tc = -rz; +Z: sc = +rx
    ((1, 0, -2), 5, 0.25, 0.5),                                # -Z: sc = -rx
])
def test_cube_face_by_hand(d, face, s, t):
    f, ss, tt = env.cube_face_coordinates(d)
    assert (int(f), float(ss), float(tt)) == pytest.approx((face, s, t))


def test_ties_go_to_x_then_y_then_z_and_both_faces_agree():
    f, s, t = env.cube_face_coordinates([[1, 1, 0], [0, -1, 1], [1, 1, 1], [-1, 0, -1]])
    assert list(f) == [0, 3, 0, 1]
    # on an edge both faces name the same direction: the round trip lands on the direction
    d = env.cube_face_direction(f, s, t)
    assert np.allclose(d, [[1, 1, 0], [0, -1, 1], [1, 1, 1], [-1, 0, -1]])
    # the other face's (s, t) of an edge direction is on its border too
    assert _spec_face([1, 1, 0])[0] == 0
    f2, s2, t2 = env.cube_face_coordinates([0.999999, 1, 0])
    assert int(f2) == 2 and np.isclose(float(s2), 1.0, atol=1e-5)


def test_round_trip_direction_face_direction():
    d = RNG.normal(size=(500, 3))
    f, s, t = env.cube_face_coordinates(d)
    back = env.cube_face_direction(f, s, t)
    assert np.allclose(back / np.linalg.norm(back, axis=1)[:, None],
                       d / np.linalg.norm(d, axis=1)[:, None])
    assert np.allclose(np.abs(back).max(axis=1), 1.0)        # on the cube
    f = RNG.integers(0, 6, 300)
    s, t = RNG.uniform(0.001, 0.999, (2, 300))
    f2, s2, t2 = env.cube_face_coordinates(env.cube_face_direction(f, s, t))
    assert np.array_equal(f, f2) and np.allclose(s, s2) and np.allclose(t, t2)


def test_face_boundaries_meet():
    # s = 1 of +Z (rx = rz) is the s = 0 ... edge of +X: the same direction from both faces
    t = np.linspace(0, 1, 7)
    a = env.cube_face_direction(4, np.ones(7), t)     # +Z right edge
    b = env.cube_face_direction(0, np.zeros(7), t)    # +X, s = 0 means rz = +1
    assert np.allclose(a, b)
    a = env.cube_face_direction(2, t, np.ones(7))     # +Y, t = 1: rz = +1
    b = env.cube_face_direction(4, t, np.ones(7))     # +Z, t = 1: ry = -1 ... not +Y
    assert np.allclose(a[:, 2], 1) and np.allclose(b[:, 1], -1)


def _cube_rgb(n=8):
    return RNG.uniform(size=(6, n, n, 3))


def test_nearest_sample_is_the_texel_containing_s_t():
    cube = _cube_rgb()
    d = RNG.normal(size=(400, 3))
    f, s, t = (np.array(x) for x in zip(*[_spec_face(r) for r in d]))
    f = f.astype(int)
    i = np.minimum((t * 8).astype(int), 7)
    j = np.minimum((s * 8).astype(int), 7)
    assert np.allclose(env.sample_cube_map(cube, d, "nearest"), cube[f, i, j])


def test_bilinear_sample_against_scipy_map_coordinates_per_face():
    cube = _cube_rgb(6)
    d = RNG.normal(size=(600, 3))
    got = env.sample_cube_map(cube, d)
    f, s, t = (np.array(x) for x in zip(*[_spec_face(r) for r in d]))
    for face in range(6):
        m = f == face
        rows, cols = t[m] * 6 - 0.5, s[m] * 6 - 0.5
        for ch in range(3):
            ref = ndimage.map_coordinates(cube[face, :, :, ch], [rows, cols], order=1,
                                          mode="nearest")
            assert np.allclose(got[m, ch], ref)


def test_cube_map_from_function_reproduces_the_function_at_texel_centres():
    cube = env.cube_map_from_function(env.axes_environment, 16)
    d = RNG.normal(size=(300, 3))
    # nearest look-up = the function at the containing texel's centre direction
    f, s, t = env.cube_face_coordinates(d)
    cs, ct = (np.floor(s * 16) + 0.5) / 16, (np.floor(t * 16) + 0.5) / 16
    centre = env.cube_face_direction(f, cs, ct)
    assert np.allclose(env.sample_cube_map(cube, d, "nearest"),
                       0.5 + 0.45 * centre / np.linalg.norm(centre, axis=1)[:, None])
    assert np.abs(env.sample_cube_map(cube, d) - env.axes_environment(d)).max() < 0.05


def test_cube_cross_layout_and_cross_position():
    cube = env.cube_map_from_function(env.axes_environment, 12)
    cross = env.cube_cross(cube, background=-1)
    assert cross.shape == (36, 48, 3)
    assert np.all(cross[:12, :12] == -1) and np.all(cross[24:, 36:] == -1)
    d = RNG.normal(size=(200, 3))
    xy = env.cross_position(d) * 12
    pix = cross[np.minimum(xy[:, 1].astype(int), 35), np.minimum(xy[:, 0].astype(int), 47)]
    assert np.abs(pix - env.axes_environment(d)).max() < 0.1
    # continuity across every fold: neighbouring pixels across cell borders are similar
    mid = cross[12:24]
    assert np.abs(np.diff(mid, axis=1)).max() < 0.1
    col = cross[:, 12:24]
    assert np.abs(np.diff(col, axis=0)).max() < 0.1


# -- sphere maps ---------------------------------------------------------------------------

def test_sphere_map_closed_form():
    r = RNG.normal(size=(500, 3))
    r /= np.linalg.norm(r, axis=1)[:, None]
    s, t = env.sphere_map_coordinates(r * 3.0)           # any length
    m = 2 * np.sqrt(r[:, 0] ** 2 + r[:, 1] ** 2 + (r[:, 2] + 1) ** 2)
    assert np.allclose(s, r[:, 0] / m + 0.5) and np.allclose(t, r[:, 1] / m + 0.5)
    assert np.all((s - 0.5) ** 2 + (t - 0.5) ** 2 <= 0.25 + 1e-12)


def test_sphere_map_is_the_mirror_ball_seen_along_minus_z():
    # the ball's normal at (s, t) reflects the view ray (0, 0, -1) into the direction shown
    s, t = RNG.uniform(0.2, 0.8, (2, 300))
    x, y = 2 * s - 1, 2 * t - 1
    n = np.stack([x, y, np.sqrt(1 - x * x - y * y)], -1)
    view = np.array([0, 0, -1.0])
    r = view - 2 * (n @ view)[:, None] * n
    assert np.allclose(env.sphere_map_direction(s, t), r)
    s2, t2 = env.sphere_map_coordinates(r)
    assert np.allclose(s2, s) and np.allclose(t2, t)


def test_sphere_map_special_points():
    s, t = env.sphere_map_coordinates([[0, 0, 1], [0, 0, -1], [0, 1, 0]])
    assert np.allclose(s, [0.5, 1.0, 0.5])
    assert np.allclose(t, [0.5, 0.5, 0.5 + 1 / (2 * np.sqrt(2))])     # m = 2 sqrt(2)
    # the whole rim is the singular direction
    a = np.linspace(0, 2 * np.pi, 9)
    assert np.allclose(env.sphere_map_direction(0.5 + 0.5 * np.cos(a), 0.5 + 0.5 * np.sin(a)),
                       [0, 0, -1], atol=1e-6)


def test_sphere_map_sampling_and_view():
    m = env.sphere_map_from_function(env.axes_environment, 96)
    d = RNG.normal(size=(200, 3))
    d = d[d[:, 2] > -0.5]                                   # away from the rim
    assert np.abs(env.sample_sphere_map(m, d) - env.axes_environment(d)).max() < 0.05
    rot = np.array([[0.0, 0, 1], [0, 1, 0], [-1, 0, 0]])   # eye axes in world space
    mv = env.sphere_map_from_function(env.axes_environment, 96, view=rot)
    dw = d @ rot.T
    assert np.abs(env.sample_sphere_map(mv, dw, view=rot) - env.axes_environment(dw)).max() < 0.05


# -- latitude-longitude ----------------------------------------------------------------------

def test_latlong_against_atan2():
    d = RNG.normal(size=(300, 3))
    u, v = env.latlong_coordinates(d)
    r = np.linalg.norm(d, axis=1)
    assert np.allclose(u, 0.5 + np.arctan2(d[:, 0], d[:, 2]) / (2 * np.pi))
    assert np.allclose(v, 0.5 + np.arcsin(d[:, 1] / r) / np.pi)
    assert np.allclose(env.latlong_direction(u, v), d / r[:, None])


def test_latlong_sampling_wraps_across_the_seam():
    m = env.latlong_map_from_function(env.axes_environment, 32)
    d = RNG.normal(size=(300, 3))
    assert np.abs(env.sample_latlong_map(m, d) - env.axes_environment(d)).max() < 0.05
    # just either side of the seam (-z, u = 0 = 1) the look-ups agree
    a = env.sample_latlong_map(m, [[1e-4, 0.1, -1], [-1e-4, 0.1, -1]])
    assert np.allclose(a[0], a[1], atol=1e-3)


# -- reflection ------------------------------------------------------------------------------

def test_reflect_view_against_numpy_and_identities():
    i = RNG.normal(size=(400, 3))
    n = RNG.normal(size=(400, 3))
    nu = n / np.linalg.norm(n, axis=1)[:, None]
    r = env.reflect_view(i, n)
    assert np.allclose(r, i - 2 * np.sum(i * nu, axis=1)[:, None] * nu)
    assert np.allclose(np.linalg.norm(r, axis=1), np.linalg.norm(i, axis=1))
    assert np.allclose(np.sum(r * nu, 1), -np.sum(i * nu, 1))      # angle in = angle out
    assert np.allclose(np.cross(r - i, nu), 0)                     # R - I along N
    assert np.allclose(env.reflect_view(r, n), i)                  # twice: identity
    householder = np.eye(3)[None] - 2 * nu[:, :, None] * nu[:, None, :]
    assert np.allclose(r, np.einsum("nij,nj->ni", householder, i))
    assert np.allclose(r, raytracing.reflect_direction(i, n))


def test_mirror_sphere_reflections():
    m = env.mirror_sphere(33, eye_direction=(1, 1, 1))
    mask = m["mask"]
    view = -np.array([1, 1, 1]) / np.sqrt(3)
    assert np.allclose(m["view"], view)
    n = m["normals"][mask]
    assert np.allclose(np.linalg.norm(n, axis=1), 1)
    assert np.all(n @ view <= 1e-12)                        # we see the front half
    assert np.allclose(m["reflections"][mask], raytracing.reflect_direction(view, n))
    assert np.isclose(mask.mean(), np.pi / 4, atol=0.03)


# -- limitations -----------------------------------------------------------------------------

def test_distant_environment_error_against_the_ray_tracer():
    p = RNG.uniform(-0.5, 0.5, size=(300, 3))
    r = RNG.normal(size=(300, 3))
    r /= np.linalg.norm(r, axis=1)[:, None]
    err = env.distant_environment_error(p, r, 3.0)
    hits = raytracing.intersect_sphere(p, r, [0, 0, 0], 3.0)
    q = p + hits.t[:, None] * r
    true_dir = q / 3.0
    assert np.allclose(np.linalg.norm(q, axis=1), 3.0)
    assert np.allclose(np.cos(err), np.sum(true_dir * r, axis=1))
    # the sine rule: at most arcsin(|d|/R), reached for r perpendicular to d
    assert np.all(err <= np.arcsin(np.linalg.norm(p, axis=1) / 3.0) + 1e-12)
    perp = np.cross(p, RNG.normal(size=(300, 3)))
    assert np.allclose(env.distant_environment_error(p, perp, 3.0),
                       np.arcsin(np.linalg.norm(p, axis=1) / 3.0))
    assert np.allclose(env.distant_environment_error(p, p, 3.0), 0, atol=1e-7)
    assert np.allclose(env.distant_environment_error([0, 0, 0], r, 3.0), 0, atol=1e-7)


def test_no_self_reflection_compared_with_the_ray_tracer():
    # a mirror sphere at the origin and a second sphere beside it: the reflected rays that
    # the ray tracer sends into the second sphere are, for the environment map, just sky
    m = env.mirror_sphere(48)
    mask = m["mask"]
    p = m["normals"][mask]                                  # unit sphere: point = normal
    r = m["reflections"][mask]
    other = raytracing.intersect_sphere(p, r, [2.2, 0, 0], 1.0, t_min=1e-6)
    blocked = np.isfinite(other.t)
    assert 0.01 < blocked.mean() < 0.5
    cube = env.cube_map_from_function(env.sky_environment, 32)
    envcol = env.sample_cube_map(cube, r)
    assert np.all(np.isfinite(envcol)) and envcol.shape == (mask.sum(), 3)


# -- bad input -------------------------------------------------------------------------------

@pytest.mark.parametrize("call, match", [
    (lambda: env.cube_face_coordinates([0, 0, 0]), "directions must not contain zero"),
    (lambda: env.cube_face_coordinates([np.nan, 0, 1]), "directions must be finite"),
    (lambda: env.cube_face_coordinates([1, 0]), "directions must have 3"),
    (lambda: env.sample_cube_map(np.zeros((5, 4, 4)), [1, 0, 0]), "cube must have 6 faces"),
    (lambda: env.sample_cube_map(np.zeros((6, 4, 3)), [1, 0, 0]), "cube's faces must be square"),
    (lambda: env.sample_cube_map(np.zeros((6, 4, 4)), [1, 0, 0], "cubic"), "filter"),
    (lambda: env.sample_cube_map(np.full((6, 2, 2), np.inf), [1, 0, 0]), "cube must be finite"),
    (lambda: env.cube_face_direction(6, 0.5, 0.5), "face must be whole numbers 0..5"),
    (lambda: env.cube_face_direction(1.5, 0.5, 0.5), "face must be whole numbers 0..5"),
    (lambda: env.sphere_map_coordinates([0, 0, 0]), "reflection must not contain zero"),
    (lambda: env.sphere_map_direction(1.0, 1.0), "s and t must lie in the sphere map's disc"),
    (lambda: env.sample_sphere_map(np.zeros(4), [0, 0, 1]), "sphere_map must be an image"),
    (lambda: env.sample_sphere_map(np.zeros((4, 4)), [0, 0, 1], view=np.eye(2)), "view must"),
    (lambda: env.latlong_coordinates([[0, 0, 0]]), "directions must not contain zero"),
    (lambda: env.reflect_view([0, 0, 0], [0, 1, 0]), "incident must not contain zero"),
    (lambda: env.reflect_view([0, 0, 1], [0, 0, 0]), "n must not contain zero"),
    (lambda: env.environment_lookup("dome", np.zeros((6, 2, 2)), [1, 0, 0]), "kind"),
    (lambda: env.distant_environment_error([0, 0, 2], [1, 0, 0], 1.0), "offset must lie"),
    (lambda: env.distant_environment_error([0, 0, 0], [1, 0, 0], 0.0), "radius"),
    (lambda: env.mirror_sphere(8, eye_direction=(0, 1, 0)), "up must not be parallel"),
    (lambda: env.mirror_sphere(8, eye_direction=(0, 0, 0)), "eye_direction must not be"),
    (lambda: env.cube_map_from_function(None, 4), "environment must be a function"),
    (lambda: env.cube_map_from_function(env.sky_environment, 0), "size"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises((ValueError, TypeError), match=match):
        call()
