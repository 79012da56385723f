"""Tests of the relief exercises (course_lib/exercises/_ch14/relief.py), on
tests/exercise_harness.py. Right answers and every anticipated slip are recomputed here with
plain numpy from the formulas typed out below: N' = normalize(N - h_u T - h_v B); the 2x2 solve
of [E1; E2] = [[du1, dv1], [du2, dv2]] [T; B] done with numpy.linalg.solve; a texel decoded as
2 c / 255 - 1 and taken to object space as x T + y B + z N."""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from course_lib.exercises._ch14 import relief as module
from course_lib.exercises.core import gap

CLASSES = [module.PerturbedNormal, module.TangentFrame, module.DecodeNormalTexel]
ch14 = SimpleNamespace(EXERCISES=CLASSES, **{c.__name__: c for c in CLASSES})


def unit(x):
    x = np.asarray(x, float)
    return x / math.sqrt(float(x @ x))


def perturbed(ex):
    n, t, b, hu, hv = ex.N, ex.T, ex.B, ex.h_u, ex.h_v
    raw = n - hu * t - hv * b
    return unit(raw), {"not normalised": raw, "signs flipped": unit(n + hu * t + hv * b),
                       "T and B swapped": unit(n - hv * t - hu * b),
                       "one sign wrong": unit(n - hu * t + hv * b)}


def tangent(ex):
    p, uv = np.asarray(ex.P, float), np.asarray(ex.UV, float)
    e = np.stack([p[1] - p[0], p[2] - p[0]])
    d = np.stack([uv[1] - uv[0], uv[2] - uv[0]])
    tb = np.linalg.solve(d, e)                         # rows: T, B
    k = 0 if ex.which == "T" else 1
    right = tb[k]
    det = d[0, 0] * d[1, 1] - d[1, 0] * d[0, 1]
    if k == 0:
        swapped_inverse = (d[0, 1] * e[0] - d[1, 1] * e[1]) / det
    else:
        swapped_inverse = (d[1, 0] * e[1] - d[0, 0] * e[0]) / det
    return right, {"T and B swapped": tb[1 - k], "determinant sign": -right,
                   "normalised": unit(right), "inverse coefficients swapped": swapped_inverse}


def texel(ex):
    c = np.asarray(ex.texel, float) / 255.0
    nt = unit(2 * c - 1)
    m = np.column_stack([ex.T, ex.B, ex.N])
    return unit(m @ nt), {"tangent frame ignored": nt, "TBN transposed": unit(m.T @ nt),
                          "not decoded": unit(m @ c)}


SPECS = {"PerturbedNormal": (perturbed, "vector"), "TangentFrame": (tangent, "vector"),
         "DecodeNormalTexel": (texel, "vector")}
GARBAGE = {"vector": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan, 0, 0], [1, math.inf, 0]]}
exercises = harness.variants(ch14)


same = harness.same


globals().update(harness.common_tests(ch14, SPECS, GARBAGE, exercises, at_least=3,
                                      distinct=(30, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert gap(worked.answer, solve(ex)[0]) < 1e-9 and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_frames_are_right_handed_and_orthonormal():
    for name in ("PerturbedNormal", "DecodeNormalTexel"):
        for ex in exercises(name, range(50)):
            m = np.column_stack([ex.T, ex.B, ex.N])
            assert np.allclose(m.T @ m, np.eye(3)) and np.linalg.det(m) == pytest.approx(1)
