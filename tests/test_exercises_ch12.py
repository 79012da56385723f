"""Tests of the chapter 12 exercises (course_lib.exercises.ch12).

For every exercise and many seeds: the statement reads, the right answer is accepted (also
rounded to 3 decimals and as a plain list), placeholders are "unanswered", garbage is "invalid",
and every anticipated mistake, rebuilt here from the question's attributes, is named by its
diagnosis. The right answers are computed here independently of the checkers, from the formulas
typed out below with plain numpy (never with course_lib.shading, which the checkers call): the
mirror vector, Lambert's law, the Phong and Blinn-Phong terms, the attenuation polynomial; the
ambient occlusion next to a wall or in a trench is integrated numerically with scipy's ``quad``
over the azimuth, not taken from its closed form.
"""
import math
import re

import numpy as np
import pytest
from scipy.integrate import quad

from course_lib.exercises import ch12
import exercise_harness as harness
from exercise_harness import SAME, SEEDS, Either
from course_lib.exercises.core import gap


# ---------------------------------------------------------------------------------------------
# Independent formulas
# ---------------------------------------------------------------------------------------------

def unit(v):
    v = np.asarray(v, dtype=float)
    return v / math.sqrt(float(v @ v))


def mirror(L, N):
    """R = 2 (N.L) N - L for a unit N."""
    return 2 * float(N @ L) * N - L


def lambert(kd, Il, cos):
    return kd * Il * max(cos, 0.0)


def reflection_vector(ex):
    N, L = np.asarray(ex.N, float), np.asarray(ex.L, float)
    n = unit(N)
    right = mirror(L, n)
    assert abs(np.linalg.norm(right) - 1) < 1e-12 and abs(n @ right - n @ L) < 1e-12
    return right, {
        "incoming formula": -right,
        "N not normalised": 2 * float(N @ L) * N - L,
        "projection only": float(n @ L) * n,
        "plus L": 2 * float(n @ L) * n + L,
    }


def diffuse_term(ex):
    kd, Il = ex.kd, ex.Il
    if ex.kind == "angle":
        t = ex.theta_deg * math.pi / 180
        right = lambert(kd, Il, math.cos(t))
        mistakes = {"degrees": kd * Il * math.cos(ex.theta_deg),
                    "sine": kd * Il * math.sin(t)}
        if math.cos(t) < 0:
            mistakes["no clamp"] = kd * Il * math.cos(t)
        return right, mistakes
    d = np.asarray(ex.Q, float) - np.asarray(ex.P, float)
    dist = math.sqrt(float(d @ d))
    cos = float(ex.N @ d) / dist
    right = lambert(kd, Il, cos)
    mistakes = {"L reversed": lambert(kd, Il, -cos)}
    if cos > 0:
        mistakes["L not normalised"] = kd * Il * float(ex.N @ d)
    else:
        mistakes["no clamp"] = Either([kd * Il * cos, kd * Il * float(ex.N @ d)])
    return right, mistakes


def specular_term(ex):
    N, L, V, ks, Il, n = ex.N, ex.L, ex.V, ex.ks, ex.Il, ex.n
    rv = float(mirror(L, N) @ V)
    right = ks * Il * max(rv, 0.0) ** n
    mistakes = {
        "N·L instead of R·V": ks * Il * max(float(N @ L), 0.0) ** n,
        "no exponent": ks * Il * max(rv, 0.0),
        "exponent on the coefficient": Either([Il * (ks * max(rv, 0)) ** n,
                                               (ks * Il * max(rv, 0)) ** n]),
    }
    if rv < 0:
        mistakes["no clamp"] = ks * Il * rv ** n
    return right, mistakes


def phong_total(ex):
    nl = float(ex.N @ ex.L)
    rv = float(mirror(ex.L, ex.N) @ ex.V)
    amb = ex.Ia * ex.ka
    light = 0.0 if nl <= 0 else ex.Il * (ex.kd * nl + ex.ks * max(rv, 0.0) ** ex.n)
    right = ex.Ie + amb + light
    mistakes = {"no ambient": right - amb, "no emission": right - ex.Ie,
                "ka forgotten": ex.Ie + ex.Ia + light}
    if nl < 0 or rv < 0:
        mistakes["no clamp"] = ex.Ie + amb + ex.Il * (ex.kd * nl + ex.ks * rv ** ex.n)
    if nl < 0:
        mistakes["specular on the dark side"] = ex.Ie + amb + ex.Il * ex.ks * max(rv, 0) ** ex.n
    return right, mistakes


def blinn_phong(ex):
    N, L, V, n = ex.N, ex.L, ex.V, ex.n
    bisector = L + V
    H = bisector / math.sqrt(float(bisector @ bisector))
    # H bisects the angle: the same angle to L and to V
    assert abs(float(H @ L) - float(H @ V)) < 1e-12
    nh = float(N @ H)
    s = max(nh, 0.0) ** n
    right = np.array([*H, s])
    d = unit(L - V)
    vector_slips = {"H not normalised": [[*bisector, s], [*(bisector / 2), s]],
                    "L - V": [[*d, s], [*-d, s]]}
    if nh < 0:
        # the halfway vector points into the surface: s = 0, and the slips of the number s
        # that stay near 0 cannot be told from it; an unclamped power can, when it is large
        mistakes = {key: Either(values) for key, values in vector_slips.items()}
        if abs(nh) ** n > 0.06:
            mistakes["no clamp"] = [*H, nh ** n]
        return right, mistakes
    return right, {
        "H not normalised": Either(vector_slips["H not normalised"]
                                   + [[*H, float(N @ bisector) ** n],
                                      [*H, float(N @ bisector / 2) ** n]]),
        "Phong's R·V": [*H, max(float(mirror(L, N) @ V), 0.0) ** n],
        "L - V": Either(vector_slips["L - V"]
                        + [[*H, float(N @ (k * d)) ** n] for k in (1, -1)
                           if float(N @ (k * d)) > 0]),
    }


def attenuation(ex):
    diff = np.asarray(ex.Q, float) - np.asarray(ex.P, float)
    d2 = float(diff @ diff)
    d = math.sqrt(d2)
    a, b, c, Il = ex.a, ex.b, ex.c, ex.Il
    return Il / (a + b * d + c * d2), {
        "1/d": Il / d, "inverse square only": Il / d2, "d not squared": Il / (a + b * d + c * d),
        "c squared": Il / (a + b * d + c * c * d2),
        "squared distance as d": Il / (a + b * d2 + c * d2 * d2),
        "multiplied": Il * (a + b * d + c * d2),
    }


def several_lights(ex):
    cos = np.array([float(L @ ex.N) for L in ex.Ls])
    Is = np.asarray(ex.Is, float)
    amb = ex.Ia * ex.ka
    lit = [I * max(c, 0.0) for I, c in zip(Is, cos)]
    right = amb + ex.kd * sum(lit)
    mistakes = {"ambient per light": len(Is) * amb + ex.kd * sum(lit),
                "averaged": amb + ex.kd * sum(lit) / len(Is),
                "one light only": amb + ex.kd * lit[0]}
    if np.any(Is != 1):
        mistakes["intensities ignored"] = amb + ex.kd * sum(max(c, 0.0) for c in cos)
    if np.any(cos < 0):
        mistakes["no clamp"] = amb + ex.kd * float(Is @ cos)
    return right, mistakes


#: Which method each situation asks for, recognised by a phrase of its text.
SITUATIONS = {"**middle** of one large triangle": "phong",
              "flickers": "gouraud",
              "only at the **vertices**": "gouraud",
              "gemstone": "flat",
              "most evaluations": "phong",
              "single uniform colour": "flat",
              "spotlight": "phong",
              "glide smoothly": "phong",
              "fragment shader": "phong",
              "purely diffuse": "gouraud",
              "GL_SMOOTH": "gouraud",
              "shaped like a star": "gouraud",
              "which one is cheaper": "gouraud",
              "sharp edges": "flat",
              "smaller than a pixel": "flat",
              "stylised low-poly": "flat"}


def shading_method(ex):
    found = [method for phrase, method in SITUATIONS.items() if phrase in ex.situation]
    assert len(found) == 1, ex.situation
    right = found[0]
    return right, {f"chose {m}": m for m in ("flat", "gouraud", "phong") if m != right}


def in_plane(deg):
    t = deg * math.pi / 180
    return np.array([math.sin(t), 0.0, math.cos(t)])


def gouraud_phong(ex):
    L, V = in_plane(ex.l_deg), in_plane(ex.v_deg)

    def intensity(N):
        nl = float(N @ L)
        if nl <= 0:
            return 0.0
        return ex.kd * nl + ex.ks * max(float((2 * nl * N - L) @ V), 0.0) ** ex.n

    NA, NB = in_plane(ex.a_deg), in_plane(ex.b_deg)
    g = (intensity(NA) + intensity(NB)) / 2
    p = intensity(in_plane((ex.a_deg + ex.b_deg) / 2))   # the renormalised mean: the mid angle
    return np.array([g, p]), {
        "normals interpolated": [p, p],
        "colours interpolated": [g, g],
        "not renormalised": [g, intensity((NA + NB) / 2)],
    }


def ao_samples(ex):
    hits, cos = np.asarray(ex.hits, float), np.asarray(ex.cos_theta, float)
    open_ = [1.0 if (math.isinf(h) or h > ex.D) else 0.0 for h in hits]
    right = sum(open_) / len(open_)
    return right, {
        "occlusion instead of visibility": 1 - right,
        "cosine twice": Either([float(np.dot(open_, cos) / cos.sum()),
                                float(np.dot(open_, cos) / len(cos))]),
        "maximum distance ignored": float(np.mean(np.isinf(hits))),
        "divided by pi": right / math.pi,
    }


def blocked_by_one_wall(a, h):
    """The cosine-weighted fraction of the hemisphere a wall at distance a, height h blocks.

    For the azimuth phi (0 = straight at the wall) a direction hits the wall when its angle
    from the normal exceeds theta0 = atan(a / (h cos phi)); integrating cos(theta) sin(theta)
    from theta0 to pi/2 gives cos^2(theta0) / 2, and the azimuth is integrated numerically.
    """
    def across(phi):
        c = math.cos(phi)
        return (h * c) ** 2 / ((h * c) ** 2 + a * a) / 2

    value, _ = quad(across, -math.pi / 2, math.pi / 2, epsabs=1e-13)
    return value / math.pi


def ao_wall(ex):
    walls = 1 if ex.kind == "wall" else 2
    right = 1 - walls * blocked_by_one_wall(ex.a, ex.h)
    mistakes = {
        "occlusion instead of visibility": 1 - right,
        "a and h swapped": 1 - walls * blocked_by_one_wall(ex.h, ex.a),
        "angles, not cosine-weighted": 1 - walls * math.atan2(ex.h, ex.a) / math.pi,
    }
    if walls == 1:
        mistakes["two walls"] = 1 - 2 * blocked_by_one_wall(ex.a, ex.h)
    else:
        mistakes["one wall"] = 1 - blocked_by_one_wall(ex.a, ex.h)
    return right, mistakes


NUMBER_GARBAGE = ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]
VECTOR_GARBAGE = ["R", {"R": 1}, [[1, 2], [3]], [1, 2], np.eye(3), [math.nan, 0, 0]]
FOUR_GARBAGE = ["H", {"h": 1}, [1, 2, 3], [[1, 2], [3, 4]], [1, 2, 3, math.nan], [1] * 5]
PAIR_GARBAGE = ["g", {"g": 1}, [1], [1, 2, 3], [[1, 2], [3, 4]], [math.nan, 1]]
METHOD_GARBAGE = ["toon", 3, ["phong"], {"phong": 1}, "wireframe", 0.5]

# class name: (independent answer and mistakes, answer form)
SPECS = {
    "ReflectionVector": (reflection_vector, "vector"),
    "DiffuseTerm": (diffuse_term, "number"),
    "SpecularTerm": (specular_term, "number"),
    "PhongTotal": (phong_total, "number"),
    "BlinnPhongHighlight": (blinn_phong, "four"),
    "DistanceAttenuation": (attenuation, "number"),
    "SeveralLights": (several_lights, "number"),
    "ShadingMethodChoice": (shading_method, "method"),
    "GouraudVersusPhong": (gouraud_phong, "pair"),
    "AmbientOcclusionSamples": (ao_samples, "number"),
    "AmbientOcclusionWall": (ao_wall, "number"),
}
GARBAGE = {"number": NUMBER_GARBAGE, "vector": VECTOR_GARBAGE, "four": FOUR_GARBAGE,
           "pair": PAIR_GARBAGE, "method": METHOD_GARBAGE}


exercises = harness.variants(ch12)


def same(a, b, form):
    if form == "method":
        return a == b
    return gap(a, b) < SAME


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

#: The exercises this file tests; the chapter's other topics have files of their own
#: (tests/test_exercises_ch12_*.py), and test_every_exercise_is_tested_in_one_file holds the
#: union to the chapter's list.
TOPIC = harness.topic(ch12, SPECS)

globals().update(harness.common_tests(
    TOPIC, SPECS, GARBAGE, exercises, at_least=8, distinct=(30, 5),
    clean=lambda text: re.sub(r"`inf`", "", text.lower()), newlines=r"\\neq?\b|\\normal"))
test_mistakes_are_diagnosed = harness.mistakes_test(
    SPECS, exercises, same, key_seeds=SEEDS)


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch12, SPECS, at_least=8)
@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "method":
            answers = [right, right.upper(), f"{right.capitalize()} shading "]
        else:
            answers = [right, np.round(right, 3), np.asarray(right).tolist()]
        harness.assert_accepted(ex, answers)


def test_wrong_answers_get_teaching_feedback():
    """An answer no slip explains still says how to get it right."""
    for name in ("ReflectionVector", "DiffuseTerm", "SpecularTerm", "PhongTotal",
                 "DistanceAttenuation", "SeveralLights", "AmbientOcclusionWall"):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(np.asarray(right) + 0.37)
            assert fb.status == "wrong" and len(fb.message) > 80, (ex, fb)
            assert fb.message.count("$") >= 2            # the formula is spelt out


def test_numbers_are_nice_for_hand_work():
    def rational(v, denominators=(1, 3, 5, 7, 10)):
        return any(np.allclose(np.asarray(v) * q, np.round(np.asarray(v) * q)) for q in
                   denominators)

    for name in ("SpecularTerm", "PhongTotal", "BlinnPhongHighlight", "SeveralLights"):
        for ex in exercises(name):
            vectors = [ex.N] + ([*ex.Ls] if name == "SeveralLights" else [ex.L, ex.V])
            for v in vectors:
                assert abs(np.linalg.norm(v) - 1) < 1e-12 and rational(v), (name, v)
    for ex in exercises("ReflectionVector"):
        assert np.all(ex.N == np.round(ex.N))
        length = np.linalg.norm(ex.N)
        assert length == round(length) and length > 1
    for ex in exercises("DistanceAttenuation"):
        d = np.linalg.norm(ex.Q - ex.P)
        assert d == round(d)
    for ex in exercises("GouraudVersusPhong"):
        for deg in (ex.a_deg, ex.b_deg, ex.l_deg, ex.v_deg):
            assert deg % 15 == 0
    for ex in exercises("DiffuseTerm"):
        if ex.kind == "angle":
            assert ex.theta_deg % 15 == 0


def test_gouraud_misses_the_highlight_that_phong_finds():
    for ex in exercises("GouraudVersusPhong"):
        g, p = gouraud_phong(ex)[0]
        assert p > g + 0.05


def test_wall_integral_matches_the_flat_floor_limits():
    # no wall (height 0) blocks nothing; an infinitely high wall at distance 0 blocks half
    assert blocked_by_one_wall(1.0, 1e-9) < 1e-12
    assert abs(blocked_by_one_wall(1e-9, 1.0) - 0.5) < 1e-6
    # and a Monte Carlo estimate with cosine-weighted directions agrees with the integral
    rng = np.random.default_rng(1)
    r, phi = np.sqrt(rng.random(400_000)), 2 * np.pi * rng.random(400_000)
    x, z = r * np.cos(phi), np.sqrt(1 - r * r)
    a, h = 3.0, 4.0
    with np.errstate(divide="ignore"):
        blocked = (x > 0) & (a * z / np.where(x > 0, x, 1) < h)
    assert abs(blocked.mean() - blocked_by_one_wall(a, h)) < 3e-3


def test_every_situation_is_asked():
    asked = {phrase for ex in exercises("ShadingMethodChoice") for phrase in SITUATIONS
             if phrase in ex.situation}
    assert asked == set(SITUATIONS)
    assert {shading_method(ex)[0] for ex in exercises("ShadingMethodChoice")} == \
        {"flat", "gouraud", "phong"}


# ---------------------------------------------------------------------------------------------
# Boundary cases, variety, advice
# ---------------------------------------------------------------------------------------------

#: 300 seeds, for the shares and the variety.
MANY = range(300)


def many(name):
    cls = getattr(ch12, name)
    return [cls(seed=seed) for seed in MANY]


def boundary_of(name, ex):
    """The boundary case a variant is, found from its numbers (None for the common case)."""
    if name == "DiffuseTerm":
        return "light behind the surface" if diffuse_term(ex)[0] == 0 else None
    if name == "SpecularTerm":
        return ("viewer away from the mirror direction"
                if float(mirror(ex.L, ex.N) @ ex.V) < 0 else None)
    if name == "PhongTotal":
        if float(ex.N @ ex.L) < 0:
            return "light behind the surface"
        return ("viewer away from the mirror direction"
                if float(mirror(ex.L, ex.N) @ ex.V) < 0 else None)
    if name == "BlinnPhongHighlight":
        return ("halfway vector below the surface" if float(ex.N @ unit(ex.L + ex.V)) < 0
                else None)
    if name == "SeveralLights":
        return "light behind the surface" if np.any(ex.Ls @ ex.N < 0) else None
    raise KeyError(name)


BOUNDARY = ("DiffuseTerm", "SpecularTerm", "PhongTotal", "BlinnPhongHighlight", "SeveralLights")


@pytest.mark.parametrize("name", BOUNDARY)
def test_boundary_cases_are_labelled_variants_of_a_few_seeds(name):
    variants = many(name)
    labels = [ex.boundary for ex in variants]
    assert labels == [boundary_of(name, ex) for ex in variants]
    share = sum(label is not None for label in labels) / len(labels)
    assert 0.10 <= share <= 0.20, (name, share)
    if name == "PhongTotal":                           # both of its cases are asked
        assert {"light behind the surface", "viewer away from the mirror direction"} <= \
            set(labels)
    for ex in variants[:100]:
        worked = " ".join(ex.worked().steps)
        assert ("boundary case" in worked) == (ex.boundary is not None), (ex, worked)


@pytest.mark.parametrize("name", ["DiffuseTerm", "SpecularTerm"])
def test_zero_is_the_answer_of_the_boundary_case_only(name):
    variants = many(name)
    zero_right = [ex for ex in variants if ex.check(0).status == "correct"]
    assert zero_right == [ex for ex in variants if ex.boundary is not None]
    assert len(zero_right) / len(variants) <= 0.20


#: Distinct variants among 300 seeds: distinct right answers, or for a choice between three
#: methods distinct statements (ShadingMethodChoice: 16 situations, several in a few settings).
MIN_VARIANTS = 30


@pytest.mark.parametrize("name", SPECS)
def test_enough_distinct_variants(name):
    variants = many(name)
    if SPECS[name][1] == "method":
        distinct = {ex.statement() for ex in variants}
        assert len({phrase for ex in variants for phrase in SITUATIONS
                    if phrase in ex.situation}) == len(SITUATIONS) == 16
    else:
        distinct = {harness.answer_key(ex.expected, decimals=9) for ex in variants}
    assert len(distinct) >= MIN_VARIANTS, (name, len(distinct))


@pytest.mark.parametrize("name", [n for n in SPECS if SPECS[n][1] != "method"])
def test_the_advice_is_given_at_most_once(name):
    checked, shown = harness.advice_counts(exercises(name), SPECS[name][0],
                                           lambda ex, right: harness.wrong_answers(right))
    assert shown >= checked // 2            # the advice is given, where no slip explains
