"""Tests of course_lib.projections: the taxonomy, vanishing points, projection onto a plane.

Expected values come from hand-typed matrices, scipy's Rotation, closed forms and far points
p + t d projected with the same matrix, never from the code under test.
"""
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from course_lib import projections as pj
from course_lib import viewing

R = np.radians


def _ortho_from_rotation(rot):
    """P_ORTHO after a scipy rotation (world -> view), typed independently of orbit_rotation."""
    m = np.eye(4)
    m[:3, :3] = rot.as_matrix()
    return np.diag([1.0, 1.0, 0.0, 1.0]) @ m


def _project(m, points):
    h = np.c_[points, np.ones(len(points))] @ m.T
    return h[:, :3] / h[:, 3:]


# ----------------------------------------------------------------------------- vanishing points
CAMERAS = [
    viewing.simple_perspective(2.0),
    viewing.perspective(R(60), 1.5, 0.5, 100.0) @ viewing.look_at([2, -5, 1.5], [-0.3, 1, -0.2], [0, 0, 1]),
    pj.perspective_view(R(30), R(25), 6.0, 1.5),
]


@pytest.mark.parametrize("m", CAMERAS)
def test_vanishing_point_is_the_limit_of_far_points(m):
    rng = np.random.default_rng(3)
    for _ in range(5):
        d = rng.normal(size=3)
        if abs(m[3, :3] @ d) < 0.2 * np.linalg.norm(m[3, :3]) * np.linalg.norm(d):
            continue
        vp = pj.vanishing_point(m, d)
        p = rng.normal(size=3)
        far = _project(m, np.array([p + t * d for t in (1e6, 1e7, 1e8, 1e9)]))
        assert np.allclose(far[-1], vp, atol=1e-6)
        # the far points approach it ever closer
        errors = np.linalg.norm(far - vp, axis=1)
        assert errors[-1] < errors[0]


def test_vanishing_points_vectorised_match_single_and_inf_for_parallel_directions():
    m = CAMERAS[1]
    rng = np.random.default_rng(0)
    dirs = rng.normal(size=(50, 3))
    many = pj.vanishing_point(m, dirs)
    for d, row in zip(dirs, many):
        assert np.allclose(pj.vanishing_point(m, d), row)
    # a direction in the image plane (perpendicular to the gaze): no vanishing point
    gaze = np.array([-0.3, 1, -0.2])
    side = np.cross(gaze, [0, 0, 1.0])
    assert pj.vanishing_point(m, side) is None
    assert np.all(np.isinf(pj.vanishing_point(m, np.array([side, dirs[0]]))[0]))


def test_simple_perspective_vanishing_point_by_hand():
    # P_PER with d = 2: (1, 2, 4, 0) -> (2, 4, 8, 4) -> (0.5, 1, 2)
    assert np.allclose(pj.vanishing_point(viewing.simple_perspective(2), [1, 2, 4]), [0.5, 1, 2])
    vps = pj.principal_vanishing_points(viewing.simple_perspective(2))
    assert vps[0] is None and vps[1] is None and np.allclose(vps[2], [0, 0, 2])


def test_parallel_projection_has_no_vanishing_points():
    assert all(v is None for v in pj.principal_vanishing_points(pj.isometric()))


@pytest.mark.parametrize("az, el, count", [(0, 0, 1), (90, 0, 1), (30, 0, 2), (-50, 0, 2),
                                           (30, 20, 3), (45, -35, 3)])
def test_number_of_principal_vanishing_points(az, el, count):
    m = pj.perspective_view(R(az), R(el))
    assert sum(v is not None for v in pj.principal_vanishing_points(m)) == count
    assert pj.classify_projection(m)["name"] == ["one", "two", "three"][count - 1] + "-point perspective"


def test_box_axes_change_the_count():
    # a box turned 30 degrees about z, seen from the front: two-point for its own axes
    axes = Rotation.from_euler("z", 30, degrees=True).as_matrix().T
    m = pj.perspective_view(0.0, 0.0)
    assert pj.classify_projection(m, axes=axes)["vanishing"] == 2
    assert pj.classify_projection(m)["vanishing"] == 1


# ------------------------------------------------------------------------------- classification
def test_classify_hand_typed_and_scipy_matrices():
    iso = _ortho_from_rotation(Rotation.from_euler("x", np.arctan(1 / np.sqrt(2)) - np.pi / 2)
                               * Rotation.from_euler("z", -np.pi / 4))
    assert pj.classify_projection(iso)["name"] == "isometric"
    dim = _ortho_from_rotation(Rotation.from_euler("x", R(20) - np.pi / 2) * Rotation.from_euler("z", -np.pi / 4))
    assert pj.classify_projection(dim)["name"] == "dimetric"
    tri = _ortho_from_rotation(Rotation.from_euler("x", R(30) - np.pi / 2) * Rotation.from_euler("z", R(-20)))
    assert pj.classify_projection(tri)["name"] == "trimetric"
    front = np.array([[1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 1.0]])
    assert pj.classify_projection(front)["name"] == "orthographic multiview"
    assert pj.classify_projection(np.diag([1.0, 1, 0, 1]))["name"] == "orthographic multiview"
    # a uniformly scaled orthographic projection is still orthographic
    assert pj.classify_projection(np.diag([3.0, 3, 0, 1]))["family"] == "orthographic"
    # hand-typed oblique matrices (xy plane): depth along (k cos, k sin)
    for k, name in [(1.0, "oblique cavalier"), (0.5, "oblique cabinet"), (0.8, "oblique (general)")]:
        c, s = k * np.cos(R(30)), k * np.sin(R(30))
        m = np.array([[1, 0, c, 0], [0, 1, s, 0], [0, 0, 0, 0], [0, 0, 0, 1.0]])
        out = pj.classify_projection(m)
        assert out["name"] == name
        assert np.isclose(out["depth_length"], k)
        assert np.isclose(out["angle"], np.arctan(1 / k))
    # the textbook's P_PER and a full camera
    assert pj.classify_projection(viewing.simple_perspective(3))["name"] == "one-point perspective"
    cam = viewing.perspective(1, 1, 1, 10) @ viewing.look_at([3, -4, 2], [-3, 4, -2], [0, 0, 1])
    assert pj.classify_projection(cam)["name"] == "three-point perspective"
    two = viewing.perspective(1, 1, 1, 10) @ viewing.look_at([3, -4, 0], [-3, 4, 0], [0, 0, 1])
    assert pj.classify_projection(two)["name"] == "two-point perspective"


def test_oblique_onto_a_tilted_plane_is_recognised():
    # projectors at 45 degrees to the plane x + y = 3 -> cavalier; a rotation of the output
    # does not change the class
    m = pj.project_onto_plane([1, 2, 0], [1, 1, 0], direction=[1, 0, 0])
    assert pj.classify_projection(m)["name"] == "oblique cavalier"
    rot = np.eye(4)
    rot[:3, :3] = Rotation.from_rotvec([0.3, -0.2, 0.5]).as_matrix()
    assert pj.classify_projection(rot @ m)["name"] == "oblique cavalier"
    # along the normal: orthographic
    m = pj.project_onto_plane([1, 2, 0], [1, 1, 0], direction=[2, 2, 0])
    assert pj.classify_projection(m)["family"] == "orthographic"


def test_isometric_foreshortening_and_120_degree_axes():
    f = pj.foreshortening(pj.isometric())
    assert np.allclose(f, np.sqrt(2 / 3))
    # the viewer sits in the direction (1, -1, 1): the axes x, -y, z point from the box's
    # nearest corner, and their images are 120 degrees apart
    images = (pj.isometric()[:2, :3] @ np.diag([1.0, -1.0, 1.0])).T
    angles = np.degrees(np.arctan2(images[:, 1], images[:, 0]))
    gaps = sorted(np.mod(np.diff(np.r_[np.sort(angles), np.sort(angles)[0] + 360]), 360))
    assert np.allclose(gaps, [120, 120, 120])
    assert np.isclose(np.degrees(np.arctan(1 / np.sqrt(2))), 35.26438968, atol=1e-6)


def test_oblique_projection_reuses_viewing_oblique():
    m = pj.oblique_projection(R(30), 0.5)
    # a unit step into the picture (world +y) is drawn at 30 degrees with length 1/2
    step = m @ [0, 1, 0, 0]
    assert np.allclose(step[:2], [0.5 * np.cos(R(30)), 0.5 * np.sin(R(30))])
    assert np.allclose(pj.foreshortening(m), [1, 0.5, 1])


def test_multiview_views():
    assert np.allclose(pj.multiview("front") @ [1, 2, 3, 1], [1, 3, 0, 1])
    assert np.allclose(pj.multiview("top") @ [1, 2, 3, 1], [1, 2, 0, 1])
    assert np.allclose(pj.multiview("side") @ [1, 2, 3, 1], [2, 3, 0, 1])


def test_preserves_table_lists_every_class():
    table = pj.preserves_table()
    for name in ("perspective", "multiview", "isometric", "dimetric", "trimetric", "cavalier", "cabinet"):
        assert name in table


# --------------------------------------------------------------------------- onto a plane
def test_perspective_onto_plane_points_on_plane_and_on_projector():
    rng = np.random.default_rng(7)
    p0, n, c = np.array([1.0, -2, 0.5]), np.array([0.3, 1.0, -0.4]), np.array([-1.0, 4, 2])
    m = pj.project_onto_plane(p0, n, centre=c)
    pts = rng.normal(size=(40, 3)) * 3
    q = _project(m, pts)
    assert np.allclose((q - p0) @ n, 0, atol=1e-9)
    # q, c and p collinear
    assert np.allclose(np.cross(q - c, pts - c), 0, atol=1e-8)


def test_parallel_onto_plane_points_on_plane_and_along_direction():
    rng = np.random.default_rng(8)
    p0, n, d = np.array([0.0, 1, 2]), np.array([1.0, 2, 2]), np.array([0.5, 0.2, 1])
    m = pj.project_onto_plane(p0, n, direction=d)
    pts = rng.normal(size=(40, 3))
    q = _project(m, pts)
    assert np.allclose((q - p0) @ n, 0, atol=1e-9)
    assert np.allclose(np.cross(q - pts, d), 0, atol=1e-9)


def test_onto_plane_z_equals_d_is_p_per():
    for d in (2.0, -1.5):
        m = pj.project_onto_plane([0, 0, d], [0, 0, 1], centre=[0, 0, 0])
        pts = np.array([[3.0, 6, 4], [1, -1, 2], [0.5, 2, -3]])
        ref = np.array([[x * d / z, y * d / z, d] for x, y, z in pts])
        assert np.allclose(_project(m, pts), ref)
        # the same matrix up to a factor
        ppr = viewing.simple_perspective(d)
        assert np.allclose(m / m[3, 2], ppr / ppr[3, 2])


@pytest.mark.parametrize("kwargs, words", [
    (dict(point_on_plane=[0, 0, 1], normal=[0, 0, 0], centre=[0, 0, 0]), "normal"),
    (dict(point_on_plane=[0, 0, 1], normal=[0, 0, 1], centre=[3, 2, 1]), "centre must not lie"),
    (dict(point_on_plane=[0, 0, 1], normal=[0, 0, 1], direction=[1, 1, 0]), "parallel to the plane"),
    (dict(point_on_plane=[0, 0, 1], normal=[0, 0, 1], direction=[0, 0, 0]), "zero"),
    (dict(point_on_plane=[0, 0, 1], normal=[0, 0, 1]), "exactly one"),
    (dict(point_on_plane=[0, 0, 1], normal=[0, 0, 1], centre=[0, 0, 0], direction=[0, 0, 1]), "exactly one"),
    (dict(point_on_plane=[0, 0], normal=[0, 0, 1], centre=[0, 0, 0]), "point_on_plane"),
])
def test_project_onto_plane_errors(kwargs, words):
    with pytest.raises(ValueError, match=words):
        pj.project_onto_plane(**kwargs)


def test_errors_of_matrix_inputs():
    with pytest.raises(ValueError, match="4x4"):
        pj.classify_projection(np.eye(3))
    with pytest.raises(ValueError, match="last row"):
        pj.classify_projection(np.diag([1.0, 1, 1, 0]))
    with pytest.raises(ValueError, match="singular in the wrong way"):
        pj.classify_projection(np.diag([1.0, 0, 0, 1]))          # onto a line
    with pytest.raises(TypeError):
        pj.vanishing_point("matrix", [1, 0, 0])
    with pytest.raises(ValueError, match="zero vector"):
        pj.vanishing_point(viewing.simple_perspective(1), [0, 0, 0])
    with pytest.raises(ValueError, match="shape"):
        pj.vanishing_point(viewing.simple_perspective(1), [1, 0])
    with pytest.raises(ValueError, match="perspective"):
        pj.foreshortening(viewing.simple_perspective(1))
    with pytest.raises(ValueError, match="axes"):
        pj.classify_projection(pj.isometric(), axes=np.eye(2))
    with pytest.raises(ValueError, match="zero vector"):
        pj.classify_projection(pj.isometric(), axes=[[1, 0, 0], [0, 0, 0], [0, 0, 1]])
    with pytest.raises(ValueError, match="view"):
        pj.multiview("back")
    with pytest.raises(ValueError, match="length"):
        pj.oblique_projection(0.3, 0.0)
