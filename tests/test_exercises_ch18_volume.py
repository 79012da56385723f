"""Tests of the chapter 18 exercises on the asymptotic decider, central-difference normals and
the order of splats (course_lib.exercises._ch18.deciders and .volume_methods).

The right answers and every anticipated slip are recomputed here from the formulas typed out
below with plain Python (never with course_lib.scivis): the saddle value of the bilinear
interpolant (f0 f2 - f1 f3)/(f0 + f2 - f1 - f3), central differences, and front-to-back
compositing in the order of p . d.
"""
import math
import types

import exercise_harness as harness
from course_lib.exercises._ch18 import deciders, volume_methods

_CLASSES = [deciders.AsymptoticDecider, volume_methods.CentralDifferenceNormal,
            volume_methods.SplatOrder]
ch = types.SimpleNamespace(EXERCISES=_CLASSES, **{cls.__name__: cls for cls in _CLASSES})


def _pair(f, c, value):
    side = [k for k in range(4) if (f[k] >= c) == (value >= c)]
    return side


def decider(ex):
    f, c = [float(v) for v in ex.corners], ex.level
    s = (f[0] * f[2] - f[1] * f[3]) / (f[0] + f[2] - f[1] - f[3])
    mean = sum(f) / 4
    right = [s] + _pair(f, c, s)
    other = [k for k in range(4) if k not in right[1:]]
    return right, {"mean": [mean] + _pair(f, c, mean), "numerator sign": [-s] + _pair(f, c, -s),
                   "wrong pair": [s] + other}


def normal(ex):
    p, m, h, f0 = list(ex.plus), list(ex.minus), ex.h, ex.centre
    g = [(a - b) / (2 * h) for a, b in zip(p, m)]
    length = math.sqrt(sum(x * x for x in g))
    fwd = [(a - f0) / h for a in p]
    lf = math.sqrt(sum(x * x for x in fwd))
    return [-x / length for x in g], {
        "forward difference": [-x / lf for x in fwd],
        "forgot /2h": [-(a - b) for a, b in zip(p, m)],
        "not normalised": [-x for x in g],
        "sign": [x / length for x in g],
    }


def splats(ex):
    depth = [sum(a * b for a, b in zip(pt, ex.view)) for pt in ex.centres.tolist()]
    order = sorted(range(3), key=lambda i: (depth[i], i))

    def comp(seq):
        C = A = 0.0
        for i in seq:
            C, A = C + (1 - A) * ex.alphas[i] * ex.colors[i], A + (1 - A) * ex.alphas[i]
        return float(C)
    return comp(order), {"reversed": comp(order[::-1]), "as listed": comp([0, 1, 2]),
                         "no transparency": float(sum(a * c for a, c in zip(ex.alphas,
                                                                           ex.colors)))}


SPECS = {"AsymptoticDecider": (decider, "vector"),
         "CentralDifferenceNormal": (normal, "vector"),
         "SplatOrder": (splats, "number")}
GARBAGE = {"number": ["C", {"C": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf],
           "vector": ["n", {"n": 1}, [[1], [2, 3]], [math.nan, 1, 2], [math.inf, 0, 0]]}

exercises = harness.variants(ch)
same = harness.same

globals().update(harness.common_tests(ch, SPECS, GARBAGE, exercises, at_least=3,
                                      distinct=(30, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


def test_worked_solutions_and_hints():
    for name, (solve, _) in SPECS.items():
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            worked = ex.worked()
            assert harness.gap(worked.answer, right) < 1e-9
            assert len(ex.hints()) >= 3 and len(worked.steps) >= 3


def test_deciders_disagree_in_some_variants_and_agree_in_others():
    disagree = [(sum(ex.corners) / 4 >= ex.level) != (decider(ex)[0][0] >= ex.level)
                for ex in exercises("AsymptoticDecider")]
    assert 20 < sum(disagree) < len(disagree) - 20
