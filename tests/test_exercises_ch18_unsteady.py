"""Tests of the unsteady-flow and LIC exercises (course_lib/exercises/_ch18/unsteady.py), on
tests/exercise_harness.py.

The right answers and every anticipated slip are recomputed here, independently: the line of
each scenario from key words typed by hand; two Euler steps of a pathline written out with
plain floats (and the frozen-time streamline, the early clock, one step, the old position);
the LIC value of a pixel as a plain loop over the table (and the whole trace, forward half,
centre left out, not renormalised, box instead of Hann).
"""
import math
from types import SimpleNamespace

import pytest

import exercise_harness as harness
from course_lib.exercises._ch18 import unsteady as module

CLASSES = [module.FlowLineKind, module.PathlineEulerSteps, module.LICPixel]
ch18 = SimpleNamespace(EXERCISES=CLASSES, **{c.__name__: c for c in CLASSES})
KINDS = ("streamline", "pathline", "streakline", "timeline")

#: The line of each scenario, by words of it (typed by hand).
LINE_BY_WORDS = {
    "fixed nozzle": "streakline", "chimney": "streakline", "from one hole": "streakline",
    "again and again": "streakline", "pen held still": "streakline", "grinding wheel":
    "streakline", "GPS": "pathline", "long camera exposure": "pathline", "drifter buoy":
    "pathline", "one tagged tracer": "pathline", "leaf": "pathline", "advancing the time":
    "pathline", "straight wire": "timeline", "Twenty floats": "timeline", "painted across":
    "timeline", "along a segment at t0": "timeline", "rubber ducks": "timeline", "Skaters":
    "timeline", "freezes the velocity": "streamline", "PIV": "streamline", "weather map":
    "streamline", "held fixed": "streamline", "iron-filing": "streamline", "one time step":
    "streamline",
}


def by_words(text):
    [found] = [kind for words, kind in LINE_BY_WORDS.items() if words in text]
    return found


def line_kind(ex):
    right = by_words(ex.scenario)
    return right, {f"{k} instead of {right}": k for k in KINDS if k != right}


def euler(ex):
    a, b, c, d = ex.a, ex.b, ex.c, ex.d

    def v(x, y, t):
        return (a * y + b * t, c * x + d * t)

    def step(p, vel):
        return (p[0] + ex.h * vel[0], p[1] + ex.h * vel[1])

    p0, t0, h = (float(ex.p[0]), float(ex.p[1])), ex.t0, ex.h
    p1 = step(p0, v(*p0, t0))
    right = step(p1, v(*p1, t0 + h))
    q1 = step(p0, v(*p0, t0 + h))
    return list(right), {
        "frozen time": list(step(p1, v(*p1, t0))),
        "time ahead": list(step(q1, v(*q1, t0 + 2 * h))),
        "one step": list(p1),
        "old position": list(step(p1, v(*p0, t0 + h))),
    }


def lic_pixel(ex):
    rows = [(int(k), float(n)) for k, n in zip(ex.offsets, ex.noise)]
    L = ex.L

    def weight(k, kernel, half):
        if abs(k) > half:
            return 0.0
        return 1.0 if kernel == "box" else 0.5 * (1 + math.cos(math.pi * k / half))

    def value(kernel, half, keep=lambda k: True, renormalise=True):
        total = used = full = 0.0
        for k, n in rows:
            if not keep(k):
                continue
            w = weight(k, kernel, half)
            full += w
            if not math.isnan(n):
                total += w * n
                used += w
        return total / (used if renormalise else full)

    right = value(ex.kernel, L)
    longest = max(abs(k) for k, _ in rows)
    mistakes = {"whole trace": value("box", longest),
                "forward only": value(ex.kernel, L, keep=lambda k: k >= 0),
                "centre left out": value(ex.kernel, L, keep=lambda k: k != 0)}
    if any(math.isnan(n) for k, n in rows if abs(k) <= L):
        mistakes["not renormalised"] = value(ex.kernel, L, renormalise=False)
    if ex.kernel == "hann":
        mistakes["box instead of hann"] = value("box", L)
    return right, mistakes


SPECS = {"FlowLineKind": (line_kind, "choice"), "PathlineEulerSteps": (euler, "point"),
         "LICPixel": (lic_pixel, "number")}
GARBAGE = {"choice": ["smoke", 1, ["pathline"], {"a": 1}, b"pathline", ""],
           "point": ["I", {"I": 1}, [1, 2, 3], [[1], [2, 3]], [math.nan, 1], math.inf],
           "number": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]}
exercises = harness.variants(ch18)


def same(a, b, form):
    if form == "choice":
        return a == b
    return harness.same(a, b)


globals().update(harness.common_tests(ch18, SPECS, GARBAGE, exercises, at_least=3))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "choice":
            answers = [right, right.upper(), f" {right} ", right[:-4] + " " + right[-4:]]
        elif form == "point":
            answers = [right, tuple(right), [round(x, 3) for x in right]]
        else:
            answers = [right, round(right, 3)]
        harness.assert_accepted(ex, answers)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, form = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        right = solve(ex)[0]
        if form == "choice":
            assert worked.answer == right
        else:
            assert harness.gap(worked.answer, right) < 1e-9
        assert ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_scenarios_agree_with_the_typed_table():
    kinds = [kind for _, kind in module.FLOW_LINE_SCENARIOS]
    for text, kind in module.FLOW_LINE_SCENARIOS:
        assert by_words(text) == kind, text
    assert set(kinds) == set(KINDS) and min(kinds.count(k) for k in KINDS) >= 6


def test_pathline_variants_are_really_time_dependent():
    for ex in exercises("PathlineEulerSteps", range(40)):
        assert (ex.b, ex.d) != (0.0, 0.0)
        right, slips = euler(ex)
        assert harness.gap(right, slips["frozen time"]) > 1e-6


def test_lic_tables_sometimes_cross_the_border_and_use_both_kernels():
    seen = {"hann": False, "box": False, "border": False}
    for ex in exercises("LICPixel", range(60)):
        seen[ex.kernel] = True
        seen["border"] |= any(math.isnan(n) for k, n in zip(ex.offsets, ex.noise)
                              if abs(k) <= ex.L)
    assert all(seen.values())
