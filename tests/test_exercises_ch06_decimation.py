"""Tests of the decimation exercises (course_lib/exercises/_ch06/decimation.py).

The answers and the anticipated mistakes are recomputed here with plain Python loops:
grid cells by floor(x / h), degenerate triangles (a repeated cell) dropped, repeats counted
once; centroid heights (v + a_i + a_(i+1)) / 3 averaged with the given areas; nearest-point
distances between two point sets, the larger one-sided maximum.
"""
import math
from types import SimpleNamespace

import numpy as np

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch06 import decimation as module

NAMES = ("ClusterSurvivors", "DecimationCriterion", "HausdorffByHand")
ch06 = SimpleNamespace(EXERCISES=[getattr(module, n) for n in NAMES],
                       **{n: getattr(module, n) for n in NAMES})


def survivors(ex):
    h = ex.h
    cell = [(math.floor(x / h), math.floor(y / h)) for x, y in ex.points.tolist()]
    kept, every, nondegenerate = set(), set(), 0
    for t in ex.triangles.tolist():
        cs = [cell[i] for i in t]
        every.add(tuple(sorted(cs)))
        if len(set(cs)) == 3:
            nondegenerate += 1
            kept.add(tuple(sorted(cs)))
    return len(kept), {"duplicates kept": nondegenerate, "degenerate kept": len(every),
                       "nothing removed": len(ex.triangles)}


def criterion(ex):
    v, ring, areas, n = ex.v.tolist(), ex.ring.tolist(), ex.areas.tolist(), ex.normal.tolist()
    k = len(ring)
    cent = [[(v[d] + ring[i][d] + ring[(i + 1) % k][d]) / 3 for d in range(3)] for i in range(k)]

    def dist(p):
        return abs(sum(n[d] * (v[d] - p[d]) for d in range(3)))

    xbar = [sum(a * c[d] for a, c in zip(areas, cent)) / sum(areas) for d in range(3)]
    mean_c = [sum(c[d] for c in cent) / k for d in range(3)]
    mean_a = [sum(a[d] for a in ring) / k for d in range(3)]
    nearest = min(math.dist(v, a) for a in ring)
    return dist(xbar), {"unweighted": dist(mean_c), "distance to a neighbour": nearest,
                        "mean of neighbours": dist(mean_a)}


def hausdorff(ex):
    A, B = ex.A.tolist(), ex.B.tolist()
    ab = max(min(math.dist(a, b) for b in B) for a in A)
    ba = max(min(math.dist(a, b) for a in A) for b in B)
    pairs = [math.dist(a, b) for a in A for b in B]
    return max(ab, ba), {"one-sided only": min(ab, ba), "min instead of max": min(pairs),
                         "max of all pairs": max(pairs)}


SPECS = {"ClusterSurvivors": (survivors, "number"), "DecimationCriterion": (criterion, "number"),
         "HausdorffByHand": (hausdorff, "number")}
GARBAGE = {"number": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]}
exercises = harness.variants(ch06)
same = harness.same

globals().update(harness.common_tests(ch06, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(30, 5)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


def test_right_answer_is_accepted():
    for name, (solve, _) in SPECS.items():
        for ex in exercises(name):
            right, _ = solve(ex)
            harness.assert_accepted(ex, [right, round(right, 3)])


def test_worked_solution_and_hints():
    for name, (solve, _) in SPECS.items():
        for ex in exercises(name, range(20)):
            worked = ex.worked()
            assert abs(worked.answer - solve(ex)[0]) < 1e-9 and ex.check(worked.answer)
            assert len(ex.hints()) >= 3


def test_criterion_data_match_the_geometry():
    """The given (rounded) areas and normal are those of the star's triangles."""
    for ex in exercises("DecimationCriterion", range(10)):
        a, b = ex.ring - ex.v, np.roll(ex.ring, -1, axis=0) - ex.v
        c = np.cross(a, b)
        assert np.allclose(ex.areas, np.linalg.norm(c, axis=1) / 2, atol=0.005)
        n = c.sum(axis=0)
        assert np.allclose(ex.normal, n / np.linalg.norm(n), atol=0.0005)
