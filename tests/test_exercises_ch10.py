"""Tests of the chapter 10 exercises (course_lib.exercises.ch10).

For every exercise and many seeds: the statement reads, the right answer is accepted (in its
equivalent forms), placeholders are "unanswered", garbage is "invalid", and every anticipated
mistake, rebuilt here from the question's attributes, is named by its diagnosis. The right
answers are computed here independently of the checkers: the normalisation and the transfer
functions by the formulas typed out below and numpy's ``interp``; colour-map look-ups with
matplotlib's ``LinearSegmentedColormap`` (at its own table entries, which fall exactly on the
question's values); lightness with scikit-image's ``rgb2lab``; the lightness curves of the maps
from matplotlib's colour maps and scikit-image; the kinds of colour map from a table typed out
here. Never with the course_lib function the checker calls.
"""
import math

import matplotlib
import numpy as np
import pytest
from matplotlib.colors import LinearSegmentedColormap
from skimage.color import rgb2lab

from course_lib import colormaps as cm
from course_lib.exercises import ch10
import exercise_harness as harness
from exercise_harness import SAME, gap


# ---------------------------------------------------------------------------------------------
# Independent answers and slips
# ---------------------------------------------------------------------------------------------

def by_formula(v, a, b, c, d):
    return [(x - a) / (b - a) * (d - c) + c for x in v]


def normalize_values(ex):
    (a, b), (c, d), v = ex.in_range, ex.out_range, list(ex.values)
    right = np.array(by_formula(v, a, b, c, d))
    lo, hi = min(v), max(v)
    return right, {
        "no offset": np.array(by_formula(v, a, b, 0, d - c)),
        "unit interval": np.array(by_formula(v, a, b, 0, 1)),
        "divided by b": np.array([(x - a) / b * (d - c) + c for x in v]),
        "no shift": np.array([x / (b - a) * (d - c) + c for x in v]),
        "data range": np.array(by_formula(v, lo, hi, c, d)),
        "ranges swapped": np.array(by_formula(v, c, d, a, b)),
    }


def denormalize(ex):
    (a, b), (c, d), g = ex.in_range, ex.out_range, ex.g
    right = a + (g - c) * (b - a) / (d - c)
    assert math.isclose(by_formula([right], a, b, c, d)[0], g)          # it maps back
    mistakes = {
        "forward formula": by_formula([g], a, b, c, d)[0],
        "no shift back": (g - c) * (b - a) / (d - c),
        "ignored c": g * (b - a) / (d - c) + a,
    }
    if d == 255:
        mistakes["256 levels"] = g * (b - a) / 256 + a
    return right, mistakes


def step_values(points, values, samples):
    """v_i on [s_i, s_{i+1}), v_0 below s_0."""
    out = []
    for s in samples:
        i = max([k for k, p in enumerate(points) if p <= s], default=0)
        out.append(values[i])
    return np.array(out, dtype=float)


def transfer_values(ex):
    p, v, s = list(ex.points), list(ex.values), list(ex.samples)
    right = np.interp(s, p, v)
    nearest = [v[min(range(len(p)), key=lambda k: abs(p[k] - x))] for x in s]

    def extrapolate(x):
        if x < p[0]:
            return v[0] + (x - p[0]) * (v[1] - v[0]) / (p[1] - p[0])
        if x > p[-1]:
            return v[-1] + (x - p[-1]) * (v[-1] - v[-2]) / (p[-1] - p[-2])
        return float(np.interp(x, p, v))

    return right, {
        "step": step_values(p, v, s),
        "nearest": np.array(nearest, dtype=float),
        "extrapolated": np.array([extrapolate(x) for x in s]),
        "ends only": np.interp(s, [p[0], p[-1]], [v[0], v[-1]]),
    }


def threshold_bands(ex):
    p, v, s = list(ex.points), list(ex.values), list(ex.samples)
    right = step_values(p, v, s)
    lower = [v[max([k for k, q in enumerate(p) if q < x], default=0)] for x in s]
    upper = [v[min(max([k for k, q in enumerate(p) if q <= x], default=-1) + 1, len(p) - 1)]
             for x in s]
    return right, {
        "boundary below": np.array(lower, dtype=float),
        "next band": np.array(upper, dtype=float),
        "interpolated": np.interp(s, p, v),
    }


def design_opacity(ex):
    lo, hi, w, a = ex.low, ex.high, ex.width, ex.alpha
    right = [(lo - w, 0.0), (lo, a), (hi, a), (hi + w, 0.0)]
    return right, {
        "ramps inside": [(lo, 0.0), (lo + w, a), (hi - w, a), (hi, 0.0)],
        "no ramps": [(lo, 0.0), (lo, a), (hi, a), (hi, 0.0)],
        "full opacity": [(lo - w, 0.0), (lo, 1.0), (hi, 1.0), (hi + w, 0.0)],
        "inverted": [(lo - w, a), (lo, 0.0), (hi, 0.0), (hi + w, a)],
    }


def mpl_lookup(colors, t):
    """The colour at t by matplotlib, whose table has an entry exactly at t."""
    n = len(colors)
    entries = 20 * (n - 1) + 1                   # entries at multiples of 1 / (20 (n - 1))
    cmap = LinearSegmentedColormap.from_list("q", [tuple(c) for c in colors], N=entries)
    k = round(t * (entries - 1))
    assert math.isclose(k / (entries - 1), t, abs_tol=1e-12)
    return np.array(cmap(k)[:3])


def hand_lookup(colors, t):
    grid = np.linspace(0, 1, len(colors))
    return np.array([np.interp(t, grid, colors[:, ch]) for ch in range(3)])


def colormap_lookup(ex):
    c = np.asarray(ex.colors, dtype=float)
    n = len(c)
    (a, b), v = ex.in_range, ex.value
    t = (v - a) / (b - a)
    right = mpl_lookup(c, t)
    assert gap(right, hand_lookup(c, t)) < 1e-6
    p = t * (n - 1)
    return right, {
        "no interpolation": c[math.floor(p)],
        "n intervals": hand_lookup(c, min(t * n / (n - 1), 1.0)),
        "reversed": mpl_lookup(c[::-1], t),
        "forgot a": hand_lookup(c, min(max(v / b, 0.0), 1.0)),
    }


def srgb_linear(c):
    c = np.asarray(c, dtype=float)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def lightness(ex):
    rgb = np.asarray(ex.rgb, dtype=float)
    right = float(rgb2lab(rgb[None, None, :])[0, 0, 0])
    weights = np.array([0.2126, 0.7152, 0.0722])
    y = float(weights @ srgb_linear(rgb))
    assert abs(right - (116 * y ** (1 / 3) - 16)) < 0.01            # the formula agrees

    def lstar(yy):
        return 116 * yy ** (1 / 3) - 16 if yy > (6 / 29) ** 3 else yy * (29 / 3) ** 3

    return right, {
        "not linearised": lstar(float(weights @ rgb)),
        "channel mean": lstar(float(srgb_linear(rgb).mean())),
        "luminance, not lightness": 100 * y,
        "forgot 16": 116 * y ** (1 / 3),
    }


HSV_RAINBOW = np.array([[0, 0, 1], [0, 1, 1], [0, 1, 0], [1, 1, 0], [1, 0, 0]], dtype=float)
MPL_NAMES = {"grey": "gray"}


def reference_lightness(name, n=9):
    """L* at n points of a map: the map from matplotlib (rainbow typed out), L* by skimage."""
    t = np.linspace(0, 1, n)
    if name == "rainbow":
        rgb = np.stack([hand_lookup(HSV_RAINBOW, x) for x in t])
    else:
        rgb = matplotlib.colormaps[MPL_NAMES.get(name, name)](t)[:, :3]
    return rgb2lab(rgb[None])[0, :, 0]


def monotonic(values):
    d = np.diff(values)
    return bool((d >= 0).all() or (d <= 0).all())


def monotonic_maps(ex):
    right = set()
    for name, row in zip(ex.maps, ex.lightness):
        reference = reference_lightness(name)
        assert gap(row, reference) < 1.0, (name, row, reference)   # the table is right
        if monotonic(reference_lightness(name, 256)):
            right.add(name)
    mistakes = {}
    for name in ex.maps:
        if name in right:
            mistakes[f"missing: {name}"] = right - {name}
        else:
            mistakes[f"extra: {name}"] = right | {name}
    return right, mistakes


#: The kind each data set needs, typed out by hand (one word or phrase of its description).
KIND_BY_WORD = {
    "rainfall": "sequential", "population density": "sequential", "CT scan": "sequential",
    "wind speed": "sequential", "pollutant": "sequential", "mountain range": "sequential",
    "age of the trees": "sequential", "visitors": "sequential", "depth of the water":
    "sequential", "camera sensor": "sequential", "household income": "sequential",
    "cars per hour": "sequential",
    "anomaly": "diverging", "election margin": "diverging", "correlation": "diverging",
    "profit or loss": "diverging", "census": "diverging", "simulation": "diverging",
    "sea floor": "diverging", "trade balance": "diverging", "class average": "diverging",
    "net migration": "diverging", "glacier": "diverging", "goal difference": "diverging",
    "parcel: forest": "qualitative", "segmented scan": "qualitative", "cluster": "qualitative",
    "new town": "qualitative", "election:": "qualitative", "soil type": "qualitative",
    "language": "qualitative", "species": "qualitative", "machine": "qualitative",
    "blood group": "qualitative", "country of origin": "qualitative",
    "car park": "qualitative",
}


def choose_kind(ex):
    [right] = [kind for word, kind in KIND_BY_WORD.items() if word in ex.scenario]
    return right, {f"{kind} instead of {right}": kind
                   for kind in ("sequential", "diverging", "qualitative") if kind != right}


VECTOR_GARBAGE = ["v", {"v": 1}, [[1, 2], [3]], [1] * 9, [[1, 2], [3, 4], [5, 6]],
                  [[math.nan]]]
NUMBER_GARBAGE = ["7", {"x": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]
DESIGN_GARBAGE = ["ramp", {"a": 1}, [1, 2, 3], [[1, 2, 3]], [(0, 0.5), (1, 2)],
                  [(0, -0.1), (1, 0.5)], [(1, 0), (1, 0.5), (1, 1)], [[math.nan, 0], [1, 1]],
                  cm.color_transfer([0, 1], [[0, 0, 0], [1, 1, 1]])]
NAMES_GARBAGE = ["viridis", {"a": 1}, [1, 2], ["nonsense"], 3, [None, "x"]]
KIND_GARBAGE = ["rainbow", 1, ["sequential"], {"a": 1}, b"diverging", ""]

SPECS = {
    "NormalizeValues": (normalize_values, "vector"),
    "Denormalize": (denormalize, "number"),
    "TransferValues": (transfer_values, "vector"),
    "ThresholdBands": (threshold_bands, "vector"),
    "DesignOpacity": (design_opacity, "design"),
    "ColormapLookup": (colormap_lookup, "vector"),
    "LightnessOfColour": (lightness, "number"),
    "MonotonicMaps": (monotonic_maps, "names"),
    "ChooseMapKind": (choose_kind, "kind"),
}
GARBAGE = {"vector": VECTOR_GARBAGE, "number": NUMBER_GARBAGE, "design": DESIGN_GARBAGE,
           "names": NAMES_GARBAGE, "kind": KIND_GARBAGE}
DISCRETE = {"names", "kind"}


#: The chapter's exercises are split over topic files: this one tests those in SPECS (section
#: 10.5), tests/test_exercises_ch10_*.py the others, and test_every_exercise_is_tested_in_one_file
#: holds the union to the chapter's list.
TOPIC = harness.topic(ch10, SPECS)
exercises = harness.variants(TOPIC)


def as_answer(value, form):
    if form == "names":
        return sorted(value)
    return value


def design_function(points):
    """A control-point list evaluated off its kinks (numpy's interp)."""
    p = np.asarray(points, dtype=float)
    grid = np.linspace(p[0, 0] - 50, p[-1, 0] + 50, 997) + 1e-3
    return np.interp(grid, p[:, 0], p[:, 1])


def same(a, b, form):
    if form in DISCRETE:
        return a == b
    if form == "design":
        return gap(design_function(a), design_function(b)) < SAME
    return gap(a, b) < SAME


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(TOPIC, SPECS, GARBAGE, exercises, at_least=8))
test_mistakes_are_diagnosed = harness.mistakes_test(
    SPECS, exercises, same, as_answer=as_answer)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "names":
            answers = [sorted(right), tuple(right), [n.upper() for n in right]]
        elif form == "kind":
            answers = [right, right.upper(), f" {right} "]
        elif form == "design":
            points = np.array(right)
            s0, s1 = ex.data_range
            answers = [right, points.tolist(), points.T.tolist(),            # two rows
                       right[::-1],                                          # any order
                       [(s0, 0.0)] + right + [(s1, 0.0)],                    # ends added
                       right[:2] + [((right[1][0] + right[2][0]) / 2, ex.alpha)] + right[2:],
                       cm.opacity_transfer(points[:, 0], points[:, 1])]
        else:
            answers = [right, np.round(right, 4), np.asarray(right).tolist()]
        harness.assert_accepted(ex, answers)


def test_wrong_answers_get_teaching_feedback():
    """An answer no slip explains still says how to get it right."""
    for name in ("NormalizeValues", "TransferValues", "ThresholdBands", "ColormapLookup",
                 "Denormalize", "LightnessOfColour"):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(np.asarray(right) + 0.37 + 0.05 * np.abs(right))
            assert fb.status == "wrong" and len(fb.message) > 80, (ex, fb)
    for ex in exercises("DesignOpacity", range(20)):
        right, _ = design_opacity(ex)
        shifted = [(s + ex.width / 2, a) for s, a in right]
        fb = ex.check(shifted)
        assert fb.status == "wrong" and fb.diagnosis == "function differs"
        assert "should be" in fb.message
    for ex in exercises("MonotonicMaps", range(30)):
        fb = ex.check(list(ex.maps))
        wrong = set(ex.maps) - monotonic_maps(ex)[0]
        assert fb.status == "wrong" and all(n in fb.message for n in wrong)


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("NormalizeValues"):
        assert np.all(ex.values == np.round(ex.values, 2))
    for ex in exercises("ColormapLookup"):
        (a, b), n = ex.in_range, len(ex.colors)
        p = (ex.value - a) / (b - a) * (n - 1)
        assert math.isclose(p * 20, round(p * 20)) and p != round(p)    # between two colours
        assert ex.value == round(ex.value)
    for ex in exercises("LightnessOfColour"):
        assert np.all(np.isin(np.round(ex.rgb, 6), [0, 0.2, 0.4, 0.6, 0.8, 1]))
    for ex in exercises("TransferValues"):
        outside = (ex.samples < ex.points[0]) | (ex.samples > ex.points[-1])
        assert outside.sum() == 1                                # one sample tests the clamping
    for ex in exercises("ThresholdBands"):
        assert np.isin(ex.samples, ex.points[1:]).sum() == 1    # one sample on a threshold


def test_every_scenario_and_kind_is_asked():
    asked = {ch10.ChooseMapKind(seed=seed).scenario for seed in range(400)}
    assert asked == {s for s, _ in ch10.SCENARIOS}
    assert len(ch10.SCENARIOS) == len(KIND_BY_WORD) >= 36
    for scenario, kind in ch10.SCENARIOS:
        assert [k for w, k in KIND_BY_WORD.items() if w in scenario] == [kind], scenario
    for kind in ch10.MAP_KINDS:
        assert sum(k == kind for _, k in ch10.SCENARIOS) >= 12


#: A fresh seed is a fresh exercise: among VARIETY_SEEDS seeds every exercise has at least
#: MIN_VARIANTS variants (distinct right answers; distinct statements where the answer is a
#: choice: map names or a kind of map).
VARIETY_SEEDS = range(300)
MIN_VARIANTS = 36       # reached: ChooseMapKind asks each of its 36 data sets


def variant_key(ex, form):
    if form in DISCRETE:
        return ex.statement()
    return harness.answer_key(SPECS[type(ex).__name__][0](ex)[0])


@pytest.mark.parametrize("name", SPECS)
def test_a_fresh_seed_is_a_fresh_exercise(name):
    cls, form = getattr(ch10, name), SPECS[name][1]
    found = {variant_key(cls(seed=seed), form) for seed in VARIETY_SEEDS}
    assert len(found) >= MIN_VARIANTS, (name, len(found))


def test_design_opacity_uses_the_tolerance_policy():
    """Control points right to 3 significant digits pass; an opacity off by more does not."""
    for ex in exercises("DesignOpacity", range(40)):
        right, _ = design_opacity(ex)
        lo, hi, w, a = ex.low, ex.high, ex.width, ex.alpha
        close = [(lo - w, 0.0), (lo, a + 0.001), (hi, a + 0.001), (hi + w, 0.0)]
        assert ex.check(close).status == "correct", ex
        off = [(lo - w, 0.0), (lo, a + 0.01), (hi, a + 0.01), (hi + w, 0.0)]
        fb = ex.check(off)
        assert fb.status == "wrong" and fb.diagnosis == "function differs", (ex, fb)


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch10, SPECS, at_least=19)
