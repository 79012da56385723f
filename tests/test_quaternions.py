"""Tests of course_lib.quaternions (scalar-first quaternions (s, x, y, z)).

Expected values come from scipy.spatial.transform.Rotation (scalar-LAST by default, so we always
pass ``scalar_first=True``), from closed forms typed out below, or from mathematical properties.
Nothing here is copied from the output of the code under test.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation, Slerp

from course_lib import quaternions as Q

PI = np.pi
ATOL = 1e-12


# ---------------------------------------------------------------------------------------------
# helpers
# ---------------------------------------------------------------------------------------------

def rng(seed):
    return np.random.default_rng(seed)


def random_quats(gen, n, unit=False):
    """n random quaternions, non-unit (lengths from 1e-3 to 1e3) unless `unit`, random signs."""
    q = gen.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    if not unit:
        q *= 10.0 ** gen.uniform(-3, 3, size=(n, 1))
    return q


def scipy_rot(q):
    """scipy Rotation of our scalar-first quaternion(s) (scipy normalizes them itself)."""
    return Rotation.from_quat(np.asarray(q, dtype=float), scalar_first=True)


def scipy_quat(r):
    return r.as_quat(scalar_first=True, canonical=False)


def assert_same_up_to_sign(got, expected, atol=ATOL):
    """Each row of `got` equals the row of `expected` or its negative (q and -q: same rotation)."""
    got, expected = np.asarray(got), np.asarray(expected)
    assert got.shape == expected.shape
    err = np.minimum(np.abs(got - expected).max(axis=-1), np.abs(got + expected).max(axis=-1))
    assert err.max() <= atol, f"max error up to sign {err.max():.3g}"


# hypothesis strategies: bounded floats with an explicit minimum norm (no degenerate inputs)
coord = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
quaternion = st.tuples(coord, coord, coord, coord).map(np.array).filter(
    lambda q: np.linalg.norm(q) > 1e-2)
axis3 = st.tuples(coord, coord, coord).map(np.array).filter(lambda v: np.linalg.norm(v) > 1e-2)
point3 = st.tuples(coord, coord, coord).map(np.array)
# angles in (-pi, pi), away from 0 (axis undefined) and from +-pi (axis sign ambiguous)
angle = st.floats(1e-3, PI - 1e-3).flatmap(lambda a: st.sampled_from([a, -a]))

FAST = settings(max_examples=150, deadline=None, database=None)   # no .hypothesis/ dir


# ---------------------------------------------------------------------------------------------
# identity, norm, normalize, conjugate, inverse: closed forms
# ---------------------------------------------------------------------------------------------

def test_identity_is_scalar_one_and_the_null_rotation():
    q = Q.identity()
    np.testing.assert_array_equal(q, [1.0, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(scipy_rot(q).as_matrix(), np.eye(3), atol=0)


def test_norm_and_normalize_closed_forms():
    # |(1,1,1,1)| = 2, |(0,0,3,4)| = 5: values worked out by hand
    assert float(Q.norm([1, 1, 1, 1])) == 2.0
    np.testing.assert_allclose(Q.norm([[0, 0, 3, 4], [2, 0, 0, 0]]), [5.0, 2.0])
    np.testing.assert_allclose(Q.normalize([0, 0, 3, 4]), [0, 0, 0.6, 0.8], atol=ATOL)
    q = random_quats(rng(1), 1000)
    u = Q.normalize(q)
    np.testing.assert_allclose(np.linalg.norm(u, axis=-1), 1.0, atol=ATOL)
    np.testing.assert_allclose(u * np.linalg.norm(q, axis=-1, keepdims=True), q, rtol=1e-12)


def test_conjugate_negates_vector_part():
    np.testing.assert_array_equal(Q.conjugate([1, 2, 3, 4]), [1, -2, -3, -4])
    q = random_quats(rng(2), 50).reshape(5, 10, 4)
    c = Q.conjugate(q)
    np.testing.assert_array_equal(c[..., 0], q[..., 0])
    np.testing.assert_array_equal(c[..., 1:], -q[..., 1:])


def test_inverse_closed_form_and_product_with_q_is_identity():
    # (0, 0, 2, 0)^-1 = (0, 0, -1/2, 0) by hand: conj / |q|^2
    np.testing.assert_allclose(Q.inverse([0, 0, 2, 0]), [0, 0, -0.5, 0], atol=ATOL)
    q = random_quats(rng(3), 2000)               # non-unit on purpose: inverse != conjugate
    inv = Q.inverse(q)
    ident = np.broadcast_to([1.0, 0, 0, 0], q.shape)
    np.testing.assert_allclose(Q.multiply(q, inv), ident, atol=1e-12)
    np.testing.assert_allclose(Q.multiply(inv, q), ident, atol=1e-12)


def test_inverse_equals_conjugate_for_unit_quaternions_and_matches_scipy_inv():
    r = Rotation.random(1000, rng=rng(4))
    q = scipy_quat(r)
    np.testing.assert_allclose(Q.inverse(q), Q.conjugate(q), atol=1e-15)
    assert_same_up_to_sign(Q.inverse(q), scipy_quat(r.inv()))


# ---------------------------------------------------------------------------------------------
# from_axis_angle / to_axis_angle
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("axis, index", [([1, 0, 0], 1), ([0, 1, 0], 2), ([0, 0, 1], 3),
                                         ([0, 0, 5], 3)])
@pytest.mark.parametrize("theta", [0.0, 0.3, PI / 2, PI, -2.0, 5.0])
def test_from_axis_angle_coordinate_axes_closed_form(axis, index, theta):
    # q = (cos(theta/2), sin(theta/2) n): the half-angle formula, typed out
    expected = np.zeros(4)
    expected[0] = np.cos(theta / 2)
    expected[index] = np.sin(theta / 2)
    np.testing.assert_allclose(Q.from_axis_angle(axis, theta), expected, atol=ATOL)


def test_from_axis_angle_matches_scipy_from_rotvec():
    gen = rng(10)
    n = 5000
    axes = gen.normal(size=(n, 3)) * 10.0 ** gen.uniform(-3, 3, size=(n, 1))   # non-unit axes
    angles = gen.uniform(-4 * PI, 4 * PI, size=n)                             # any angle
    unit = axes / np.linalg.norm(axes, axis=-1, keepdims=True)
    # scipy's from_rotvec keeps the sign (no canonicalization), so the comparison is exact
    expected = scipy_quat(Rotation.from_rotvec(unit * angles[:, None]))
    np.testing.assert_allclose(Q.from_axis_angle(axes, angles), expected, atol=1e-12)


def test_from_axis_angle_broadcasting():
    gen = rng(11)
    angles = gen.uniform(-PI, PI, size=7)
    axis = np.array([1.0, -2.0, 0.5])
    q = Q.from_axis_angle(axis, angles)                     # one axis, many angles
    assert q.shape == (7, 4)
    expected = scipy_quat(Rotation.from_rotvec(np.outer(angles, axis / np.linalg.norm(axis))))
    np.testing.assert_allclose(q, expected, atol=ATOL)
    axes = gen.normal(size=(2, 3, 3))                       # many axes, one angle
    q = Q.from_axis_angle(axes, 0.8)
    assert q.shape == (2, 3, 4)
    unit = axes / np.linalg.norm(axes, axis=-1, keepdims=True)
    np.testing.assert_allclose(q, scipy_quat(Rotation.from_rotvec(0.8 * unit.reshape(-1, 3)))
                               .reshape(2, 3, 4), atol=ATOL)


def test_to_axis_angle_matches_scipy_as_rotvec():
    gen = rng(12)
    q = random_quats(gen, 5000)                 # non-unit, random sign (s < 0 half of the time)
    axis, ang = Q.to_axis_angle(q)
    assert axis.shape == (5000, 3) and ang.shape == (5000,)
    assert np.all((ang >= 0) & (ang <= PI))
    np.testing.assert_allclose(np.linalg.norm(axis, axis=-1), 1.0, atol=ATOL)
    rotvec = scipy_rot(q).as_rotvec()          # magnitude in [0, pi]
    np.testing.assert_allclose(ang, np.linalg.norm(rotvec, axis=-1), atol=1e-12)
    np.testing.assert_allclose(axis * ang[:, None], rotvec, atol=1e-12)
    # -q is the same rotation: same axis and angle
    axis2, ang2 = Q.to_axis_angle(-q)
    np.testing.assert_allclose(axis2, axis, atol=ATOL)
    np.testing.assert_allclose(ang2, ang, atol=ATOL)


def test_to_axis_angle_identity_and_half_turn():
    axis, ang = Q.to_axis_angle([3.0, 0, 0, 0])             # identity (non-unit)
    assert float(ang) == 0.0
    np.testing.assert_allclose(axis, [1.0, 0, 0])           # documented default axis
    axis, ang = Q.to_axis_angle([0.0, 0, 0, -2])            # 180 degrees about z
    np.testing.assert_allclose(ang, PI, atol=ATOL)
    np.testing.assert_allclose(np.abs(axis), [0, 0, 1], atol=ATOL)


@FAST
@given(axis=axis3, theta=angle)
def test_axis_angle_round_trip(axis, theta):
    # (n, theta) and (-n, -theta) are the same rotation; to_axis_angle returns theta >= 0
    got_axis, got_angle = Q.to_axis_angle(Q.from_axis_angle(axis, theta))
    n = axis / np.linalg.norm(axis)
    np.testing.assert_allclose(got_angle, abs(theta), atol=1e-9)
    np.testing.assert_allclose(got_axis, np.sign(theta) * n, atol=1e-9)


# ---------------------------------------------------------------------------------------------
# to_matrix
# ---------------------------------------------------------------------------------------------

def test_to_matrix_closed_forms_quarter_turns():
    c = s = np.sqrt(0.5)
    # 90 degrees about x: y -> z, z -> -y
    np.testing.assert_allclose(Q.to_matrix([c, s, 0, 0]),
                               [[1, 0, 0], [0, 0, -1], [0, 1, 0]], atol=ATOL)
    # 90 degrees about y: z -> x, x -> -z (top-left entry 1 - 2y^2 - 2z^2 = 0, not 1 - 2y^2)
    np.testing.assert_allclose(Q.to_matrix([c, 0, s, 0]),
                               [[0, 0, 1], [0, 1, 0], [-1, 0, 0]], atol=ATOL)
    # 90 degrees about z: x -> y, y -> -x
    np.testing.assert_allclose(Q.to_matrix([c, 0, 0, s]),
                               [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=ATOL)
    # 120 degrees about (1,1,1): cyclic permutation x -> y -> z -> x; q = (1/2)(1, 1, 1, 1)
    np.testing.assert_allclose(Q.to_matrix([0.5, 0.5, 0.5, 0.5]),
                               [[0, 0, 1], [1, 0, 0], [0, 1, 0]], atol=ATOL)


def test_to_matrix_textbook_formula_entry_by_entry():
    s, x, y, z = Q.normalize([0.3, -0.5, 0.7, 0.2])     # normalize is checked separately
    expected = np.array([
        [1 - 2 * y * y - 2 * z * z, 2 * x * y - 2 * s * z, 2 * x * z + 2 * s * y],
        [2 * x * y + 2 * s * z, 1 - 2 * x * x - 2 * z * z, 2 * y * z - 2 * s * x],
        [2 * x * z - 2 * s * y, 2 * y * z + 2 * s * x, 1 - 2 * x * x - 2 * y * y]])
    np.testing.assert_allclose(Q.to_matrix([s, x, y, z]), expected, atol=ATOL)


def test_to_matrix_matches_scipy_for_many_non_unit_quaternions():
    # 20000 > the 8192 block size used internally, so several blocks are exercised
    q = random_quats(rng(20), 20000)
    m = Q.to_matrix(q)
    assert m.shape == (20000, 3, 3)
    np.testing.assert_allclose(m, scipy_rot(q).as_matrix(), atol=1e-12)


def test_to_matrix_homogeneous_is_4x4_without_translation():
    q = random_quats(rng(21), 3000)
    m = Q.to_matrix(q, homogeneous=True)
    assert m.shape == (3000, 4, 4)
    np.testing.assert_allclose(m[:, :3, :3], scipy_rot(q).as_matrix(), atol=1e-12)
    np.testing.assert_array_equal(m[:, 3, :3], 0.0)
    np.testing.assert_array_equal(m[:, :3, 3], 0.0)
    np.testing.assert_array_equal(m[:, 3, 3], 1.0)


def test_to_matrix_stack_shapes():
    q = random_quats(rng(22), 35).reshape(5, 7, 4)
    m = Q.to_matrix(q)
    assert m.shape == (5, 7, 3, 3)
    np.testing.assert_allclose(m.reshape(-1, 3, 3), scipy_rot(q.reshape(-1, 4)).as_matrix(),
                               atol=1e-12)
    assert Q.to_matrix(q[0, 0]).shape == (3, 3)
    assert Q.to_matrix(q, homogeneous=True).shape == (5, 7, 4, 4)


@FAST
@given(q=quaternion)
def test_to_matrix_is_a_rotation_and_q_minus_q_agree(q):
    m = Q.to_matrix(q)
    np.testing.assert_allclose(m.T @ m, np.eye(3), atol=1e-12)
    assert abs(np.linalg.det(m) - 1.0) < 1e-12
    np.testing.assert_allclose(Q.to_matrix(-q), m, atol=1e-12)


# ---------------------------------------------------------------------------------------------
# from_matrix
# ---------------------------------------------------------------------------------------------

def test_from_matrix_matches_scipy_up_to_sign_with_non_negative_scalar():
    r = Rotation.random(5000, rng=rng(30))
    q = Q.from_matrix(r.as_matrix())
    assert q.shape == (5000, 4)
    assert np.all(q[:, 0] >= 0)
    np.testing.assert_allclose(np.linalg.norm(q, axis=-1), 1.0, atol=ATOL)
    assert_same_up_to_sign(q, scipy_quat(r), atol=1e-12)


def test_from_matrix_accepts_homogeneous_4x4_and_stacks():
    r = Rotation.random(30, rng=rng(31))
    m4 = np.zeros((30, 4, 4))
    m4[:, :3, :3] = r.as_matrix()
    m4[:, 3, 3] = 1.0
    q = Q.from_matrix(m4.reshape(5, 6, 4, 4))
    assert q.shape == (5, 6, 4)
    assert_same_up_to_sign(q.reshape(30, 4), scipy_quat(r), atol=1e-12)


@pytest.mark.parametrize("m", [np.eye(3), np.eye(4)])
def test_from_matrix_identity_is_exact(m):
    np.testing.assert_array_equal(Q.from_matrix(m), [1.0, 0.0, 0.0, 0.0])


@pytest.mark.parametrize("diag, expected", [
    ([1, -1, -1], [0, 1, 0, 0]),      # 180 degrees about x
    ([-1, 1, -1], [0, 0, 1, 0]),      # about y
    ([-1, -1, 1], [0, 0, 0, 1]),      # about z
])
def test_from_matrix_coordinate_half_turns(diag, expected):
    q = Q.from_matrix(np.diag(np.array(diag, dtype=float)))
    assert_same_up_to_sign(q, np.array(expected, dtype=float), atol=0.0)


def test_from_matrix_half_turns_about_random_axes_are_exact():
    # 180 degrees about n: R = 2 n n^T - I (closed form), and q = +-(0, n)
    gen = rng(32)
    n = gen.normal(size=(3000, 3))
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    m = 2 * n[:, :, None] * n[:, None, :] - np.eye(3)
    q = Q.from_matrix(m)
    assert np.all(q[:, 0] >= 0)
    np.testing.assert_allclose(q[:, 0], 0.0, atol=1e-15)
    assert_same_up_to_sign(q, np.concatenate([np.zeros((3000, 1)), n], axis=1), atol=1e-15)


@pytest.mark.parametrize("delta", [1e-9, 1e-10, 1e-12, 1e-14])
def test_from_matrix_within_delta_of_half_turn(delta):
    # theta = pi - delta: s = cos(theta/2) = sin(delta/2) is tiny; the textbook recipe that
    # divides by s breaks down, Shepperd's method must not. Expected q typed from the formula.
    gen = rng(33)
    n = gen.normal(size=(500, 3))
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    theta = PI - delta
    # Rodrigues: R = cos I + sin [n]x + (1 - cos) n n^T
    c, s = np.cos(theta), np.sin(theta)
    cross = np.zeros((500, 3, 3))
    cross[:, 0, 1], cross[:, 0, 2], cross[:, 1, 2] = -n[:, 2], n[:, 1], -n[:, 0]
    cross -= np.swapaxes(cross, 1, 2)
    m = c * np.eye(3) + s * cross + (1 - c) * n[:, :, None] * n[:, None, :]
    expected = np.concatenate([np.full((500, 1), np.cos(theta / 2)),
                               np.sin(theta / 2) * n], axis=1)
    q = Q.from_matrix(m)
    assert np.all(q[:, 0] >= 0)
    np.testing.assert_allclose(q, expected, atol=1e-14)


@FAST
@given(q=quaternion)
def test_quaternion_matrix_quaternion_round_trip(q):
    back = Q.from_matrix(Q.to_matrix(q))
    assert back[0] >= 0
    assert_same_up_to_sign(back, q / np.linalg.norm(q), atol=1e-12)


@FAST
@given(q=quaternion)
def test_matrix_quaternion_matrix_round_trip(q):
    m = scipy_rot(q).as_matrix()                    # an independent rotation matrix
    np.testing.assert_allclose(Q.to_matrix(Q.from_matrix(m)), m, atol=1e-12)


# ---------------------------------------------------------------------------------------------
# multiply
# ---------------------------------------------------------------------------------------------

ONE, I, J, K = (np.eye(4)[k] for k in range(4))


@pytest.mark.parametrize("a, b, expected", [
    (I, J, K), (J, K, I), (K, I, J),          # ij = k, jk = i, ki = j
    (J, I, -K), (K, J, -I), (I, K, -J),       # anti-commutative
    (I, I, -ONE), (J, J, -ONE), (K, K, -ONE), # i^2 = j^2 = k^2 = -1
    (ONE, I, I), (K, ONE, K),
])
def test_multiply_hamilton_table(a, b, expected):
    np.testing.assert_array_equal(Q.multiply(a, b), expected)


def test_multiply_matches_scipy_composition():
    gen = rng(40)
    r1, r2 = Rotation.random(5000, rng=gen), Rotation.random(5000, rng=gen)
    got = Q.multiply(scipy_quat(r1), scipy_quat(r2))
    # scipy: r1 * r2 applies r2 first, the same as our q1 q2
    assert_same_up_to_sign(got, scipy_quat(r1 * r2), atol=1e-12)


def test_multiply_non_unit_scales_by_the_norms_and_broadcasts():
    gen = rng(41)
    a, b = random_quats(gen, 2000), random_quats(gen, 2000)
    got = Q.multiply(a, b)
    na, nb = np.linalg.norm(a, axis=-1), np.linalg.norm(b, axis=-1)
    unit = scipy_quat(scipy_rot(a) * scipy_rot(b))
    assert_same_up_to_sign(got / (na * nb)[:, None], unit, atol=1e-12)
    # one quaternion against a stack
    q = Q.multiply(a[0], b.reshape(40, 50, 4))
    assert q.shape == (40, 50, 4)
    np.testing.assert_allclose(q.reshape(2000, 4), Q.multiply(np.tile(a[0], (2000, 1)), b),
                               rtol=1e-15, atol=0)


@FAST
@given(a=quaternion, b=quaternion)
def test_multiply_composes_like_matrices(a, b):
    np.testing.assert_allclose(Q.to_matrix(Q.multiply(a, b)), Q.to_matrix(a) @ Q.to_matrix(b),
                               atol=1e-11)


@FAST
@given(a=quaternion, b=quaternion)
def test_norm_is_multiplicative(a, b):
    np.testing.assert_allclose(Q.norm(Q.multiply(a, b)), Q.norm(a) * Q.norm(b), rtol=1e-12)


@FAST
@given(a=quaternion, b=quaternion)
def test_conjugate_of_product_reverses_order(a, b):
    np.testing.assert_allclose(Q.conjugate(Q.multiply(a, b)),
                               Q.multiply(Q.conjugate(b), Q.conjugate(a)), atol=1e-12)


# ---------------------------------------------------------------------------------------------
# rotate
# ---------------------------------------------------------------------------------------------

def test_rotate_quarter_turn_closed_form():
    q = [np.sqrt(0.5), 0, 0, np.sqrt(0.5)]                  # 90 degrees about z
    np.testing.assert_allclose(Q.rotate(q, [[1, 0, 0], [0, 1, 0], [0, 0, 1]]),
                               [[0, 1, 0], [-1, 0, 0], [0, 0, 1]], atol=ATOL)


def test_rotate_one_quaternion_many_points_matches_scipy_apply():
    gen = rng(50)
    q = random_quats(gen, 1)[0] * 7.0                      # non-unit: rotate normalizes
    p = gen.normal(size=(4000, 3)) * 10
    np.testing.assert_allclose(Q.rotate(q, p), scipy_rot(q).apply(p), atol=1e-11)


def test_rotate_one_quaternion_per_point_matches_scipy_apply():
    gen = rng(51)
    q = random_quats(gen, 4000)
    p = gen.normal(size=(4000, 3)) * 10
    np.testing.assert_allclose(Q.rotate(q, p), scipy_rot(q).apply(p), atol=1e-11)


def test_rotate_stack_broadcasting():
    gen = rng(52)
    q = random_quats(gen, 35).reshape(5, 7, 4)
    p = gen.normal(size=(5, 7, 3))
    got = Q.rotate(q, p)
    assert got.shape == (5, 7, 3)
    expected = scipy_rot(q.reshape(-1, 4)).apply(p.reshape(-1, 3)).reshape(5, 7, 3)
    np.testing.assert_allclose(got, expected, atol=1e-12)
    # many quaternions, one point
    got = Q.rotate(q, [1.0, 2.0, 3.0])
    assert got.shape == (5, 7, 3)
    np.testing.assert_allclose(got.reshape(-1, 3),
                               scipy_rot(q.reshape(-1, 4)).apply([1.0, 2.0, 3.0]), atol=1e-12)
    # a single quaternion and a single point
    assert Q.rotate(q[0, 0], [1.0, 2.0, 3.0]).shape == (3,)


@FAST
@given(q=quaternion, p1=point3, p2=point3)
def test_rotate_preserves_lengths_and_dot_products(q, p1, p2):
    r1, r2 = Q.rotate(q, p1), Q.rotate(q, p2)
    np.testing.assert_allclose(np.linalg.norm(r1), np.linalg.norm(p1), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(r1 @ r2, p1 @ p2, atol=1e-10)


@FAST
@given(q=quaternion, p=point3)
def test_rotate_q_and_minus_q_and_matrix_agree(q, p):
    np.testing.assert_allclose(Q.rotate(-q, p), Q.rotate(q, p), atol=1e-12)
    np.testing.assert_allclose(Q.rotate(q, p), Q.to_matrix(q) @ p, atol=1e-11)


# ---------------------------------------------------------------------------------------------
# angle_between, slerp, nlerp
# ---------------------------------------------------------------------------------------------

def test_angle_between_matches_scipy_magnitude():
    gen = rng(60)
    a, b = random_quats(gen, 5000), random_quats(gen, 5000)
    expected = (scipy_rot(a).inv() * scipy_rot(b)).magnitude()
    got = Q.angle_between(a, b)
    assert np.all((got >= 0) & (got <= PI + 1e-15))
    np.testing.assert_allclose(got, expected, atol=1e-12)


def test_angle_between_closed_forms_and_tiny_angles():
    q = Q.from_axis_angle([0, 1, 0], 0.5)
    np.testing.assert_allclose(Q.angle_between(Q.identity(), q), 0.5, atol=ATOL)
    np.testing.assert_allclose(Q.angle_between(q, -q), 0.0, atol=ATOL)
    np.testing.assert_allclose(Q.angle_between([1, 0, 0, 0], [0, 1, 0, 0]), PI, atol=ATOL)
    # accurate also for tiny angles (where arccos would lose digits)
    tiny = Q.from_axis_angle([1, 2, 3], 1e-9)
    np.testing.assert_allclose(Q.angle_between(q, Q.multiply(q, tiny)), 1e-9, rtol=1e-6)


def test_slerp_matches_scipy_slerp():
    gen = rng(61)
    ts = np.concatenate([[0.0, 1.0], np.linspace(0, 1, 11), gen.uniform(0, 1, 10)])
    for r0, r1 in zip(Rotation.random(300, rng=gen), Rotation.random(300, rng=gen)):
        q0, q1 = scipy_quat(r0) * gen.uniform(0.1, 10), scipy_quat(r1) * gen.choice([-3, 0.5])
        expected = scipy_quat(Slerp([0, 1], Rotation.concatenate([r0, r1]))(ts))
        got = Q.slerp(q0, q1, ts)
        assert got.shape == (len(ts), 4)
        assert_same_up_to_sign(got, expected, atol=1e-12)


def test_slerp_end_points_are_exact():
    gen = rng(62)
    q0, q1 = random_quats(gen, 200), random_quats(gen, 200)
    u0, u1 = q0 / Q.norm(q0)[:, None], q1 / Q.norm(q1)[:, None]
    np.testing.assert_allclose(Q.slerp(q0, q1, 0.0), u0, atol=1e-15)   # t = 0 gives q0 itself
    assert_same_up_to_sign(Q.slerp(q0, q1, 1.0), u1, atol=1e-15)       # t = 1: q1 (or -q1)


def test_slerp_constant_angular_speed_and_closed_form():
    # slerp from identity to a turn by 2.4 about n is the turn by 2.4 t about n
    n = np.array([1.0, -2.0, 2.0]) / 3.0
    ts = np.linspace(0, 1, 9)
    got = Q.slerp(Q.identity(), Q.from_axis_angle(n, 2.4), ts)
    expected = np.column_stack([np.cos(1.2 * ts), np.outer(np.sin(1.2 * ts), n)])
    np.testing.assert_allclose(got, expected, atol=1e-12)
    gen = rng(63)
    a, b = random_quats(gen, 100), random_quats(gen, 100)
    total = Q.angle_between(a, b)
    for t1, t2 in [(0.0, 0.3), (0.2, 0.7), (0.5, 1.0)]:
        np.testing.assert_allclose(Q.angle_between(Q.slerp(a, b, t1), Q.slerp(a, b, t2)),
                                   (t2 - t1) * total, atol=1e-10)


def test_slerp_not_shortest_takes_the_long_way():
    # 4D angle Omega > 90 degrees between q0 and q1: with shortest=False the midpoint lies at
    # the rotation angle Omega from both ends (half of the long way, 2*Omega), not at theta/2
    q0 = Q.identity()
    q1 = -Q.from_axis_angle([0, 0, 1], 1.0)          # rotation by 1 rad, but q0.q1 < 0
    mid = Q.slerp(q0, q1, 0.5, shortest=False)
    omega = np.arccos(np.dot(q0, q1))                # = pi - 0.5
    np.testing.assert_allclose(Q.angle_between(q0, mid), omega, atol=1e-12)
    np.testing.assert_allclose(Q.angle_between(q1, mid), omega, atol=1e-12)
    np.testing.assert_allclose(Q.angle_between(q0, Q.slerp(q0, q1, 0.5)), 0.5, atol=1e-12)


def test_nlerp_lies_on_the_slerp_arc_and_agrees_at_0_half_1():
    gen = rng(64)
    a, b = random_quats(gen, 500), random_quats(gen, 500)
    total = Q.angle_between(a, b)
    for t in [0.0, 0.1, 0.25, 0.5, 0.8, 1.0]:
        n = Q.nlerp(a, b, t)
        np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, atol=ATOL)
        # on the great arc between a and b: the two distances add up to the whole
        np.testing.assert_allclose(Q.angle_between(a, n) + Q.angle_between(n, b), total,
                                   atol=1e-9)
        if t in (0.0, 0.5, 1.0):
            assert_same_up_to_sign(n, Q.slerp(a, b, t), atol=1e-12)
    # but not at constant speed: for a large angle nlerp(0.25) != slerp(0.25)
    q1 = Q.from_axis_angle([0, 0, 1], 3.0)
    assert Q.angle_between(Q.nlerp(Q.identity(), q1, 0.25), Q.slerp(Q.identity(), q1, 0.25)) \
        > 1e-2


def test_nlerp_opposite_quaternions_midpoint_is_an_error():
    q = Q.from_axis_angle([1, 0, 0], 0.3)
    with pytest.raises(ValueError, match="zero"):
        Q.nlerp(q, -q, 0.5, shortest=False)


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("func", [
    Q.normalize, Q.inverse, Q.to_matrix, lambda q: Q.rotate(q, [1, 2, 3]), Q.to_axis_angle,
    lambda q: Q.angle_between(q, [1, 0, 0, 0]), lambda q: Q.slerp([1, 0, 0, 0], q, 0.5)])
def test_zero_quaternion_is_rejected(func):
    with pytest.raises(ValueError, match="zero"):
        func([0.0, 0.0, 0.0, 0.0])


def test_zero_quaternion_deep_in_a_big_stack_is_rejected():
    q = random_quats(rng(70), 20000)
    q[15000] = 0.0                                    # in the second internal block
    with pytest.raises(ValueError, match="zero"):
        Q.to_matrix(q)


@pytest.mark.parametrize("func", [Q.normalize, Q.conjugate, Q.norm, Q.inverse, Q.to_matrix])
@pytest.mark.parametrize("bad", [[1, 2, 3], [1, 2, 3, 4, 5], 1.0, np.ones((2, 3))])
def test_wrong_quaternion_shape_names_q(func, bad):
    with pytest.raises(ValueError, match=r"\bq\b.*4 components"):
        func(bad)


@pytest.mark.parametrize("bad", [[1, np.nan, 0, 0], [np.inf, 0, 0, 0], [0, 0, -np.inf, 1]])
def test_non_finite_quaternion_is_rejected(bad):
    for func in (Q.normalize, Q.to_matrix, Q.conjugate, lambda q: Q.multiply(q, q)):
        with pytest.raises(ValueError, match="finite"):
            func(bad)


@pytest.mark.parametrize("bad", ["1, 0, 0, 0", None, b"abcd"])
def test_strings_and_none_are_type_errors(bad):
    for func in (Q.normalize, Q.to_matrix, Q.from_matrix, lambda q: Q.multiply(q, Q.identity()),
                 lambda q: Q.from_axis_angle(q, 1.0)):
        with pytest.raises(TypeError):
            func(bad)


def test_multiply_names_the_bad_argument():
    with pytest.raises(ValueError, match="q1"):
        Q.multiply([1, 2, 3], [1, 0, 0, 0])
    with pytest.raises(ValueError, match="q2"):
        Q.multiply([1, 0, 0, 0], [1, 2])


@pytest.mark.parametrize("axis", [[0, 0, 0], [0.0, 1e-14, 0.0]])
def test_from_axis_angle_zero_axis(axis):
    with pytest.raises(ValueError, match="axis"):
        Q.from_axis_angle(axis, 1.0)
    with pytest.raises(ValueError, match="axis"):
        Q.from_axis_angle([[1, 0, 0], axis], 1.0)     # one bad axis in a stack


def test_from_axis_angle_bad_values():
    with pytest.raises(ValueError, match="finite"):
        Q.from_axis_angle([np.nan, 0, 1], 1.0)
    with pytest.raises(ValueError, match="finite"):
        Q.from_axis_angle([0, 0, 1], np.inf)
    with pytest.raises(ValueError, match="axis"):
        Q.from_axis_angle([0, 1], 1.0)
    with pytest.raises(TypeError):
        Q.from_axis_angle([0, 0, 1], "pi")
    with pytest.raises(TypeError):
        Q.from_axis_angle([0, 0, 1], None)


def test_rotate_bad_points():
    with pytest.raises(ValueError, match="points"):
        Q.rotate(Q.identity(), [[1, 2], [3, 4]])
    with pytest.raises(ValueError, match="finite"):
        Q.rotate(Q.identity(), [1, np.nan, 2])
    with pytest.raises(TypeError):
        Q.rotate(Q.identity(), None)


def _not_rotations():
    shear = np.eye(3)
    shear[0, 1] = 0.5
    translated = np.eye(4)
    translated[:3, 3] = [1, 2, 3]
    projective = np.eye(4)
    projective[3, 2] = 1.0
    return {
        "scale": (np.diag([2.0, 2.0, 2.0]), r"\bm\b.*not a rotation"),
        "nonuniform scale": (np.diag([1.0, 1.0, 1.1]), r"\bm\b.*not a rotation"),
        "shear": (shear, r"\bm\b.*not a rotation"),
        "mirror": (np.diag([1.0, 1.0, -1.0]), r"\bm\b.*mirroring"),
        "point reflection": (-np.eye(3), r"\bm\b.*mirroring"),
        "rotation then mirror": (Rotation.from_rotvec([0.3, -1, 2]).as_matrix()
                                 @ np.diag([-1.0, 1, 1]), r"\bm\b.*mirroring"),
        "4x4 translation": (translated, r"\bm\b.*translation"),
        "4x4 projective": (projective, r"\bm\b.*projective"),
        "zero": (np.zeros((3, 3)), r"\bm\b.*not a rotation"),
    }


@pytest.mark.parametrize("name", list(_not_rotations()))
def test_from_matrix_rejects_non_rotations(name):
    m, pattern = _not_rotations()[name]
    with pytest.raises(ValueError, match=pattern):
        Q.from_matrix(m)


def test_from_matrix_rejects_bad_shapes_and_values():
    with pytest.raises(ValueError, match=r"\bm\b"):
        Q.from_matrix(np.eye(3)[:, :2])
    with pytest.raises(ValueError, match=r"\bm\b"):
        Q.from_matrix([1.0, 0, 0])
    with pytest.raises(ValueError, match=r"\bm\b"):
        Q.from_matrix(np.eye(2))
    with pytest.raises(ValueError, match="finite"):
        Q.from_matrix(np.full((3, 3), np.nan))
    stack = np.stack([np.eye(3), np.diag([1.0, 2.0, 1.0])])   # one bad matrix in a stack
    with pytest.raises(ValueError, match=r"\bm\b.*not a rotation"):
        Q.from_matrix(stack)


def test_slerp_bad_input():
    with pytest.raises(ValueError, match="finite"):
        Q.slerp(Q.identity(), Q.identity(), np.nan)
    with pytest.raises(ValueError, match="zero"):
        Q.slerp([0, 0, 0, 0], Q.identity(), 0.5)
    with pytest.raises(TypeError):
        Q.slerp(Q.identity(), Q.identity(), "half")


@pytest.mark.parametrize("scale", [1e160, 1e200])
def test_huge_but_finite_quaternions_are_handled(scale):
    # BUG: s*s + x*x + ... overflows to inf for |q| > ~1e154, so normalize returns the zero
    # quaternion and to_matrix the identity, silently. q = scale * (1, 1, 0, 0) is a finite,
    # non-zero quaternion: the turn by 90 degrees about x (closed form typed below).
    q = [scale, scale, 0.0, 0.0]
    np.testing.assert_allclose(Q.normalize(q), [np.sqrt(0.5), np.sqrt(0.5), 0, 0], atol=ATOL)
    np.testing.assert_allclose(Q.to_matrix(q), [[1, 0, 0], [0, 0, -1], [0, 1, 0]], atol=ATOL)
    np.testing.assert_allclose(Q.rotate(q, [0.0, 1.0, 0.0]), [0, 0, 1], atol=ATOL)


@pytest.mark.parametrize("call, names", [
    (lambda: Q.from_axis_angle(np.ones((3, 3)), [1.0, 2.0]), ("axis", "angle")),
    (lambda: Q.multiply(np.ones((3, 4)), np.ones((2, 4))), ("q1", "q2")),
    (lambda: Q.rotate(np.ones((3, 4)), np.ones((2, 3))), ("q", "points")),
    (lambda: Q.slerp(np.ones((3, 4)), np.ones((2, 4)), 0.5), ("q0", "q1")),
    (lambda: Q.angle_between(np.ones((3, 4)), np.ones((2, 4))), ("q0", "q1")),
])
def test_mismatched_stacks_are_reported_by_name(call, names):
    """Stacks that cannot pair up get an error naming both arguments, not numpy's."""
    with pytest.raises(ValueError) as info:
        call()
    message = str(info.value)
    assert all(name in message for name in names) and "broadcast" not in message


def test_rotate_equals_the_two_hamilton_products():
    """rotate() uses the expanded formula; it must equal q (0, p) q̄ computed literally."""
    gen = rng(99)
    q = random_quats(gen, 500, unit=True)
    p = gen.normal(size=(500, 3))
    pure = np.column_stack([np.zeros(500), p])
    literal = Q.multiply(Q.multiply(q, pure), Q.conjugate(q))
    assert np.allclose(literal[:, 0], 0, atol=1e-12)
    assert np.allclose(Q.rotate(q, p), literal[:, 1:], atol=1e-12)
