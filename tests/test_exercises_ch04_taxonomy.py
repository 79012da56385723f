"""Tests of the taxonomy exercises (course_lib/exercises/_ch04/taxonomy.py), on
tests/exercise_harness.py.

The right answers and the anticipated slips are recomputed here from closed forms typed below:
the vanishing point of u under a projection from c onto n.x = h is c + (h - n.c) u / (n.u); a
unit axis a seen along the unit v is drawn with length sqrt(1 - (a.v)^2); the cabinet matrix is
typed entry by entry; a box axis has a vanishing point iff a.g != 0; the class of a matrix is
decided by its last row, the orthonormality of its first two rows and its column lengths.
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch04 import taxonomy as module

NAMES = ["CameraVanishingPoint", "ClassifyProjection", "AxonometricForeshortening",
         "CabinetMatrix", "PrincipalVanishingCount", "PlaneProjectionPoint"]
ch04 = SimpleNamespace(EXERCISES=[getattr(module, n) for n in NAMES],
                       **{n: getattr(module, n) for n in NAMES})


def camera_vp(ex):
    c, n, h, u = ex.centre, ex.normal, ex.h, ex.u
    right = c + (h - n @ c) * u / (n @ u)
    point = c + (h - n @ c) * (ex.p0 - c) / (n @ (ex.p0 - c))
    hom = ex.matrix @ np.append(u, 0.0)
    as_point = ex.matrix @ np.append(u, 1.0)
    return right, {"no divide": hom[:3], "w = 1 for the direction": as_point[:3] / as_point[3],
                   "projected a point": point}


CLASS_NAMES = ("one-point perspective", "two-point perspective", "three-point perspective",
               "multiview", "isometric", "dimetric", "trimetric", "cavalier", "cabinet",
               "general oblique")
FAMILY = {"one-point perspective": "perspective", "two-point perspective": "perspective",
          "three-point perspective": "perspective", "multiview": "orthographic",
          "isometric": "orthographic", "dimetric": "orthographic", "trimetric": "orthographic",
          "cavalier": "oblique", "cabinet": "oblique", "general oblique": "oblique"}


def _class_of(m):
    last = m[3, :3]
    if np.any(np.abs(last) > 1e-12):
        return CLASS_NAMES[int(np.sum(np.abs(last) > 1e-12)) - 1]
    r0, r1 = m[0, :3], m[1, :3]
    if abs(r0 @ r1) < 1e-9 and abs(r0 @ r0 - r1 @ r1) < 1e-9:
        f = np.hypot(m[0, :3], m[1, :3]) / np.linalg.norm(r0)
        if np.any(f < 1e-9):
            return "multiview"
        same = sum(abs(f[i] - f[j]) < 1e-6 for i, j in ((0, 1), (0, 2), (1, 2)))
        return {3: "isometric", 1: "dimetric", 0: "trimetric"}[same]
    k = math.hypot(m[0, 2], m[1, 2])       # P_OBLI onto z = 0: the drawn length of a unit of z
    return "cavalier" if abs(k - 1) < 1e-9 else "cabinet" if abs(k - 0.5) < 1e-9 else "general oblique"


def _key(given, right):
    fg, fr = FAMILY[given], FAMILY[right]
    if fg != fr:
        return f"{fg} for {fr}"
    return {"perspective": "vanishing points miscounted", "oblique": "depth length misread"}.get(
        fr, "multiview confused" if "multiview" in (given, right) else "foreshortening misread")


def classify(ex):
    right = _class_of(ex.matrix)
    slips = {}
    for c in CLASS_NAMES:
        if c != right:
            slips.setdefault(_key(c, right), harness.Either()).append(c)
    return right, slips


def axo(ex):
    L = ex.length
    if ex.kind == "elevation":
        right = math.degrees(math.asin(1 / math.sqrt(3)))
        return right, {"drawing angle": 30.0, "angle from the vertical": 90 - right,
                       "radians": math.radians(right), "azimuth instead": 45.0}
    a, e = math.radians(ex.azimuth_deg), math.radians(ex.elevation_deg)
    v = [math.sin(a) * math.cos(e), -math.cos(a) * math.cos(e), math.sin(e)]
    dot = v[ex.axis]
    right = L * math.sqrt(1 - dot * dot)
    slips = {"true length": L, "cos instead of sin": L * abs(dot)}
    if ex.kind == "isometric":
        assert abs(right - L * math.sqrt(2 / 3)) < 1e-12
        slips["factor inverted"] = L * math.sqrt(3 / 2)
        slips["1/sqrt 2"] = L / math.sqrt(2)
    else:
        a, e = ex.azimuth_deg, ex.elevation_deg            # degrees fed to sin and cos
        w = [math.sin(a) * math.cos(e), -math.cos(a) * math.cos(e), math.sin(e)]
        slips["degrees as radians"] = L * math.sqrt(max(0.0, 1 - w[ex.axis] ** 2))
    return right, slips


def _oblique(c, s, keep=False):
    return np.array([[1, 0, c, 0], [0, 1, s, 0], [0, 0, 1.0 if keep else 0.0, 0], [0, 0, 0, 1]])


def cabinet(ex):
    k = 0.5 if ex.kind == "cabinet" else 1.0
    phi = math.radians(ex.angle_deg)
    c, s = k * math.cos(phi), k * math.sin(phi)
    other = 1.0 if k == 0.5 else 0.5
    norm = math.sqrt(c * c + s * s + 1)
    return _oblique(-c, -s), {
        "wrong length": _oblique(-other * math.cos(phi), -other * math.sin(phi)),
        "angle sign": _oblique(c, s),
        "DOP not normalised in z": _oblique(-c / norm, -s / norm),
        "cos and sin swapped": _oblique(-k * math.sin(phi), -k * math.cos(phi)),
        "kept z": _oblique(-c, -s, keep=True),
    }


def vp_count(ex):
    right = sum(abs(a @ ex.gaze) > 1e-9 for a in ex.axes)
    return right, {"counted the parallel axes": 3 - right,
                   "eye position instead of gaze": sum(abs(a @ ex.eye) > 1e-9 for a in ex.axes)}


def plane_point(ex):
    # the line c + t (p - c) solved against the plane by numpy (two equations: on the line, on
    # the plane), not by the closed form
    c, n, h, p = ex.centre, ex.normal, ex.h, ex.p
    t = np.linalg.solve([[n @ (p - c)]], [h - n @ c])[0]
    right = c + t * (p - c)
    return right, {"orthographic onto the plane": p - (n @ p - h) / (n @ n) * n,
                   "t inverted": c + (p - c) / t,
                   "centre at the origin": p * h / (n @ p),
                   "no divide": c + (h - n @ c) * (p - c)}


SPECS = {"CameraVanishingPoint": (camera_vp, "point"), "ClassifyProjection": (classify, "name"),
         "AxonometricForeshortening": (axo, "number"), "CabinetMatrix": (cabinet, "matrix"),
         "PrincipalVanishingCount": (vp_count, "number"),
         "PlaneProjectionPoint": (plane_point, "point")}
GARBAGE = {"point": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan, 1, 2]],
           "name": ["perspective-ish", 3, [1, 2], {"a": 1}],
           "number": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf],
           "matrix": ["I", np.eye(3), [[1, 2], [3]], np.full((4, 4), math.nan)]}
exercises = harness.variants(ch04)


def same(a, b, form=None):
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    return harness.same(a, b)


globals().update(harness.common_tests(ch04, SPECS, GARBAGE, exercises, at_least=6,
                                      distinct=(30, 6)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "name":
            harness.assert_accepted(ex, [right, right.upper(), " " + right + " "])
        else:
            harness.assert_accepted(ex, [right, np.round(right, 4), np.asarray(right).tolist()])


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, form = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        right = solve(ex)[0]
        if form == "name":
            assert worked.answer == right
        else:
            assert np.allclose(worked.answer, right)
        assert ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_every_class_and_count_occurs():
    assert {ex.expected for ex in exercises("ClassifyProjection")} == set(CLASS_NAMES) - {"trimetric"} \
        or {ex.expected for ex in exercises("ClassifyProjection")} == set(CLASS_NAMES)
    assert {ex.expected for ex in exercises("PrincipalVanishingCount")} == {1, 2, 3}
    assert {ex.kind for ex in exercises("AxonometricForeshortening")} == {"elevation", "isometric",
                                                                         "axonometric"}
