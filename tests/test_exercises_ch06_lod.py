"""Tests of the level-of-detail exercises (course_lib/exercises/_ch06/lod.py), on
tests/exercise_harness.py.

The right answers and every anticipated slip are recomputed here from the rules typed out below
with plain loops: a level's screen-space error is eps * (H / 2) / (d * tan(fov / 2)) pixels and the
renderer takes the largest level index within the tolerance; a progressive mesh's split j undoes
collapse K - j + 1, adding one vertex and that collapse's faces back.
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch06 import lod as module

ch06 = SimpleNamespace(EXERCISES=[module.LODChoice, module.SplitRecord],
                       LODChoice=module.LODChoice, SplitRecord=module.SplitRecord)


def lod_choice(ex):
    fov = math.radians(ex.fov_deg)

    def choose(pixels_of):
        best = 0
        for i, e in enumerate(ex.errors):
            if pixels_of(e) <= ex.tolerance:
                best = i
        return best

    H, d = ex.height, ex.distance
    right = choose(lambda e: e * (H / 2) / (d * math.tan(fov / 2)))
    mistakes = {"tan of the full angle": choose(lambda e: e * (H / 2) / (d * math.tan(fov))),
                "full viewport": choose(lambda e: e * H / (d * math.tan(fov / 2))),
                "finest instead of coarsest": 0}
    if right + 1 < len(ex.errors):
        mistakes["first level above the tolerance"] = right + 1
    return right, mistakes


def split_record(ex):
    K = len(ex.removed)
    undone = [K - s for s in range(1, ex.j + 1)]          # 0-based collapses, last first
    restored = ex.removed[undone[-1]]
    added = sum(ex.faces_removed[k] for k in undone)
    V, F = ex.V0 + ex.j, ex.F0 + added
    right = [restored, V, F]
    return right, {
        "record read forwards": [ex.removed[ex.j - 1], V, F],
        "kept instead of removed": [ex.kept[undone[-1]], V, F],
        "vertices subtracted": [restored, ex.V0 - ex.j, F],
        "two vertices per split": [restored, ex.V0 + 2 * ex.j, F],
        "two faces per split": [restored, V, ex.F0 + 2 * ex.j],
        "faces read forwards": [restored, V, ex.F0 + sum(ex.faces_removed[:ex.j])],
        "faces subtracted": [restored, V, ex.F0 - added],
    }


SPECS = {"LODChoice": (lod_choice, "number"), "SplitRecord": (split_record, "numbers")}
GARBAGE = {"number": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf],
           "numbers": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan, 1, 2], 1.5]}
exercises = harness.variants(ch06)
same = harness.same

globals().update(harness.common_tests(ch06, SPECS, GARBAGE, exercises, at_least=2,
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
        assert np.allclose(worked.answer, solve(ex)[0]) and ex.check(worked.answer)
        assert len(ex.hints()) >= 3
    assert len({str(ex.worked()) + " ".join(ex.worked().steps)
                for ex in exercises(name, range(20))}) >= 10


def test_lod_choice_levels_are_not_borderline():
    """No level's screen-space error lies within 6 % of the tolerance (rounding-proof)."""
    for ex in exercises("LODChoice"):
        fov = math.radians(ex.fov_deg)
        px = np.asarray(ex.errors[1:]) * ex.height / (2 * ex.distance * math.tan(fov / 2))
        assert np.abs(px / ex.tolerance - 1).min() > 0.06


def test_lod_choice_agrees_with_the_library():
    from course_lib.mesh import select_level
    for ex in exercises("LODChoice", range(40)):
        assert select_level(ex.errors, ex.distance, math.radians(ex.fov_deg), ex.height,
                            ex.tolerance) == ex.expected


def test_split_record_is_a_legal_record():
    """Each removed vertex is gone afterwards: never kept or removed by a later collapse."""
    for ex in exercises("SplitRecord"):
        for k, r in enumerate(ex.removed):
            assert r not in ex.kept[k + 1:] and r not in ex.removed[k + 1:]
            assert r != ex.kept[k]
