"""Tests of the data exercises of chapter 10 (course_lib/exercises/_ch10/data.py), on
tests/exercise_harness.py.

The right answers and every anticipated slip are rebuilt here independently of the module and
of course_lib.dataviz: the levels of the attributes and their tempting wrong levels, and the
grid kinds of the scenarios, from tables typed out below; the memory counts from the formulas
typed here; Shepard's value by a plain loop; nearest neighbour by the smallest distance and the
linear value from the plane through the triangle's three samples (numpy's solve).
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from course_lib.exercises._ch10 import data as module

CLASSES = [module.ClassifyLevels, module.ChooseGridKind, module.GridMemory,
           module.ShepardByHand, module.NearestVsLinear]
ch10 = SimpleNamespace(EXERCISES=CLASSES, **{c.__name__: c for c in CLASSES})
exercises = harness.variants(ch10)


# ---------------------------------------------------------------------------------------------
# Independent answers and slips
# ---------------------------------------------------------------------------------------------

#: attribute -> (its level, the tempting wrong level, the slip's name), typed out by hand.
LEVELS = {
    "postcode": ("nominal", "interval", "labels read as numbers"),
    "telephone number": ("nominal", "interval", "labels read as numbers"),
    "player's shirt number": ("nominal", "interval", "labels read as numbers"),
    "blood group (A, B, AB, O)": ("nominal", "ordinal", "order invented"),
    "land-use class": ("nominal", "ordinal", "order invented"),
    "country of birth": ("nominal", "ordinal", "order invented"),
    "school grade (A to F)": ("ordinal", "nominal", "order ignored"),
    "pain level (none, mild, moderate, severe)": ("ordinal", "nominal", "order ignored"),
    "finishing place in a race (1st, 2nd, ...)": ("ordinal", "interval",
                                                  "ranks read as amounts"),
    "answer on a scale 'disagree' to 'agree' (1 to 5)": ("ordinal", "interval",
                                                         "ranks read as amounts"),
    "hurricane category (1 to 5)": ("ordinal", "interval", "ranks read as amounts"),
    "hardness on the Mohs scale": ("ordinal", "interval", "ranks read as amounts"),
    "temperature in °C": ("interval", "ratio", "no true zero"),
    "temperature in °F": ("interval", "ratio", "no true zero"),
    "calendar year": ("interval", "ratio", "no true zero"),
    "time of day on a 24-hour clock": ("interval", "ratio", "no true zero"),
    "longitude in degrees": ("interval", "ratio", "no true zero"),
    "temperature in kelvin": ("ratio", "interval", "true zero missed"),
    "mass in kg": ("ratio", "interval", "true zero missed"),
    "height of a person in cm": ("ratio", "interval", "true zero missed"),
    "number of children in a household": ("ratio", "interval", "true zero missed"),
    "income in euros": ("ratio", "interval", "true zero missed"),
    "duration of a phone call in seconds": ("ratio", "interval", "true zero missed"),
    "rainfall in mm per year": ("ratio", "interval", "true zero missed"),
    "wind speed in m/s": ("ratio", "interval", "true zero missed"),
}


def classify_levels(ex):
    right = [LEVELS[a][0] for a in ex.attributes]
    mistakes = {}
    for k, attribute in enumerate(ex.attributes):
        _, wrong, key = LEVELS[attribute]
        answer = list(right)
        answer[k] = wrong
        mistakes[key] = answer
    return right, mistakes


#: The grid kind of each scenario, from a phrase of its description, typed out by hand.
GRID_BY_WORD = {
    "CT scan": "uniform", "digital photograph": "uniform", "room's temperature": "uniform",
    "satellite image": "uniform", "climate model": "uniform",
    "wind-tunnel": "rectilinear", "40 depth levels": "rectilinear",
    "measurements of a material": "rectilinear", "30 vertical levels": "rectilinear",
    "around a cylinder": "curvilinear", "terrain-following": "curvilinear",
    "bent artery": "curvilinear", "follow the coastline": "curvilinear",
    "bracket": "unstructured", "scanned statue": "unstructured", "car-crash": "unstructured",
    "(TIN)": "unstructured", "around a crack": "unstructured",
    "air-quality": "scattered", "sounded by a ship": "scattered", "boreholes": "scattered",
    "bird counts": "scattered", "rain gauges": "scattered",
}
KINDS = ("uniform", "rectilinear", "curvilinear", "unstructured", "scattered")


def choose_grid_kind(ex):
    [right] = [kind for word, kind in GRID_BY_WORD.items() if word in ex.scenario]
    return right, {f"{k} instead of {right}": k for k in KINDS if k != right}


def grid_memory(ex):
    shape, k, b = ex.shape, ex.components, ex.bytes_per_number
    d = len(shape)
    n = 1
    cells = 1
    for s in shape:
        n *= s
        cells *= s - 1
    split = 2 if d == 2 else 6
    corners = 3 if d == 2 else 4
    geometry, topology = {
        "uniform": (2 * d, d), "rectilinear": (sum(shape), d), "curvilinear": (d * n, d),
        "unstructured": (d * n, split * cells * corners), "scattered": (d * n, 0)}[ex.kind]
    values = n * k
    right = b * (geometry + topology + values)
    mistakes = {"values forgotten": b * (geometry + topology),
                "numbers, not bytes": geometry + topology + values}
    if k > 1:
        mistakes["components forgotten"] = b * (geometry + topology + n)
    if ex.kind == "rectilinear":
        mistakes["positions per sample"] = b * (d * n + d + values)
        mistakes["stored as uniform"] = b * (3 * d + values)
    if ex.kind in ("curvilinear", "unstructured", "scattered"):
        mistakes["one coordinate per sample"] = b * (n + topology + values)
    if ex.kind == "unstructured":
        mistakes["cells miscounted"] = b * (geometry + split * n * corners + values)
        mistakes["one cell per quad"] = b * (geometry + cells * corners + values)
    if ex.kind == "uniform":
        mistakes["positions stored"] = b * (d * n + values)
    return right, mistakes


def shepard_value(distances, values, power):
    top = bottom = 0.0
    for d, f in zip(distances, values):
        top += f / d ** power
        bottom += 1 / d ** power
    return top / bottom


def shepard_by_hand(ex):
    d = [math.dist(p, ex.query) for p in ex.points]
    f = list(ex.values)
    p = ex.power
    right = shepard_value(d, f, p)
    mistakes = {
        "not normalised": sum(v / di ** p for v, di in zip(f, d)),
        "distance, not inverse": shepard_value([1 / x for x in d], f, p),
        "plain mean": sum(f) / len(f),
        "nearest only": f[d.index(min(d))],
    }
    if p == 2:
        mistakes["power forgotten"] = shepard_value(d, f, 1)
        mistakes["squared twice"] = shepard_value(d, f, 4)
    else:
        mistakes["power 2 used"] = shepard_value(d, f, 2)
    return right, mistakes


def plane_value(points, values, x):
    """The plane z = a x + b y + c through three samples, at x."""
    m = np.column_stack([points, np.ones(3)])
    a, b, c = np.linalg.solve(m, values)
    return a * x[0] + b * x[1] + c


def inside(points, x):
    (ax, ay), (bx, by), (cx, cy) = points

    def side(px, py, qx, qy):
        return (qx - px) * (x[1] - py) - (qy - py) * (x[0] - px)
    s = [side(ax, ay, bx, by), side(bx, by, cx, cy), side(cx, cy, ax, ay)]
    return all(v >= 0 for v in s) or all(v <= 0 for v in s)


def nearest_vs_linear(ex):
    d = [math.dist(p, ex.query) for p in ex.points]
    nearest = float(ex.values[d.index(min(d))])
    [t] = [t for t in range(2) if inside(ex.points[ex.triangles[t]], ex.query)]
    tri, other = ex.triangles[t], ex.triangles[1 - t]
    linear = plane_value(ex.points[tri], ex.values[tri], ex.query)
    # barycentric weights as areas of the sub-triangles opposite each corner
    a, b, c = ex.points[tri]

    def area(u, v, w):
        return abs((v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])) / 2
    whole = area(a, b, c)
    lam = [area(ex.query, b, c) / whole, area(a, ex.query, c) / whole,
           area(a, b, ex.query) / whole]
    f = ex.values[tri]
    return [nearest, linear], {
        "order swapped": [linear, nearest],
        "plain average": [nearest, float(np.mean(f))],
        "wrong triangle": [nearest, plane_value(ex.points[other], ex.values[other], ex.query)],
        "weights on the wrong corners": [nearest, lam[2] * f[0] + lam[0] * f[1]
                                         + lam[1] * f[2]],
    }


SPECS = {
    "ClassifyLevels": (classify_levels, "levels"),
    "ChooseGridKind": (choose_grid_kind, "kind"),
    "GridMemory": (grid_memory, "number"),
    "ShepardByHand": (shepard_by_hand, "number"),
    "NearestVsLinear": (nearest_vs_linear, "vector"),
}
GARBAGE = {
    "levels": ["nominal", ["nominal"], ["nominal"] * 5, [1, 2, 3, 4], {"a": 1},
               ["nominal", "ordinal", "cardinal", "ratio"], 3],
    "kind": ["grid", 1, ["uniform"], {"a": 1}, b"uniform", ""],
    "number": ["7", {"x": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf],
    "vector": ["v", {"v": 1}, [1, 2, 3], [[1, 2], [3]], [math.nan, 1], [1, math.inf]],
}


def same(a, b, form):
    if form in ("levels", "kind"):
        return a == b
    return harness.gap(a, b) < harness.SAME


globals().update(harness.common_tests(ch10, SPECS, GARBAGE, exercises, at_least=5,
                                      distinct=(20, 8)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "levels":
            answers = [right, tuple(right), [f" {r.upper()} " for r in right]]
        elif form == "kind":
            answers = [right, right.upper(), f" {right} "]
        elif form == "number" and name == "GridMemory":
            answers = [right, float(right), np.int64(right)]
        else:
            answers = [right, np.round(right, 4), np.asarray(right).tolist()]
        harness.assert_accepted(ex, answers)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, form = SPECS[name]
    for ex in exercises(name, range(30)):
        worked, right = ex.worked(), solve(ex)[0]
        if form in ("levels", "kind"):
            assert worked.answer == right
        else:
            assert harness.gap(worked.answer, right) < 1e-9
        assert ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_classify_levels_explains_every_wrong_attribute():
    for ex in exercises("ClassifyLevels", range(40)):
        right, _ = classify_levels(ex)
        flipped = [LEVELS[a][1] for a in ex.attributes]
        fb = ex.check(flipped)
        assert fb.status == "wrong" and fb.diagnosis == "several levels wrong"
        assert all(a in fb.message for a in ex.attributes) and fb.credit == 0
        other = list(right)
        options = [lv for lv in ("nominal", "ordinal", "interval", "ratio")
                   if lv not in (right[0], LEVELS[ex.attributes[0]][1])]
        other[0] = options[0]
        fb = ex.check(other)
        assert fb.diagnosis == "wrong level" and right[0] in fb.message
        assert fb.credit == pytest.approx(0.75)
        assert len({LEVELS[a][2] for a in ex.attributes}) == 4       # four different traps


def test_tables_cover_the_catalogues():
    from course_lib.dataviz import ATTRIBUTE_EXAMPLES

    assert set(LEVELS) == set(ATTRIBUTE_EXAMPLES)
    assert {a: LEVELS[a][0] for a in LEVELS} == {a: v[0] for a, v in ATTRIBUTE_EXAMPLES.items()}
    asked = {module.ChooseGridKind(seed=s).scenario for s in range(300)}
    assert asked == {text for text, _ in module.GRID_SCENARIOS}
    for text, kind in module.GRID_SCENARIOS:
        assert [k for w, k in GRID_BY_WORD.items() if w in text] == [kind], text
    for kind in KINDS:
        assert sum(k == kind for _, k in module.GRID_SCENARIOS) >= 4


def test_numbers_work_by_hand():
    for ex in exercises("ShepardByHand"):
        d = [math.dist(p, ex.query) for p in ex.points]
        assert all(x == round(x) for x in d) and ex.power in (1, 2)
        assert sorted(d)[0] < sorted(d)[1]                          # one nearest sample
    for ex in exercises("NearestVsLinear"):
        assert np.all(ex.query * 4 == np.round(ex.query * 4))       # quarters
        assert np.all(ex.points == np.round(ex.points)) and np.all(ex.values == np.round(ex.values))
    for ex in exercises("GridMemory"):
        assert isinstance(ex.expected, int) and ex.expected > 0
