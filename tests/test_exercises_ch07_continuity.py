"""Tests of the continuity and matrix-form exercises (course_lib/exercises/_ch07/continuity.py).

The right answers and the anticipated mistakes are recomputed here independently: the join's
continuity from the end derivatives of the Bézier polygons with plain arithmetic (exact
integer comparisons for C^k and G1, signed curvature cross(d1, d2) / |d1|^3 for G2); the
matrix-form point from the blending functions typed out as polynomials (Bernstein, Hermite,
uniform B-spline, Catmull-Rom); Q1 of a C1 join from n/h0 (Pn - Pn-1) = m/h1 (Q1 - Q0).
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch07 import continuity as module

NAMES = ("JoinContinuityCheck", "MatrixFormPoint", "C1JoinPoint")
ch07 = SimpleNamespace(EXERCISES=[getattr(module, n) for n in NAMES],
                       **{n: getattr(module, n) for n in NAMES})


# --------------------------------------------------------------------------- join continuity

def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def join(ex):
    P, Q = ex.P.tolist(), ex.Q.tolist()
    sub = lambda a, b: [a[0] - b[0], a[1] - b[1]]                      # noqa: E731
    a1 = [3 * v for v in sub(P[3], P[2])]
    b1 = [3 * v for v in sub(Q[1], Q[0])]
    a2 = [6 * (P[3][k] - 2 * P[2][k] + P[1][k]) for k in range(2)]
    b2 = [6 * (Q[2][k] - 2 * Q[1][k] + Q[0][k]) for k in range(2)]
    assert P[3] == Q[0]
    c = 0
    if a1 == b1:
        c = 2 if a2 == b2 else 1
    same_dir = _cross(a1, b1) == 0 and a1[0] * b1[0] + a1[1] * b1[1] > 0
    g = 0
    if same_dir:
        ka = _cross(a1, a2) / math.hypot(*a1) ** 3
        kb = _cross(b1, b2) / math.hypot(*b1) ** 3
        g = 2 if abs(ka - kb) < 1e-9 else 1
    g = max(g, c)
    mistakes = {}
    if c < g:
        mistakes["G taken for C"] = [g, g]
    if _cross(a1, b1) == 0 and a1[0] * b1[0] + a1[1] * b1[1] < 0:
        mistakes["opposite tangent accepted"] = [0, 1]
    if c >= 1:
        mistakes["C without G"] = [c, 0]
    if g == 1:
        mistakes["curvature not checked"] = [c, 2]
    return [c, g], mistakes


# --------------------------------------------------------------------------- matrix form

def _blend(form, t, scale=1.0):
    s = 1 - t
    if form == "bezier":
        return [s ** 3, 3 * t * s * s, 3 * t * t * s, t ** 3]
    if form == "hermite":
        return [2 * t ** 3 - 3 * t ** 2 + 1, -2 * t ** 3 + 3 * t ** 2, t ** 3 - 2 * t ** 2 + t,
                t ** 3 - t ** 2]
    if form == "bspline":
        return [scale * v / 6 for v in (s ** 3, 3 * t ** 3 - 6 * t ** 2 + 4,
                                        -3 * t ** 3 + 3 * t ** 2 + 3 * t + 1, t ** 3)]
    return [scale * v / 2 for v in (-t ** 3 + 2 * t ** 2 - t, 3 * t ** 3 - 5 * t ** 2 + 2,
                                     -3 * t ** 3 + 4 * t ** 2 + t, t ** 3 - t ** 2)]


TYPED = {  # the matrices typed again, rows = t^3, t^2, t, 1
    "bezier": [[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 3, 0, 0], [1, 0, 0, 0]],
    "hermite": [[2, -2, 1, 1], [-3, 3, -2, -1], [0, 0, 1, 0], [1, 0, 0, 0]],
    "bspline": [[-1 / 6, 3 / 6, -3 / 6, 1 / 6], [3 / 6, -1, 3 / 6, 0], [-3 / 6, 0, 3 / 6, 0],
                [1 / 6, 4 / 6, 1 / 6, 0]],
    "catmull-rom": [[-0.5, 1.5, -1.5, 0.5], [1, -2.5, 2, -0.5], [-0.5, 0, 0.5, 0], [0, 1, 0, 0]],
}


def matrix_point(ex):
    G = ex.G.tolist()
    t = ex.t

    def combine(w, rows=G):
        return [sum(w[i] * rows[i][k] for i in range(4)) for k in range(2)]

    right = combine(_blend(ex.form, t))
    M = TYPED[ex.form]
    T_rev = [1, t, t * t, t ** 3]
    mistakes = {"T reversed": combine([sum(T_rev[r] * M[r][c] for r in range(4))
                                       for c in range(4)])}
    T = [t ** 3, t * t, t, 1]
    transposed = combine([sum(T[r] * M[c][r] for r in range(4)) for c in range(4)])
    if ex.form != "bezier":
        mistakes["M transposed"] = transposed
    if ex.form == "hermite":
        mistakes["Hermite order"] = combine(_blend("hermite", t), [G[0], G[2], G[1], G[3]])
    if ex.form == "bspline":
        mistakes["1/6 forgotten"] = combine(_blend("bspline", t, 6.0))
    if ex.form == "catmull-rom":
        mistakes["1/2 forgotten"] = combine(_blend("catmull-rom", t, 2.0))
    return right, mistakes


# --------------------------------------------------------------------------- C1 join

def c1_point(ex):
    P = ex.P.tolist()
    d = [P[-1][k] - P[-2][k] for k in range(2)]

    def q(f):
        return [P[-1][k] + f * d[k] for k in range(2)]

    n, m, h0, h1 = ex.n, ex.m, ex.h0, ex.h1
    right = q(n * h1 / (m * h0))
    return right, {"wrong sign": q(-n * h1 / (m * h0)), "degree ratio forgotten": q(h1 / h0),
                   "interval ratio forgotten": q(n / m), "ratio inverted": q(m * h0 / (n * h1))}


SPECS = {"JoinContinuityCheck": (join, "pair"), "MatrixFormPoint": (matrix_point, "point"),
         "C1JoinPoint": (c1_point, "point")}
GARBAGE = {"pair": ["C1", {"C": 1}, [1, 2, 3], [[1], [2, 3]], [math.nan, 1]],
           "point": ["P", {"x": 1}, [1, 2, 3, 4], [[1], [2, 3]], [math.nan, 1]]}
exercises = harness.variants(ch07)

globals().update(harness.common_tests(ch07, SPECS, GARBAGE, exercises, at_least=3,
                                      distinct=(30, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, harness.same,
                                                    key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        harness.assert_accepted(ex, [right, np.round(right, 3), np.asarray(right).tolist()])


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    texts = set()
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert np.allclose(worked.answer, solve(ex)[0]) and ex.check(worked.answer)
        assert len(ex.hints()) >= 3
        texts.add(worked.markdown())
    assert len(texts) >= 10


def test_every_kind_of_join_appears():
    kinds = {ex.kind for ex in exercises("JoinContinuityCheck")}
    assert kinds == {"cusp", "G1", "C1", "G2", "C1G2", "C2"}
    answers = {tuple(join(ex)[0]) for ex in exercises("JoinContinuityCheck")}
    assert answers == {(0, 0), (0, 1), (1, 1), (0, 2), (1, 2), (2, 2)}
