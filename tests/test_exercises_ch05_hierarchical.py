"""Tests of the hierarchical occlusion culling exercises (course_lib/exercises/_ch05/hierarchical.py),
on tests/exercise_harness.py.

The right answers and every anticipated mistake are recomputed here with plain Python loops
from the rules typed out below (not with course_lib.visibility): a z-pyramid texel is the max of
its 2 x 2 block; the hierarchical test reads the finest level where the rectangle spans at most
2 texels each way and rejects when the nearest depth exceeds the largest texel; a query counts
the samples with z < stored; an occlusion-map texel is the mean of its block.
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch05 import hierarchical as module

NAMES = ["ZPyramidNextLevel", "HZBRejection", "OcclusionQueryCount", "HOMOpacity"]
ch05 = SimpleNamespace(EXERCISES=[getattr(module, n) for n in NAMES],
                       **{n: getattr(module, n) for n in NAMES})


def _block_reduce(d, reduce, r, c):
    return reduce([d[2 * r + a][2 * c + b] for a in range(2) for b in range(2)])


def next_level(ex):
    d = ex.depth.tolist()

    def level(reduce):
        return [[_block_reduce(d, reduce, r, c) for c in range(2)] for r in range(2)]

    right = level(max)
    return right, {"min instead of max": level(min),
                   "average instead of max": level(lambda v: sum(v) / 4),
                   "rows upside down": right[::-1]}


def _level0(ex):
    """Level 1 and level 2 as given; level k texel (r, c) of the pyramid (k = 1, 2)."""
    return {1: ex.level1.tolist(), 2: ex.level2.tolist()}


def rejection(ex):
    levels = _level0(ex)
    # level 2 is the max of level 1's blocks, as a z-pyramid must be
    for r in range(2):
        for c in range(2):
            assert levels[2][r][c] == _block_reduce(levels[1], max, r, c)

    def texels(rect, divide=True):
        i0, j0, i1, j1 = (int(v) for v in rect)
        k = 0
        while max((i1 >> k) - (i0 >> k), (j1 >> k) - (j0 >> k)) + 1 > 2:
            k += 1
        lv = levels[k]
        n = len(lv) - 1
        if divide:
            rows, cols = range(j0 >> k, (j1 >> k) + 1), range(i0 >> k, (i1 >> k) + 1)
        else:
            rows, cols = range(min(j0, n), min(j1, n) + 1), range(min(i0, n), min(i1, n) + 1)
        return [lv[j][i] for j in rows for i in cols]

    def decide(depths, pick, divide=True):
        return [1.0 if z > pick(texels(rect, divide)) else 0.0
                for rect, z in zip(ex.rects, depths)]

    right = decide(ex.z_near, max)
    return right, {"compared with the min": decide(ex.z_near, min),
                   "used the far depth": decide(ex.z_far, max),
                   "coordinates not divided": decide(ex.z_near, max, divide=False)}


def query(ex):
    i0, j0, i1, j1 = ex.rect
    cells = [float(ex.depth[j, i]) for j in range(j0, j1 + 1) for i in range(i0, i1 + 1)]
    right = sum(ex.z < v for v in cells)
    return right, {"counted hidden samples": sum(not ex.z < v for v in cells),
                   "<= instead of <": sum(ex.z <= v for v in cells),
                   "empty pixels skipped": sum(ex.z < v for v in cells if math.isfinite(v)),
                   "whole rectangle": len(cells)}


def hom(ex):
    r, c = ex.texel
    cov = ex.coverage.tolist()

    def block(rr):
        return [cov[4 * rr + a][4 * c + b] for a in range(4) for b in range(4)]

    level1 = [[_block_reduce(cov, lambda v: sum(v) / 4, 2 * r + a, 2 * c + b)
               for b in range(2)] for a in range(2)]
    right = sum(sum(row) for row in level1) / 4
    return right, {"max instead of average": max(block(r)),
                   "max at level 1": sum(v > 0 for row in level1 for v in row) / 4,
                   "count, not fraction": sum(block(r)),
                   "rows upside down": sum(block(1 - r)) / 16}


SPECS = {"ZPyramidNextLevel": (next_level, "matrix"), "HZBRejection": (rejection, "vector"),
         "OcclusionQueryCount": (query, "number"), "HOMOpacity": (hom, "number")}
GARBAGE = {"matrix": ["M", {"a": 1}, [[1, 2], [3]], [1, 2, 3], [[1, "a"], [0, 1]],
                      [[math.nan] * 2] * 2],
           "vector": ["p", {"x": 1}, [[1, 2], [3]], [1, 2], np.eye(3), [math.inf, 0, 0, 0]],
           "number": ["v", {"v": 1}, [1, 2], [[1], [2, 3]], math.nan]}
exercises = harness.variants(ch05)
same = harness.same

globals().update(harness.common_tests(ch05, SPECS, GARBAGE, exercises, at_least=4,
                                      distinct=(30, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        harness.assert_accepted(ex, [right, np.asarray(right, dtype=float).tolist()])


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert np.allclose(np.asarray(worked.answer, float), np.asarray(solve(ex)[0], float))
        assert ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_rejection_variants_have_both_decisions_and_both_levels():
    levels = set()
    for ex in exercises("HZBRejection"):
        right, _ = rejection(ex)
        assert 0 < sum(right) < 4
        for i0, j0, i1, j1 in ex.rects:
            k = 0
            while max((i1 >> k) - (i0 >> k), (j1 >> k) - (j0 >> k)) + 1 > 2:
                k += 1
            levels.add(k)
    assert levels == {1, 2}


def test_query_variants_have_ties_and_holes():
    for ex in exercises("OcclusionQueryCount", range(50)):
        i0, j0, i1, j1 = ex.rect
        block = ex.depth[j0:j1 + 1, i0:i1 + 1]
        assert (block == ex.z).any() and np.isinf(block).any()
