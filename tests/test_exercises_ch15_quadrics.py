"""Tests of the quadric exercises (course_lib/exercises/_ch15/quadrics.py), on
tests/exercise_harness.py.

The right answers and every anticipated slip are recomputed here from the attributes: the
cylinder's quadratic by numpy.roots with the height test typed out below, the disks by the
plane formula and the radius test written here (never with course_lib.raytracing).
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SAME, SEEDS, Either, gap
from course_lib.exercises._ch15 import quadrics as module

ch15 = SimpleNamespace(EXERCISES=[module.RayCylinderHit, module.RayDiskHit],
                       RayCylinderHit=module.RayCylinderHit, RayDiskHit=module.RayDiskHit)


def smallest_positive(coefficients):
    roots = np.roots(coefficients)
    real = sorted(r.real for r in roots if abs(r.imag) < 1e-9 and r.real > 1e-9)
    return real[0] if real else None


def cylinder(ex):
    o, d, r, h = ex.o, ex.d, ex.radius, ex.height
    roots = np.sort(np.roots([d[0]**2 + d[1]**2, 2 * (o[0] * d[0] + o[1] * d[1]),
                              o[0]**2 + o[1]**2 - r * r]).real)
    valid = [t for t in roots if t > 0 and 0 <= o[2] + t * d[2] <= h]
    t = valid[0]
    p = o + t * d
    n = np.array([p[0], p[1], 0.0]) / r
    right = np.r_[t, n]
    mistakes = {"normal with z": np.r_[t, p / np.linalg.norm(p)],
                "not normalised": np.r_[t, p[0], p[1], 0.0]}
    if t == roots[0]:
        mistakes["far root"] = np.r_[roots[1], n]
    else:
        mistakes["height test"] = np.r_[roots[0], n]
        mistakes["inward normal"] = np.r_[t, -n]
    for key, coeffs in (("a = d.d", [d @ d, 2 * (o[0] * d[0] + o[1] * d[1]),
                                     o[0]**2 + o[1]**2 - r * r]),
                        ("a = 1", [1.0, 2 * (o[0] * d[0] + o[1] * d[1]),
                                   o[0]**2 + o[1]**2 - r * r]),
                        ("sphere equation", [d @ d, 2 * o @ d, o @ o - r * r])):
        bad = smallest_positive(coeffs)
        if bad is not None:
            mistakes[key] = np.r_[bad, n]
    return right, mistakes


def disks(ex):
    candidates = []
    plane_t = []
    for c, n, r in zip(ex.centers, ex.normals, ex.radii):
        t = ((c - ex.o) @ n) / (ex.d @ n)
        plane_t.append(t)
        if t > 0 and np.linalg.norm(ex.o + t * ex.d - c) <= r:
            candidates.append(t)
    right = min(candidates)
    t_a = plane_t[0]
    mistakes = {"sign of the distance": -right,
                "no division by d.n": (ex.centers[1] - ex.o) @ ex.normals[1]}
    if t_a > 0:
        mistakes["outside the radius"] = t_a
    else:
        mistakes["behind the origin"] = Either([t_a, abs(t_a)])
    return right, mistakes


SPECS = {"RayCylinderHit": (cylinder, "parts"), "RayDiskHit": (disks, "number")}
GARBAGE = {"number": ["x", [1, 2], [math.nan], {"a": 1}, math.inf],
           "parts": ["x", [1], [[1, 2, 3, 4, 5]], {"a": 1}, [1, 2, math.nan, 0]]}
exercises = harness.variants(ch15)

globals().update(harness.common_tests(ch15, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(30, 10), newlines=None))
test_mistakes_are_diagnosed = harness.mistakes_test(
    SPECS, exercises, lambda a, b, form: gap(a, b) < SAME, min_message=30, key_seeds=SEEDS)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert gap(worked.answer, solve(ex)[0]) < 1e-9 and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_both_kinds_of_each_exercise_occur_and_numbers_are_whole():
    assert {ex.kind for ex in exercises("RayCylinderHit")} == {"outside", "open end"}
    assert {ex.kind for ex in exercises("RayDiskHit")} == {"outside", "behind"}
    for ex in exercises("RayCylinderHit"):
        assert np.all(ex.o == np.round(ex.o)) and np.all(ex.d == np.round(ex.d))
    for ex in exercises("RayDiskHit"):
        assert np.all(ex.d == np.round(ex.d)) and ex.expected == round(ex.expected)
