"""Tests of the SSAO exercises (course_lib/exercises/_ch12/ssao.py), on tests/exercise_harness.py.

The right answers and every anticipated mistake are recomputed here from the rules typed out
below with plain Python loops (not with the module's helper): a sample is occluded when the
stored depth is nearer the camera than the sample by more than the bias and, with the range
check, within the radius of the pixel's depth; the sample count solves
p(1 - p) / (n^2 k) <= sigma^2 for the smallest whole k.
"""
import math
from types import SimpleNamespace

import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch12 import ssao as module

ch12 = SimpleNamespace(EXERCISES=[module.SSAOPixel, module.SSAOSampleCount],
                       SSAOPixel=module.SSAOPixel, SSAOSampleCount=module.SSAOSampleCount)


def pixel(ex):
    rows = list(zip(ex.d_sample.tolist(), ex.d_stored.tolist()))
    k = len(rows)

    def count(bias, range_check, reverse=False):
        n = 0
        for q, s in rows:
            hidden = (s > q + bias) if reverse else (s < q - bias)
            if range_check and abs(s - ex.d_pixel) > ex.radius:
                hidden = False
            n += hidden
        return n

    right = 1 - count(ex.bias, True) / k
    return right, {
        "occlusion instead of visibility": 1 - right,
        "bias ignored": 1 - count(0.0, True) / k,
        "range check ignored": 1 - count(ex.bias, False) / k,
        "comparison reversed": 1 - count(ex.bias, True, reverse=True) / k,
    }


def sample_count(ex):
    var = ex.p * (1 - ex.p)
    n2 = ex.n ** 2

    def smallest(v, m):
        k = 1
        while v / (m * k) > ex.sigma ** 2 * (1 + 1e-12):
            k += 1
        return k

    right = smallest(var, n2)
    mistakes = {"variance 1": smallest(1.0, n2)}
    mistakes["no square"] = math.ceil(math.sqrt(var) / ex.sigma - 1e-9)
    if ex.kind == "known":
        mistakes["worst case used"] = smallest(0.25, 1)
    if ex.kind == "blur":
        mistakes["blur ignored"] = smallest(0.25, 1)
    exact = var / (ex.sigma ** 2 * n2)
    if abs(exact - round(exact)) > 1e-6:
        mistakes["rounded down"] = math.floor(exact)
    return right, mistakes


SPECS = {"SSAOPixel": (pixel, "number"), "SSAOSampleCount": (sample_count, "number")}
GARBAGE = {"number": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]}
exercises = harness.variants(ch12)


same = harness.same


globals().update(harness.common_tests(ch12, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(30, 5)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        harness.assert_accepted(ex, [right, round(right, 3)])


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert abs(worked.answer - solve(ex)[0]) < 1e-9 and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_pixel_tables_have_every_kind_of_sample():
    for ex in exercises("SSAOPixel"):
        q, s = ex.d_sample, ex.d_stored
        in_front = s < q - ex.bias
        far = abs(s - ex.d_pixel) > ex.radius
        assert (in_front & ~far).any() and (in_front & far).any()    # occluders and halos
        assert ((s >= q - ex.bias) & (s < q)).any()                   # within the bias
        assert (s > q).any()                                          # behind the sample
