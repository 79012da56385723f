"""Tests of the chapter 3 exercises on normals, frames, scaling about a point, w != 1 and
mirroring about a plane (course_lib/exercises/_ch03/frames.py), on tests/exercise_harness.py.

The right answers and every anticipated slip are recomputed here from closed forms typed out
below (the 2x2 inverse by the adjugate, frame coordinates as dot products, c - S c, atan2 of
the divided entries) and trimesh's reflection_matrix, never with course_lib.frames.
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest
from trimesh import transformations as tt

import exercise_harness as harness
from course_lib.exercises._ch03 import frames as module

NAMES = ["NormalUnderShear", "FrameCoordinates", "ScaleAboutPoint", "HomogeneousRotationAngle",
         "MirrorAboutPlane"]
ch03 = SimpleNamespace(EXERCISES=[getattr(module, n) for n in NAMES],
                       **{n: getattr(module, n) for n in NAMES})


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / math.hypot(*v)


def affine(block, column):
    out = np.eye(len(column) + 1)
    out[:-1, :-1], out[:-1, -1] = block, column
    return out


def normal(ex):
    (a, b), (c, d) = ex.A
    det = a * d - b * c
    inv = np.array([[d, -b], [-c, a]]) / det
    raw = inv.T @ ex.n
    return unit(raw), {"used M": unit(ex.A @ ex.n), "inverse not transposed": unit(inv @ ex.n),
                       "transposed only": unit(ex.A.T @ ex.n), "not normalised": raw}


def frame_coordinates(ex):
    d = ex.p - ex.o
    right = np.array([ex.u @ d, ex.v @ d])
    R = np.array([[ex.u[0], ex.v[0]], [ex.u[1], ex.v[1]]])
    return right, {"frame to world": ex.o + ex.p[0] * ex.u + ex.p[1] * ex.v,
                   "transposed": R @ d,
                   "forgot origin": np.array([ex.u @ ex.p, ex.v @ ex.p]),
                   "origin not rotated": np.array([ex.u @ ex.p, ex.v @ ex.p]) - ex.o}


def scale_about(ex):
    s = np.array([ex.sx, ex.sy])
    c = np.asarray(ex.c, dtype=float)
    S = np.diag(s)
    return affine(S, c - s * c), {"wrong order": affine(S, s * c - c),
                                  "about origin": affine(S, [0, 0]),
                                  "missing T(c)": affine(S, -s * c),
                                  "missing T(-c)": affine(S, c)}


def wrap(a):
    a = (a + 180.0) % 360.0 - 180.0
    return 180.0 if a == -180.0 else a


def rotation_angle(ex):
    w = ex.M[2, 2]
    right = math.degrees(math.atan2(ex.M[1, 0] / w, ex.M[0, 0] / w))
    mistakes = {"called a scale": 0.0, "angle sign": -right, "radians": math.radians(right)}
    if w < 0:
        mistakes["w not divided"] = math.degrees(math.atan2(ex.M[1, 0], ex.M[0, 0]))
    return right, mistakes


def mirror_plane(ex):
    m = np.asarray(ex.m, dtype=float)
    L2 = m @ m
    point = ex.k / L2 * m                                  # on the plane m . p = k
    right = tt.reflection_matrix(point, m)
    n = m / math.sqrt(L2)
    d = ex.k / math.sqrt(L2)
    H = np.eye(3) - 2 * np.outer(n, n)
    return right, {"not normalised": affine(np.eye(3) - 2 * np.outer(m, m), 2 * ex.k * m),
                   "projection": affine(np.eye(3) - np.outer(n, n), d * n),
                   "through origin": affine(H, [0, 0, 0]),
                   "translation sign": affine(H, -2 * d * n)}


SPECS = {"NormalUnderShear": (normal, "vector"), "FrameCoordinates": (frame_coordinates, "point"),
         "ScaleAboutPoint": (scale_about, "matrix"),
         "HomogeneousRotationAngle": (rotation_angle, "number"),
         "MirrorAboutPlane": (mirror_plane, "matrix")}
MATRIX_GARBAGE = ["M", {"a": 1}, [[1, 2], [3]], [1, 2, 3], [[1, "a"], [0, 1]],
                  [[math.nan] * 3] * 3, 3 + 2j]
VECTOR_GARBAGE = ["p", {"x": 1}, [[1, 2], [3]], [1, 2, 3, 4, 5], np.eye(3), [math.inf, 0],
                  [..., 1]]
GARBAGE = {"matrix": MATRIX_GARBAGE, "vector": VECTOR_GARBAGE,
           "point": VECTOR_GARBAGE + [[True, 0], [1, 2, 0]],
           "number": ["v", {"v": 1}, [1, 2], [[1], [2, 3]], math.nan]}
exercises = harness.variants(ch03)

globals().update(harness.common_tests(ch03, SPECS, GARBAGE, exercises, at_least=5,
                                      distinct=(20, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, harness.same,
                                                    key_seeds=harness.SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        harness.assert_accepted(ex, [right, np.round(right, 4), np.asarray(right).tolist()])


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert harness.gap(worked.answer, solve(ex)[0]) < 1e-9 and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_exam_style_numbers():
    for ex in exercises("HomogeneousRotationAngle"):
        assert ex.M[2, 2] == ex.w and abs(ex.w) >= 2
    assert any(ex.w < 0 for ex in exercises("HomogeneousRotationAngle"))
    for ex in exercises("FrameCoordinates"):
        assert abs(ex.u @ ex.v) < 1e-12 and math.isclose(ex.u @ ex.u, 1.0)
    for ex in exercises("MirrorAboutPlane"):
        assert ex.length in (3.0, 5.0)
