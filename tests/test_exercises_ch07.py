"""Tests of the chapter 7 exercises (course_lib.exercises.ch07).

For every exercise and many seeds: the statement reads, the right answer is accepted,
placeholders are "unanswered", garbage is "invalid", and every anticipated mistake, rebuilt here
from the question's attributes, is named by its diagnosis. The right answers are computed here
independently of the checkers: with the `bezier` package (Bézier curves, their hodographs,
subdivision and degree elevation), scipy's BSpline (basis functions and B-spline curves), geomdl
(knot vectors and Bézier patches) and closed forms typed out below (Bernstein polynomials, the
circular arc, the conic invariant, the table of properties), never with the course_lib function
the checker calls.
"""
import math

import bezier
import numpy as np
import pytest
from geomdl import BSpline as GeomdlBSpline
from geomdl import knotvector
from scipy.interpolate import BSpline, PPoly

from course_lib.exercises import ch07
import exercise_harness as harness
from exercise_harness import SAME, Either, gap


# ---------------------------------------------------------------------------------------------
# Independent tools
# ---------------------------------------------------------------------------------------------

def bezier_point(points, t):
    """The Bézier curve of `points` (rows) at t, by the `bezier` package."""
    p = np.asarray(points, dtype=float)
    curve = bezier.Curve(np.asfortranarray(p.T), degree=len(p) - 1)
    return curve.evaluate(float(t)).ravel()


def bezier_curve(points):
    p = np.asarray(points, dtype=float)
    return bezier.Curve(np.asfortranarray(p.T), degree=len(p) - 1)


def bernstein_by_hand(n, t):
    return np.array([math.comb(n, i) * t ** i * (1 - t) ** (n - i) for i in range(n + 1)])


def basis_values(knots, degree, t):
    """All B-spline basis functions at t, by scipy."""
    n_basis = len(knots) - degree - 1
    return BSpline(np.asarray(knots, dtype=float), np.eye(n_basis), degree)(t)


def even_knots(knots, degree):
    n_control = len(knots) - degree - 1
    a, b = knots[degree], knots[n_control]
    return np.array([a + (j - degree) * (b - a) / (n_control - degree)
                     for j in range(len(knots))])


def naive_cox_de_boor(knots, degree, t):
    """The recursion with plain divisions (no 0/0 := 0 rule): NaN where a 0/0 was met."""
    u = np.asarray(knots, dtype=float)
    level = np.array([1.0 if u[i] <= t < u[i + 1] else 0.0 for i in range(len(u) - 1)])
    with np.errstate(divide="ignore", invalid="ignore"):
        for r in range(1, degree + 1):
            i = np.arange(len(level) - 1)
            level = ((t - u[i]) / (u[i + r] - u[i]) * level[:-1]
                     + (u[i + r + 1] - t) / (u[i + r + 1] - u[i + 1]) * level[1:])
    return level


# ---------------------------------------------------------------------------------------------
# Per exercise: the expected answer and the anticipated mistakes, from the attributes
# ---------------------------------------------------------------------------------------------

def de_casteljau_point(ex):
    P, t, n = np.asarray(ex.P, dtype=float), ex.t, ex.n
    right = bezier_point(P, t)
    first, second = bezier_point(P[:-1], t), bezier_point(P[1:], t)   # level n - 1
    return right, {
        "no binomial": sum(t ** i * (1 - t) ** (n - i) * P[i] for i in range(n + 1)),
        "t swapped": bezier_point(P, 1 - t),
        "stopped early": Either([first, second]),
        "end points only": (1 - t) * P[0] + t * P[n],
    }


def casteljau_level(P, t, r):
    """Level r of de Casteljau's triangle: P_i^r(t) is the Bézier curve of P_i..P_{i+r}."""
    P = np.asarray(P, dtype=float)
    if r == 0:
        return P
    return np.array([bezier_point(P[i:i + r + 1], t) for i in range(len(P) - r)])


def de_casteljau_level(ex):
    P, t, r = np.asarray(ex.P, dtype=float), ex.t, ex.r
    mistakes = {
        "t swapped": casteljau_level(P, 1 - t, r),
        "midpoints": casteljau_level(P, 0.5, r),
        "wrong level": casteljau_level(P, t, r + 1),
    }
    if r == 2:
        mistakes["skipped a level"] = (1 - t) * P[:-2] + t * P[2:]
    return casteljau_level(P, t, r), mistakes


def bernstein_values(ex):
    n, t = ex.n, ex.t
    right = bernstein_by_hand(n, t)
    assert math.isclose(right.sum(), 1.0)
    return right, {
        "no binomial": [t ** i * (1 - t) ** (n - i) for i in range(n + 1)],
        "powers swapped": bernstein_by_hand(n, 1 - t),
    }


def end_tangent(ex):
    P, n = np.asarray(ex.P, dtype=float), ex.n
    right = bezier_curve(P).evaluate_hodograph(float(ex.end)).ravel()
    other = bezier_curve(P).evaluate_hodograph(1.0 - ex.end).ravel()
    return right, {
        "missing factor n": right / n,
        "reversed": -right,
        "reversed, missing n": -right / n,
        "wrong end": other,
        "normalised": right / np.linalg.norm(right),
    }


def subdivision(ex):
    curve = bezier_curve(ex.P)
    left = curve.specialize(0.0, ex.t).nodes.T
    right = curve.specialize(ex.t, 1.0).nodes.T
    return left, {
        "right part": right,
        "reversed order": left[::-1],
        "t swapped": curve.specialize(0.0, 1 - ex.t).nodes.T,
    }


def elevation(ex):
    P, n = np.asarray(ex.P, dtype=float), ex.n
    right = bezier_curve(P).elevate().nodes.T

    def blend(weights):
        return np.vstack([P[:1]] + [w * P[i - 1] + (1 - w) * P[i]
                                    for i, w in enumerate(weights, start=1)] + [P[-1:]])

    return right, {
        "weights swapped": blend([1 - i / (n + 1) for i in range(1, n + 1)]),
        "midpoints": blend([0.5] * n),
        "divided by n": blend([i / n for i in range(1, n + 1)]),
        "not elevated": P,
    }


def clamped_knot_vector(ex):
    N, p = ex.n_control, ex.p
    a, b = 0.0, 1.0
    right = unit = np.array(knotvector.generate(p, N), dtype=float)       # geomdl: on [0, 1]
    assert len(right) == N + p + 1

    def clamped(copies, interior):
        inner = [a + (b - a) * j / (interior + 1) for j in range(1, interior + 1)]
        return np.array([a] * copies + inner + [b] * copies)

    odd = right.copy()
    odd[p + 1:N] = a + (b - a) * unit[p + 1:N] ** 2          # ends right, interior uneven
    mistakes = {
        "p copies at the ends": clamped(p, N - p - 1),
        "end multiplicity": clamped(p + 2, N - p - 1),
        "one knot short": clamped(p + 1, N - p - 2),
        "one knot too many": clamped(p + 1, N - p),
        "wrong count": clamped(p + 1, N - p + 1),
        "interior knots": odd,
        "decreasing": right[::-1],
    }
    if p > 1:                                 # for p = 1 these are the "p copies" above
        mistakes["not clamped"] = np.linspace(a, b, N + p + 1)
    mistakes["not normalised"] = unit * (N - p)                  # whole knots on [0, N - p]
    return right, mistakes


def cox_de_boor(ex):
    u, p, t = np.asarray(ex.knots, dtype=float), ex.p, ex.t
    right = basis_values(u, p, t)
    assert len(right) == ex.n_control and math.isclose(right.sum(), 1.0)
    return right, {
        "index shift": Either([np.append(right[1:], 0.0), np.insert(right[:-1], 0, 0.0)]),
        "uniform knots": basis_values(even_knots(u, p), p, t),
        "zero denominator": naive_cox_de_boor(u, p, t),
        "one degree short": basis_values(u, p - 1, t),
    }


def basis_support(ex):
    u, p, i = np.asarray(ex.knots, dtype=float), ex.p, ex.i
    right = np.array([u[i], u[i + p + 1]])
    coefficients = np.zeros(len(u) - p - 1)
    coefficients[i] = 1.0
    spline = BSpline(u, coefficients, p, extrapolate=False)
    inside = np.linspace(right[0], right[1], 9)[1:-1]
    assert np.all(spline(inside) > 0)                     # non-zero inside, by scipy
    outside = [x for x in np.arange(u[0], u[-1], 0.25) if x < right[0] or x >= right[1]]
    assert not np.any(np.nan_to_num(spline(outside)))
    mistakes = {"one span short": [u[i], u[i + p]], "indices, not knots": [i, i + p + 1]}
    if i + p + 2 < len(u):
        mistakes["one span too many"] = [u[i], u[i + p + 2]]
    if i >= p:
        mistakes["backwards"] = [u[i - p], u[i + 1]]
    return right, mistakes


def active_points(ex):
    u, p, t, N = np.asarray(ex.knots, dtype=float), ex.p, ex.t, ex.n_control
    right = {int(i) for i in np.flatnonzero(basis_values(u, p, t) > 1e-12)}
    assert len(right) == p + 1
    lo, hi = min(right), max(right)
    candidates = {
        "span k+1": [set(range(lo + 1, hi + 2))],                # P_{k-p+1}, ..., P_{k+1}
        "span k-1": [set(range(lo - 1, hi))],
        "one too few": [set(range(lo + 1, hi + 1)), set(range(lo, hi))],
        "one too many": [set(range(lo - 1, hi + 1)), set(range(lo, hi + 2))],
        "global control": [set(range(N))],
    }
    return right, {key: Either([s for s in sets if min(s) >= 0 and max(s) < N])
                   for key, sets in candidates.items()}


def spline_piece(P, u, p, span, t):
    """The polynomial piece of the B-spline on knot span `span`, evaluated at t (also outside
    that span): scipy's piecewise-polynomial form of the spline, one coordinate at a time."""
    return np.array([np.polyval(PPoly.from_spline((u, P[:, d], p)).c[:, span], t - u[span])
                     for d in range(P.shape[1])])


def bspline_point(ex):
    P, u, p, t = np.asarray(ex.P, dtype=float), np.asarray(ex.knots, dtype=float), ex.p, ex.t
    right = BSpline(u, P, p)(t)
    N = len(P)
    a, b = u[p], u[N]
    k = int(np.searchsorted(u, t, side="right")) - 1
    assert gap(spline_piece(P, u, p, k, t), right) < 1e-9          # the piece of t's own span
    mistakes = {
        "Bézier curve": bezier_point(P, (t - a) / (b - a)),
        "uniform knots": BSpline(even_knots(u, p), P, p)(t),
        "local Bézier": bezier_point(P[k - p:k + 1], (t - u[k]) / (u[k + 1] - u[k])),
    }
    for other, key in ((k + 1, "span k+1"), (k - 1, "span k-1")):
        if p <= other < N and u[other] < u[other + 1]:          # a non-empty span of the domain
            mistakes[key] = spline_piece(P, u, p, other, t)
    weights = basis_values(u, p, t)
    shifted = [weights[k - p:k + 1] @ P[k - p + s:k + 1 + s] for s in (1, -1)
               if k - p + s >= 0 and k + s < N]
    if shifted:
        mistakes["points shifted"] = Either(shifted)
    return right, mistakes


def rational_point(ex):
    P, w, t = np.asarray(ex.P, dtype=float), np.asarray(ex.w, dtype=float), ex.t
    homogeneous = bezier_point(np.column_stack([w[:, None] * P, w]), t)   # one dimension up
    right = homogeneous[:-1] / homogeneous[-1]
    b = bernstein_by_hand(2, t)
    return right, {
        "no division": homogeneous[:-1],
        "numerator unweighted": (b @ P) / (b @ w),
        "divided by the sum of weights": homogeneous[:-1] / w.sum(),
        "weights ignored": bezier_point(P, t),
    }


def circle_arc(ex):
    c, r = np.asarray(ex.center, dtype=float), ex.radius
    theta = math.radians(ex.theta_deg)
    a = math.radians(ex.alpha_deg)
    P0, P1, P2 = (np.asarray(q, dtype=float) for q in (ex.P0, ex.P1, ex.P2))
    assert gap(P0, c + r * np.array([math.cos(a), math.sin(a)])) < 1e-12
    assert gap(P2, c + r * np.array([math.cos(a + theta), math.sin(a + theta)])) < 1e-12
    assert abs(np.dot(P1 - P0, P0 - c)) < 1e-9 and abs(np.dot(P1 - P2, P2 - c)) < 1e-9
    mid = c + r * np.array([math.cos(a + theta / 2), math.sin(a + theta / 2)])

    def with_weight(w):
        return [w, *((P0 + 2 * w * P1 + P2) / (2 + 2 * w))]

    w = math.cos(theta / 2)
    mistakes = {
        "full angle": with_weight(math.cos(theta)),
        "degrees": with_weight(math.cos(ex.theta_deg / 2)),
        "parabola": with_weight(1.0),
        "no division": [w, *((P0 + 2 * w * P1 + P2) / 4)],
    }
    if ex.theta_deg != 90:
        mistakes["sin"] = with_weight(math.sin(theta / 2))
    return np.array([w, *mid]), mistakes


def conic_type(ex):
    def kind(w0, w1, w2):
        k = w1 * w1 / (w0 * w2)               # exact for these weights
        return "ellipse" if k < 1 else "parabola" if k == 1 else "hyperbola"

    right = [kind(*row) for row in ex.weights]
    swap = {"ellipse": "hyperbola", "hyperbola": "ellipse", "parabola": "parabola"}
    return right, {
        "middle weight alone": [kind(1, w1, 1) for _, w1, _ in ex.weights],
        "ellipse and hyperbola swapped": [swap[name] for name in right],
    }


def geomdl_patch(grid):
    g = np.asarray(grid, dtype=float)
    m, n = g.shape[0] - 1, g.shape[1] - 1
    surface = GeomdlBSpline.Surface()
    surface.degree_u, surface.degree_v = m, n
    surface.ctrlpts2d = g.tolist()
    surface.knotvector_u = [0.0] * (m + 1) + [1.0] * (m + 1)
    surface.knotvector_v = [0.0] * (n + 1) + [1.0] * (n + 1)
    return surface


def surface_point(ex):
    g, u, v = np.asarray(ex.grid, dtype=float), ex.u, ex.v
    patch = geomdl_patch(g)
    right = np.array(patch.evaluate_single((u, v)))
    corners = g[[0, -1]][:, [0, -1]]
    bilinear = ((1 - u) * (1 - v) * corners[0, 0] + (1 - u) * v * corners[0, 1]
                + u * (1 - v) * corners[1, 0] + u * v * corners[1, 1])
    mistakes = {
        "u and v swapped": np.array(patch.evaluate_single((v, u))),
        "one direction only": Either([bezier_point(g[:, 0], u), bezier_point(g[0], v)]),
    }
    if max(ex.m, ex.n) > 1:
        mistakes["corners only"] = bilinear
    return right, mistakes


#: The table of properties, typed out: which hold for which kind.
PROPERTY_TABLE = {
    #                          Bez  BSp  RBez NURBS BezS BSpS NURBSS
    "convex hull":            (1,   1,   1,   1,    1,   1,   1),
    "strong convex hull":     (0,   1,   0,   1,    0,   1,   1),
    "local control":          (0,   1,   0,   1,    0,   1,   1),
    "pseudo-local control":   (1,   0,   1,   0,    1,   0,   0),
    "affine invariance":      (1,   1,   1,   1,    1,   1,   1),
    "projective invariance":  (0,   0,   1,   1,    0,   0,   1),
    "variation diminishing":  (1,   1,   1,   1,    0,   0,   0),
    "endpoint interpolation": (1,   1,   1,   1,    1,   1,   1),
    "exact conics":           (0,   0,   1,   1,    0,   0,   1),
    "independent degree":     (0,   1,   0,   1,    0,   1,   1),
}
KINDS = ("Bézier curve", "B-spline curve", "rational Bézier curve", "NURBS curve",
         "Bézier surface", "B-spline surface", "NURBS surface")


def curve_properties(ex):
    column = KINDS.index(ex.kind)
    assert len(ex.menu) == 6 and set(ex.menu) <= set(PROPERTY_TABLE)
    right = {name for name, row in PROPERTY_TABLE.items() if row[column] and name in ex.menu}
    mistakes = {}
    for name in ex.menu:
        if name in right:
            mistakes[f"missing: {name}"] = right - {name}
        else:
            mistakes[f"extra: {name}"] = right | {name}
    return right, mistakes


POINT_GARBAGE = ["p", {"x": 1}, [[1, 2], [3]], [1, 2, 3, 4], np.eye(3), [math.inf, 0],
                 [1, 2, 0], [math.nan, 1]]
POINT3_GARBAGE = ["p", {"x": 1}, [[1, 2], [3]], [1, 2], np.eye(3), [math.inf, 0, 0],
                  [1, 2, 3, 0]]
VECTOR_GARBAGE = ["v", {"v": 1}, [[1, 2], [3]], [1] * 9, [[1, 2], [3, 4], [5, 6]],
                  [[math.nan]]]
POLYGON_GARBAGE = ["P", {"P": 1}, [[1, 2], [3]], [1, 2, 3], np.ones((7, 5)),
                   [[math.nan, 0]] * 3]
NUMBERS_GARBAGE = ["w", {"w": 1}, [1, 2], [[1], [2, 3]], [1, math.nan, 2], ("a", 1, 2)]
INDEX_GARBAGE = ["all", {"a": 1}, [0.5], [-1], [99], ["a", 1], [True, 1], 3]
NAMES_GARBAGE = ["ellipse", {"a": 1}, [1, 2, 3], ["ellipse"], ["circle", "ellipse", "ellipse"],
                 ["egg", "ellipse", "parabola"], 7]
PROPERTY_GARBAGE = ["convex hull", {"a": 1}, [1, 2], ["smoothness"], 3, [None, "x"]]
KNOTS_GARBAGE = ["U", {"u": 1}, [[0, 1], [1]], [[0, 0], [1, 1]], [0, math.nan, 1], [3]]

# class name: (independent answer and mistakes, answer form)
SPECS = {
    "DeCasteljauPoint": (de_casteljau_point, "point"),
    "DeCasteljauLevel": (de_casteljau_level, "polygon"),
    "BernsteinValues": (bernstein_values, "vector"),
    "BezierEndTangent": (end_tangent, "vector"),
    "BezierSubdivision": (subdivision, "polygon"),
    "DegreeElevation": (elevation, "polygon"),
    "ClampedKnotVector": (clamped_knot_vector, "knots"),
    "CoxDeBoorBasis": (cox_de_boor, "vector"),
    "BasisSupport": (basis_support, "vector"),
    "ActiveControlPoints": (active_points, "indices"),
    "BSplinePoint": (bspline_point, "point"),
    "RationalBezierPoint": (rational_point, "point"),
    "CircleArc": (circle_arc, "numbers"),
    "ConicType": (conic_type, "names"),
    "BezierSurfacePoint": (surface_point, "point3"),
    "CurveProperties": (curve_properties, "properties"),
}
GARBAGE = {"point": POINT_GARBAGE, "point3": POINT3_GARBAGE, "vector": VECTOR_GARBAGE,
           "polygon": POLYGON_GARBAGE, "numbers": NUMBERS_GARBAGE, "indices": INDEX_GARBAGE,
           "names": NAMES_GARBAGE, "properties": PROPERTY_GARBAGE, "knots": KNOTS_GARBAGE}
#: Answer forms whose answers are not arrays of numbers.
DISCRETE = {"indices", "names", "properties"}


#: The chapter's exercises may be split over topic files: this one tests those in SPECS,
#: tests/test_exercises_ch07_*.py the others, and test_every_exercise_is_tested_in_one_file
#: holds the union to the chapter's list.
TOPIC = harness.topic(ch07, SPECS)
exercises = harness.variants(TOPIC)


def as_answer(value, form):
    """A value of the spec in the form a student would type it."""
    if form in ("indices", "properties"):
        return sorted(value)
    return value


def same(a, b, form):
    if form in DISCRETE:
        return a == b
    if not np.all(np.isfinite(a)):                        # a NaN answer is never "right"
        return False
    return gap(a, b) < SAME


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(TOPIC, SPECS, GARBAGE, exercises, at_least=12))


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form in DISCRETE:
            answers = [as_answer(right, form)]
            if form != "names":
                answers.append(tuple(as_answer(right, form)))
            if form == "properties":
                answers.append([n.upper().replace(" ", "-") for n in right])   # lenient names
        else:
            answers = [right, np.round(right, 3), np.asarray(right).tolist()]
        harness.assert_accepted(ex, answers)
        if form in ("point", "point3"):                     # homogeneous with w = 1 is fine too
            assert ex.check(np.append(right, 1.0)).status == "correct"


@pytest.mark.parametrize("name", SPECS)
def test_mistakes_are_diagnosed(name):
    harness.check_mistakes(name, SPECS, exercises, same, as_answer=as_answer)
    if name == "DeCasteljauPoint":                    # both points of the last-but-one level
        for ex in exercises(name):
            _, mistakes = de_casteljau_point(ex)
            fb = ex.check(np.array(list(mistakes["stopped early"])))
            assert fb.diagnosis == "stopped early", (ex, fb)


def test_wrong_answers_get_teaching_feedback():
    """An answer no slip explains still says how to get it right."""
    for name in ("DeCasteljauPoint", "BezierSubdivision", "CoxDeBoorBasis", "BSplinePoint",
                 "BezierSurfacePoint", "BernsteinValues"):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(np.asarray(right) + 0.37)
            assert fb.status == "wrong" and len(fb.message) > 80, (ex, fb)
    for ex in exercises("CurveProperties", range(30)):
        right, _ = curve_properties(ex)
        everything = list(ex.menu)
        fb = ex.check(everything)
        wrong = set(everything) - right
        assert fb.status == "wrong" and all(n in fb.message for n in wrong)
    for ex in exercises("ConicType", range(20)):
        right, _ = conic_type(ex)
        flipped = ["parabola" if right[0] != "parabola" else "ellipse"] + right[1:]
        fb = ex.check(flipped)
        assert fb.status == "wrong"
        if fb.diagnosis == "types differ":                  # no anticipated slip
            assert "Arc 1 is not right" in fb.message


def test_numbers_are_nice_for_hand_work():
    quarters = {0.25, 0.5, 0.75}
    thirds = {1 / 3, 2 / 3}
    for name in ("DeCasteljauPoint", "DeCasteljauLevel", "BezierSubdivision",
                 "RationalBezierPoint"):
        for ex in exercises(name):
            assert ex.t in quarters | thirds
            assert np.all(ex.P == np.round(ex.P)) and np.abs(ex.P).max() <= 4
    for name in ("CoxDeBoorBasis", "ActiveControlPoints", "BSplinePoint", "BasisSupport"):
        for ex in exercises(name):
            assert np.all(ex.knots == np.round(ex.knots))
            if hasattr(ex, "t"):
                assert ex.t * 4 == round(ex.t * 4) and ex.t not in set(ex.knots)
    for ex in exercises("BezierSurfacePoint"):
        assert ex.u != ex.v and {ex.u, ex.v} <= quarters | thirds
        assert np.all(ex.grid == np.round(ex.grid))
    for ex in exercises("CircleArc"):
        assert ex.theta_deg in (60, 90, 120)


def test_clamped_knots_agree_with_the_textbook_count():
    for ex in exercises("ClampedKnotVector"):
        right, _ = clamped_knot_vector(ex)
        assert len(right) == ex.n_control + ex.p + 1
        assert np.all(right[:ex.p + 1] == 0) and np.all(right[-ex.p - 1:] == 1)


def test_every_kind_of_curve_and_surface_is_asked():
    assert {ex.kind for ex in exercises("CurveProperties")} == set(KINDS)
    assert set(ch07.PROPERTY_MENU) == set(PROPERTY_TABLE)


#: A fresh seed is a fresh exercise: among VARIETY_SEEDS seeds every exercise has at least
#: MIN_VARIANTS variants (distinct right answers; distinct statements where the answer is a
#: choice from a menu or a list of indices).
VARIETY_SEEDS = range(300)
MIN_VARIANTS = 40       # reached: ClampedKnotVector and BasisSupport have 40


def variant_key(ex, form):
    if form in DISCRETE:
        return ex.statement()
    return harness.answer_key(SPECS[type(ex).__name__][0](ex)[0])


@pytest.mark.parametrize("name", SPECS)
def test_a_fresh_seed_is_a_fresh_exercise(name):
    cls, form = getattr(ch07, name), SPECS[name][1]
    found = {variant_key(cls(seed=seed), form) for seed in VARIETY_SEEDS}
    assert len(found) >= MIN_VARIANTS, (name, len(found))


def test_whole_numbers_are_compared_exactly():
    """Indices and whole-number knots: 3.0 is 3, and one more or one less is wrong."""
    for ex in exercises("BasisSupport", range(40)):
        right, _ = basis_support(ex)
        assert ex.check([float(x) for x in right]).status == "correct"
        for k in range(2):
            for step in (1, -1):
                near = np.array(right, dtype=float)
                near[k] += step
                fb = ex.check(near)
                assert fb.status == "wrong", (ex, near, fb)
        off = np.array(right, dtype=float) + [0, 0.001]      # close is not enough
        assert ex.check(off).status == "wrong"
    for ex in exercises("ActiveControlPoints", range(40)):
        right, _ = active_points(ex)
        assert ex.check([float(i) for i in sorted(right)]).status == "correct"
        assert ex.check(np.array(sorted(right))).status == "correct"
        top = max(right)
        if top + 1 < ex.n_control:                            # the last index one too high
            fb = ex.check(sorted(right - {top} | {top + 1}))
            assert fb.status == "wrong", (ex, fb)
        assert ex.check(sorted(right)[:-1] + [top + 0.5]).status == "invalid"


def test_an_off_by_one_span_is_named_with_this_variants_span():
    """The slips "span k-1" and "span k+1" are explained with the span of t in this variant."""
    seen = {("ActiveControlPoints", "span k-1"): 0, ("ActiveControlPoints", "span k+1"): 0,
            ("BSplinePoint", "span k-1"): 0, ("BSplinePoint", "span k+1"): 0,
            ("BSplinePoint", "points shifted"): 0}
    for name, solve in (("ActiveControlPoints", active_points), ("BSplinePoint", bspline_point)):
        for ex in exercises(name):
            u, t = np.asarray(ex.knots, dtype=float), ex.t
            k = int(np.searchsorted(u, t, side="right")) - 1
            _, mistakes = solve(ex)
            for key in ("span k-1", "span k+1", "points shifted"):
                for value in mistakes.get(key, []) if isinstance(mistakes.get(key), Either) \
                        else ([mistakes[key]] if key in mistakes else []):
                    fb = ex.check(as_answer(value, SPECS[name][1]))
                    assert fb.diagnosis == key, (ex, key, fb)
                    assert f"k = {k}" in fb.message, (ex, key, fb.message)
                    seen[(name, key)] += 1
    assert min(seen.values()) >= 50, seen


def test_properties_not_shown_may_be_named_when_they_hold():
    """Listing every property that holds (the table shows 6 of the 10) is right; naming one
    that is not shown and fails is an error, diagnosed as extra."""
    for ex in exercises("CurveProperties"):
        column = KINDS.index(ex.kind)
        holds = {name for name, row in PROPERTY_TABLE.items() if row[column]}
        assert ex.check(sorted(holds)).status == "correct", ex
        hidden_false = [n for n in PROPERTY_TABLE if n not in ex.menu and n not in holds]
        right, _ = curve_properties(ex)
        for name in hidden_false:
            fb = ex.check(sorted(right | {name}))
            assert fb.status == "wrong" and fb.diagnosis == f"extra: {name}", (ex, name, fb)


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch07, SPECS, at_least=12)
