"""Tests of the texture-hierarchy exercises (course_lib/exercises/_ch14/hierarchies.py), on
tests/exercise_harness.py.

The right answers and every anticipated mistake are recomputed here with plain loops over the
levels (halve both sides with the floor rule, at least 1, down to 1 x 1) and the closed forms of
the geometric series, not with course_lib.texturing.
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SAME, SEEDS, Either
from course_lib.exercises._ch14 import hierarchies as module
from course_lib.exercises.core import gap

ch14 = SimpleNamespace(EXERCISES=[module.PyramidMemory, module.ClipmapMemory],
                       PyramidMemory=module.PyramidMemory, ClipmapMemory=module.ClipmapMemory)
MIB = 2 ** 20


def levels(w, h):
    out = [(w, h)]
    while out[-1] != (1, 1):
        a, b = out[-1]
        out.append((max(1, a // 2), max(1, b // 2)))
    return out


def replaced(right, index, *values):
    out = []
    for value in values:
        answer = np.array(right, dtype=float)
        answer[index] = value
        out.append(answer)
    return Either(out)


def pyramid_memory(ex):
    W, H = ex.width, ex.height
    lv = levels(W, H)
    texels = sum(a * b for a, b in lv)
    exact, bound = 4 * texels, 4 * W * H * 4 / 3
    right = [exact, bound]
    base = 4 * W * H
    return right, {
        "forgot the 1x1 level": replaced(right, 0, exact - 4),
        "base only": Either(replaced(right, 0, base) + replaced(right, 1, base)),
        "halves instead of quarters": Either(
            replaced(right, 0, 4 * sum(W * H / 2 ** k for k in range(len(lv))))
            + replaced(right, 1, 2 * base)),
        "texels, not bytes": Either(replaced(right, 0, texels) + replaced(right, 1, W * H * 4 / 3)),
        "the 3D bound": replaced(right, 1, base * 8 / 7),
    }


def clipmap_memory(ex):
    N, c = ex.size, ex.clip
    n, m = int(math.log2(N)), int(math.log2(c))
    clipped = n - m
    tail = (4 ** (m + 1) - 1) // 3                     # c^2 + (c/2)^2 + ... + 1
    full = (4 ** (n + 1) - 1) // 3
    right = [clipped, 4 * (clipped * c * c + tail) / MIB, 4 * full / MIB]
    return right, {
        "the level of side c counted as clipped": replaced(right, 0, clipped + 1),
        "every level": replaced(right, 0, n + 1),
        "tail forgotten": replaced(right, 1, 4 * clipped * c * c / MIB),
        "no clipping": replaced(right, 1, 4 * full / MIB),
        "tail as one window": replaced(right, 1, 4 * (clipped + 1) * c * c / MIB),
        "base only": replaced(right, 2, 4 * N * N / MIB),
        "halves instead of quarters": replaced(right, 2, 8 * N * N / MIB),
    }


SPECS = {"PyramidMemory": (pyramid_memory, "two"), "ClipmapMemory": (clipmap_memory, "three")}
GARBAGE = {"two": ["m", {"m": 1}, [1], [[1, 2], [3, 4]], [1, math.nan], [1, 2, 3]],
           "three": ["j", {"j": 1}, [1, 2], [[1, 2, 3], [4, 5, 6]], [1, math.nan, 2],
                     [1, 2, 3, 4]]}
exercises = harness.variants(ch14)

globals().update(harness.common_tests(ch14, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(30, 8)))
test_mistakes_are_diagnosed = harness.mistakes_test(
    SPECS, exercises, lambda a, b, form: gap(a, b) < SAME, key_seeds=SEEDS)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert gap(worked.answer, solve(ex)[0]) < 1e-9 and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_whole_numbers_are_compared_exactly():
    for name, index in (("PyramidMemory", 0), ("ClipmapMemory", 0)):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(40)):
            right = np.array(solve(ex)[0], dtype=float)
            assert ex.check(list(right)).status == "correct"
            for delta in (1, -1, 0.001):
                nearly = right.copy()
                nearly[index] += delta
                assert ex.check(nearly).status == "wrong", (ex, nearly)


def test_variants_cover_square_and_oblong_textures():
    shapes = {(ex.width == ex.height) for ex in exercises("PyramidMemory")}
    assert shapes == {True, False}
    assert len({(ex.size, ex.clip) for ex in exercises("ClipmapMemory")}) >= 10
