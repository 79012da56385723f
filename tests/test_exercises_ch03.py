"""Tests of the chapter 3 exercises (course_lib.exercises.ch03).

For every exercise and many seeds: the statement reads, the right answer (computed here
independently: scipy's Rotation, which is scalar-LAST unless told ``scalar_first=True``, or
closed forms typed out below, never the course_lib function the checker calls) is accepted,
placeholders are "unanswered", garbage is "invalid", and every anticipated mistake, rebuilt here
from the question's attributes, is named by its diagnosis. Nothing is copied from the checker's
output.
"""
import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation, Slerp

from course_lib.exercises import ch03
import exercise_harness as harness
from exercise_harness import MIN_DIAGNOSED


# ---------------------------------------------------------------------------------------------
# Independent closed forms
# ---------------------------------------------------------------------------------------------

def rot2(theta):
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def trans2(d):
    return np.array([[1.0, 0.0, d[0]], [0.0, 1.0, d[1]], [0.0, 0.0, 1.0]])


def scale2(sx, sy):
    return np.diag([sx, sy, 1.0])


def affine2(linear, t):
    m = np.eye(3)
    m[:2, :2] = linear
    m[:2, 2] = t
    return m


def reflection_about_line(c, phi):
    """Reflection about the line through c with direction (cos phi, sin phi): p -> c + L(p - c)."""
    u = np.array([math.cos(phi), math.sin(phi)])
    L = 2 * np.outer(u, u) - np.eye(2)
    c = np.asarray(c, dtype=float)
    return affine2(L, c - L @ c)


# which coordinate drives each shear, and which two it shifts (x=0, y=1, z=2)
SHEAR_LAYOUT = {"xy": (2, 0, 1), "xz": (1, 0, 2), "yz": (0, 1, 2)}


def shear3(kind, a, b):
    driver, first, second = SHEAR_LAYOUT[kind]
    m = np.eye(4)
    m[first, driver] = a
    m[second, driver] = b
    return m


def hom(m, p):
    """Apply the homogeneous matrix m to the point p."""
    p = np.append(np.asarray(p, dtype=float), 1.0)
    return (m @ p)[:-1]


def rotation(axis, theta):
    axis = np.asarray(axis, dtype=float)
    return Rotation.from_rotvec(axis / np.linalg.norm(axis) * theta)


def quat_of(r):
    return r.as_quat(scalar_first=True)


def hamilton(p, q):
    """p q through the 4x4 matrix of left multiplication by p."""
    s, x, y, z = p
    left = np.array([[s, -x, -y, -z],
                     [x, s, -z, y],
                     [y, z, s, -x],
                     [z, -y, x, s]])
    return left @ np.asarray(q, dtype=float)


def scalar_last(q):
    return np.array([q[1], q[2], q[3], q[0]])


def gap(a, b, sign_free=False):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    d = np.abs(a - b).max()
    return min(d, np.abs(a + b).max()) if sign_free else d


# ---------------------------------------------------------------------------------------------
# Per exercise: the expected answer and the anticipated mistakes, from the attributes
# ---------------------------------------------------------------------------------------------

def compose2d(ex):
    S, R, T = scale2(ex.sx, ex.sy), rot2(ex.theta), trans2(ex.d)
    right = affine2(rot2(ex.theta)[:2, :2] @ np.diag([ex.sx, ex.sy]), ex.d)
    bottom = np.eye(3)
    bottom[:2, :2] = right[:2, :2]
    bottom[2, :2] = ex.d
    return right, {
        "wrong order": S @ R @ T,
        "scale and rotation swapped": T @ S @ R,
        "angle sign": T @ rot2(-ex.theta) @ S,
        "translation in bottom row": bottom,
        "transposed": right.T,
        "degrees": T @ rot2(ex.theta_deg) @ S,        # cos and sin of the degrees as radians
    }


def rotate_about_point(ex):
    R, c = rot2(ex.theta), np.asarray(ex.c)
    right = affine2(R[:2, :2], c - R[:2, :2] @ c)
    R_back = rot2(-ex.theta)[:2, :2]
    return right, {
        "wrong order": trans2(-c) @ R @ trans2(c),
        "about origin": R,
        "angle sign": affine2(R_back, c - R_back @ c),
        "missing T(c)": R @ trans2(-c),
        "missing T(-c)": trans2(c) @ R,
        "degrees": trans2(c) @ rot2(ex.theta_deg) @ trans2(-c),
    }


def inverse_of_composite(ex):
    M = trans2(ex.d) @ rot2(ex.theta) @ scale2(ex.sx, ex.sy)
    assert np.allclose(ex.M, M)
    linear_inv = np.linalg.inv(M[:2, :2])
    return np.linalg.inv(M), {
        "same order": trans2(-ex.d) @ rot2(-ex.theta) @ scale2(1 / ex.sx, 1 / ex.sy),
        "transposed only": M.T,
        "translation not transformed": affine2(linear_inv, -np.asarray(ex.d)),
        "scale not inverted": scale2(ex.sx, ex.sy) @ rot2(-ex.theta) @ trans2(-ex.d),
        "rotation not inverted": scale2(1 / ex.sx, 1 / ex.sy) @ rot2(ex.theta) @ trans2(-ex.d),
        "degrees": scale2(1 / ex.sx, 1 / ex.sy) @ rot2(-ex.theta_deg) @ trans2(-ex.d),
    }


def mirror_about_line(ex):
    c = np.asarray(ex.c, dtype=float)
    through_origin = reflection_about_line([0, 0], ex.phi)
    L = through_origin[:2, :2]
    flip = np.diag([1.0, -1.0])
    return reflection_about_line(c, ex.phi), {
        "line through origin": through_origin,
        "rotations swapped": reflection_about_line(c, -ex.phi),
        "translations swapped": affine2(L, -c + L @ c),
        "no rotation": affine2(flip, c - flip @ c),
        "degrees": reflection_about_line(c, ex.phi_deg),
    }


def shear_inverse(ex):
    H = shear3(ex.kind, ex.a, ex.b)
    return shear3(ex.kind, -ex.a, -ex.b), {
        "not negated": H,
        "transposed": H.T,
        "negated but transposed": shear3(ex.kind, -ex.a, -ex.b).T,
        "reciprocal": shear3(ex.kind, 1 / ex.a, 1 / ex.b),
    }


def shear_image(ex):
    driver, first, second = SHEAR_LAYOUT[ex.kind]
    p = np.asarray(ex.p, dtype=float)
    image = p.copy()
    image[first] += ex.a * p[driver]
    image[second] += ex.b * p[driver]
    return image, {
        "transposed": hom(shear3(ex.kind, ex.a, ex.b).T, p),
        "opposite shear": hom(shear3(ex.kind, -ex.a, -ex.b), p),
    }


def sheared_box_volume(ex):
    box = ex.w * ex.h * ex.l
    M = np.diag([ex.sx, ex.sy, ex.sz]) @ shear3(ex.kind, ex.a, ex.b)[:3, :3]
    edges = M @ np.diag([ex.w, ex.h, ex.l])
    return box * abs(ex.sx * ex.sy * ex.sz), {
        "edge lengths": float(np.prod(np.linalg.norm(edges, axis=0))),
        "negative volume": box * ex.sx * ex.sy * ex.sz,
        "scaling ignored": box,
    }


def rotation_about_axis(ex):
    a, p = np.asarray(ex.a, dtype=float), np.asarray(ex.p, dtype=float)
    r = rotation(ex.u, ex.theta)
    return a + r.apply(p - a), {
        "axis through origin": r.apply(p),
        "angle sign": a + rotation(ex.u, -ex.theta).apply(p - a),
        "missing T(a)": r.apply(p - a),
        "missing T(-a)": r.apply(p) + a,
        "degrees": a + rotation(ex.u, ex.theta_deg).apply(p - a),
    }


def quaternion_from_axis_angle(ex):
    n = np.asarray(ex.axis) / np.linalg.norm(ex.axis)
    h, hd = ex.theta / 2, ex.theta_deg / 2
    right = quat_of(rotation(ex.axis, ex.theta))
    return right, {
        "axis not normalized": np.r_[math.cos(h), math.sin(h) * np.asarray(ex.axis)],
        "full angle": np.r_[math.cos(ex.theta), math.sin(ex.theta) * n],
        "scalar last": scalar_last(right),
        "degrees": np.r_[math.cos(hd), math.sin(hd) * n],
        "sin and cos swapped": np.r_[math.sin(h), math.cos(h) * n],
        "conjugate": quat_of(rotation(ex.axis, -ex.theta)),        # the rotation by -theta
    }


def quaternion_product(ex):
    right = hamilton(ex.q1, ex.q2)
    s1, v1, s2, v2 = ex.q1[0], np.asarray(ex.q1[1:]), ex.q2[0], np.asarray(ex.q2[1:])
    return right, {
        "wrong order": hamilton(ex.q2, ex.q1),
        "component-wise": np.asarray(ex.q1) * np.asarray(ex.q2),
        "scalar last": scalar_last(right),
        "scalar sign": np.r_[s1 * s2 + v1 @ v2, right[1:]],
    }


def rotate_with_quaternion(ex):
    p = np.asarray(ex.p, dtype=float)
    r = rotation(ex.axis, ex.theta)
    h = ex.theta / 2
    # with the raw axis, q = (cos h, sin h u) has length^2 = cos^2 h + sin^2 h |u|^2 and
    # q p q-bar = |q|^2 (rotation of q / |q|) p; q / |q| turns by a different angle
    raw = np.r_[math.cos(h), math.sin(h) * np.asarray(ex.axis)]
    s, v = math.cos(h), math.sin(h) * np.asarray(ex.axis) / np.linalg.norm(ex.axis)
    return r.apply(p), {
        "other way": rotation(ex.axis, -ex.theta).apply(p),
        "full angle": rotation(ex.axis, 2 * ex.theta).apply(p),
        "axis not normalized": (raw @ raw) * Rotation.from_quat(raw, scalar_first=True).apply(p),
        "missing conjugate": s * p + np.cross(v, p),
        "degrees": rotation(ex.axis, ex.theta_deg).apply(p),
    }


def quaternion_to_matrix(ex):
    right = Rotation.from_quat(ex.q, scalar_first=True).as_matrix()
    y = ex.q[2]
    printed = right.copy()
    printed[0, 0] = 1 - 2 * y ** 2
    return right, {
        "compendium top-left": printed,
        "transposed": right.T,
        "factor 2 missing": (np.eye(3) + right) / 2,
    }


def matrix_to_quaternion(ex):
    right = quat_of(Rotation.from_matrix(ex.R))
    mistakes = {
        "conjugate": right * np.array([1, -1, -1, -1]),
        "scalar last": scalar_last(right),
    }
    if abs(right[0]) > 1e-9:
        mistakes["divided by 2s"] = np.r_[right[0], 2 * right[1:]]
    return right, mistakes


def axis_angle_of_matrix(ex):
    rotvec = Rotation.from_matrix(ex.R).as_rotvec()
    angle = float(np.linalg.norm(rotvec))
    axis = rotvec / angle
    return (axis, angle), {
        "degrees": (axis, math.degrees(angle)),
        "opposite rotation": (-axis, angle),
        "not normalized": (3 * axis, angle),
    }


def compose_rotations(ex):
    r1, r2 = rotation(ex.axis1, ex.theta1), rotation(ex.axis2, ex.theta2)
    right = quat_of(r2 * r1)            # scipy: r2 * r1 applies r1 first
    doubled = rotation(ex.axis2, 2 * ex.theta2) * rotation(ex.axis1, 2 * ex.theta1)
    mistakes = {
        "wrong order": quat_of(r1 * r2),
        "scalar last": scalar_last(right),
        "full angle": quat_of(doubled),
        "degrees": quat_of(rotation(ex.axis2, ex.theta2_deg) * rotation(ex.axis1, ex.theta1_deg)),
    }
    if 180 not in (ex.theta1_deg, ex.theta2_deg):
        # both factors conjugated: the inverses of r1 and r2, in the right order (with a half
        # turn that is the rotation of the wrong order, diagnosed as such)
        mistakes["conjugate"] = quat_of(r2.inv() * r1.inv())
        assert gap(mistakes["conjugate"], mistakes["wrong order"], sign_free=True) > 0.05
    else:
        assert gap(quat_of(r2.inv() * r1.inv()), mistakes["wrong order"], sign_free=True) < 1e-9
    return right, mistakes


def slerp_midpoint(ex):
    pair = Rotation.from_quat(np.stack([ex.q0, ex.q1]), scalar_first=True)
    right = quat_of(Slerp([0.0, 1.0], pair)([0.5])[0])
    near = ex.q1 if ex.q0 @ ex.q1 >= 0 else -ex.q1
    mistakes = {"not normalized": (ex.q0 + near) / 2}
    if ex.q0 @ ex.q1 < 0:
        plain = ex.q0 + ex.q1
        mistakes["longer arc"] = plain / np.linalg.norm(plain)
    return right, mistakes


MATRIX_GARBAGE = ["M", {"a": 1}, [[1, 2], [3]], [1, 2, 3], [[1, "a"], [0, 1]],
                  [[math.nan] * 3] * 3, 3 + 2j]
VECTOR_GARBAGE = ["p", {"x": 1}, [[1, 2], [3]], [1, 2], np.eye(3), [math.inf, 0, 0], [..., 1]]
POINT_GARBAGE = VECTOR_GARBAGE + [[1, 2, 3, 0], [1, 2, 3, 2], [True, 0, 0], [[1], [2], [True]],
                                  np.array([1, 0, 1], dtype=bool), [1, 2, 3, True]]
QUATERNION_GARBAGE = ["q", {"s": 1}, [[1, 2], [3, 4, 5]], [1, 2, 3], np.eye(4),
                      [math.nan] * 4, (1, 2, 3, "z")]
NUMBER_GARBAGE = ["v", {"v": 1}, [1, 2], [[1], [2, 3]], math.nan]
AXIS_ANGLE_GARBAGE = ["n", {"axis": [1, 0, 0]}, [1, 2, 3], ([1, 0, 0],), ([1, 2], 0.5),
                      ([1, 0, 0], [1, 2]), ([0, 0, 0], 1.0), ("x", 1.0), ([1, 0, 0], "pi"),
                      ([1, 0, 0], 0.5, 2)]

# class name: (independent answer and mistakes, answer form)
SPECS = {
    "ComposeMatrix2D": (compose2d, "matrix"),
    "RotateAboutPoint": (rotate_about_point, "matrix"),
    "InverseOfComposite": (inverse_of_composite, "matrix"),
    "MirrorAboutLine": (mirror_about_line, "matrix"),
    "ShearInverse": (shear_inverse, "matrix"),
    "ShearImage": (shear_image, "point"),
    "ShearedBoxVolume": (sheared_box_volume, "number"),
    "RotationAboutArbitraryAxis": (rotation_about_axis, "point"),
    "QuaternionFromAxisAngle": (quaternion_from_axis_angle, "quaternion"),
    "QuaternionProduct": (quaternion_product, "vector"),
    "RotatePointWithQuaternion": (rotate_with_quaternion, "point"),
    "QuaternionToMatrix": (quaternion_to_matrix, "matrix"),
    "MatrixToQuaternion": (matrix_to_quaternion, "quaternion"),
    "AxisAngleOfMatrix": (axis_angle_of_matrix, "axis-angle"),
    "ComposeRotationsWithQuaternions": (compose_rotations, "quaternion"),
    "SlerpMidpoint": (slerp_midpoint, "quaternion"),
}
GARBAGE = {"matrix": MATRIX_GARBAGE, "vector": VECTOR_GARBAGE, "point": POINT_GARBAGE,
           "number": NUMBER_GARBAGE, "quaternion": QUATERNION_GARBAGE,
           "axis-angle": AXIS_ANGLE_GARBAGE}
#: The exercises whose answer is a list of numbers (a point, a vector, a quaternion).
LISTS = [name for name, (_, form) in SPECS.items() if form in ("point", "vector", "quaternion")]


#: This file tests the chapter's older topics (SPECS); tests/test_exercises_ch03_*.py the others,
#: and test_every_exercise_is_tested_in_one_file holds the union to the chapter's list.
TOPIC = harness.topic(ch03, SPECS)
exercises = harness.variants(TOPIC)


def rounded(answer, decimals=3):
    if isinstance(answer, tuple):
        return tuple(rounded(part, decimals) for part in answer)
    return np.round(answer, decimals)


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(
    TOPIC, SPECS, GARBAGE, exercises, at_least=10, distinct=None, words=r"nan|inf",
    clean=lambda text: text.replace("infinity", "").lower(), newlines=r"\\neq", odd=None))


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        for answer in (right, rounded(right)):
            fb = ex.check(answer)
            assert fb.status == "correct", (ex, fb)
            assert bool(fb)
        if form in ("matrix", "vector", "quaternion", "point"):
            assert ex.check(np.asarray(right).tolist()).status == "correct"


@pytest.mark.parametrize("name", [n for n, (_, form) in SPECS.items() if form == "quaternion"])
def test_both_signs_of_a_quaternion_are_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        assert ex.check(right).status == "correct"
        assert ex.check(-right).status == "correct", ex


def test_axis_angle_accepts_every_description_of_the_rotation():
    for ex in exercises("AxisAngleOfMatrix"):
        (axis, angle), _ = axis_angle_of_matrix(ex)
        for answer in [(-axis, -angle), (axis, angle + 2 * math.pi), (-axis, 2 * math.pi - angle),
                       (list(axis), float(angle)), [axis, angle], (axis.reshape(3, 1), angle),
                       (axis.reshape(1, 3).tolist(), np.array([[angle]]))]:
            assert ex.check(answer).status == "correct", (ex, answer)


def test_homogeneous_4x4_rotation_is_accepted():
    for ex in exercises("QuaternionToMatrix", range(50)):
        right, _ = quaternion_to_matrix(ex)
        big = np.eye(4)
        big[:3, :3] = right
        assert ex.check(big).status == "correct"


@pytest.mark.parametrize("name", SPECS)
def test_mistakes_are_diagnosed(name):
    solve, form = SPECS[name]
    sign_free = form == "quaternion"
    diagnosed = {}
    for ex in exercises(name):
        right, mistakes = solve(ex)
        for key, value in mistakes.items():
            fb = ex.check(value)
            if form == "axis-angle":
                coincide = False
            else:
                coincide = gap(value, right, sign_free) < 1e-9
            if coincide:            # in this variant the slip happens to give the right answer
                assert fb.status == "correct", (ex, key, fb)
                continue
            assert fb.status == "wrong", (ex, key, fb)
            assert fb.diagnosis == key, (ex, key, fb.diagnosis, fb.message)
            assert len(fb.message) > 40
            diagnosed[key] = diagnosed.get(key, 0) + 1
            if sign_free:
                assert ex.check(-np.asarray(value)).diagnosis == key, (ex, key)
    keys = set().union(*(solve(ex)[1] for ex in exercises(name, range(30))))
    for key in keys:
        assert diagnosed.get(key, 0) >= MIN_DIAGNOSED, (key, diagnosed)


def test_half_turns_occur_and_nan_is_explained():
    half_turns = [ex for ex in exercises("MatrixToQuaternion")
                  if abs(quat_of(Rotation.from_matrix(ex.R))[0]) < 1e-9]
    assert 30 <= len(half_turns) <= 120
    for ex in half_turns:
        assert np.allclose(ex.R, ex.R.T)            # a turn by 180 degrees is symmetric
        fb = ex.check([math.nan, math.nan, math.nan, math.nan])
        assert fb.status == "invalid" and fb.diagnosis == "division by zero"


def test_slerp_variants_need_the_shorter_arc_sometimes():
    dots = [ex.q0 @ ex.q1 for ex in exercises("SlerpMidpoint")]
    assert sum(d < 0 for d in dots) >= 40 and sum(d > 0 for d in dots) >= 40


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("ComposeMatrix2D"):
        assert ex.theta_deg % 15 == 0 and math.isclose(ex.theta, math.radians(ex.theta_deg))
        assert np.all(np.asarray(ex.d) == np.round(ex.d))
    for ex in exercises("QuaternionFromAxisAngle"):
        length = np.linalg.norm(ex.axis)
        assert length == round(length) and length > 1          # a whole length, not unit
    for ex in exercises("MatrixToQuaternion"):
        denominators = [k * k for k in range(1, 11)]
        assert any(np.allclose(ex.R * n2, np.round(ex.R * n2)) for n2 in denominators)


# ---------------------------------------------------------------------------------------------
# Shapes, True and False, rounding, variety
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", [n for n in LISTS if SPECS[n][1] == "point"])
def test_a_point_reads_the_same_in_every_form(name):
    for ex in exercises(name, range(40)):
        right, _ = SPECS[name][0](ex)
        right = np.asarray(right, dtype=float)
        homogeneous = np.append(right, 1.0)
        for answer in (right, list(right), right.reshape(3, 1), right.reshape(1, 3),
                       [[v] for v in right], homogeneous, homogeneous.reshape(4, 1),
                       [list(homogeneous)], tuple(right)):
            assert ex.check(answer).status == "correct", (ex, answer)


@pytest.mark.parametrize("name", LISTS)
def test_a_column_is_read_as_the_vector_it_is(name):
    for ex in exercises(name, range(40)):
        right, _ = SPECS[name][0](ex)
        column = np.asarray(right, dtype=float).reshape(-1, 1)
        assert ex.check(column).status == "correct", ex
        assert ex.check(column.tolist()).status == "correct", ex


@pytest.mark.parametrize("name", SPECS)
def test_true_and_false_are_no_numbers(name):
    solve, form = SPECS[name]
    for ex in exercises(name, range(10)):
        right, _ = solve(ex)
        if form == "axis-angle":
            axis, angle = right
            odd = [(axis, True), ([True, False, False], angle), (np.ones(3, dtype=bool), angle)]
        else:
            flat = np.asarray(right, dtype=float)
            odd = [True, False, np.ones(flat.shape, dtype=bool),
                   np.where(flat > 0, True, False).tolist()]
        for answer in odd:
            fb = ex.check(answer)
            assert fb.status == "invalid" and fb.diagnosis == "not a number", (ex, answer, fb)


@pytest.mark.parametrize("name", LISTS + ["AxisAngleOfMatrix"])
def test_an_answer_rounded_to_2_decimals_is_right_or_called_rounded(name):
    """Never "wrong length", "not normalized" or "components differ" for a mere rounding."""
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        fb = ex.check(rounded(right, 2))
        assert fb.status == "correct" or fb.diagnosis == "rounded", (ex, rounded(right, 2), fb)


#: A fresh seed is a fresh exercise: among 300 seeds every exercise has at least this many
#: different right answers (computed by the independent solvers). The fewest is 82, for
#: ComposeRotationsWithQuaternions, which has at most 6 x 5 x 5 = 150 (two coordinate axes, two
#: angles of five).
MIN_VARIANTS = 80


@pytest.mark.parametrize("name", SPECS)
def test_a_fresh_seed_is_a_fresh_exercise(name):
    cls, (solve, _) = getattr(ch03, name), SPECS[name]
    answers = {harness.answer_key(solve(cls(seed=seed))[0]) for seed in range(300)}
    assert len(answers) >= MIN_VARIANTS, (name, len(answers))


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch03, SPECS, at_least=10)
