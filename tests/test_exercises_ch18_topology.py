"""Tests of the vector-field topology exercises (course_lib/exercises/_ch18/topology.py), on
tests/exercise_harness.py.

The right answers and the anticipated slips are recomputed here independently: the class from
numpy.linalg.eigvals and the textbook rules typed below; the bilinear velocity by interpolating
along x on the bottom and top edges and then along y (two linear interpolations, not the
four-weight formula of the module), the Euler and midpoint steps written out.
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch18 import topology as module

NAMES = ["ClassifyCriticalPoint", "GriddedFieldStep"]
ch18 = SimpleNamespace(EXERCISES=[getattr(module, n) for n in NAMES],
                       **{n: getattr(module, n) for n in NAMES})

ALL = ("saddle", "attracting node", "repelling node", "attracting focus", "repelling focus",
       "centre", "degenerate")


def _class(j):
    lam = np.linalg.eigvals(j)
    if np.abs(lam).min() < 1e-9:
        return "degenerate", lam
    if np.abs(lam.imag).max() > 1e-6:
        re = lam.real[0]
        return ("centre" if abs(re) < 1e-9 else
                "attracting focus" if re < 0 else "repelling focus"), lam
    if lam.real.min() < 0 < lam.real.max():
        return "saddle", lam
    return ("attracting node" if lam.real.max() < 0 else "repelling node"), lam


def classify(ex):
    assert np.allclose(ex.J @ ex.point + ex.c, 0)           # the point is a zero of the field
    right, lam = _class(ex.J)
    complex_pair = np.abs(lam.imag).max() > 1e-6
    slips = {}
    for given in ALL:
        if given == right:
            continue
        if given == "degenerate":
            key = "degenerate"
        elif right == "saddle":
            key = "saddle missed"
        elif given == "saddle":
            key = "not a saddle"
        elif "node" in given and complex_pair:
            key = "node for complex"
        elif "node" not in given and not complex_pair:
            key = "focus for real"
        elif given == "centre" or right == "centre":
            key = "centre vs focus"
        else:
            key = "attracting vs repelling"
        slips.setdefault(key, harness.Either()).append(given)
    return right, slips


def _lerp(a, b, f):
    return np.asarray(a, float) + f * (np.asarray(b, float) - np.asarray(a, float))


def _velocity(ex, q, rule="right"):
    s = (q[0] - ex.x0) / ex.spacing
    t = (q[1] - ex.y0) / ex.spacing
    c = ex.corners
    if rule == "nearest":
        return np.asarray(c[f"{int(s > 0.5)}{int(t > 0.5)}"], float)
    if rule == "corner":
        return np.asarray(c["00"], float)
    if rule == "swapped":
        s, t = t, s
    if rule == "mirrored":
        s, t = 1 - s, 1 - t
    bottom = _lerp(c["00"], c["10"], s)
    top = _lerp(c["01"], c["11"], s)
    return _lerp(bottom, top, t)


def _step(ex, rule="right", h=None, euler=False):
    h = ex.h if h is None else h
    k1 = _velocity(ex, ex.p, rule)
    if ex.method == "euler" or euler:
        return ex.p + h * k1
    return ex.p + h * _velocity(ex, ex.p + 0.5 * h * k1, rule)


def step(ex):
    right = _step(ex)
    slips = {"nearest node": _step(ex, "nearest"), "swapped weights": _step(ex, "swapped"),
             "mirrored weights": _step(ex, "mirrored"), "wrong corner": _step(ex, "corner"),
             "no h": ex.p + (right - ex.p) / ex.h}
    if ex.method == "rk2":
        slips["euler"] = _step(ex, euler=True)
    return right, slips


SPECS = {"ClassifyCriticalPoint": (classify, "name"), "GriddedFieldStep": (step, "point")}
GARBAGE = {"name": ["a whirlpool", 3, [1, 2], {"saddle": 1}],
           "point": ["I", {"I": 1}, [1, 2, 3], [[1], [2, 3]], [math.nan, 1]]}
exercises = harness.variants(ch18)


def same(a, b, form=None):
    if form == "name":
        return a == b
    return harness.same(a, b)


globals().update(harness.common_tests(ch18, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(30, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "name":
            harness.assert_accepted(ex, [right, right.upper(), f"  {right} "])
        else:
            harness.assert_accepted(ex, [right, np.round(right, 3), list(right)])


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, form = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert same(worked.answer, solve(ex)[0], form) and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_every_class_is_drawn():
    drawn = {classify(ex)[0] for ex in exercises("ClassifyCriticalPoint")}
    assert drawn == set(ALL) - {"degenerate"}


def test_synonyms_are_accepted():
    for ex in exercises("ClassifyCriticalPoint", range(40)):
        if ex.expected == "centre":
            assert ex.check("center").status == "correct"
        if ex.expected == "attracting focus":
            assert ex.check("spiral sink").status == "correct"


def test_steps_use_both_methods_and_stay_in_the_cell():
    methods = set()
    for ex in exercises("GriddedFieldStep"):
        methods.add(ex.method)
        s, t = (ex.p - [ex.x0, ex.y0]) / ex.spacing
        assert 0 < s < 1 and 0 < t < 1
    assert methods == {"euler", "rk2"}
