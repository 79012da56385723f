"""Tests of the model-form exercises (course_lib/exercises/_ch06/forms.py), on
tests/exercise_harness.py.

The counts of each described solid are rebuilt here from the shape by hand rules typed below
(a p-sided prism hole adds 2p vertices, 3p edges, p walls and 2 rings; a pocket the same
vertices and edges, p walls and a floor, and 1 ring; a box 8, 12, 6), the right answers and
every slip from Euler-Poincaré written out here; the model forms from a table typed here.
"""
from types import SimpleNamespace

import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch06 import forms as module

ch06 = SimpleNamespace(EXERCISES=[module.BRepEulerRings, module.ChooseModelForm],
                       BRepEulerRings=module.BRepEulerRings,
                       ChooseModelForm=module.ChooseModelForm)


def counts(ex):
    p, t, k, b = ex.sides, ex.n_through, ex.n_pocket, ex.n_boxes
    V = 8 * b + 2 * p * (t + k)
    E = 12 * b + 3 * p * (t + k)
    F = 6 * b + p * t + (p + 1) * k
    return V, E, F, 2 * t + k, b, t


def brep(ex):
    V, E, F, R, S, H = counts(ex)
    assert (V, E, F, R, S, H) == (ex.V, ex.E, ex.F, ex.R, ex.S, ex.H)
    assert V - E + F - R == 2 * (S - H)
    if ex.ask == "H":
        right = S - (V - E + F - R) // 2
        slips = {"rings forgotten": S - (V - E + F) / 2,
                 "rings as boundary loops": S - (V - E + F + R) / 2,
                 "not halved": S - (V - E + F - R)}
        if S > 1:
            slips["one shell"] = 1 - (V - E + F - R) / 2
    else:
        right = V + F - R - 2 * (S - H)
        slips = {"rings forgotten": V + F - 2 * (S - H),
                 "rings as boundary loops": V + F + R - 2 * (S - H),
                 "holes ignored": V + F - R - 2 * S}
        if S > 1:
            slips["one shell"] = V + F - R - 2 * (1 - H)
    return right, {k: v for k, v in slips.items() if float(v).is_integer()}


RIGHT_FORM = {"realtime": "mesh", "scan": "point cloud", "volume": "voxels",
              "booleans": "csg", "freeform": "parametric", "inside": "implicit",
              "topology": "brep"}


def choose(ex):
    right = RIGHT_FORM[ex.need]
    return right, {f"said {m}": m for m in ex.menu if m != right}


SPECS = {"BRepEulerRings": (brep, "number"), "ChooseModelForm": (choose, "name")}
GARBAGE = {"number": ["I", {"I": 1}, [1, 2], [[1], [2, 3]]],
           "name": [3, "teapot", ["mesh", "voxels"], {"mesh": 1}]}
exercises = harness.variants(ch06)


def same(a, b, form=None):
    if form == "name" or isinstance(a, str):
        return a == b
    return harness.same(a, b)


globals().update(harness.common_tests(ch06, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(30, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        answers = [right, float(right)] if form == "number" else [right, right.upper(),
                                                                  [right], " " + right]
        harness.assert_accepted(ex, answers)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(20)):
        worked = ex.worked()
        assert worked.answer == solve(ex)[0] and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_every_kind_of_solid_and_question_appears():
    seen = {(ex.ask, ex.n_through > 0, ex.n_pocket > 0, ex.n_boxes > 1)
            for ex in exercises("BRepEulerRings")}
    assert {"H", "E"} == {s[0] for s in seen}
    assert any(s[1] and s[2] for s in seen) and any(not s[1] for s in seen)
    assert any(s[3] for s in seen)


def test_every_need_and_every_form_appear():
    menus = [ex for ex in exercises("ChooseModelForm")]
    assert {ex.need for ex in menus} == set(RIGHT_FORM)
    assert all(len(set(ex.menu)) == 4 and ex.expected in ex.menu for ex in menus)
