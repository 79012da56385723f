"""Tests of the chapter 12 exercise on a light with separate ambient, diffuse and specular colours
(course_lib.exercises.ch12.PhongLightColours).

The right colour is recomputed here channel by channel from the model typed out with plain
numpy, from the cosines the statement gives (never with course_lib.shading, which the checker
calls with a light built from those colours and directions built from those cosines); every
anticipated slip is rebuilt from the question's attributes and must be named.
"""
import math
import types

import numpy as np
import pytest

import exercise_harness as harness
from course_lib.exercises import ch12
from exercise_harness import SEEDS

BEHIND = "light behind the surface"


def light_colours(ex):
    C, Ia, Id, Is, ks, n = ex.C, ex.Ia, ex.Id, ex.Is, ex.ks, ex.n
    lit = ex.NL > 0
    ambient = [C[k] * Ia[k] for k in range(3)]
    diffuse = [C[k] * Id[k] * ex.NL if lit else 0.0 for k in range(3)]
    specular = [ks * Is[k] * max(ex.RV, 0.0) ** n if lit else 0.0 for k in range(3)]
    right = np.array(ambient) + diffuse + specular
    if not lit:
        return right, {
            "ambient dropped too": np.zeros(3),
            "no clamp": np.array(ambient) + C * Id * ex.NL + ks * Is * ex.RV ** n,
            "specular on the dark side": np.array(ambient) + ks * Is * ex.RV ** n,
        }
    return right, {
        "no light ambient": np.array(diffuse) + specular,
        "diffuse colour in the highlight": np.array(ambient) + diffuse + ks * Id * ex.RV ** n,
        "specular colour in the diffuse term": np.array(ambient) + C * Is * ex.NL + specular,
        "highlight tinted": np.array(ambient) + diffuse + C * np.array(specular),
        "no exponent": np.array(ambient) + diffuse + ks * Is * ex.RV,
    }


SPECS = {"PhongLightColours": (light_colours, "vector")}
GARBAGE = {"vector": ["I", {"I": 1}, [[1, 2], [3]], [1, 2], np.eye(3), [math.nan, 0, 0]]}
module = types.SimpleNamespace(EXERCISES=(ch12.PhongLightColours,),
                               PhongLightColours=ch12.PhongLightColours)
exercises = harness.variants(module)


same = harness.same


globals().update(harness.common_tests(module, SPECS, GARBAGE, exercises, at_least=1,
                                      distinct=(30, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


def test_the_given_cosines_are_the_geometry_the_checker_shades():
    """The directions the checker builds have exactly the cosines the statement gives."""
    for ex in exercises("PhongLightColours", range(60)):
        L, V = ex._geometry
        N = np.array([0.0, 0.0, 1.0])
        R = 2 * (N @ L) * N - L
        assert math.isclose(N @ L, ex.NL, abs_tol=1e-12)
        assert math.isclose(R @ V, ex.RV, abs_tol=1e-12)
        assert V[2] > 0 and math.isclose(np.linalg.norm(V), 1, abs_tol=1e-12)


def test_boundary_variant_keeps_only_the_ambient_part():
    seen = 0
    for ex in exercises("PhongLightColours"):
        if ex.boundary == BEHIND:
            seen += 1
            assert ex.NL < 0 and np.allclose(ex.expected, ex.C * ex.Ia)
        else:
            assert ex.boundary is None and ex.NL > 0
    assert 0.08 * len(SEEDS) <= seen <= 0.25 * len(SEEDS)


def test_a_wrong_colour_gets_the_formula():
    for ex in exercises("PhongLightColours", range(20)):
        fb = ex.check(ex.expected + 0.37)
        assert fb.status == "wrong" and r"\odot" in fb.message


def test_hints_and_worked_solution_lead_to_the_answer():
    for ex in exercises("PhongLightColours", range(30)):
        hints = ex.hints()
        assert len(hints) >= 3 and all(len(h) > 40 for h in hints)
        worked = ex.worked()
        assert np.allclose(worked.answer, light_colours(ex)[0])


@pytest.mark.parametrize("seed", [0, 1, 7])
def test_numbers_are_tenths(seed):
    ex = ch12.PhongLightColours(seed=seed)
    for v in (ex.C, ex.Ia, ex.Id, ex.Is, [ex.ks, ex.NL, ex.RV]):
        assert np.allclose(np.asarray(v) * 10, np.round(np.asarray(v) * 10))
