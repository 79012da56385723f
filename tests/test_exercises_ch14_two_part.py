"""Tests of the texture-transform and two-part mapping exercises
(course_lib/exercises/_ch14/two_part.py), on tests/exercise_harness.py.

Right answers and anticipated mistakes are recomputed here by hand formulas: the texture matrix
step by step (tile, subtract the centre, rotate with cos/sin, add it back) and its slips; the
cylinder's O-mappings solved here (the ray's quadratic in x and z, the centroid's scaling, the
radial projection) and the S-mapping u = 1/2 + atan2(x, z)/2 pi, v = (y + s)/2s.
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch14 import two_part as module

ch14 = SimpleNamespace(EXERCISES=[module.TextureTransform, module.TwoPartMapping],
                       TextureTransform=module.TextureTransform,
                       TwoPartMapping=module.TwoPartMapping)


def _rot(u, v, deg, cu=0.5, cv=0.5):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    du, dv = u - cu, v - cv
    return [cu + c * du - s * dv, cv + s * du + c * dv]


def texture(ex):
    u, v = ex.uv
    ku, kv, deg = ex.ku, ex.kv, ex.degrees
    right = _rot(ku * u, kv * v, deg)
    ru, rv = _rot(u, v, deg)
    # inverse: undo the rotation, then the tiling
    iu, iv = _rot(u, v, -deg)
    mistakes = {"wrong order": [ku * ru, kv * rv],
                "inverse": [iu / ku, iv / kv],
                "rotated about the origin": _rot(ku * u, kv * v, deg, 0.0, 0.0),
                "divided by the tiling": _rot(u / ku, v / kv, deg)}
    if deg != 180:
        mistakes["rotation sign"] = _rot(ku * u, kv * v, -deg)
    return right, mistakes


def _cyl_uv(q, s):
    return [0.5 + math.atan2(q[0], q[2]) / (2 * math.pi), (q[1] + s) / (2 * s)]


def cylinder(ex):
    s = ex.radius
    px, py, pz = ex.P

    def q_of(method):
        if method == "intermediate_normal":
            r = math.hypot(px, pz)
            return [px * s / r, py, pz * s / r]
        if method == "centroid":
            lam = s / math.hypot(px, pz)
            return [lam * px, lam * py, lam * pz]
        n = np.asarray(ex.N, float) / math.sqrt(sum(c * c for c in ex.N))
        # (px + t nx)^2 + (pz + t nz)^2 = s^2, the positive root
        a = n[0] ** 2 + n[2] ** 2
        b = 2 * (px * n[0] + pz * n[2])
        c = px * px + pz * pz - s * s
        t = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
        return [px + t * n[0], py + t * n[1], pz + t * n[2]]

    q = q_of(ex.method)
    right = _cyl_uv(q, s)
    mistakes = {"u and v swapped": right[::-1],
                "v from the middle": [right[0], q[1] / (2 * s)]}
    if q[2] != 0:
        mistakes["atan instead of atan2"] = [0.5 + math.atan(q[0] / q[2]) / (2 * math.pi),
                                             right[1]]
    for m in ("centroid", "intermediate_normal"):
        if m != ex.method:
            mistakes[f"O-mapped by the {m.replace('_', ' ')}"] = _cyl_uv(q_of(m), s)
    return right, mistakes


SPECS = {"TextureTransform": (texture, "uv"), "TwoPartMapping": (cylinder, "uv")}
GARBAGE = {"uv": ["uv", {"u": 1}, [[1, 2], [3]], [1, 2, 3], np.eye(2), [math.nan, 0]]}
exercises = harness.variants(ch14)


same = harness.same


globals().update(harness.common_tests(ch14, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(30, 8)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        harness.assert_accepted(ex, [right, list(np.round(right, 3))])


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert np.allclose(worked.answer, solve(ex)[0]) and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_every_method_is_asked():
    methods = {ex.method for ex in exercises("TwoPartMapping")}
    assert methods == {"normal", "centroid", "intermediate_normal"}
    for ex in exercises("TwoPartMapping"):
        assert math.hypot(ex.P[0], ex.P[2]) < ex.radius          # the object is inside
