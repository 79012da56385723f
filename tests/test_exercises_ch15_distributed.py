"""Tests of the distributed ray tracing exercises (course_lib/exercises/_ch15/distributed.py),
on tests/exercise_harness.py.

The answers are recomputed here independently: the domain of each situation from key phrases
typed below (what blurs, and why), and the soft-shadow intensity from the rule
I = A + D (N - k) / N with every anticipated slip written out.
"""
import math
from types import SimpleNamespace

import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch15 import distributed as module

ch15 = SimpleNamespace(EXERCISES=[module.DistributedDomainChoice, module.SoftShadowShare],
                       DistributedDomainChoice=module.DistributedDomainChoice,
                       SoftShadowShare=module.SoftShadowShare)

DOMAINS = ("pixel", "light", "reflection", "lens", "time")
#: a phrase of each situation -> the domain it needs
PHRASES = {
    "frosted globe": "light", "overcast sky": "light", "ceiling panel": "light",
    "reflects the window": "reflection", "polished wooden floor": "reflection",
    "chrome": "reflection",
    "portrait photo": "lens", "macro shot": "lens", "refocused": "lens",
    "smeared along its path": "time", "strobing": "time", "spinning": "time",
    "dotted line": "pixel", "moir": "pixel", "staircases": "pixel",
}


def domain(ex):
    found = [d for phrase, d in PHRASES.items() if phrase in ex.situation]
    assert len(found) == 1, ex.situation
    right = found[0]
    return right, {f"chose {d}": d for d in DOMAINS if d != right}


def share(ex):
    n, k, a, d = ex.n, len(ex.blocked), ex.ambient, ex.direct
    right = a + d * (n - k) / n
    return right, {
        "blocked share used": a + d * k / n,
        "ambient shadowed": (a + d) * (n - k) / n,
        "one shadow ray": a if ex.centre_blocked else a + d,
        "ambient forgotten": d * (n - k) / n,
    }


SPECS = {"DistributedDomainChoice": (domain, "domain"), "SoftShadowShare": (share, "number")}
GARBAGE = {"number": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf],
           "domain": ["camera", 3, ["lens"], {"lens": 1}, "shadow", 0.5]}
exercises = harness.variants(ch15)


def same(a, b, form):
    if form == "domain":
        return a == b
    return harness.same(a, b, form)


globals().update(harness.common_tests(ch15, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(30, 8)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


def test_right_answer_is_accepted():
    for ex in exercises("SoftShadowShare"):
        right, _ = share(ex)
        harness.assert_accepted(ex, [right, round(right, 3)])
    for ex in exercises("DistributedDomainChoice"):
        right, _ = domain(ex)
        harness.assert_accepted(ex, [right, right.upper(), f" {right} "])


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert worked.answer == pytest.approx(solve(ex)[0]) if name == "SoftShadowShare" \
            else worked.answer == solve(ex)[0]
        assert ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_every_situation_and_domain_is_asked():
    many = [module.DistributedDomainChoice(seed=s) for s in range(300)]
    asked = {phrase for ex in many for phrase in PHRASES if phrase in ex.situation}
    assert asked == set(PHRASES)
    assert {domain(ex)[0] for ex in many} == set(DOMAINS)


def test_wrong_choice_explains_the_right_effect():
    ex = module.DistributedDomainChoice(seed=3)
    right, _ = domain(ex)
    wrong = next(d for d in DOMAINS if d != right)
    fb = ex.check(wrong)
    assert fb.status == "wrong" and fb.diagnosis == f"chose {wrong}"
    names = {"pixel": "antialiasing", "light": "soft shadows", "reflection": "glossy",
             "lens": "depth of field", "time": "motion blur"}
    assert names[right] in fb.message
