"""Tests of the chapter 12 radiometry exercises (course_lib.exercises._ch12.radiometry).

The right answers and every anticipated mistake are recomputed here from formulas typed out
with plain math (never with course_lib.shading, which the checkers call); the cone and region
solid angles are also integrated numerically with scipy, and the exitance too.
"""
import math
import types

import numpy as np
import pytest
from scipy.integrate import dblquad

import exercise_harness as harness
from exercise_harness import Either
from course_lib.exercises._ch12 import radiometry as mod

R = math.radians


def point_light(ex):
    I = ex.I
    if ex.kind == "angle":
        cos, sin, d = math.cos(R(ex.theta_deg)), math.sin(R(ex.theta_deg)), ex.d
    else:
        d = math.sqrt(ex.x ** 2 + ex.h ** 2)
        cos, sin = ex.h / d, ex.x / d
    right = I * max(cos, 0) / d ** 2
    mistakes = {"cosine forgotten": I / d ** 2, "sine for cosine": I * max(sin, 0) / d ** 2}
    if cos > 0:
        mistakes["1/d instead of 1/d^2"] = I * cos / d
    if ex.kind == "angle":
        mistakes["degrees as radians"] = I * math.cos(ex.theta_deg) / d ** 2
    else:
        mistakes["height for distance"] = I * max(cos, 0) / ex.h ** 2
    if cos < 0:
        mistakes["no clamp"] = I * cos / d ** 2
    return right, mistakes


def sphere_integral(t1, t2, p1, p2):
    value, _ = dblquad(lambda t, p: math.sin(t), p1, p2, t1, t2, epsabs=1e-12)
    return value


def solid_angle(ex):
    if ex.kind == "cone":
        a = R(ex.alpha_deg)
        right = 2 * math.pi * (1 - math.cos(a))
        assert abs(right - sphere_integral(0, a, 0, 2 * math.pi)) < 1e-9
        return right, {"small-angle formula": math.pi * a * a,
                       "hemisphere confusion": 4 * math.pi * (1 - math.cos(a)),
                       "degrees as radians": 2 * math.pi * (1 - math.cos(ex.alpha_deg)),
                       "sine for cosine": 2 * math.pi * (1 - math.sin(a))}
    if ex.kind == "patch":
        a_msr = ex.A_cm2 * 0.1          # cm² -> m² (1e-4), sr -> msr (1e3)
        t, d = R(ex.theta_deg), ex.d
        right = a_msr * math.cos(t) / d ** 2
        mistakes = {"cosine forgotten": a_msr / d ** 2, "d instead of d^2": a_msr * math.cos(t) / d,
                    "sine for cosine": a_msr * math.sin(t) / d ** 2}
        if ex.theta_deg:
            mistakes["degrees as radians"] = a_msr * math.cos(ex.theta_deg) / d ** 2
        return right, mistakes
    t1, t2, p1, p2 = (R(v) for v in (ex.theta1_deg, ex.theta2_deg, ex.phi1_deg, ex.phi2_deg))
    right = sphere_integral(t1, t2, p1, p2)
    return right, {"sin theta forgotten": (p2 - p1) * (t2 - t1),
                   "sine for cosine": (p2 - p1) * (math.sin(t2) - math.sin(t1)),
                   "full azimuth": 2 * math.pi * (math.cos(t1) - math.cos(t2))}


def radiance_intensity(ex):
    if ex.kind == "emitter":
        la = ex.L * ex.A_cm2 * 1e-4
        t = R(ex.theta_deg)
        right = la * math.cos(t)
        mistakes = {"pi factor": Either([math.pi * right, right / math.pi])}
        if ex.theta_deg:
            mistakes["cosine forgotten"] = la
            mistakes["sine for cosine"] = la * math.sin(t)
        return right, mistakes
    if ex.kind == "isotropic":
        f = ex.flux
        return f / (4 * math.pi), {"2 pi instead of 4 pi": f / (2 * math.pi),
                                   "pi factor": f / math.pi, "flux for intensity": f}
    L = ex.L
    right, _ = dblquad(lambda t, p: L * math.cos(t) * math.sin(t), 0, 2 * math.pi, 0, math.pi / 2)
    return right, {"hemisphere confusion": 2 * math.pi * L, "2 pi instead of 4 pi": 4 * math.pi * L,
                   "pi factor": L}


SPECS = {
    "PointLightIrradiance": (point_light, "number"),
    "SolidAngle": (solid_angle, "number"),
    "RadianceIntensity": (radiance_intensity, "number"),
}
NUMBER_GARBAGE = ["E", {"E": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]
GARBAGE = {"number": NUMBER_GARBAGE}
MODULE = types.SimpleNamespace(EXERCISES=[mod.PointLightIrradiance, mod.SolidAngle,
                                          mod.RadianceIntensity],
                               **{name: getattr(mod, name) for name in SPECS})

exercises = harness.variants(MODULE)


same = harness.same


globals().update(harness.common_tests(MODULE, SPECS, GARBAGE, exercises, at_least=3,
                                      distinct=(30, 8)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_reaches_the_right_answer(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(60)):
        right, _ = solve(ex)
        worked = ex.worked()
        assert abs(worked.answer - right) < 1e-9
        assert len(ex.hints()) >= 3
        assert ex.check(worked.answer).status == "correct"


def test_every_kind_is_asked():
    for name, kinds in (("PointLightIrradiance", {"angle", "position"}),
                        ("SolidAngle", {"cone", "patch", "region"}),
                        ("RadianceIntensity", {"emitter", "isotropic", "exitance"})):
        assert {ex.kind for ex in exercises(name)} == kinds


def test_boundary_case_is_a_labelled_share_of_the_seeds():
    variants = [mod.PointLightIrradiance(seed=s) for s in range(300)]
    labels = [ex.boundary for ex in variants]
    assert labels == ["light below the horizon" if point_light(ex)[0] == 0 else None
                      for ex in variants]
    share = sum(label is not None for label in labels) / len(labels)
    assert 0.10 <= share <= 0.20
    for ex in variants[:100]:
        assert ("boundary case" in " ".join(ex.worked().steps)) == (ex.boundary is not None)
        if ex.boundary:
            assert ex.check(0).status == "correct"
            assert ex.theta_deg > 90


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("PointLightIrradiance"):
        if ex.kind == "position":
            d = math.hypot(ex.x, ex.h)
            assert d == round(d)
        else:
            assert ex.theta_deg % 15 == 0
    for ex in exercises("SolidAngle"):
        if ex.kind == "region":
            assert all(v % 30 == 0 for v in (ex.theta1_deg, ex.theta2_deg, ex.phi1_deg,
                                              ex.phi2_deg))


def test_enough_distinct_variants():
    for name in SPECS:
        distinct = {harness.answer_key(mod.__dict__[name](seed=s).expected, decimals=9)
                    for s in range(300)}
        assert len(distinct) >= 30, (name, len(distinct))


def test_wrong_answers_get_teaching_feedback():
    for name, (solve, _) in SPECS.items():
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(np.asarray(right) * 1.13 + 0.37)   # off by more than the tolerance
            assert fb.status == "wrong" and len(fb.message) > 80, (ex, fb)
            assert fb.message.count("$") >= 2
