"""Tests of the chapter 18 exercises (course_lib.exercises.ch18).

For every exercise and many seeds: the statement reads, the right answer is accepted (in its
equivalent forms), placeholders are "unanswered", garbage is "invalid", and every anticipated
mistake, rebuilt here from the question's attributes, is named by its diagnosis. The right
answers are computed here independently of the checkers: marching-squares crossings with
scikit-image's ``find_contours``, triangle counts with scikit-image's ``marching_cubes`` (and
its mesh's connected parts for the number of polygons), the case index, the saddle rule, the
compositing, the opacity correction, the projection and the integration steps by the formulas
typed out below (checked against scipy's matrix exponential and the closed form of Euler's
drift), never with the course_lib function the checker calls.
"""
import math

import numpy as np
import pytest
from scipy.linalg import expm
from skimage.measure import find_contours, marching_cubes

from course_lib.exercises import ch18
import exercise_harness as harness
from exercise_harness import SAME, Either, gap


#: Corner k of a cube as (x, y, z), typed out (the textbook numbering of the statement).
CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def unordered_gap(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return math.inf
    return min(gap(a, b), gap(a, b[::-1]))


# ---------------------------------------------------------------------------------------------
# Independent answers and slips
# ---------------------------------------------------------------------------------------------

def case_index(ex):
    f, c = list(ex.corners), ex.level
    bit = [1 if v >= c else 0 for v in f]
    right = bit[0] + 2 * bit[1] + 4 * bit[2] + 8 * bit[3]
    strict = [1 if v > c else 0 for v in f]
    mistakes = {
        "below counted": sum((1 - b) << k for k, b in enumerate(bit)),
        "clockwise": bit[0] + 2 * bit[3] + 4 * bit[2] + 8 * bit[1],
        "strict": sum(b << k for k, b in enumerate(strict)),
    }
    reversed_bits = 8 * bit[0] + 4 * bit[1] + 2 * bit[2] + bit[3]
    if reversed_bits != mistakes["below counted"]:      # else "below counted" names both
        mistakes["reversed bits"] = reversed_bits
    return right, mistakes


def cell_points(ex, t_of):
    f, c = list(ex.corners), ex.level
    pos = [np.array(p, dtype=float) + ex.cell for p in ((0, 0), (1, 0), (1, 1), (0, 1))]
    points = []
    for e in range(4):
        f0, f1 = f[e], f[(e + 1) % 4]
        if (f0 >= c) != (f1 >= c):
            points.append(pos[e] + t_of(f0, f1) * (pos[(e + 1) % 4] - pos[e]))
    return np.array(points)


def square_crossings(ex):
    f, c = ex.corners, ex.level
    field = np.array([[f[0], f[1]], [f[3], f[2]]])                 # rows are y
    [contour] = find_contours(field, c)
    right = contour[:, ::-1] + ex.cell                             # (row, col) -> (x, y)
    assert len(right) == 2
    return right, {
        "midpoints": cell_points(ex, lambda f0, f1: 0.5),
        "wrong end": cell_points(ex, lambda f0, f1: (f1 - c) / (f1 - f0)),
        "divided by f1": cell_points(ex, lambda f0, f1: (c - f0) / f1),
    }


def saddle(ex):
    f, c = list(ex.corners), ex.level
    centre = sum(f) / 4
    above = [k for k in range(4) if f[k] >= c]
    below = [k for k in range(4) if f[k] < c]
    # corner k lies between edges k - 1 and k: cutting it off joins those two edges
    cut = below if centre >= c else above
    right = {frozenset(((k - 1) % 4, k)) for k in cut}
    other = {frozenset(((k - 1) % 4, k)) for k in (above if centre >= c else below)}
    return right, {"other resolution": other,
                   "crossing": {frozenset((0, 2)), frozenset((1, 3))}}


def cube_volume(above):
    vol = np.zeros((2, 2, 2))
    for k in above:
        x, y, z = CORNERS[k]
        vol[z, y, x] = 1.0
    return vol


def components(faces):
    parent = {}

    def find(a):
        parent.setdefault(a, a)
        while parent[a] != a:
            a = parent[a]
        return a

    for tri in faces:
        for a, b in zip(tri, tri[1:]):
            parent[find(int(a))] = find(int(b))
    return len({find(int(v)) for v in np.unique(faces)})


def triangle_count(ex):
    _, faces, _, _ = marching_cubes(cube_volume(ex.above), 0.5)
    right = len(faces)
    above = set(ex.above)
    edges = sum((a in above) != (b in above) for a in range(8) for b in range(a + 1, 8)
                if sum(abs(p - q) for p, q in zip(CORNERS[a], CORNERS[b])) == 1)
    return right, {
        "vertices": edges,
        "one polygon": edges - 2,
        "corners": len(ex.above),
        "one per polygon": components(faces),
    }


def front_to_back(colors, alphas):
    C = A = 0.0
    for c, a in zip(colors, alphas):
        C += (1 - A) * a * c
        A += (1 - A) * a
    return C, A


def back_to_front(colors, alphas):
    C = A = 0.0
    for c, a in zip(reversed(colors), reversed(alphas)):
        C = a * c + (1 - a) * C
        A = a + (1 - a) * A
    return C, A


def composite(ex):
    c, a = list(ex.colors), list(ex.alphas)
    right = np.array(front_to_back(c, a))
    assert gap(right, back_to_front(c, a)) < 1e-12                 # both orders agree
    C = A = 0.0
    for ci, ai in zip(c, a):
        C, A = C + (1 - A) * ci, A + (1 - A) * ai
    return right, {
        "back first": np.array(front_to_back(c[::-1], a[::-1])),
        "alpha forgotten": np.array([C, A]),
        "no transparency": np.array([sum(x * y for x, y in zip(c, a)), sum(a)]),
    }


def early_termination(ex):
    transparency, right = 1.0, None
    for k, a in enumerate(ex.alphas, start=1):
        transparency *= 1 - a                                      # A = 1 - prod(1 - alpha)
        if 1 - transparency >= ex.threshold - 1e-12:
            right = k
            break
    total, summed = 0.0, None
    for k, a in enumerate(ex.alphas, start=1):
        total += a
        if total >= ex.threshold - 1e-12:
            summed = k
            break
    return right, {"summed opacities": summed, "off by one": Either([right - 1, right + 1])}


def opacity_correction(ex):
    a, d = ex.alpha, ex.step
    right = 1 - (1 - a) ** d
    if d == 2:                                  # two unit slabs in a row, composited
        assert math.isclose(right, front_to_back([1, 1], [a, a])[1])
    return right, {"linear": a * d, "power of alpha": a ** d, "transparency": (1 - a) ** d,
                   "inverse step": 1 - (1 - a) ** (1 / d)}


def projection(volume, axis, reduce):
    out = np.zeros((3, 3))
    for r in range(3):
        for s in range(3):
            index = [r, s]
            index.insert(axis, slice(None))
            out[r, s] = reduce(list(volume[tuple(index)]))
    return out


def mip(ex):
    v, ax = ex.volume, ex.axis
    return projection(v, ax, max), {
        "wrong axis": Either([projection(v, other, max) for other in range(3) if other != ax]),
        "sum": projection(v, ax, sum),
        "mean": projection(v, ax, lambda xs: sum(xs) / len(xs)),
        "min": projection(v, ax, min),
    }


def rk4(ex):
    M, p, h = np.asarray(ex.M), np.asarray(ex.p), ex.h

    def v(q):
        return np.array([M[0, 0] * q[0] + M[0, 1] * q[1], M[1, 0] * q[0] + M[1, 1] * q[1]])

    k1 = v(p)
    k2 = v(p + h / 2 * k1)
    k3 = v(p + h / 2 * k2)
    k4 = v(p + h * k3)
    right = p + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    # for a linear field RK4 is the Taylor series of exp(hM) up to h^4
    taylor = sum(np.linalg.matrix_power(h * M, k) / math.factorial(k) for k in range(5)) @ p
    assert gap(right, taylor) < 1e-9
    # and for a small step it is far closer to the exact flow exp(hM) p than Euler's step
    small = h / 20
    t1 = v(p)
    t2 = v(p + small / 2 * t1)
    t3 = v(p + small / 2 * t2)
    t4 = v(p + small * t3)
    exact = expm(small * M) @ p
    assert np.linalg.norm(p + small / 6 * (t1 + 2 * t2 + 2 * t3 + t4) - exact) <= \
        1e-3 * np.linalg.norm(p + small * t1 - exact) + 1e-13
    f2 = v(p + h * k1)
    f3 = v(p + h * f2)
    f4 = v(p + h * f3)
    return right, {
        "euler": p + h * k1,
        "rk2": p + h * k2,
        "equal weights": p + h / 4 * (k1 + k2 + k3 + k4),
        "full steps": p + h / 6 * (k1 + 2 * f2 + 2 * f3 + f4),
        "no h": p + (k1 + 2 * k2 + 2 * k3 + k4) / 6,
    }


def euler_drift(ex):
    x, y = ex.r0, 0.0
    for _ in range(ex.n):
        x, y = x - ex.h * y, y + ex.h * x
    right = math.hypot(x, y)
    assert math.isclose(right, ex.r0 * (1 + ex.h ** 2) ** (ex.n / 2))
    r, h, n = ex.r0, ex.h, ex.n
    return right, {"no drift": r, "one step": r * math.sqrt(1 + h * h),
                   "no root": r * (1 + h * h) ** n, "radial step": r * (1 + h) ** n}


NUMBER_GARBAGE = ["7", {"x": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]
POINTS_GARBAGE = ["p", {"x": 1}, [[1, 2], [3]], [1, 2], np.eye(3), [[1, 2], [3, math.nan]],
                  [[1, 2], [3, 4], [5, 6]]]
PAIRS_GARBAGE = ["(0, 1)", {"a": 1}, [(0, 1)], [(0, 1), (1, 2)], [(0, 1), (2, 4)],
                 [(0.5, 1), (2, 3)], [(0, 0), (2, 3)], [(0, 1, 2), (3, 0, 1)], 5]
VECTOR_GARBAGE = ["v", {"v": 1}, [[1, 2], [3]], [1] * 9, [[1, 2], [3, 4], [5, 6]],
                  [[math.nan]]]
POINT_GARBAGE = ["p", {"x": 1}, [[1, 2], [3]], [1, 2, 3, 4], np.eye(3), [math.inf, 0],
                 [1, 2, 0], [math.nan, 1]]
MATRIX_GARBAGE = ["M", {"m": 1}, [[1, 2], [3]], np.eye(2), np.ones((3, 3, 3)),
                  [[math.nan] * 3] * 3]

SPECS = {
    "SquareCaseIndex": (case_index, "number"),
    "SquareCrossings": (square_crossings, "points"),
    "SaddleResolution": (saddle, "pairs"),
    "CubeTriangleCount": (triangle_count, "number"),
    "CompositeFrontToBack": (composite, "vector"),
    "EarlyTermination": (early_termination, "number"),
    "OpacityCorrection": (opacity_correction, "number"),
    "MaxIntensityProjection": (mip, "matrix"),
    "RK4Step": (rk4, "point"),
    "EulerDrift": (euler_drift, "number"),
}
GARBAGE = {"number": NUMBER_GARBAGE, "points": POINTS_GARBAGE, "pairs": PAIRS_GARBAGE,
           "vector": VECTOR_GARBAGE, "point": POINT_GARBAGE, "matrix": MATRIX_GARBAGE}


#: This file tests the chapter's older topics (SPECS); tests/test_exercises_ch18_*.py the others,
#: and test_every_exercise_is_tested_in_one_file holds the union to the chapter's list.
TOPIC = harness.topic(ch18, SPECS)
exercises = harness.variants(TOPIC)


def as_answer(value, form):
    if form == "pairs":
        return [sorted(p) for p in value]
    return value


def same(a, b, form):
    if form == "pairs":
        return a == b
    if form == "points":
        return unordered_gap(a, b) < SAME
    return gap(a, b) < SAME


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(
    TOPIC, SPECS, GARBAGE, exercises, at_least=8,
    odd=harness.ODD + harness.EMPTY_ODD + [[[..., 1], [2, 3]]]))
test_mistakes_are_diagnosed = harness.mistakes_test(
    SPECS, exercises, same, as_answer=as_answer)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "pairs":
            pairs = [sorted(p) for p in right]
            answers = [pairs, pairs[::-1], [p[::-1] for p in pairs], tuple(map(tuple, pairs)),
                       np.array(pairs)]
        elif form == "points":
            answers = [right, right[::-1], np.round(right, 4).tolist()]
        elif form == "number":
            answers = [right, round(right, 4), np.float64(right)]
        else:
            answers = [right, np.round(right, 4), np.asarray(right).tolist()]
        if form == "point":
            answers.append(np.append(right, 1.0))                  # homogeneous with w = 1
        harness.assert_accepted(ex, answers)


def test_wrong_answers_get_teaching_feedback():
    """An answer no slip explains still says how to get it right."""
    for name in ("CompositeFrontToBack", "RK4Step", "MaxIntensityProjection",
                 "OpacityCorrection", "EulerDrift", "SquareCaseIndex"):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(np.asarray(right) + 0.37 + 0.05 * np.abs(right))
            assert fb.status == "wrong" and len(fb.message) > 80, (ex, fb)
    for ex in exercises("SquareCrossings", range(20)):
        right, _ = square_crossings(ex)
        fb = ex.check(right + [[0.0, 0.0], [0.37, 0.37]])
        assert fb.status == "wrong" and "1 of your 2 points is right" in fb.message


def test_questions_are_well_posed():
    for ex in exercises("SaddleResolution"):
        f, c = ex.corners, ex.level
        above = [k for k in range(4) if f[k] >= c]
        assert above in ([0, 2], [1, 3])                          # a saddle
        assert abs(sum(f) / 4 - c) >= 0.25                          # the decider is clear
    for ex in exercises("SquareCrossings"):
        assert (ex.corners != ex.level).all()
    for ex in exercises("CubeTriangleCount"):
        assert 1 <= len(ex.above) <= 7
        vol = cube_volume(ex.above)
        for face in (vol[0], vol[1], vol[:, 0], vol[:, 1], vol[:, :, 0], vol[:, :, 1]):
            assert not (face[0, 0] == face[1, 1] != face[0, 1] == face[1, 0])   # no saddle face
    counts = {triangle_count(ex)[0] for ex in exercises("CubeTriangleCount")}
    assert counts == {1, 2, 3, 4}
    for ex in exercises("EarlyTermination"):
        assert 3 <= early_termination(ex)[0] <= 9
    assert {ex.axis for ex in exercises("MaxIntensityProjection")} == {0, 1, 2}


# ---------------------------------------------------------------------------------------------
# The tolerance policy, whole numbers, boundary variants and variety
# ---------------------------------------------------------------------------------------------

#: The exercises whose answer is a whole number (a case index, a count), compared exactly.
WHOLE = ("SquareCaseIndex", "CubeTriangleCount", "EarlyTermination")
#: The exercises whose answer is real numbers.
REAL = ("SquareCrossings", "CompositeFrontToBack", "OpacityCorrection", "MaxIntensityProjection",
        "RK4Step", "EulerDrift")
#: Seeds for the shares and the variety.
MANY = range(300)
#: Among 300 seeds every exercise has at least this many variants: distinct right answers, or
#: distinct statements where the answer is one of a few choices (WHOLE, SaddleResolution).
MIN_VARIANTS = 30


@pytest.mark.parametrize("name", REAL)
def test_right_answer_to_3_significant_digits_is_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        typed = np.vectorize(harness.significant)(np.asarray(right, dtype=float))
        answer = float(typed) if typed.ndim == 0 else typed.tolist()
        fb = ex.check(answer)
        assert fb.status == "correct", (ex, right, answer, fb)


def test_crossings_rounded_too_far_are_close_not_wrong():
    for ex in exercises("SquareCrossings", range(40)):
        right, mistakes = square_crossings(ex)
        coarse = np.vectorize(lambda x: harness.significant(x, 2))(right)
        if unordered_gap(coarse, right) > 0.01 and not any(
                unordered_gap(coarse, m) < SAME for m in mistakes.values()):
            assert ex.check(coarse.tolist()).diagnosis == "rounded", ex


@pytest.mark.parametrize("name", WHOLE)
def test_whole_answers_are_compared_exactly(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, mistakes = solve(ex)
        assert ex.check(float(right)).status == "correct"                 # 3.0 is 3
        assert ex.check(right + 0.4).status == "wrong"                    # no tolerance
        slips = {v for values in mistakes.values()
                 for v in (values if isinstance(values, Either) else [values])}
        for wrong in (right - 1, right + 1):
            fb = ex.check(wrong)
            assert fb.status == "wrong", (ex, wrong, fb)
            if wrong not in slips:
                assert fb.diagnosis == "off by one", (ex, wrong, fb)


def test_a_corner_on_the_level_is_a_labelled_variant():
    variants = [ch18.SquareCaseIndex(seed=seed) for seed in MANY]
    ties = 0
    for ex in variants:
        tied = any(f == ex.level for f in ex.corners)
        assert ex.boundary == ("corner on the level" if tied else None), ex
        assert r"f_k \ge c" in ex.statement()
        if tied:
            ties += 1
            assert any("exactly on the level" in step and "above" in step
                       for step in ex.worked().steps)
            right, mistakes = case_index(ex)
            assert mistakes["strict"] != right                     # the slip shows here
            assert ex.check(mistakes["strict"]).status == "wrong"
    assert 0.10 <= ties / len(MANY) <= 0.20, ties


def test_both_saddle_resolutions_come_up_evenly_with_varied_numbers():
    variants = [ch18.SaddleResolution(seed=seed) for seed in MANY]
    joined_above = sum(sum(ex.corners) / 4 >= ex.level for ex in variants)
    assert 0.4 <= joined_above / len(MANY) <= 0.6, joined_above
    assert len({ex.level for ex in variants}) >= 5
    assert len({(tuple(ex.corners), ex.level) for ex in variants}) >= 200


@pytest.mark.parametrize("name", SPECS)
def test_variants_are_many(name):
    cls = getattr(ch18, name)
    variants = [cls(seed=seed) for seed in MANY]
    solve, form = SPECS[name]
    if name in WHOLE or form == "pairs":            # the answer is one of a few choices
        count = len({ex.statement() for ex in variants})
    else:
        count = len({harness.answer_key(solve(ex)[0]) for ex in variants})
    assert count >= MIN_VARIANTS, (name, count)


def test_the_choices_all_come_up():
    assert {case_index(ch18.SquareCaseIndex(seed=seed))[0] for seed in MANY} == set(range(1, 15))
    assert len({early_termination(ch18.EarlyTermination(seed=seed))[0] for seed in MANY}) >= 5


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch18, SPECS, at_least=8)
