"""Tests of the clip-space exercises (course_lib/exercises/_ch05/clip3d.py), on
tests/exercise_harness.py.

The right answers and every anticipated slip are recomputed here from rules typed out below with
plain Python, not with course_lib: the outcode from the six inequalities -w <= x, y, z <= w; the
(p, q) pairs from f = (w + x, w - x, w + y, w - y, w + z, w - z) at both ends; the exit point by
bisection on "inside the view volume" along the segment (clip space) or along the divided
segment (NDC, the slip).
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch05 import clip3d as module

NAMES = ["ClipSpaceOutcode", "ClipSpaceLiangBarskyPairs", "ClipSpaceExitPoint",
         "ClipSpaceSutherlandHodgman"]
ch05 = SimpleNamespace(EXERCISES=[getattr(module, n) for n in NAMES],
                       **{n: getattr(module, n) for n in NAMES})


def code_of(x, y, z, lo, hi):
    """Outcode with bounds lo (left/bottom/near) and hi, bits typed out."""
    return ((x < lo) * 1 + (x > hi) * 2 + (y < lo) * 4 + (y > hi) * 8 + (z < lo) * 16
            + (z > hi) * 32)


def outcode(ex):
    x, y, z, w = map(float, ex.point)
    right = code_of(x, y, z, -w, w)
    bits = format(right, "06b")
    swapped = sum(1 << (k ^ 1) for k in range(6) if right >> k & 1)
    mistakes = {"compared with 1": code_of(x, y, z, -1, 1),
                "bit order reversed": int(bits[::-1], 2),
                "sides swapped": swapped}
    if w < 0:
        mistakes["divided with w < 0"] = code_of(x / w, y / w, z / w, -1, 1)
    return right, mistakes


def f(p):
    x, y, z, w = map(float, p)
    return [w + x, w - x, w + y, w - y, w + z, w - z]


def pairs(ex):
    a, b = f(ex.p0), f(ex.p1)
    right = [[a[k] - b[k], a[k]] for k in range(6)]
    x0, y0, z0 = map(float, ex.p0[:3])
    dx, dy, dz = (float(ex.p1[i] - ex.p0[i]) for i in range(3))
    return right, {
        "sign of p": [[-p, q] for p, q in right],
        "q from the wrong end": [[a[k] - b[k], b[k]] for k in range(6)],
        "w ignored": [[-dx, x0 + 1], [dx, 1 - x0], [-dy, y0 + 1], [dy, 1 - y0], [-dz, z0 + 1],
                      [dz, 1 - z0]],
    }


def last_inside(start, end, inside):
    """The largest t in [0, 1] with inside(start + t (end - start)), start inside (bisection)."""
    lo, hi = 0.0, 1.0
    if inside(end):
        return 1.0
    for _ in range(80):
        mid = (lo + hi) / 2
        if inside(start + mid * (end - start)):
            lo = mid
        else:
            hi = mid
    return lo


def exit_point(ex):
    a, b = np.asarray(ex.p0, float), np.asarray(ex.p1, float)
    t = last_inside(a, b, lambda p: abs(p[0]) <= p[3] and abs(p[1]) <= p[3]
                    and abs(p[2]) <= p[3])
    at = a + t * (b - a)
    right = at[:3] / at[3]
    mistakes = {"not divided": at[:3]}
    # t of the next leaving side: the second smallest q/p with p > 0
    fa, fb = f(a), f(b)
    ts = sorted(fa[k] / (fa[k] - fb[k]) for k in range(6) if fa[k] - fb[k] > 0)
    second = a + ts[1] * (b - a)
    if second[3] > 0:
        mistakes["t from the wrong plane"] = second[:3] / second[3]
    na, nb = a[:3] / a[3], b[:3] / b[3]
    s = last_inside(na, nb, lambda p: np.all(np.abs(p) <= 1))
    mistakes["clipped after the divide"] = na + s * (nb - na)
    return right, mistakes


def sh_one_plane(tri, f, cut_t):
    """Sutherland-Hodgman by the four rules; `f` the boundary function (>= 0 inside), `cut_t`
    the parameter at which a crossing edge S -> E is cut."""
    out = []
    for i in range(len(tri)):
        S, E = tri[i], tri[(i + 1) % len(tri)]
        s_in, e_in = f(S) >= 0, f(E) >= 0
        if s_in and e_in:
            out.append(E)
        elif s_in:
            out.append(S + cut_t(S, E) * (E - S))
        elif e_in:
            out.append(S + cut_t(S, E) * (E - S))
            out.append(E)
    return np.array(out)


def sutherland_hodgman(ex):
    k = module._SIDES.index(ex.side)
    axis, sign = k // 2, (1.0 if k % 2 == 0 else -1.0)
    tri = np.asarray(ex.triangle, float)

    def f(p):
        return p[3] + sign * p[axis]

    right = sh_one_plane(tri, f, lambda S, E: f(S) / (f(S) - f(E)))
    originals = [i for i, p in enumerate(right) if not any(np.allclose(p, q) for q in tri)]
    mistakes = {
        "missing intersection vertex": harness.Either(
            [np.delete(right, i, axis=0) for i in originals]),
        "reversed order": right[::-1],
        "kept the outside part": sh_one_plane(tri, lambda p: -f(p),
                                              lambda S, E: f(S) / (f(S) - f(E))),
    }
    crossing = [(tri[i], tri[(i + 1) % 3]) for i in range(3)
                if (f(tri[i]) >= 0) != (f(tri[(i + 1) % 3]) >= 0)]
    if all(S[3] > 0 and E[3] > 0 for S, E in crossing):
        def ndc_t(S, E):
            s, e = S[axis] / S[3], E[axis] / E[3]
            return (-sign - s) / (e - s)
        mistakes["t after the divide"] = sh_one_plane(tri, f, ndc_t)
    return right, mistakes


SPECS = {"ClipSpaceOutcode": (outcode, "number"),
         "ClipSpaceLiangBarskyPairs": (pairs, "table"),
         "ClipSpaceExitPoint": (exit_point, "point"),
         "ClipSpaceSutherlandHodgman": (sutherland_hodgman, "polygon")}
GARBAGE = {"number": ["v", {"v": 1}, [1, 2], [[1], [2, 3]], math.nan],
           "table": ["t", {"a": 1}, np.eye(4), [1, 2, 3], [[math.nan] * 2] * 6],
           "point": ["p", {"a": 1}, [1, 2], [[1, 2, 3]] * 2, [math.nan] * 3],
           "polygon": ["poly", {"a": 1}, [1, 2, 3, 4], [[1, 2, 3]] * 3, [[math.inf, 0, 0, 1]]]}
exercises = harness.variants(ch05)


def same(a, b, form=None):
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.shape != b.shape:
        return False
    if form == "polygon":                               # any starting vertex
        return any(np.allclose(np.roll(a, s, axis=0), b, atol=1e-7) for s in range(len(a)))
    return np.allclose(a, b, atol=1e-7)


globals().update(harness.common_tests(ch05, SPECS, GARBAGE, exercises, at_least=3,
                                      distinct=(20, 15)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        answers = [right, np.round(right, 3), np.asarray(right).tolist()]
        if name == "ClipSpaceSutherlandHodgman":
            answers.append(np.roll(right, 1, axis=0))          # another starting vertex
        harness.assert_accepted(ex, answers)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert same(worked.answer, solve(ex)[0], SPECS[name][1]) and ex.check(worked.answer)
        assert len(ex.hints()) >= 3
    assert len({" ".join(ex.worked().steps) for ex in exercises(name, range(20))}) >= 10


def test_outcode_variants_put_a_third_behind_the_eye():
    behind = sum(ex.point[3] < 0 for ex in exercises("ClipSpaceOutcode"))
    assert 0.2 * len(SEEDS) < behind < 0.5 * len(SEEDS)


def test_exit_point_lies_on_the_cube_and_p1_behind_the_eye():
    for ex in exercises("ClipSpaceExitPoint"):
        assert ex.p1[3] < 0 < ex.p0[3]
        assert np.isclose(np.abs(ex.expected).max(), 1.0)


def test_sutherland_hodgman_variants_have_a_vertex_behind_the_eye_sometimes():
    behind = sum((ex.triangle[:, 3] < 0).any() for ex in exercises("ClipSpaceSutherlandHodgman"))
    assert 0.15 * len(SEEDS) < behind < 0.5 * len(SEEDS)
