"""Tests of the chapter 4 exercises (course_lib.exercises.ch04).

For every exercise and many seeds: the statement reads, the right answer (computed here
independently: PyGLM's lookAt, perspective, frustum and ortho, which are column-major and in
single precision, or closed forms typed out below, never the course_lib function the checker
calls) is accepted, placeholders are "unanswered", garbage is "invalid", and every anticipated
mistake, rebuilt here from the question's attributes, is named by its diagnosis.
"""
import math

import numpy as np
import pytest

from course_lib.exercises import ch04
import exercise_harness as harness
from exercise_harness import MIN_DIAGNOSED, Either

try:
    from pyglm import glm            # PyGLM >= 2.8 (plain `import glm` is being deprecated)
except ImportError:                  # pragma: no cover - older PyGLM
    import glm

#: PyGLM computes in single precision: values closer than this are "the same".
SAME = 1e-5


# ---------------------------------------------------------------------------------------------
# Independent closed forms
# ---------------------------------------------------------------------------------------------

def rows(m):
    """A PyGLM matrix (column-major) as a numpy array of rows."""
    return np.array(m.to_list(), dtype=float).T


def glm_look_at(eye, gaze, up):
    eye, gaze, up = (glm.dvec3(*map(float, v)) for v in (eye, gaze, up))
    return rows(glm.lookAt(eye, eye + gaze, up))


def hom(m, p):
    """m applied to the point p with the homogeneous divide."""
    q = np.asarray(m, dtype=float) @ np.append(np.asarray(p, dtype=float), 1.0)
    return q[:-1] / q[-1]


def affine(rotation, translation):
    m = np.eye(4)
    m[:3, :3] = rotation
    m[:3, 3] = translation
    return m


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def perspective_by_hand(t, r, n, f):
    """The OpenGL perspective matrix of the window [-r, r] x [-t, t] on the near plane."""
    return np.array([[n / r, 0, 0, 0], [0, n / t, 0, 0],
                     [0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)], [0, 0, -1, 0]])


def gap(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.abs(a - b).max())


def projective_gap(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    k = int(np.argmax(np.abs(b)))
    return gap(a, a.flat[k] / b.flat[k] * b)


# ---------------------------------------------------------------------------------------------
# Per exercise: the expected answer and the anticipated mistakes, from the attributes
# ---------------------------------------------------------------------------------------------

def simple_perspective_point(ex):
    x, y, z = ex.p
    d = ex.d
    return np.array([x * d / z, y * d / z, d]), {
        "no divide": [x * d, y * d, z * d],
        "ratio upside down": [x * z / d, y * z / d, d],
        "kept z": [x * d / z, y * d / z, z],
        # w = -z (the OpenGL camera's last row): the plane z = -d, or only x and y flipped
        "divided by -z": Either([[-x * d / z, -y * d / z, -d], [-x * d / z, -y * d / z, d]]),
    }


def eye_axes(ex):
    R = glm_look_at(ex.eye, ex.gaze, ex.up)[:3, :3]
    x, y, z = R
    raw_z = -np.asarray(ex.gaze, dtype=float)
    raw_x = np.cross(ex.up, raw_z)
    return R, {
        "z_e along gaze": [-x, y, -z],
        "up not orthogonalized": [x, unit(ex.up), z],
        "not normalized": [raw_x, np.cross(raw_z, raw_x), raw_z],
        "cross product order": [-x, -y, z],
        "transposed": R.T,
    }


def look_at(ex):
    M = glm_look_at(ex.eye, ex.gaze, ex.up)
    R, E = M[:3, :3], np.asarray(ex.eye, dtype=float)
    flipped = np.array([-R[0], R[1], -R[2]])
    raw_z = -np.asarray(ex.gaze, dtype=float)
    raw_x = np.cross(ex.up, raw_z)
    raw = np.array([raw_x, np.cross(raw_z, raw_x), raw_z])
    mistakes = {
        "wrong order": affine(R, -E),
        "translation sign": affine(R, R @ E),
        "axes in columns": affine(R.T, -R.T @ E),
        "z_e along gaze": affine(flipped, -flipped @ E),
        "not normalized": affine(raw, -raw @ E),
    }
    if np.linalg.norm(np.cross(np.asarray(ex.gaze) - E, ex.up)) > 1e-9:
        mistakes["gaze as target"] = glm_look_at(E, np.asarray(ex.gaze) - E, ex.up)
    return M, mistakes


def point_to_eye(ex):
    M = glm_look_at(ex.eye, ex.gaze, ex.up)
    R, E, p = M[:3, :3], np.asarray(ex.eye, dtype=float), np.asarray(ex.p, dtype=float)
    flipped = np.array([-R[0], R[1], -R[2]])
    return hom(M, p), {
        "not translated": R @ p,
        "translated after rotating": R @ p - E,
        "z_e along gaze": flipped @ (p - E),
        "axes in columns": R.T @ (p - E),
    }


def perspective_matrix(ex):
    n, f, a = ex.near, ex.far, ex.aspect
    right = rows(glm.perspective(math.radians(ex.fov_deg), a, n, f))
    t = n * math.tan(math.radians(ex.fov_deg) / 2)
    last = right.copy()
    last[3, 2] = 1
    t_deg = n * math.tan(ex.fov_deg / 2)
    mistakes = {
        "compendium matrix": np.array([[2 / (2 * a * t), 0, 0, 0], [0, 2 / (2 * t), 0, 0],
                                       [0, 0, 2 / (f - n), -2 * n * f / (f - n)], [0, 0, 1, 0]]),
        "near/far signs": -perspective_by_hand(t, a * t, -n, -f),   # signed n, f plugged in
        "last row sign": last,
        "degrees": perspective_by_hand(t_deg, a * t_deg, n, f),
    }
    if ex.fov_deg != 90:
        t_full = n * math.tan(math.radians(ex.fov_deg))
        mistakes["full angle"] = perspective_by_hand(t_full, a * t_full, n, f)
    if a != 1:
        mistakes["aspect inverted"] = perspective_by_hand(t, t / a, n, f)
    mistakes["near and far swapped"] = rows(glm.perspective(math.radians(ex.fov_deg), a, f, n))
    return right, mistakes


def perspective_divide(ex):
    M = rows(glm.frustum(ex.left, ex.right, ex.bottom, ex.top, ex.near, ex.far))
    assert np.allclose(M, ex.M, atol=1e-6)
    clip = M @ np.append(ex.p, 1.0)
    return clip[:3] / clip[3], {
        "no divide": clip[:3],
        "divided by z_e": -clip[:3] / clip[3],
        "depth not divided": [clip[0] / clip[3], clip[1] / clip[3], clip[2]],
    }


def css_depth(ex):
    n, f, D = ex.near, ex.far, ex.distance
    clip = rows(glm.perspective(math.radians(90), 1.0, n, f)) @ [0.0, 0.0, -D, 1.0]
    return clip[2] / clip[3], {
        "linear depth": 2 * (D - n) / (f - n) - 1,
        "reversed depth": -clip[2] / clip[3],
        "no divide": clip[2],
    }


def orthographic_matrix(ex):
    l, r, b, t, n, f = ex.left, ex.right, ex.bottom, ex.top, ex.near, ex.far
    right = rows(glm.ortho(l, r, b, t, n, f))
    positive = right.copy()
    positive[2, 2] = 2 / (f - n)
    flipped = right.copy()
    flipped[:3, 3] *= -1
    unscaled = right.copy()
    unscaled[:3, 3] = [-(l + r) / 2, -(b + t) / 2, (n + f) / 2]
    return right, {"near/far signs": positive, "translation sign": flipped,
                   "translation not scaled": unscaled,
                   "near and far swapped": rows(glm.ortho(l, r, b, t, f, n))}


def oblique(ex):
    p, dop = np.asarray(ex.p, dtype=float), np.asarray(ex.dop, dtype=float)
    image = p - p[2] / dop[2] * dop
    mistakes = {
        # moved by +z/DOP_z DOP: with z' = 0 written down, or the 2z it gives
        "shift reversed": Either([p + p[2] / dop[2] * dop * [1, 1, 0] - [0, 0, p[2]],
                                  p + p[2] / dop[2] * dop]),
        "orthographic": [p[0], p[1], 0.0],
        "kept z": [image[0], image[1], p[2]],
    }
    if abs(dop[2]) != 1:
        mistakes["not divided by DOP_z"] = [p[0] - p[2] * dop[0], p[1] - p[2] * dop[1], 0.0]
    return image, mistakes


def cavalier_cabinet(ex):
    L = {"cavalier": 1.0, "cabinet": 0.5}[ex.kind]
    assert ex.length == L
    x, y, z = ex.p
    a = math.radians(ex.alpha_deg)

    def drawn(length, angle, sign=1):
        return [x + sign * length * z * math.cos(angle), y + sign * length * z * math.sin(angle),
                0.0]

    mistakes = {
        "depth factor": drawn(1.5 - L, a),
        "receding direction reversed": drawn(L, a, -1),
        "orthographic": [x, y, 0.0],
    }
    if ex.alpha_deg != 45:
        mistakes["sin/cos swapped"] = drawn(L, math.pi / 2 - a)
    return np.array(drawn(L, a)), mistakes


def viewport_by_hand(ex, depth_scale=None, y_sign=1.0, scale=0.5, offset_sign=1.0):
    """The viewport matrix typed out, with knobs to rebuild the anticipated slips."""
    w, h, depth = ex.xmax - ex.xmin, ex.ymax - ex.ymin, ex.zmax - ex.zmin
    if depth_scale is not None:
        depth = depth_scale
    m = np.diag([w * scale, y_sign * h * scale, depth * scale, 1.0])
    m[:3, 3] = offset_sign * np.array([ex.xmax + ex.xmin, ex.ymax + ex.ymin,
                                       ex.zmax + ex.zmin]) / 2
    return m


def viewport_matrix(ex):
    return viewport_by_hand(ex), {
        "compendium depth row": viewport_by_hand(ex, depth_scale=ex.ymax - ex.ymin),
        "translation sign": viewport_by_hand(ex, offset_sign=-1.0),
        "missing halves": viewport_by_hand(ex, scale=1.0),
        "y flipped": viewport_by_hand(ex, y_sign=-1.0),
    }


def viewport_pixel(ex):
    qx, qy, qz = ex.q
    w, h = ex.xmax - ex.xmin, ex.ymax - ex.ymin
    x = ex.xmin + (qx + 1) * w / 2
    y = ex.ymin + (qy + 1) * h / 2
    z = ex.zmin + (qz + 1) * (ex.zmax - ex.zmin) / 2
    return np.array([x, y, z]), {
        "y flipped": [x, ex.ymax - (qy + 1) * h / 2, z],
        "compendium depth row": [x, y, qz * h / 2 + (ex.zmax + ex.zmin) / 2],
        "offset missing": [(qx + 1) * w / 2, (qy + 1) * h / 2, z],
        "centre shift missing": [qx * w / 2 + ex.xmin, qy * h / 2 + ex.ymin, z],
    }


def cross_ratio_by_hand(points):
    a, b, c, d = (np.asarray(p, dtype=float) for p in points)
    dist = np.linalg.norm
    return dist(c - a) * dist(d - b) / (dist(c - b) * dist(d - a))


def cross_ratio(ex):
    points = [ex.A, ex.B, ex.C, ex.D]
    images = [ex.d * np.asarray(p) / p[2] for p in points]
    a, b, c, _ = points
    r = np.linalg.norm(b - a) / np.linalg.norm(c - b)
    ia, ib, ic, _ = images
    r_after = np.linalg.norm(ib - ia) / np.linalg.norm(ic - ib)
    cr, cr_after = cross_ratio_by_hand(points), cross_ratio_by_hand(images)
    assert math.isclose(cr, cr_after, rel_tol=1e-9)
    return np.array([r, r_after, cr, cr_after]), {
        "ratio inverted": [1 / r, 1 / r_after, cr, cr_after],
        "ratio assumed preserved": [r, r, cr, cr_after],
        "cross ratio inverted": [r, r_after, 1 / cr, 1 / cr_after],
    }


def vanishing_point(ex):
    u, p0, d = np.asarray(ex.u, dtype=float), np.asarray(ex.p0, dtype=float), ex.d
    far = p0 + 1e7 * u * np.sign(u[2])              # far along the line, in front of the eye
    limit = d * far / far[2]
    right = d * u / u[2]
    assert gap(limit, right) < 1e-5
    mistakes = {"projected a point": d * p0 / p0[2], "no divide": d * u}
    if d != 1:
        mistakes["forgot d"] = u / u[2]
    if u[0] and u[1]:
        mistakes["ratio upside down"] = [d * u[2] / u[0], d * u[2] / u[1], d]
    return right, mistakes


MATRIX_GARBAGE = ["M", {"a": 1}, [[1, 2], [3]], [1, 2, 3], [[1, "a"], [0, 1]],
                  [[math.nan] * 4] * 4, np.eye(5)]
POINT_GARBAGE = ["p", {"x": 1}, [[1, 2], [3]], [1, 2], np.eye(3), [math.inf, 0, 0], [1, 2, 3, 0],
                 [True, 0, 0], [[1], [2], [True]], np.array([1, 0, 1], dtype=bool),
                 [1, 2, 3, True]]
NUMBER_GARBAGE = ["v", {"v": 1}, [1, 2], [[1], [2, 3]], math.nan]
FOUR_GARBAGE = ["r", {"r": 1}, [1, 2, 3], [[1, 2], [3, 4]], [1, 2, 3, math.nan], ("a", 1, 2, 3)]

# class name: (independent answer and mistakes, answer form)
SPECS = {
    "SimplePerspectivePoint": (simple_perspective_point, "point"),
    "EyeCoordinateAxes": (eye_axes, "matrix"),
    "LookAtMatrix": (look_at, "matrix"),
    "PointToEyeCoordinates": (point_to_eye, "point"),
    "PerspectiveMatrix": (perspective_matrix, "projective"),
    "PerspectiveDivide": (perspective_divide, "point"),
    "CssDepth": (css_depth, "number"),
    "OrthographicMatrix": (orthographic_matrix, "matrix"),
    "ObliqueProjection": (oblique, "point"),
    "CavalierCabinet": (cavalier_cabinet, "point"),
    "ViewportMatrix": (viewport_matrix, "matrix"),
    "ViewportPixel": (viewport_pixel, "point"),
    "CrossRatioUnderProjection": (cross_ratio, "four"),
    "VanishingPoint": (vanishing_point, "point"),
}
GARBAGE = {"matrix": MATRIX_GARBAGE, "projective": MATRIX_GARBAGE, "point": POINT_GARBAGE,
           "number": NUMBER_GARBAGE, "four": FOUR_GARBAGE}


#: This file tests the chapter's older topics (SPECS); tests/test_exercises_ch04_*.py the others,
#: and test_every_exercise_is_tested_in_one_file holds the union to the chapter's list.
TOPIC = harness.topic(ch04, SPECS)
exercises = harness.variants(TOPIC)


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(
    TOPIC, SPECS, GARBAGE, exercises, at_least=10, distinct=(20, 10), words=r"nan|inf",
    newlines=r"\\neq", odd=harness.ODD))


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        for answer in (right, np.round(right, 3), np.asarray(right).tolist()):
            fb = ex.check(answer)
            assert fb.status == "correct", (ex, fb)
            assert bool(fb)
        if form == "point":                                 # homogeneous with w = 1 is fine too
            assert ex.check(np.append(right, 1.0)).status == "correct"
        if form == "projective":                            # and any multiple of a projection
            assert ex.check(-2.5 * right).status == "correct"


@pytest.mark.parametrize("name", SPECS)
def test_mistakes_are_diagnosed(name):
    solve, form = SPECS[name]
    diagnosed = {}
    for ex in exercises(name):
        right, mistakes = solve(ex)
        for key, values in mistakes.items():
            for value in (values if isinstance(values, Either) else [values]):
                fb = ex.check(value)
                distance = projective_gap(value, right) if form == "projective" \
                    else gap(value, right)
                if distance < SAME:  # in this variant the slip happens to give the right answer
                    assert fb.status == "correct", (ex, key, fb)
                    continue
                assert fb.status == "wrong", (ex, key, fb)
                assert fb.diagnosis == key, (ex, key, fb.diagnosis, fb.message)
                assert len(fb.message) > 40
                diagnosed[key] = diagnosed.get(key, 0) + 1
                if form == "projective":                 # the same slip in the signed form
                    assert ex.check(-np.asarray(value)).diagnosis == key
    keys = set().union(*(solve(ex)[1] for ex in exercises(name, range(30))))
    for key in keys:
        assert diagnosed.get(key, 0) >= MIN_DIAGNOSED, (key, diagnosed)


@pytest.mark.parametrize("name", ["SimplePerspectivePoint", "PerspectiveDivide",
                                  "VanishingPoint"])
def test_homogeneous_answer_without_the_divide_is_named(name):
    for ex in exercises(name, range(50)):
        right, _ = SPECS[name][0](ex)
        w = 3.0
        fb = ex.check(np.append(w * np.asarray(right), w))
        assert (fb.status, fb.diagnosis) == ("wrong", "no divide"), (ex, fb)


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("EyeCoordinateAxes"):
        axes, _ = eye_axes(ex)
        assert any(np.allclose(axes * n, np.round(axes * n), atol=1e-5) for n in (1, 3, 5, 7))
        assert np.all(ex.gaze == np.round(ex.gaze)) and np.all(ex.up == np.round(ex.up))
        assert abs(np.dot(unit(ex.gaze), unit(ex.up))) > 0.1        # up is not perpendicular
    for ex in exercises("PerspectiveMatrix"):
        assert ex.fov_deg in (60, 90, 120)
    for ex in exercises("PerspectiveDivide"):
        right, _ = perspective_divide(ex)
        assert np.all(np.abs(right) <= 1 + 1e-9)                     # inside the view volume
        assert np.allclose(ex.M * 4, np.round(ex.M * 4))


# ---------------------------------------------------------------------------------------------
# Shapes, True and False, rounding, variety
# ---------------------------------------------------------------------------------------------

POINTS = [name for name, (_, form) in SPECS.items() if form == "point"]


@pytest.mark.parametrize("name", POINTS)
def test_a_point_reads_the_same_in_every_form(name):
    for ex in exercises(name, range(40)):
        right, _ = SPECS[name][0](ex)
        right = np.asarray(right, dtype=float)
        homogeneous = np.append(right, 1.0)
        for answer in (right, list(right), right.reshape(3, 1), right.reshape(1, 3),
                       [[v] for v in right], homogeneous, homogeneous.reshape(4, 1),
                       [list(homogeneous)], tuple(right)):
            assert ex.check(answer).status == "correct", (ex, answer)


@pytest.mark.parametrize("name", POINTS + ["CrossRatioUnderProjection"])
def test_a_column_or_a_row_is_read_as_the_vector_it_is(name):
    for ex in exercises(name, range(40)):
        right, _ = SPECS[name][0](ex)
        right = np.asarray(right, dtype=float)
        for answer in (right.reshape(-1, 1), right.reshape(1, -1), right.reshape(-1, 1).tolist()):
            assert ex.check(answer).status == "correct", (ex, answer)


@pytest.mark.parametrize("name", SPECS)
def test_true_and_false_are_no_numbers(name):
    for ex in exercises(name, range(10)):
        right, _ = SPECS[name][0](ex)
        flat = np.asarray(right, dtype=float)
        for answer in (True, False, np.ones(flat.shape, dtype=bool),
                       np.where(flat > 0, True, False).tolist()):
            fb = ex.check(answer)
            assert fb.status == "invalid" and fb.diagnosis == "not a number", (ex, answer, fb)


@pytest.mark.parametrize("name", POINTS)
def test_an_answer_rounded_to_2_decimals_is_right_or_called_rounded(name):
    """Never "wrong length", "not normalized" or "components differ" for a mere rounding."""
    for ex in exercises(name):
        right, _ = SPECS[name][0](ex)
        fb = ex.check(np.round(right, 2))
        assert fb.status == "correct" or fb.diagnosis == "rounded", (ex, np.round(right, 2), fb)


def test_pixels_given_as_whole_numbers_are_called_rounded():
    """Floored or rounded pixel coordinates are close, not of the "wrong length"."""
    told = 0
    for ex in exercises("ViewportPixel"):
        right, _ = viewport_pixel(ex)
        for whole in (np.floor, np.round, np.ceil):
            answer = np.array([whole(right[0]), whole(right[1]), right[2]])
            fb = ex.check(answer)
            assert fb.status == "correct" or fb.diagnosis == "rounded", (ex, answer, fb)
            told += fb.diagnosis == "rounded"
        fb = ex.check(np.round(right, 1))
        assert fb.status == "correct" or fb.diagnosis == "rounded", (ex, fb)
    assert told >= 20                       # some pixels are not whole (e.g. 37.5)


#: A fresh seed is a fresh exercise: among 300 seeds every exercise has at least this many
#: different right answers (computed by the independent solvers). The fewest is 88, for
#: PerspectiveMatrix, which has at most 3 x 3 x 2 x 5 = 90 (field of view, aspect, near, far).
MIN_VARIANTS = 80


@pytest.mark.parametrize("name", SPECS)
def test_a_fresh_seed_is_a_fresh_exercise(name):
    cls, (solve, _) = getattr(ch04, name), SPECS[name]
    answers = {harness.answer_key(solve(cls(seed=seed))[0]) for seed in range(300)}
    assert len(answers) >= MIN_VARIANTS, (name, len(answers))


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch04, SPECS, at_least=10)
