"""Tests of course_lib.transforms (homogeneous 2D and 3D transformation matrices).

Expected values are the textbook matrices typed out entry by entry, scipy's Rotation, numpy's
linalg.inv, or mathematical properties (fixed points, preserved distances, determinants).
Nothing here is copied from the output of the code under test.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from course_lib import transforms as T

PI = np.pi
ATOL = 1e-12
FAST = settings(max_examples=150, deadline=None, database=None)   # no .hypothesis/ dir


def rng(seed):
    return np.random.default_rng(seed)


def hom(p):
    """Column-vector homogeneous coordinates of one point, built by hand."""
    return np.append(np.asarray(p, dtype=float), 1.0)


# ---------------------------------------------------------------------------------------------
# translate, scale, mirror
# ---------------------------------------------------------------------------------------------

def test_translate_2d_closed_form():
    np.testing.assert_array_equal(T.translate([2, -3]),
                                  [[1, 0, 2],
                                   [0, 1, -3],
                                   [0, 0, 1]])


def test_translate_3d_closed_form():
    np.testing.assert_array_equal(T.translate([2, -3, 0.5]),
                                  [[1, 0, 0, 2],
                                   [0, 1, 0, -3],
                                   [0, 0, 1, 0.5],
                                   [0, 0, 0, 1]])


def test_scale_2d_and_3d_closed_forms():
    np.testing.assert_array_equal(T.scale([2, 3]),
                                  [[2, 0, 0],
                                   [0, 3, 0],
                                   [0, 0, 1]])
    np.testing.assert_array_equal(T.scale([2, -3, 0.5]),
                                  [[2, 0, 0, 0],
                                   [0, -3, 0, 0],
                                   [0, 0, 0.5, 0],
                                   [0, 0, 0, 1]])


MIRRORS = {
    # 2D: about the x axis negates y, about the y axis negates x
    "x": [[1, 0, 0], [0, -1, 0], [0, 0, 1]],
    "y": [[-1, 0, 0], [0, 1, 0], [0, 0, 1]],
    # 3D: about a coordinate plane negates the coordinate not in it
    "xy": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]],
    "yx": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]],
    "yz": [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
    "zy": [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
    "xz": [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
    "zx": [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
    "origin": [[-1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]],
}


@pytest.mark.parametrize("name", list(MIRRORS))
def test_mirror_closed_forms(name):
    m = T.mirror(name)
    np.testing.assert_array_equal(m, MIRRORS[name])
    n = m.shape[0] - 1
    assert np.linalg.det(m[:n, :n]) == pytest.approx(-1.0)     # turns handedness
    np.testing.assert_array_equal(m @ m, np.eye(n + 1))        # its own inverse


@pytest.mark.parametrize("bad", ["z", "xyz", "", "xx", 3])
def test_mirror_unknown_name(bad):
    with pytest.raises(ValueError, match="about"):
        T.mirror(bad)


# ---------------------------------------------------------------------------------------------
# 2D rotations
# ---------------------------------------------------------------------------------------------

def test_rotate_2d_special_angles():
    r3 = np.sqrt(3) / 2
    np.testing.assert_allclose(T.rotate(PI / 6), [[r3, -0.5, 0],
                                                  [0.5, r3, 0],
                                                  [0, 0, 1]], atol=ATOL)
    np.testing.assert_allclose(T.rotate(PI / 2), [[0, -1, 0],
                                                  [1, 0, 0],
                                                  [0, 0, 1]], atol=ATOL)
    np.testing.assert_allclose(T.rotate(PI / 2) @ [1, 0, 1], [0, 1, 1], atol=ATOL)  # CCW


@pytest.mark.parametrize("theta", [-7.0, -PI, -0.4, 0.0, 1.0, 2.5, 10.0])
def test_rotate_2d_closed_form(theta):
    c, s = np.cos(theta), np.sin(theta)
    np.testing.assert_allclose(T.rotate(theta), [[c, -s, 0],
                                                 [s, c, 0],
                                                 [0, 0, 1]], atol=ATOL)


@pytest.mark.parametrize("theta, center", [(0.7, [1, 2]), (PI, [1, 1]), (-2.0, [-3, 0.5]),
                                           (0.0, [5, 5])])
def test_rotate_about_closed_form_and_fixed_center(theta, center):
    c, s = np.cos(theta), np.sin(theta)
    cx, cy = center
    # T(c) R T(-c) multiplied out by hand
    expected = [[c, -s, cx - c * cx + s * cy],
                [s, c, cy - s * cx - c * cy],
                [0, 0, 1]]
    m = T.rotate_about(theta, center)
    np.testing.assert_allclose(m, expected, atol=ATOL)
    np.testing.assert_allclose(m @ hom(center), hom(center), atol=ATOL)


@FAST
@given(theta=st.floats(-10, 10), cx=st.floats(-100, 100), cy=st.floats(-100, 100),
       px=st.floats(-100, 100), py=st.floats(-100, 100))
def test_rotate_about_keeps_distances_to_center(theta, cx, cy, px, py):
    m = T.rotate_about(theta, [cx, cy])
    image = (m @ [px, py, 1])[:2]
    np.testing.assert_allclose(np.hypot(*(image - [cx, cy])), np.hypot(px - cx, py - cy),
                               atol=1e-10)
    np.testing.assert_allclose(m @ [cx, cy, 1], [cx, cy, 1], atol=1e-10)


# ---------------------------------------------------------------------------------------------
# 3D rotations
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("theta", [-4.0, -0.3, 0.0, 0.5, PI / 2, 3.0])
def test_rotate_xyz_closed_forms(theta):
    c, s = np.cos(theta), np.sin(theta)
    np.testing.assert_allclose(T.rotate_x(theta), [[1, 0, 0, 0],
                                                   [0, c, -s, 0],
                                                   [0, s, c, 0],
                                                   [0, 0, 0, 1]], atol=ATOL)
    np.testing.assert_allclose(T.rotate_y(theta), [[c, 0, s, 0],
                                                   [0, 1, 0, 0],
                                                   [-s, 0, c, 0],
                                                   [0, 0, 0, 1]], atol=ATOL)
    np.testing.assert_allclose(T.rotate_z(theta), [[c, -s, 0, 0],
                                                   [s, c, 0, 0],
                                                   [0, 0, 1, 0],
                                                   [0, 0, 0, 1]], atol=ATOL)


@pytest.mark.parametrize("func, axis", [(T.rotate_x, "x"), (T.rotate_y, "y"), (T.rotate_z, "z")])
def test_rotate_xyz_match_scipy(func, axis):
    for theta in rng(100).uniform(-2 * PI, 2 * PI, size=200):
        m = func(theta)
        np.testing.assert_allclose(m[:3, :3], Rotation.from_euler(axis, theta).as_matrix(),
                                   atol=ATOL)
        np.testing.assert_array_equal(m[3], [0, 0, 0, 1])
        np.testing.assert_array_equal(m[:3, 3], 0)


def test_rotate_xyz_positive_sense():
    # positive angles: x rotation turns y to z, y rotation turns z to x, z rotation x to y
    np.testing.assert_allclose(T.rotate_x(PI / 2) @ [0, 1, 0, 1], [0, 0, 1, 1], atol=ATOL)
    np.testing.assert_allclose(T.rotate_y(PI / 2) @ [0, 0, 1, 1], [1, 0, 0, 1], atol=ATOL)
    np.testing.assert_allclose(T.rotate_z(PI / 2) @ [1, 0, 0, 1], [0, 1, 0, 1], atol=ATOL)


def test_rotate_axis_matches_scipy_from_rotvec():
    gen = rng(101)
    for _ in range(1000):
        axis = gen.normal(size=3) * 10.0 ** gen.uniform(-3, 3)
        theta = gen.uniform(-2 * PI, 2 * PI)
        m = T.rotate_axis(axis, theta)
        expected = Rotation.from_rotvec(theta * axis / np.linalg.norm(axis)).as_matrix()
        np.testing.assert_allclose(m[:3, :3], expected, atol=ATOL)
        np.testing.assert_array_equal(m[3], [0, 0, 0, 1])
        np.testing.assert_allclose(m[:3, 3], 0, atol=0)


@pytest.mark.parametrize("axis, func", [([1, 0, 0], T.rotate_x), ([0, 2, 0], T.rotate_y),
                                        ([0, 0, 0.1], T.rotate_z)])
def test_rotate_axis_coordinate_axes(axis, func):
    np.testing.assert_allclose(T.rotate_axis(axis, 0.9), func(0.9), atol=ATOL)
    np.testing.assert_allclose(T.rotate_axis(-np.array(axis), 0.9), func(-0.9), atol=ATOL)


def test_rotate_axis_body_diagonal_permutes_axes():
    # 120 degrees about (1,1,1): x -> y -> z -> x
    np.testing.assert_allclose(T.rotate_axis([1, 1, 1], 2 * PI / 3),
                               [[0, 0, 1, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 1]],
                               atol=ATOL)


def test_rotate_axis_through_point():
    gen = rng(102)
    for _ in range(300):
        axis, p = gen.normal(size=3), gen.normal(size=3) * 5
        theta = gen.uniform(-PI, PI)
        m = T.rotate_axis(axis, theta, point=p)
        k = axis / np.linalg.norm(axis)
        # points on the axis are fixed
        for lam in (-3.0, 0.0, 2.5):
            np.testing.assert_allclose(m @ hom(p + lam * k), hom(p + lam * k), atol=1e-11)
        # any point: equals translating p to the origin, rotating (scipy), translating back
        x = gen.normal(size=3) * 5
        expected = p + Rotation.from_rotvec(theta * k).apply(x - p)
        np.testing.assert_allclose(m @ hom(x), hom(expected), atol=1e-11)


def test_rotate_axis_steps_labels():
    steps = T.rotate_axis_steps([1, 2, 2], 0.7, point=[1, 0, 0])
    assert [label for label, _ in steps] == ["T(-p)", "R_x(alpha)", "R_y(beta)", "R_z(theta)",
                                             "R_y(-beta)", "R_x(-alpha)", "T(p)"]
    assert all(m.shape == (4, 4) for _, m in steps)


AXES = [[1, 0, 0], [-1, 0, 0], [3, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1],
        [1, 2, 2], [-1, 1e-3, 0], [0.2, -0.5, -3.0]]


@pytest.mark.parametrize("axis", AXES)
@pytest.mark.parametrize("point", [[0, 0, 0], [1, -2, 0.5]])
def test_rotate_axis_steps_compose_to_rotate_axis(axis, point):
    theta = 1.1
    steps = T.rotate_axis_steps(axis, theta, point)
    total = T.compose(*[m for _, m in steps])
    np.testing.assert_allclose(total, T.rotate_axis(axis, theta, point), atol=1e-12)
    # and independently of rotate_axis: against scipy
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    x = np.array([0.3, 0.7, -1.9])
    expected = point + Rotation.from_rotvec(theta * k).apply(x - np.asarray(point, float))
    np.testing.assert_allclose(total @ hom(x), hom(expected), atol=1e-12)


@pytest.mark.parametrize("axis", AXES)
def test_rotate_axis_steps_align_axis_with_z(axis):
    p = np.array([1.0, -2.0, 0.5])
    steps = dict(T.rotate_axis_steps(axis, 0.4, p))
    align = steps["R_y(beta)"] @ steps["R_x(alpha)"] @ steps["T(-p)"]
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    np.testing.assert_allclose(align @ hom(p), [0, 0, 0, 1], atol=1e-12)            # p -> 0
    np.testing.assert_allclose(align @ np.append(k, 0.0), [0, 0, 1, 0], atol=1e-12)  # k -> +z
    # after R_x(alpha) alone the axis lies in the xz plane with non-negative z
    in_xz = steps["R_x(alpha)"] @ np.append(k, 0.0)
    assert abs(in_xz[1]) < 1e-12 and in_xz[2] >= -1e-12
    # the undo steps are the inverses of the do steps
    np.testing.assert_allclose(steps["R_y(-beta)"] @ steps["R_y(beta)"], np.eye(4), atol=1e-12)
    np.testing.assert_allclose(steps["R_x(-alpha)"] @ steps["R_x(alpha)"], np.eye(4), atol=1e-12)
    np.testing.assert_allclose(steps["T(p)"] @ steps["T(-p)"], np.eye(4), atol=1e-12)
    np.testing.assert_allclose(steps["R_z(theta)"][:3, :3],
                               Rotation.from_euler("z", 0.4).as_matrix(), atol=1e-12)


def test_euler_zyx_matches_scipy_intrinsic_ZYX():
    gen = rng(103)
    angles = gen.uniform(-PI, PI, size=(500, 3))
    angles[:, 1] /= 2                                   # pitch in [-pi/2, pi/2]
    expected = Rotation.from_euler("ZYX", angles).as_matrix()
    for (yaw, pitch, roll), e in zip(angles, expected):
        m = T.euler_zyx(yaw, pitch, roll)
        np.testing.assert_allclose(m[:3, :3], e, atol=ATOL)
        np.testing.assert_array_equal(m[3], [0, 0, 0, 1])


def test_euler_zyx_gimbal_lock():
    # at pitch = 90 degrees only yaw - roll matters
    np.testing.assert_allclose(T.euler_zyx(0.5, PI / 2, 0.2), T.euler_zyx(0.8, PI / 2, 0.5),
                               atol=ATOL)


# ---------------------------------------------------------------------------------------------
# shears
# ---------------------------------------------------------------------------------------------

def test_shear_2d_closed_forms():
    np.testing.assert_array_equal(T.shear_x(2.5), [[1, 2.5, 0], [0, 1, 0], [0, 0, 1]])
    np.testing.assert_array_equal(T.shear_y(-1.5), [[1, 0, 0], [-1.5, 1, 0], [0, 0, 1]])


def test_shear_3d_closed_forms():
    a, b = 2.0, -0.5
    np.testing.assert_array_equal(T.shear_xy(a, b), [[1, 0, a, 0],
                                                     [0, 1, b, 0],
                                                     [0, 0, 1, 0],
                                                     [0, 0, 0, 1]])
    np.testing.assert_array_equal(T.shear_xz(a, b), [[1, a, 0, 0],
                                                     [0, 1, 0, 0],
                                                     [0, b, 1, 0],
                                                     [0, 0, 0, 1]])
    np.testing.assert_array_equal(T.shear_yz(a, b), [[1, 0, 0, 0],
                                                     [a, 1, 0, 0],
                                                     [b, 0, 1, 0],
                                                     [0, 0, 0, 1]])


def test_shears_act_as_defined_on_points():
    x, y, z = 1.5, -2.0, 3.0
    a, b = 0.7, -1.3
    np.testing.assert_allclose(T.shear_x(a) @ [x, y, 1], [x + a * y, y, 1])
    np.testing.assert_allclose(T.shear_y(b) @ [x, y, 1], [x, y + b * x, 1])
    np.testing.assert_allclose(T.shear_xy(a, b) @ [x, y, z, 1], [x + a * z, y + b * z, z, 1])
    np.testing.assert_allclose(T.shear_xz(a, b) @ [x, y, z, 1], [x + a * y, y, z + b * y, 1])
    np.testing.assert_allclose(T.shear_yz(a, b) @ [x, y, z, 1], [x, y + a * x, z + b * x, 1])


@pytest.mark.parametrize("make", [
    lambda a, b: T.shear_x(a), lambda a, b: T.shear_y(b),
    T.shear_xy, T.shear_xz, T.shear_yz])
def test_shear_determinant_one_and_inverse_negated(make):
    for a, b in [(0.5, -2.0), (3.0, 0.25), (-1.0, 0.0)]:
        m = make(a, b)
        assert np.linalg.det(m) == pytest.approx(1.0)
        np.testing.assert_allclose(m @ make(-a, -b), np.eye(len(m)), atol=ATOL)
        np.testing.assert_allclose(T.inverse(m), make(-a, -b), atol=ATOL)


# ---------------------------------------------------------------------------------------------
# inverse
# ---------------------------------------------------------------------------------------------

ANALYTIC_INVERSES = {
    "translate 2D": (T.translate([2, -3]), T.translate([-2, 3])),
    "translate 3D": (T.translate([2, -3, 7]), T.translate([-2, 3, -7])),
    "scale 2D": (T.scale([2, -4]), T.scale([0.5, -0.25])),
    "scale 3D": (T.scale([2, 5, -0.1]), T.scale([0.5, 0.2, -10])),
    "rotate": (T.rotate(0.8), T.rotate(-0.8)),
    "rotate_about": (T.rotate_about(0.8, [1, 2]), T.rotate_about(-0.8, [1, 2])),
    "rotate_x": (T.rotate_x(0.8), T.rotate_x(-0.8)),
    "rotate_y": (T.rotate_y(-2.1), T.rotate_y(2.1)),
    "rotate_z": (T.rotate_z(3.0), T.rotate_z(-3.0)),
    "rotate_axis": (T.rotate_axis([1, 2, 3], 0.6, [1, 1, 0]),
                    T.rotate_axis([1, 2, 3], -0.6, [1, 1, 0])),
    "shear_x": (T.shear_x(2), T.shear_x(-2)),
    "shear_yz": (T.shear_yz(2, -1), T.shear_yz(-2, 1)),
    "mirror xz": (T.mirror("xz"), T.mirror("xz")),
}


@pytest.mark.parametrize("name", list(ANALYTIC_INVERSES))
def test_inverse_of_elementary_matrices(name):
    m, expected = ANALYTIC_INVERSES[name]
    np.testing.assert_allclose(T.inverse(m), expected, atol=ATOL)


def test_inverse_of_random_compositions_matches_numpy():
    gen = rng(110)
    for _ in range(200):
        parts = [T.translate(gen.normal(size=3) * 5), T.rotate_axis(gen.normal(size=3),
                                                                     gen.uniform(-PI, PI)),
                 T.scale(gen.uniform(0.2, 5, size=3) * gen.choice([-1, 1], size=3)),
                 T.shear_xz(*gen.normal(size=2)), T.euler_zyx(*gen.normal(size=3))]
        order = gen.permutation(len(parts))
        m = T.compose(*[parts[i] for i in order])
        inv = T.inverse(m)
        np.testing.assert_allclose(inv, np.linalg.inv(m), rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(inv @ m, np.eye(4), atol=1e-9)
    for _ in range(100):
        m = T.compose(T.rotate_about(gen.uniform(-PI, PI), gen.normal(size=2)),
                      T.scale(gen.uniform(0.2, 5, size=2)), T.shear_y(gen.normal()),
                      T.translate(gen.normal(size=2)))
        np.testing.assert_allclose(T.inverse(m), np.linalg.inv(m), rtol=1e-9, atol=1e-9)


PERSPECTIVE = np.array([[1.0, 0, 0, 0],
                        [0, 1, 0, 0],
                        [0, 0, 1, 0],
                        [0, 0, 1, 0]])          # w = z: a pinhole projection's last row...
PERSPECTIVE_INVERTIBLE = np.array([[2.0, 0, 0, 0],     # ...made invertible (OpenGL-like)
                                   [0, 2, 0, 0],
                                   [0, 0, -1.2, -2.2],
                                   [0, 0, -1, 0]])


@pytest.mark.parametrize("m", [np.diag([1.0, 1, 1, 2]), PERSPECTIVE_INVERTIBLE,
                               np.array([[1.0, 0, 3], [0, 1, 0], [0.5, 0.5, 1]]),
                               np.diag([1.0, 1, 1, 1 + 1e-3])])
def test_inverse_of_projective_matrices(m):
    inv = T.inverse(m)
    np.testing.assert_allclose(inv, np.linalg.inv(m), atol=1e-12)
    np.testing.assert_allclose(inv @ m, np.eye(len(m)), atol=1e-12)


@pytest.mark.parametrize("last_row", [[0, 0, 0, 1 + 1e-6], [1e-9, 0, 0, 1], [0, 0, -1e-9, 1]])
def test_inverse_of_nearly_affine_projective_matrices(last_row):
    # BUG: inverse() decides "affine" with np.allclose / np.isclose (atol 1e-8, rtol 1e-5) and
    # then silently drops the projective last row. The matrix is invertible and apply() does
    # use its last row, so inverse(M) must undo apply(M, .).
    m = np.eye(4)
    m[3] = last_row
    inv = T.inverse(m)
    p = np.array([1e6, 2.0, -1e6])
    np.testing.assert_allclose(T.apply(inv, T.apply(m, p)), p, rtol=1e-9)
    np.testing.assert_allclose(inv @ m, np.eye(4), atol=1e-13)


@pytest.mark.parametrize("m", [T.scale([2, 0]), T.scale([1, 0, 1]), T.scale([0, 0, 0]),
                               np.zeros((4, 4)), PERSPECTIVE,
                               np.array([[1.0, 2, 0], [2, 4, 0], [0, 0, 1]])])
def test_inverse_of_singular_matrix_raises(m):
    with pytest.raises(ValueError, match="singular"):
        T.inverse(m)


@FAST
@given(theta=st.floats(-PI, PI), d=st.tuples(*[st.floats(-50, 50)] * 3),
       s=st.tuples(*[st.floats(0.1, 10)] * 3))
def test_inverse_undoes_apply(theta, d, s):
    m = T.compose(T.scale(s), T.rotate_y(theta), T.translate(d))
    p = np.array([[1.0, 2.0, 3.0], [-4.0, 0.5, 9.0]])
    np.testing.assert_allclose(T.apply(T.inverse(m), T.apply(m, p)), p, atol=1e-9)


# ---------------------------------------------------------------------------------------------
# compose
# ---------------------------------------------------------------------------------------------

def test_compose_order_is_first_to_last():
    a, b, c = T.translate([1, 2, 3]), T.rotate_x(0.4), T.scale([2, 3, 4])
    np.testing.assert_allclose(T.compose(a, b, c), c @ b @ a, atol=ATOL)
    np.testing.assert_allclose(T.compose(a), a, atol=0)
    # translate first then rotate: (0,0) -> (1,0) -> (0,1)
    np.testing.assert_allclose(T.compose(T.translate([1, 0]), T.rotate(PI / 2)) @ [0, 0, 1],
                               [0, 1, 1], atol=ATOL)


def test_compose_order_matters():
    t, r = T.translate([1, 0]), T.rotate(PI / 2)
    assert not np.allclose(T.compose(t, r), T.compose(r, t))
    # rotate first then translate: (0,0) -> (0,0) -> (1,0)
    np.testing.assert_allclose(T.compose(r, t) @ [0, 0, 1], [1, 0, 1], atol=ATOL)


def test_compose_does_not_alias_its_argument():
    a = T.translate([1, 2])
    out = T.compose(a)
    out[0, 0] = 99.0
    assert a[0, 0] == 1.0


def test_compose_errors():
    with pytest.raises(ValueError, match="at least one"):
        T.compose()
    with pytest.raises(ValueError, match="2D and 3D"):
        T.compose(T.translate([1, 2]), T.translate([1, 2, 3]))
    with pytest.raises(ValueError, match=r"matrices\[1\]"):
        T.compose(np.eye(3), np.eye(3)[:2])
    with pytest.raises(ValueError, match="finite"):
        T.compose(np.eye(3), np.full((3, 3), np.nan))
    with pytest.raises(TypeError):
        T.compose(np.eye(3), None)


@FAST
@given(t1=st.floats(-PI, PI), t2=st.floats(-PI, PI), dx=st.floats(-10, 10),
       dy=st.floats(-10, 10))
def test_compose_matches_sequential_apply(t1, t2, dx, dy):
    steps = [T.rotate(t1), T.translate([dx, dy]), T.shear_x(0.5), T.rotate_about(t2, [1, -1])]
    p = np.array([[0.0, 0.0], [1.0, 2.0], [-3.0, 5.0]])
    q = p
    for m in steps:
        q = T.apply(m, q)
    np.testing.assert_allclose(T.apply(T.compose(*steps), p), q, atol=1e-9)


# ---------------------------------------------------------------------------------------------
# apply, to_homogeneous, from_homogeneous
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("shape", [(2,), (10, 2), (10, 3), (4, 5, 3), (4, 5, 2), (3,)])
def test_apply_shapes_and_manual_homogeneous_product(shape):
    gen = rng(120)
    d = shape[-1]
    m = gen.normal(size=(d + 1, d + 1))
    m[d] = np.append(np.zeros(d), 1.0)                         # a random affine matrix
    p = gen.normal(size=shape)
    got = T.apply(m, p)
    assert got.shape == shape
    flat = p.reshape(-1, d)
    expected = np.array([(m @ np.append(x, 1.0))[:d] for x in flat]).reshape(shape)
    np.testing.assert_allclose(got, expected, atol=1e-12)


def test_apply_square_example():
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    np.testing.assert_allclose(T.apply(T.translate([2, 3]), square),
                               [[2, 3], [3, 3], [3, 4], [2, 4]], atol=0)


def test_apply_homogeneous_divide():
    np.testing.assert_allclose(T.apply(np.diag([1.0, 1, 1, 2]), [2, 4, 6]), [1, 2, 3])
    # w = z: perspective projection onto the plane z = 1
    pts = np.array([[2.0, 4.0, 2.0], [3.0, -6.0, 3.0], [1.0, 1.0, -0.5]])
    expected = np.column_stack([pts[:, 0] / pts[:, 2], pts[:, 1] / pts[:, 2], np.ones(3)])
    np.testing.assert_allclose(T.apply(PERSPECTIVE, pts), expected, atol=ATOL)
    # random projective 2D matrix vs the manual divide
    gen = rng(121)
    m = gen.normal(size=(3, 3))
    p = gen.normal(size=(50, 2))
    h = np.column_stack([p, np.ones(50)]) @ m.T
    np.testing.assert_allclose(T.apply(m, p), h[:, :2] / h[:, 2:], rtol=1e-10, atol=1e-10)


def test_apply_3x3_linear_map_to_3d_points():
    gen = rng(122)
    a = gen.normal(size=(3, 3))
    p = gen.normal(size=(6, 4, 3))
    np.testing.assert_allclose(T.apply(a, p), np.einsum("ij,...j->...i", a, p), atol=1e-12)
    r = Rotation.from_rotvec([0.2, 0.3, -0.5])
    np.testing.assert_allclose(T.apply(r.as_matrix(), p.reshape(-1, 3)),
                               r.apply(p.reshape(-1, 3)), atol=1e-12)


def test_apply_point_mapped_to_infinity_raises():
    with pytest.raises(ValueError, match="infinity"):
        T.apply(PERSPECTIVE, [[1.0, 2.0, 3.0], [1.0, 2.0, 0.0]])     # z = 0 gives w = 0


def test_apply_bad_input():
    with pytest.raises(ValueError, match=r"\bM\b"):
        T.apply(np.eye(4), [1.0, 2.0])                  # 3D matrix, 2D point
    with pytest.raises(ValueError, match=r"\bM\b"):
        T.apply(np.eye(2), [1.0, 2.0])
    with pytest.raises(ValueError, match="points"):
        T.apply(np.eye(4), [[1.0, 2.0, 3.0, 4.0]])
    with pytest.raises(ValueError, match="points"):
        T.apply(np.eye(3), 5.0)
    with pytest.raises(ValueError, match="finite"):
        T.apply(np.eye(3), [np.nan, 1.0])
    with pytest.raises(TypeError):
        T.apply(np.eye(3), "1, 2")
    with pytest.raises(TypeError):
        T.apply(None, [1.0, 2.0])


def test_to_and_from_homogeneous():
    np.testing.assert_array_equal(T.to_homogeneous([[1, 2], [3, 4]]), [[1, 2, 1], [3, 4, 1]])
    np.testing.assert_array_equal(T.to_homogeneous([1, 2, 3]), [1, 2, 3, 1])
    np.testing.assert_allclose(T.from_homogeneous([2, 4, 6, 2]), [1, 2, 3])
    np.testing.assert_allclose(T.from_homogeneous([[3, 6, -3], [1, 1, 0.5]]), [[-1, -2], [2, 2]])
    gen = rng(130)
    for shape in [(3,), (7, 2), (4, 5, 3)]:
        p = gen.normal(size=shape)
        h = T.to_homogeneous(p)
        assert h.shape == shape[:-1] + (shape[-1] + 1,)
        np.testing.assert_array_equal(T.from_homogeneous(h), p)
        # scaling a homogeneous vector does not change the point
        np.testing.assert_allclose(T.from_homogeneous(-2.5 * h), p, rtol=1e-14)


def test_from_homogeneous_point_at_infinity_raises():
    with pytest.raises(ValueError, match="infinity"):
        T.from_homogeneous([1.0, 2.0, 0.0])
    with pytest.raises(ValueError, match="infinity"):
        T.from_homogeneous([[1.0, 2.0, 3.0, 1.0], [1.0, 0.0, 0.0, 0.0]])


# ---------------------------------------------------------------------------------------------
# bad input to the constructors
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("func, args, name", [
    (T.translate, ([1],), "d"), (T.translate, ([1, 2, 3, 4],), "d"),
    (T.translate, ([[1, 2]],), "d"), (T.scale, ([1],), "factors"),
    (T.rotate, ([1, 2],), "theta"), (T.rotate_x, (np.ones(3),), "theta"),
    (T.rotate_about, (0.3, [1, 2, 3]), "center"),
    (T.rotate_axis, ([1, 0], 0.3), "axis"), (T.rotate_axis, ([1, 0, 0], 0.3, [1, 2]), "point"),
    (T.rotate_axis_steps, ([1, 0, 0, 0], 0.3), "axis"),
    (T.euler_zyx, (0.1, [0.2, 0.3], 0.4), "pitch"),
    (T.shear_xy, (1.0, [1.0, 2.0]), "b"), (T.shear_x, ([1.0, 2.0],), "a"),
    (T.inverse, (np.eye(5),), "M"), (T.inverse, (np.ones((3, 4)),), "M"),
    (T.to_homogeneous, ([1, 2, 3, 4],), "points"),
])
def test_wrong_shapes_name_the_argument(func, args, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        func(*args)


@pytest.mark.parametrize("call", [
    lambda v: T.translate([v, 0]), lambda v: T.scale([1, v, 1]), lambda v: T.rotate(v),
    lambda v: T.rotate_about(v, [0, 0]), lambda v: T.rotate_about(0.1, [v, 0]),
    lambda v: T.rotate_y(v), lambda v: T.rotate_axis([0, v, 1], 0.2),
    lambda v: T.rotate_axis([0, 0, 1], 0.2, [v, 0, 0]), lambda v: T.euler_zyx(0, 0, v),
    lambda v: T.shear_yz(v, 0), lambda v: T.inverse(np.diag([1, v, 1])),
    lambda v: T.from_homogeneous([1, v, 1]),
])
@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_non_finite_values_are_rejected(call, value):
    with pytest.raises(ValueError, match="finite"):
        call(value)


@pytest.mark.parametrize("call", [
    lambda v: T.translate(v), lambda v: T.scale(v), lambda v: T.rotate(v),
    lambda v: T.rotate_about(v, [0, 0]), lambda v: T.rotate_z(v), lambda v: T.rotate_axis(v, 1),
    lambda v: T.rotate_axis([0, 0, 1], v), lambda v: T.euler_zyx(v, 0, 0),
    lambda v: T.shear_y(v), lambda v: T.shear_xz(0, v), lambda v: T.inverse(v),
    lambda v: T.to_homogeneous(v),
])
@pytest.mark.parametrize("value", ["1", None])
def test_strings_and_none_are_type_errors(call, value):
    with pytest.raises(TypeError):
        call(value)


@pytest.mark.parametrize("axis", [[0, 0, 0], [0, 1e-13, 0]])
def test_zero_axis_is_rejected(axis):
    with pytest.raises(ValueError, match="axis"):
        T.rotate_axis(axis, 0.5)
    with pytest.raises(ValueError, match="axis"):
        T.rotate_axis_steps(axis, 0.5)
