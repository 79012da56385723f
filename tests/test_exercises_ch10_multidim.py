"""Tests of the multidimensional-data exercises (course_lib/exercises/_ch10/multidim.py and
pca.py), on tests/exercise_harness.py.

The right answers and every anticipated slip are recomputed here independently: crossings of
parallel-coordinate lines by a double loop over the pairs of records; the point-line duality by
intersecting two of the dual lines with numpy.linalg.solve; brushes by plain Python
comparisons; the star glyph from the angle typed out here; the covariance with numpy.cov and
its eigen-decomposition with scipy.linalg.eigh (the sign convention applied here).
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest
import scipy.linalg

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch10 import multidim, pca

NAMES = ["ReadParallelCoordinates", "DualLine", "DualPoint", "BrushSelection",
         "StarGlyphVertex", "CovarianceEigen", "ProjectRecord"]
CLASSES = {n: getattr(pca if hasattr(pca, n) else multidim, n) for n in NAMES}
topic = SimpleNamespace(EXERCISES=list(CLASSES.values()), **CLASSES)


# ---------------------------------------------------------------------------------------------
# Independent answers and slips
# ---------------------------------------------------------------------------------------------

def read_pc(ex):
    h = ex.heights
    words = []
    for j in range(3):
        crossings = 0
        for i in range(5):
            for k in range(i + 1, 5):
                if (h[i, j] > h[k, j]) != (h[i, j + 1] > h[k, j + 1]):
                    crossings += 1
        words.append("positive" if crossings <= 2 else "negative" if crossings >= 8 else "none")
    swap = {"positive": "negative", "negative": "positive", "none": "none"}
    return words, {"crossings read as positive": [swap[w] for w in words]}


def dual_line(ex):
    (xl, xh), (yl, yh) = ex.x_range, ex.y_range
    a, b = ex.point
    an, bn = (a - xl) / (xh - xl), (b - yl) / (yh - yl)
    mistakes = {"not normalised": [b - a, a], "axes swapped": [an - bn, bn]}
    if (xl != 0 or yl != 0) and xh != 0 and yh != 0:
        mistakes["divided by the maximum"] = [b / yh - a / xh, a / xh]
    return [bn - an, an], mistakes


def dual_point(ex):
    (xl, xh), (yl, yh) = ex.x_range, ex.y_range

    def meet(m, c, rx, ry, lows):
        # the dual lines of two points of y = m x + c, intersected numerically
        rows, rhs = [], []
        for x in (xl + 0.3 * rx, xl + 0.9 * rx):
            a = (x - lows[0]) / rx
            b = (m * x + c - lows[1]) / ry
            rows.append([b - a, -1.0])                # v = a + (b - a) u
            rhs.append(-a)
        return list(np.linalg.solve(rows, rhs))

    right = meet(ex.m, ex.c, xh - xl, yh - yl, (xl, yl))
    mn = ex.m * (xh - xl) / (yh - yl)
    cn = (ex.m * xl + ex.c - yl) / (yh - yl)
    mistakes = {"slope not normalised": [1 / (1 - ex.m), cn / (1 - ex.m)],
                "intercept not normalised": [1 / (1 - mn), ex.c / (1 - mn)]}
    if abs(1 + mn) > 0.2:
        mistakes["sign of the slope"] = [1 / (1 + mn), cn / (1 + mn)]
    return right, mistakes


def brush(ex):
    def select(how, strict):
        out = set()
        for i, row in enumerate(ex.table):
            inside = []
            for name, lo, hi in ex.brushes:
                v = row[list(ex.names).index(name)]
                inside.append(lo < v < hi if strict else lo <= v <= hi)
            if (all(inside) if how == "AND" else any(inside)):
                out.add(i + 1)
        return out

    right = select(ex.how, False)
    other = "OR" if ex.how == "AND" else "AND"
    return right, {"AND and OR swapped": select(other, False),
                   "bounds excluded": select(ex.how, True),
                   "complement": set(range(1, 9)) - right}


def star(ex):
    d, k = len(ex.names), ex.spoke - 1
    lo, hi = ex.ranges[k]
    x = ex.record[k]
    v = (x - lo) / (hi - lo)

    def at(deg, length):
        return [length * math.cos(math.radians(deg)), length * math.sin(math.radians(deg))]

    angle = 90 + 360 * k / d
    right = at(angle, v)
    mistakes = {"not normalised": at(angle, x), "clockwise": at(90 - 360 * k / d, v),
                "started at the x axis": at(360 * k / d, v),
                "sin and cos swapped": right[::-1]}
    if lo != 0 and hi != 0:
        mistakes["divided by the maximum"] = at(angle, x / hi)
    return right, mistakes


def covariance(ex):
    c = np.cov(ex.data.T)
    c0 = np.cov(ex.data.T, ddof=0)
    raw = ex.data.T @ ex.data / 4
    e, e0, er = (scipy.linalg.eigh(m, eigvals_only=True)[::-1] for m in (c, c0, raw))

    def answer(m, values):
        return [m[0, 0], m[0, 1], m[1, 1], values[0], values[1]]

    return answer(c, e), {"divided by n": answer(c0, e0), "not centred": answer(raw, er),
                          "eigenvalues swapped": answer(c, e[::-1])}


def _signed(v):
    lead = max(range(len(v)), key=lambda i: (abs(v[i]) > max(abs(v)) - 1e-9, -i))
    return v if v[lead] > 0 else -v


def project(ex):
    c = np.cov(ex.data.T)
    values, vectors = scipy.linalg.eigh(c)
    w1, w2 = _signed(vectors[:, 1]), _signed(vectors[:, 0])
    p = ex.data[ex.record - 1] - ex.data.mean(axis=0)
    u = _signed(np.array([c[0, 1], values[1] - c[0, 0]]))
    return [w1[0], w1[1], p @ w1], {
        "second eigenvector": [w2[0], w2[1], p @ w2],
        "not normalised": [u[0], u[1], p @ u],
        "sign": [-w1[0], -w1[1], -(p @ w1)],
        "not centred": [w1[0], w1[1], ex.data[ex.record - 1] @ w1],
    }


SPECS = {
    "ReadParallelCoordinates": (read_pc, "words"),
    "DualLine": (dual_line, "vector"),
    "DualPoint": (dual_point, "vector"),
    "BrushSelection": (brush, "records"),
    "StarGlyphVertex": (star, "vector"),
    "CovarianceEigen": (covariance, "five"),
    "ProjectRecord": (project, "three"),
}
GARBAGE = {
    "words": ["positive", {"a": 1}, [1, 2, 3], ["positive", "negative"], ["up", "down", "none"],
              [None, "none", "none"]],
    "vector": ["v", {"v": 1}, [[1, 2], [3]], [1] * 9, [[math.nan, 1]]],
    "records": ["1, 2", {"a": 1}, [1.5], ["one"], [math.nan], [True, 2]],
    "five": ["c", {"c": 1}, [1, 2], [[1, 2], [3, 4]], [math.nan] * 5],
    "three": ["w", {"w": 1}, [1, 2], [[1, 2, 3], [4]], [math.nan] * 3],
}
DISCRETE = {"words", "records"}
exercises = harness.variants(topic)


def same(a, b, form):
    if form in DISCRETE:
        return (set(a) == set(b)) if form == "records" else list(a) == list(b)
    return harness.gap(a, b) < harness.SAME


def as_answer(value, form):
    return sorted(value) if form == "records" else value


globals().update(harness.common_tests(topic, SPECS, GARBAGE, exercises, at_least=7,
                                      distinct=(20, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, as_answer=as_answer,
                                                    key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "words":
            answers = [right, tuple(right), [w.upper() for w in right]]
        elif form == "records":
            answers = [sorted(right), sorted(right, reverse=True), tuple(right),
                       [float(i) for i in right]]
        else:
            answers = [right, np.round(right, 4), np.asarray(right).tolist()]
        harness.assert_accepted(ex, answers)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, form = SPECS[name]
    for ex in exercises(name, range(40)):
        worked = ex.worked()
        right = solve(ex)[0]
        assert same(worked.answer, right, form), (ex, worked.answer, right)
        assert ex.check(as_answer(worked.answer, form)).status == "correct"
        assert len(ex.hints()) >= 3


def test_wrong_answers_get_teaching_feedback():
    for name in ("DualLine", "DualPoint", "StarGlyphVertex", "CovarianceEigen",
                 "ProjectRecord"):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(20)):
            right = np.asarray(solve(ex)[0])
            fb = ex.check(right + 0.37 + 0.05 * np.abs(right))
            assert fb.status == "wrong" and len(fb.message) > 60, (ex, fb)
    for ex in exercises("BrushSelection", range(20)):
        right = brush(ex)[0]
        some = sorted(right)[:1] + [i for i in range(1, 9) if i not in right][:1]
        fb = ex.check(some)
        assert fb.status == "wrong"
        assert ex.check([9]).diagnosis == "out of range"
    for ex in exercises("ReadParallelCoordinates", range(20)):
        right = read_pc(ex)[0]
        one = list(right)
        one[1] = "none" if right[1] != "none" else "positive"
        fb = ex.check(one)
        assert fb.status == "wrong" and "B–C" in fb.message


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("CovarianceEigen"):
        c = np.cov(ex.data.T)
        values = np.linalg.eigvalsh(c)
        assert np.allclose(c, np.round(c)) and np.allclose(values, np.round(values))
        assert np.all(ex.data == np.round(ex.data)) and ex.data.min() >= 0
    for ex in exercises("ProjectRecord"):
        assert np.allclose(ex.cov, np.cov(ex.data.T))
    for ex in exercises("DualPoint"):
        assert ex.m == round(ex.m, 2)
    for ex in exercises("StarGlyphVertex"):
        k = ex.spoke - 1
        lo, hi = ex.ranges[k]
        assert ((ex.record[k] - lo) / (hi - lo) * 20) % 1 < 1e-9       # a twentieth
    for ex in exercises("BrushSelection"):
        right, slips = brush(ex)
        assert slips["bounds excluded"] != right                       # a record on a bound


def test_every_relation_is_asked():
    seen = {w for ex in exercises("ReadParallelCoordinates") for w in read_pc(ex)[0]}
    assert seen == {"positive", "negative", "none"}
    where = {0 < dual_point(ex)[0][0] < 1 for ex in exercises("DualPoint")}
    assert where == {True, False}                       # between the axes and outside them
    assert {ex.how for ex in exercises("BrushSelection")} == {"AND", "OR"}


@pytest.mark.parametrize("name", SPECS)
def test_a_fresh_seed_is_a_fresh_exercise(name):
    cls = CLASSES[name]
    found = {cls(seed=seed).statement() for seed in range(100)}
    assert len(found) >= 40, (name, len(found))
