"""Tests of the chapter 12 BRDF exercises (course_lib.exercises._ch12.brdf).

The right answers are recomputed here from formulas typed out below (never with
course_lib.shading): the Lambertian radiance rho/pi * I cos / d^2, the Phong constant from the
integral of cos^(n+1) theta by scipy's ``quad``, the lobe's reflectance by ``quad`` as well,
and Schlick's formula with F0 = ((1 - n) / (1 + n))^2. Every named mistake is rebuilt here.
"""
import math
import types

import pytest
from scipy.integrate import quad

from course_lib.exercises._ch12 import brdf as module
import exercise_harness as harness

_CLASSES = [module.LambertRadiance, module.PhongNormalization, module.LobeReflectance,
            module.SchlickFresnel]
ch = types.SimpleNamespace(EXERCISES=_CLASSES, **{cls.__name__: cls for cls in _CLASSES})


def hemisphere_cos_power(p):
    """2 pi * int_0^{pi/2} cos^p(theta) sin(theta) d theta, numerically."""
    return 2 * math.pi * quad(lambda t: math.cos(t) ** p * math.sin(t), 0, math.pi / 2,
                              epsabs=1e-13)[0]


def lambert(ex):
    E = ex.I * ex.cos_theta / ex.d ** 2
    right = ex.albedo / math.pi * E
    return right, {
        "forgot 1/pi": ex.albedo * E,
        "1/(2 pi)": ex.albedo / (2 * math.pi) * E,
        "cosine forgotten": ex.albedo / math.pi * ex.I / ex.d ** 2,
        "distance not squared": ex.albedo / math.pi * ex.I * ex.cos_theta / ex.d,
    }


def normalization(ex):
    n = ex.n
    right = 1 / hemisphere_cos_power(n + 1)
    assert right == pytest.approx((n + 2) / (2 * math.pi), rel=1e-10)
    return right, {
        "cos(theta) forgotten": 1 / hemisphere_cos_power(n),
        "exponent ignored": 1 / (2 * math.pi),
        "azimuth over pi": (n + 2) / math.pi,
        "integral, not its reciprocal": hemisphere_cos_power(n + 1),
    }


def lobe(ex):
    right = ex.kd + ex.ks * hemisphere_cos_power(ex.n + 1)
    return right, {
        "normalised lobe assumed": ex.kd + ex.ks,
        "cos(theta) forgotten": ex.kd + ex.ks * hemisphere_cos_power(ex.n),
        "diffuse BRDF not integrated": ex.kd / math.pi + ex.ks * hemisphere_cos_power(ex.n + 1),
        "lost the pi": ex.kd + 2 * ex.ks / (ex.n + 2),
    }


def schlick(ex):
    t = math.radians(ex.theta_deg)
    r = (1 - ex.n2) / (1 + ex.n2)
    f0 = r * r
    right = f0 + (1 - f0) * (1 - math.cos(t)) ** 5
    return right, {
        "normal incidence only": f0,
        "F0 not squared": abs(r) + (1 - abs(r)) * (1 - math.cos(t)) ** 5,
        "fifth power forgotten": f0 + (1 - f0) * (1 - math.cos(t)),
    }


SPECS = {
    "LambertRadiance": (lambert, "number"),
    "PhongNormalization": (normalization, "number"),
    "LobeReflectance": (lobe, "number"),
    "SchlickFresnel": (schlick, "number"),
}
GARBAGE = {"number": ["L", {"L": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]}

exercises = harness.variants(module)


same = harness.same


globals().update(harness.common_tests(ch, SPECS, GARBAGE, exercises, at_least=3,
                                      distinct=(30, 5)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


def test_wrong_answers_get_teaching_feedback():
    for name, (solve, _) in SPECS.items():
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(right + 0.37)
            assert fb.status == "wrong" and len(fb.message) > 60, (ex, fb)


def test_worked_solutions_and_hints():
    for name, (solve, _) in SPECS.items():
        for ex in exercises(name, range(10)):
            right, _ = solve(ex)
            assert len(ex.hints()) >= 3
            worked = ex.worked()
            assert worked.answer == pytest.approx(right, rel=1e-9)
            assert len(worked.steps) >= 3


def test_both_sides_of_energy_conservation_are_asked():
    values = [lobe(ex)[0] for ex in exercises("LobeReflectance")]
    assert min(values) < 1 < max(values)
