"""Tests of the chapter 7 interpolating-curve exercises (course_lib.exercises._ch07.interpolating).

The right answers are recomputed here without course_lib: the Hermite point by
scipy's CubicHermiteSpline on the segment's own parameter interval, Catmull-Rom tangents as
(P_{i+1} - P_{i-1}) / 2, the Catmull-Rom point by scipy as well, and the spline's second
derivatives by scipy's CubicSpline (natural or clamped). Every named mistake is rebuilt here.
"""
import math
import types

import numpy as np
from scipy.interpolate import CubicHermiteSpline, CubicSpline

from course_lib.exercises._ch07 import interpolating as module
import exercise_harness as harness

_CLASSES = [module.HermitePoint, module.CatmullRomTangent, module.CatmullRomPoint,
            module.SplineSecondDerivatives]
ch = types.SimpleNamespace(EXERCISES=_CLASSES, **{cls.__name__: cls for cls in _CLASSES})


def _h(u):
    return (1 - 3 * u ** 2 + 2 * u ** 3, 3 * u ** 2 - 2 * u ** 3, u - 2 * u ** 2 + u ** 3,
            u ** 3 - u ** 2)


def hermite(ex):
    a, h = ex.a, ex.h
    right = CubicHermiteSpline([a, a + h], [ex.P0, ex.P1], [ex.T0, ex.T1])(ex.t)
    H = _h(ex.u)

    def comb(p0, p1, t0, t1):
        return H[0] * p0 + H[1] * p1 + H[2] * t0 + H[3] * t1
    return right, {
        "tangents not scaled": comb(ex.P0, ex.P1, ex.T0, ex.T1),
        "basis swapped": comb(ex.P0, ex.P1, h * ex.T1, h * ex.T0),
        "points swapped": comb(ex.P1, ex.P0, h * ex.T0, h * ex.T1),
        "tangents divided by h": comb(ex.P0, ex.P1, ex.T0 / h, ex.T1 / h),
    }


def cr_tangent(ex):
    a, b, c = ex.P
    return (c - a) / 2, {"forgot the 1/2": c - a, "forward difference": c - b,
                         "backward difference": b - a, "reversed": (a - c) / 2}


def cr_point(ex):
    P, u = ex.P, ex.u

    def seg(p1, p2, t1, t2):
        return CubicHermiteSpline([0, 1], [p1, p2], [t1, t2])(u)
    return seg(P[1], P[2], (P[2] - P[0]) / 2, (P[3] - P[1]) / 2), {
        "forgot the 1/2": seg(P[1], P[2], P[2] - P[0], P[3] - P[1]),
        "forward difference": seg(P[1], P[2], P[2] - P[1], P[3] - P[2]),
        "basis swapped": seg(P[1], P[2], (P[3] - P[1]) / 2, (P[2] - P[0]) / 2),
        "outer points": seg(P[0], P[3], (P[2] - P[0]) / 2, (P[3] - P[1]) / 2),
    }


def _moments(y, end, slopes, middle=4.0):
    n = len(y)
    t = np.arange(n, dtype=float)
    if middle == 4.0:
        bc = "natural" if end == "natural" else ((1, slopes[0]), (1, slopes[1]))
        return CubicSpline(t, y, bc_type=bc)(t, 2)
    a = np.zeros((n, n))
    r = np.zeros(n)
    for i in range(1, n - 1):
        a[i, i - 1], a[i, i], a[i, i + 1] = 1, middle, 1
        r[i] = 6 * ((y[i + 1] - y[i]) - (y[i] - y[i - 1]))
    if end == "natural":
        a[0, 0] = a[-1, -1] = 1
    else:
        a[0, 0], a[0, 1], r[0] = 2, 1, 6 * (y[1] - y[0] - slopes[0])
        a[-1, -2], a[-1, -1], r[-1] = 1, 2, 6 * (slopes[1] - (y[-1] - y[-2]))
    return np.linalg.solve(a, r)


def spline(ex):
    right = _moments(ex.y, ex.end, ex.slopes)
    if ex.end == "natural":
        swapped = _moments(ex.y, "clamped", (0.0, 0.0))
    else:
        swapped = _moments(ex.y, "natural", None)
    return right, {"natural/clamped rows swapped": swapped, "forgot the 6": right / 6,
                   "right-hand side reversed": -right,
                   "diagonal 2": _moments(ex.y, ex.end, ex.slopes, middle=2.0)}


SPECS = {
    "HermitePoint": (hermite, "point"),
    "CatmullRomTangent": (cr_tangent, "vector"),
    "CatmullRomPoint": (cr_point, "point"),
    "SplineSecondDerivatives": (spline, "vector"),
}
GARBAGE = {"point": ["p", {"x": 1}, [[1, 2], [3]], [1, 2, 3, 4], np.eye(3), [math.inf, 0],
                     [math.nan, 1]],
           "vector": ["v", {"v": 1}, [[1, 2], [3]], [1] * 9, [[1, 2], [3, 4], [5, 6]],
                      [[math.nan]]]}

exercises = harness.variants(module)

globals().update(harness.common_tests(ch, SPECS, GARBAGE, exercises, at_least=4,
                                      distinct=(20, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, harness.same)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


def test_worked_solutions_and_hints():
    for name, (solve, _) in SPECS.items():
        for ex in exercises(name, range(10)):
            right, _ = solve(ex)
            assert len(ex.hints()) >= 3
            worked = ex.worked()
            assert np.allclose(worked.answer, right)
            assert len(worked.steps) >= 3


def test_both_end_conditions_and_sizes_are_asked():
    seen = {(ex.end, len(ex.y)) for ex in exercises("SplineSecondDerivatives", range(30))}
    assert {("natural", 3), ("natural", 4), ("clamped", 3)} <= seen
