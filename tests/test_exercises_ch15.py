"""Tests of the chapter 15 exercises (course_lib.exercises.ch15).

For every exercise and many seeds: the statement reads, the right answer is accepted,
placeholders are "unanswered", garbage is "invalid", and every anticipated mistake, rebuilt here
from the question's attributes, is named by its diagnosis. The right answers are computed here
independently of the checkers: numpy's polynomial roots (ray-sphere), a linear solve (ray-
triangle), PyGLM's GLSL ``reflect`` and ``refract``, the closest point of a segment to a ball
(shadow rays), an explicit enumeration of the ray tree, a halving loop for the BVH, and formulas
typed out below; never with the course_lib.raytracing function the checker calls.
"""
import math

import numpy as np
import pytest
from pyglm import glm

from course_lib.exercises import ch15
import exercise_harness as harness
from exercise_harness import SAME, SEEDS, gap
from course_lib.exercises.core import APART, TOLERANCES_APART, tolerance


# ---------------------------------------------------------------------------------------------
# Per exercise: the expected answer and the anticipated mistakes, from the attributes
# ---------------------------------------------------------------------------------------------

def ray_sphere_hit(ex):
    o, d, c, r = ex.o, ex.d, ex.center, ex.radius
    f = o - c
    roots = np.sort(np.roots([d @ d, 2 * d @ f, f @ f - r * r]).real)
    right = o + roots[0] * d
    mistakes = {"far root": o + roots[1] * d, "sign of b": o - roots[1] * d}
    unit = np.roots([1.0, 2 * d @ f, f @ f - r * r])
    if np.isreal(unit).all():
        mistakes["a = 1"] = o + np.min(unit.real) * d
    return right, mistakes


def ray_triangle_hit(ex):
    v0, v1, v2 = ex.V
    t, u, v = np.linalg.solve(np.column_stack([ex.d, v0 - v1, v0 - v2]), v0 - ex.o)
    right = np.array([t, u, v])
    return right, {"distance": np.array([t * np.linalg.norm(ex.d), u, v]),
                   "u and v swapped": np.array([t, v, u]),
                   "weight of v0": np.array([t, 1 - u - v, v])}


def reflected_ray(ex):
    n = ex.n / np.linalg.norm(ex.n)
    right = np.array(glm.reflect(glm.dvec3(*ex.d), glm.dvec3(*n)))
    return right, {"Phong formula": -right,
                   "n not normalized": ex.d - 2 * (ex.d @ ex.n) * ex.n,
                   "factor 2": ex.d - (ex.d @ n) * n,
                   "plus sign": ex.d + 2 * (ex.d @ n) * n}


def refracted_ray(ex):
    right = np.array(glm.refract(glm.dvec3(*ex.d), glm.dvec3(*ex.n), ex.eta1 / ex.eta2))
    mistakes = {"reflected": np.array(glm.reflect(glm.dvec3(*ex.d), glm.dvec3(*ex.n))),
                "not bent": ex.d}
    upside = np.array(glm.refract(glm.dvec3(*ex.d), glm.dvec3(*ex.n), ex.eta2 / ex.eta1))
    if upside.any():
        mistakes["ratio upside down"] = upside
    return right, mistakes


def apart(a, b):
    """Two answers the course's tolerance policy tells apart (APART and 2 tolerances)."""
    distance = abs(a - b)
    return distance >= APART - SAME and distance >= TOLERANCES_APART * max(
        float(tolerance(a)), float(tolerance(b)))


def critical_angle(ex):
    ratio = ex.eta2 / ex.eta1
    return math.degrees(math.asin(ratio)), {"arccos": 90 - math.degrees(math.asin(ratio)),
                                            "Brewster": math.degrees(math.atan(ratio)),
                                            "radians": math.asin(ratio)}


def schlick_reflectance(ex):
    r = (ex.eta2 - ex.eta1) / (ex.eta2 + ex.eta1)
    grazing = (1 - math.cos(math.radians(ex.angle))) ** 5
    right = r * r + (1 - r * r) * grazing
    mistakes = {"R0 not squared": abs(r) + (1 - abs(r)) * grazing, "R0 only": r * r}
    # np.cos(75): the angle's number taken as radians; named where it is apart from the others
    as_radians = r * r + (1 - r * r) * (1 - np.cos(ex.angle)) ** 5
    if all(apart(as_radians, other) for other in [right, *mistakes.values()]):
        mistakes["degrees"] = as_radians
    if abs(r * r + grazing - right) >= APART:
        mistakes["no (1 - R0)"] = r * r + grazing
    return right, mistakes


def shadow_ray(ex):
    p, q, c = ex.P, ex.light, ex.center
    s = np.clip((c - p) @ (q - p) / ((q - p) @ (q - p)), 0, 1)      # closest point of segment
    blocked = np.linalg.norm(p + s * (q - p) - c) < ex.radius
    assert blocked == ex.blocked
    cos = (q - p)[1] / np.linalg.norm(q - p)
    lit = ex.ka + ex.kd * cos
    mistakes = {"no ambient": 0.0,
                "L not normalized": ex.ka + ex.kd * (q - p)[1]}
    if blocked:
        mistakes["ignored the shadow"] = lit
    else:
        mistakes["false shadow"] = ex.ka
    return (ex.ka if blocked else lit), mistakes


def chain(local, kr, depth, multiply=True):
    def colour(k, weight):
        if k > depth:
            return 0.0
        nxt = weight * kr[k] if multiply else kr[k]
        return weight * local[k] + colour(k + 1, nxt)
    return colour(0, 1.0)


def mirror_chain_colour(ex):
    return chain(ex.local, ex.kr, ex.depth), {
        "no weights": sum(ex.local[:ex.depth + 1]),
        "weights not multiplied": chain(ex.local, ex.kr, ex.depth, multiply=False),
        "one too deep": chain(ex.local, ex.kr, ex.depth + 1),
        "one too shallow": chain(ex.local, ex.kr, ex.depth - 1)}


def tree_nodes(depth, children):
    level, total = [0], 0
    while level:
        total += len(level)
        level = [k + 1 for k in level if k < depth for _ in range(children)]
    return total


def ray_tree_count(ex):
    nodes = tree_nodes(ex.depth, 2 if ex.glass else 1)
    right = np.array([nodes, nodes * ex.lights], dtype=float)
    mistakes = {"primary forgotten": [nodes - 1, nodes * ex.lights],
                "shadows of primary only": [nodes, ex.lights],
                "one per hit": [nodes, nodes]}
    if ex.glass:
        mistakes["last level only"] = [2 ** ex.depth, nodes * ex.lights]
        mistakes["chain"] = [tree_nodes(ex.depth, 1), nodes * ex.lights]
    else:
        mistakes["binary tree"] = [tree_nodes(ex.depth, 2), nodes * ex.lights]
    return right, {k: np.array(v, dtype=float) for k, v in mistakes.items()}


def bvh_savings(ex):
    depth, count = 0, ex.triangles
    while count > ex.leaf_size:
        count //= 2
        depth += 1
    boxes = 2 * depth
    right = np.array([depth, boxes, ex.leaf_size, ex.triangles / (boxes + ex.leaf_size)])
    return right, {"leaf size ignored": np.r_[math.log2(ex.triangles), right[1:]],
                   "one box per level": np.r_[right[0], depth, right[2:]],
                   "brute force": np.r_[right[:2], ex.triangles, right[3]],
                   "boxes free": np.r_[right[:3], ex.triangles / ex.leaf_size]}


SPECS = {
    "RaySphereHit": (ray_sphere_hit, "vector"),
    "RayTriangleHit": (ray_triangle_hit, "parts"),
    "ReflectedRay": (reflected_ray, "vector"),
    "RefractedRay": (refracted_ray, "vector"),
    "CriticalAngle": (critical_angle, "number"),
    "SchlickReflectance": (schlick_reflectance, "number"),
    "ShadowRay": (shadow_ray, "number"),
    "MirrorChainColour": (mirror_chain_colour, "number"),
    "RayTreeCount": (ray_tree_count, "parts"),
    "BVHSavings": (bvh_savings, "parts"),
}
GARBAGE = {"vector": ["x", [1, 2], [[1, 2, 3], [4, 5, 6]], [1, float("nan"), 2], {"a": 1}],
           "number": ["x", [1, 2], [float("nan")], {"a": 1}],
           "parts": ["x", [1], [[1, 2, 3, 4, 5]], {"a": 1}]}


#: This file tests the chapter's older topics (SPECS); tests/test_exercises_ch15_*.py the others,
#: and test_every_exercise_is_tested_in_one_file holds the union to the chapter's list.
TOPIC = harness.topic(ch15, SPECS)
exercises = harness.variants(TOPIC)


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(
    TOPIC, SPECS, GARBAGE, exercises, at_least=8, distinct=(40, 5), newlines=None))
test_mistakes_are_diagnosed = harness.mistakes_test(
    SPECS, exercises, lambda a, b, form: gap(a, b) < SAME,
    min_message=30, key_seeds=SEEDS)


test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


def test_wrong_answers_get_teaching_feedback():
    for name in ("RaySphereHit", "ReflectedRay", "RefractedRay", "ShadowRay", "BVHSavings"):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(np.asarray(right) + 0.37)
            assert fb.status == "wrong" and len(fb.message) > 60, (ex, fb)


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("RaySphereHit"):
        assert np.all(ex.d == np.round(ex.d)) and np.all(ex.center == np.round(ex.center))
        assert np.all(ex.o == np.round(ex.o))
        assert np.allclose(ex.expected, np.round(ex.expected))
    for ex in exercises("RayTriangleHit"):
        assert np.all(ex.V == np.round(ex.V)) and np.all(ex.expected * 8 == np.round(
            ex.expected * 8))
    for ex in exercises("RefractedRay"):
        assert ex.angle % 15 == 0
    both = {ex.blocked for ex in exercises("ShadowRay")}
    assert both == {True, False}                  # lit and shadowed variants both occur


# ---------------------------------------------------------------------------------------------
# The tolerance policy, whole numbers, boundary variants, named slips and variety
# ---------------------------------------------------------------------------------------------

#: The parts of an answer that are counts (whole numbers, compared exactly), by exercise.
WHOLE = {"RayTreeCount": (0, 1), "BVHSavings": (0, 1, 2)}
#: The exercises whose answer has real numbers in it (all but the ray tree's two counts).
REAL = [name for name in SPECS if name != "RayTreeCount"]
#: Seeds for the shares and the variety.
MANY = range(300)
#: Among 300 seeds every exercise has at least this many distinct right answers.
MIN_VARIANTS = 30


@pytest.mark.parametrize("name", REAL)
def test_right_answer_to_3_significant_digits_is_accepted(name):
    solve, _ = SPECS[name]
    whole = WHOLE.get(name, ())
    for ex in exercises(name):
        right, _ = solve(ex)
        flat = np.ravel(np.asarray(right, dtype=float))
        typed = [x if i in whole else harness.significant(x) for i, x in enumerate(flat)]
        answer = typed[0] if np.ndim(right) == 0 else typed
        fb = ex.check(answer)
        assert fb.status == "correct", (ex, right, answer, fb)


@pytest.mark.parametrize("name", WHOLE)
def test_counts_are_whole_numbers_compared_exactly(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, mistakes = solve(ex)
        right = np.asarray(right, dtype=float)
        assert ex.check([float(x) for x in right]).status == "correct"     # 3.0 is 3
        assert ex.check([int(x) if i in WHOLE[name] else x
                         for i, x in enumerate(right)]).status == "correct"
        for i in WHOLE[name]:
            for step in (-1, 1):
                wrong = right.copy()
                wrong[i] += step
                fb = ex.check(wrong.tolist())
                assert fb.status == "wrong", (ex, i, step, fb)
                if not any(gap(wrong, m) < SAME for m in mistakes.values()):
                    assert fb.diagnosis == "off by one", (ex, i, step, fb)
    ex = exercises(name)[0]
    right, _ = solve(ex)
    fb = ex.check([x + 0.5 if i == WHOLE[name][0] else x for i, x in enumerate(right)])
    assert fb.status == "wrong"                                            # no tolerance


def edge_of(u, v):
    """The triangle's edge that the barycentric point (u, v) lies on, or None inside."""
    if abs(v) < 1e-9:
        return "edge v0v1"
    if abs(u) < 1e-9:
        return "edge v0v2"
    if abs(u + v - 1) < 1e-9:
        return "edge v1v2"
    return None


def test_a_hit_on_an_edge_is_a_labelled_variant():
    variants = [ch15.RayTriangleHit(seed=seed) for seed in MANY]
    on_edge = 0
    for ex in variants:
        (t, u, v), _ = ray_triangle_hit(ex)
        assert ex.boundary == edge_of(u, v), (ex, u, v)
        assert "counts as a hit" in ex.statement()
        if ex.boundary is not None:
            on_edge += 1
            assert "exactly on the boundary" in ex.worked().steps[-1]
            assert ex.check([t, u, v]).status == "correct"
    assert 0.10 <= on_edge / len(MANY) <= 0.20, on_edge
    assert {ex.boundary for ex in variants} == {None, "edge v0v1", "edge v0v2", "edge v1v2"}


def test_the_plus_sign_slip_is_named_and_a_flipped_normal_is_no_slip():
    for ex in exercises("ReflectedRay"):
        n = ex.n / np.linalg.norm(ex.n)
        fb = ex.check(ex.d + 2 * (ex.d @ n) * n)
        assert fb.diagnosis == "plus sign" and "minus sign" in fb.message, (ex, fb)
        flipped = -n                                       # n the other way: the same mirror
        assert ex.check(ex.d - 2 * (ex.d @ flipped) * flipped).status == "correct"


def test_degrees_in_schlick_are_named_in_most_variants():
    named = 0
    for ex in exercises("SchlickReflectance"):
        right, mistakes = schlick_reflectance(ex)
        if "degrees" in mistakes:
            fb = ex.check(mistakes["degrees"])
            assert fb.diagnosis == "degrees" and "radians" in fb.message
            named += 1
        assert ex.check(right).status == "correct"
    assert named >= len(SEEDS) // 2, named


@pytest.mark.parametrize("name", SPECS)
def test_variants_are_many(name):
    cls = getattr(ch15, name)
    solve, _ = SPECS[name]
    answers = {harness.answer_key(solve(cls(seed=seed))[0]) for seed in MANY}
    assert len(answers) >= MIN_VARIANTS, (name, len(answers))


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch15, SPECS, at_least=8)
