"""Tests of the chapter 10 exercises on good plots (course_lib.exercises._ch10.integrity).

The right answers are computed here independently of the checkers (which call
course_lib.dataviz.integrity): lie factors by the closed forms v1 / (v1 - b) for truncated bars
and ((1 + e)^k - 1) / e for shapes scaled in k dimensions; data-ink ratios by plain sums;
banking by exact fractions (Python's ``fractions`` and ``statistics.median``); the visual
variable by a table typed here. Every anticipated slip is rebuilt the same way and must be
named by its diagnosis.
"""
import math
import statistics
from fractions import Fraction
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from course_lib.exercises._ch10 import integrity as module

CLASSES = [module.LieFactor, module.DataInkRatio, module.BankingAspect,
           module.ChooseVisualVariable]
ch10 = SimpleNamespace(EXERCISES=CLASSES, **{c.__name__: c for c in CLASSES})


def lie_factor(ex):
    v1, v2 = ex.values
    e = (v2 - v1) / v1                                        # signed relative change
    if ex.kind == "truncated":
        b = ex.baseline
        right = v1 / (v1 - b)
        s1, s2 = v1 - b, v2 - b
    else:
        k = {"circle": 2, "icon": 2, "cube": 3}[ex.kind]
        right = abs((1 + e) ** k - 1) / abs(e)
        s1, s2 = v1 ** k, v2 ** k
    mistakes = {
        "ratio instead of relative change": (s2 / s1) / (v2 / v1),
        "inverted": 1 / right,
        "relative to the second value": (abs(s2 - s1) / s2) / (abs(v2 - v1) / v2),
    }
    mistakes["bars from 0" if ex.kind == "truncated" else "size not raised to a power"] = 1.0
    if ex.kind == "cube":
        mistakes["area instead of volume"] = abs((1 + e) ** 2 - 1) / abs(e)
    return right, mistakes


SIDES = "the 3D side and top faces of the bars"


def data_ink(ex):
    [data_name] = ex.data
    d = ex.elements[data_name]
    left = {n: v for n, v in ex.elements.items() if n not in ex.erase}
    t = sum(left.values())
    mistakes = {"over non-data ink": d / (t - d), "non-data share": (t - d) / t}
    if SIDES in left:
        mistakes["3D faces counted as data"] = (d + left[SIDES]) / t
    if ex.erase:
        mistakes["erased ink still counted"] = d / sum(ex.elements.values())
    return d / t, mistakes


def banking(ex):
    xs = [Fraction(int(v)) for v in ex.x]
    ys = [Fraction(int(v)) for v in ex.y]
    rx, ry = max(xs) - min(xs), max(ys) - min(ys)
    dx = [b - a for a, b in zip(xs, xs[1:])]
    dy = [b - a for a, b in zip(ys, ys[1:])]
    s = [abs(q) / ry * rx / p for p, q in zip(dx, dy)]
    right = 1 / statistics.median(s)
    signed = statistics.median([q / ry * rx / p for p, q in zip(dx, dy)])
    mistakes = {
        "width over height": statistics.median(s),
        "ranges not used": 1 / statistics.median([abs(q) / p for p, q in zip(dx, dy)]),
        "mean instead of median": 1 / (sum(s) / len(s)),
    }
    if signed != 0:
        mistakes["signed slopes"] = 1 / abs(signed)
    return float(right), {k: float(v) for k, v in mistakes.items()}


#: The level of each scenario's attribute, by words of it (typed by hand).
LEVEL_BY_WORDS = {
    "party": "nominal", "species": "nominal", "continent": "nominal", "blood group": "nominal",
    "land use": "nominal", "brand": "nominal", "programming language": "nominal",
    "type of each fault": "nominal", "grade": "ordinal", "risk level": "ordinal",
    "satisfaction": "ordinal", "hurricane category": "ordinal", "education level": "ordinal",
    "air-quality class": "ordinal", "star rating": "ordinal", "class of each hotel": "ordinal",
    "population of each city": "quantitative", "rainfall": "quantitative",
    "number of goals": "quantitative", "population of each country": "quantitative",
    "passengers": "quantitative", "energy": "quantitative", "weight": "quantitative",
    "sales": "quantitative",
}


def visual_variable(ex):
    [level] = [v for w, v in LEVEL_BY_WORDS.items() if w in ex.attribute]
    # the variable that suits the level: size for amounts, lightness for an order, a hue or
    # a shape (whichever is offered) for categories
    if level == "quantitative":
        right = "size"
    elif level == "ordinal":
        right = "value"
    else:
        [right] = [v for v in ex.menu if v in ("colour hue", "shape")]
    return right, {f"{v} for {level} data": v for v in ex.menu if v != right}


SPECS = {"LieFactor": (lie_factor, "number"), "DataInkRatio": (data_ink, "number"),
         "BankingAspect": (banking, "number"), "ChooseVisualVariable": (visual_variable,
                                                                        "choice")}
GARBAGE = {"number": ["7", {"x": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf],
           "choice": ["motion", 1, ["size"], {"a": 1}, b"size", "", "position"]}

exercises = harness.variants(ch10)


def same(a, b, form):
    if form == "choice":
        return a == b
    return harness.gap(a, b) < harness.SAME


globals().update(harness.common_tests(ch10, SPECS, GARBAGE, exercises, at_least=4))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "choice":
            aliases = {"colour hue": "hue", "value": "lightness", "size": "Size", "shape": "SHAPE"}
            answers = [right, right.upper(), f" {right} ", aliases[right]]
        else:
            answers = [right, round(right, 4), harness.significant(right, 3)]
        harness.assert_accepted(ex, answers)


def test_wrong_numbers_get_the_advice():
    for name in ("LieFactor", "DataInkRatio", "BankingAspect"):
        checked, advised = harness.advice_counts(
            exercises(name, range(20)), SPECS[name][0],
            lambda ex, right: [right * 1.61 + 0.77])
        assert advised == checked > 0


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("LieFactor"):
        assert all(v == int(v) for v in ex.values) and ex.baseline == int(ex.baseline)
        assert ex.baseline < min(ex.values)
        assert (ex.baseline > 0) == (ex.kind == "truncated")
    for ex in exercises("DataInkRatio"):
        assert all(v % 5 == 0 for v in ex.elements.values())
        assert set(ex.erase) <= set(ex.elements) and not set(ex.erase) & set(ex.data)
    for ex in exercises("BankingAspect"):
        right, _ = banking(ex)
        assert round(right, 2) == pytest.approx(right, abs=1e-12)
        assert len(ex.x) % 2 == 0                       # an odd number of segments
        assert np.all(ex.y == np.round(ex.y))


def test_every_kind_and_scenario_is_asked():
    kinds = {module.LieFactor(seed=s).kind for s in range(60)}
    assert kinds == {"truncated", "circle", "icon", "cube"}
    asked = {module.ChooseVisualVariable(seed=s).attribute for s in range(400)}
    assert asked == {a for _, a, _ in module.VARIABLE_SCENARIOS}
    for _, attribute, level in module.VARIABLE_SCENARIOS:
        assert [v for w, v in LEVEL_BY_WORDS.items() if w in attribute] == [level], attribute
    assert any(module.DataInkRatio(seed=s).erase for s in range(20))
    assert any(SIDES in module.DataInkRatio(seed=s).elements for s in range(40))


def test_a_wrong_variable_is_told_why_it_misleads():
    for ex in exercises("ChooseVisualVariable", range(40)):
        for v in ex.menu:
            if v != ex.expected:
                fb = ex.check(v)
                assert fb.status == "wrong" and ex.level in fb.message
                assert "Better: " + ex.expected in fb.message
