"""Tests of course_lib.curves (Bézier, B-spline, rational Bézier and NURBS curves).

Expected values come from independent libraries (scipy.interpolate.BSpline and insert, geomdl,
the `bezier` package), from closed forms typed out below, or from the curves' mathematical
properties (checked with hypothesis). Nothing here is copied from the output of the code under
test. Random inputs use seeded numpy generators.
"""
import math

import bezier as bezier_pkg             # test-only references: `bezier` and geomdl
import numpy as np
import pytest
from geomdl import BSpline as GeomdlBSpline
from geomdl import NURBS as GeomdlNURBS
from geomdl import operations as geomdl_operations
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline, PPoly, insert
from scipy.optimize import linprog

from course_lib import curves as C

FAST = settings(max_examples=60, deadline=None, database=None)   # no .hypothesis/ dir


# ---------------------------------------------------------------------------------------------
# helpers (independent of the code under test)
# ---------------------------------------------------------------------------------------------

def rng(seed):
    return np.random.default_rng(seed)


def random_knots(gen, n_control, degree, clamped, repeat=0):
    """A random knot vector on [0, 1] (first knot 0, last 1, as geomdl normalises them).

    Unclamped: distinct knots with random gaps. Clamped: degree + 1 equal end knots. `repeat`
    > 0 gives one interior knot that multiplicity, strictly inside the domain (the domain ends
    keep distinct neighbours, so every reference library agrees on t at the end).
    """
    m = n_control + degree + 1
    gaps = gen.uniform(0.2, 1.0, m - 1)
    u = np.concatenate([[0.0], np.cumsum(gaps)])
    u /= u[-1]
    if clamped:
        u[:degree + 1] = 0.0
        u[-degree - 1:] = 1.0
    if repeat and n_control - degree - 1 >= repeat + 1:
        # interior knot indices are degree+1 .. n_control-1; keep knots[n_control - 1] distinct
        j = gen.integers(degree + 1, n_control - repeat)
        u[j:j + repeat] = u[j]
    return u


def bspline_domain(u, p):
    n = len(u) - p - 1
    return u[p], u[n]


def params_in(gen, a, b, count, knots=()):
    """Random parameters in [a, b], plus both ends and the knots inside (exactly)."""
    inside = [k for k in knots if a <= k <= b]
    return np.concatenate([gen.uniform(a, b, count), [a, b], inside])


def scipy_curve(points, knots, degree):
    return BSpline(knots, points, degree, extrapolate=False)


def bezier_as_bspline(points):
    """A Bézier curve is the B-spline with knots 0 (n + 1 times) and 1 (n + 1 times)."""
    n = len(points) - 1
    return BSpline(np.r_[np.zeros(n + 1), np.ones(n + 1)], points, n, extrapolate=False)


def hull_distance(points, x):
    """Smallest s with |sum(l_i P_i) - x|_inf <= s over l >= 0, sum(l) = 1 (linprog)."""
    points = np.asarray(points, float)
    n, d = points.shape
    # variables: lambda_0..lambda_{n-1}, s; minimise s
    cost = np.r_[np.zeros(n), 1.0]
    a_ub = np.block([[points.T, -np.ones((d, 1))], [-points.T, -np.ones((d, 1))]])
    b_ub = np.r_[x, -np.asarray(x)]
    a_eq = np.r_[np.ones(n), 0.0][None]
    result = linprog(cost, A_ub=a_ub, b_ub=b_ub, A_eq=a_eq, b_eq=[1.0],
                     bounds=[(0, None)] * n + [(0, None)], method="highs")
    assert result.status == 0, result.message
    return result.fun


def sign_changes(values, eps=1e-12):
    s = np.sign(values[np.abs(values) > eps])
    return int(np.count_nonzero(s[1:] != s[:-1]))


def greville(u, p, n):
    return np.array([u[i + 1:i + p + 1].mean() for i in range(n)])


# hypothesis strategies
seeds = st.integers(0, 2**32 - 1)
degrees = st.integers(1, 7)
dims = st.integers(1, 3)
unit_t = st.floats(0.0, 1.0, allow_nan=False)


def test_hull_distance_helper_can_fail():
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    assert hull_distance(square, [0.5, 0.5]) <= 1e-12
    assert hull_distance(square, [1.5, 0.5]) == pytest.approx(0.5)


# ---------------------------------------------------------------------------------------------
# Bernstein polynomials
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("n", range(0, 11))
def test_bernstein_closed_form(n):
    t = np.r_[0.0, 1.0, np.linspace(0, 1, 37), rng(n).uniform(-0.5, 1.5, 20)]
    for i in range(n + 1):
        expected = np.array([math.comb(n, i) * x**i * (1 - x)**(n - i) for x in t])
        np.testing.assert_allclose(C.bernstein(n, i, t), expected, rtol=1e-12, atol=1e-14)
    matrix = C.bernstein(n, None, t)
    assert matrix.shape == t.shape + (n + 1,)
    for i in range(n + 1):
        np.testing.assert_allclose(matrix[:, i], C.bernstein(n, i, t), rtol=1e-13, atol=1e-16)


def test_bernstein_shapes_and_broadcasting():
    t = np.linspace(0, 1, 12).reshape(3, 4)
    assert C.bernstein(4, None, t).shape == (3, 4, 5)
    assert C.bernstein(4, 2, t).shape == (3, 4)
    i = np.arange(5)[:, None]
    np.testing.assert_allclose(C.bernstein(4, i, t[0]), C.bernstein(4, None, t[0]).T, rtol=1e-13)
    # 0^0 = 1: B_0^n(0) = B_n^n(1) = 1
    assert float(C.bernstein(5, 0, 0.0)) == 1.0 and float(C.bernstein(5, 5, 1.0)) == 1.0
    assert float(C.bernstein(0, 0, 0.3)) == 1.0


@FAST
@given(n=st.integers(0, 25), t=unit_t)
def test_bernstein_partition_of_unity_non_negative_and_symmetric(n, t):
    # symmetry B_i(t) = B_{n-i}(1 - t) needs parameters that are exact complements: for a tiny
    # t, 1 - t rounds (to 1 - 2^-53), and comparing against that would test the rounding of
    # the input, not the basis. With s = fl(1 - t) and t' = 1 - s (exact), 1 - t' = s exactly.
    t = 1.0 - (1.0 - t)
    b = C.bernstein(n, None, t)
    assert np.all(b >= 0)
    assert abs(b.sum() - 1.0) <= 1e-12
    np.testing.assert_allclose(b, C.bernstein(n, None, 1.0 - t)[::-1], rtol=1e-9, atol=1e-15)


def test_bernstein_maximum_at_i_over_n():
    n = 6
    t = np.linspace(0, 1, 6001)
    b = C.bernstein(n, None, t)
    np.testing.assert_allclose(t[np.argmax(b, axis=0)], np.arange(n + 1) / n, atol=1e-12)


# ---------------------------------------------------------------------------------------------
# Bézier curves: evaluation, de Casteljau, derivatives
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("degree", range(1, 11))
@pytest.mark.parametrize("dim", [1, 2, 3])
def test_bezier_matches_bezier_package_and_scipy(degree, dim):
    gen = rng(100 * degree + dim)
    P = gen.normal(size=(degree + 1, dim))
    t = np.r_[0.0, 1.0, gen.uniform(0, 1, 200)]
    expected = bezier_pkg.Curve(P.T, degree=degree).evaluate_multi(t).T
    np.testing.assert_allclose(C.bezier(P, t), expected, atol=1e-12)
    np.testing.assert_allclose(C.de_casteljau(P, t), expected, atol=1e-12)
    np.testing.assert_allclose(C.bezier(P, t), bezier_as_bspline(P)(t), atol=1e-12)


def test_bezier_quadratic_closed_form_and_shapes():
    P = np.array([[0.0, 0.0], [1.0, 3.0], [4.0, 1.0]])
    t = np.linspace(0, 1, 11)
    expected = ((1 - t)**2)[:, None] * P[0] + (2 * t * (1 - t))[:, None] * P[1] \
        + (t**2)[:, None] * P[2]
    np.testing.assert_allclose(C.bezier(P, t), expected, atol=1e-15)
    assert C.bezier(P, 0.5).shape == (2,)
    assert C.bezier(P, np.zeros((3, 4))).shape == (3, 4, 2)
    assert C.de_casteljau(P, np.zeros((3, 4))).shape == (3, 4, 2)


def test_de_casteljau_triangle_levels():
    gen = rng(7)
    P = gen.normal(size=(5, 2))
    t = 0.3
    point, levels = C.de_casteljau(P, t, triangle=True)
    assert len(levels) == 5
    assert [lv.shape for lv in levels] == [(5 - r, 2) for r in range(5)]
    np.testing.assert_array_equal(levels[0], P)
    for r in range(1, 5):                     # each level interpolates the one before
        np.testing.assert_allclose(levels[r], (1 - t) * levels[r - 1][:-1] + t * levels[r - 1][1:],
                                   atol=1e-15)
    np.testing.assert_allclose(levels[4][0], point, atol=0)
    np.testing.assert_allclose(point, bezier_pkg.Curve(P.T, 4).evaluate(t).ravel(), atol=1e-12)
    # many t at once: levels gain the leading axes of t
    ts = np.array([0.1, 0.5, 0.9])
    points, levels = C.de_casteljau(P, ts, triangle=True)
    assert [lv.shape for lv in levels] == [(3, 5 - r, 2) for r in range(5)]
    np.testing.assert_allclose(levels[-1][:, 0], points, atol=0)


@pytest.mark.parametrize("degree", range(1, 9))
def test_bezier_derivatives_match_references(degree):
    gen = rng(200 + degree)
    P = gen.normal(size=(degree + 1, 3))
    t = np.r_[0.0, 1.0, gen.uniform(0, 1, 50)]
    curve = bezier_pkg.Curve(P.T, degree=degree)
    first = np.array([curve.evaluate_hodograph(x).ravel() for x in t])
    np.testing.assert_allclose(C.bezier_derivative(P, t), first, atol=1e-11)
    reference = bezier_as_bspline(P)
    for order in range(0, degree + 2):
        expected = reference.derivative(order)(t) if order <= degree else np.zeros((len(t), 3))
        np.testing.assert_allclose(C.bezier_derivative(P, t, order), expected,
                                   atol=1e-10 * 4.0**order * math.factorial(degree))


def test_bezier_hodograph_closed_form_and_end_tangents():
    P = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 0.0]])
    np.testing.assert_allclose(C.bezier_hodograph(P), 3 * np.diff(P, axis=0), atol=0)
    # C'(0) = n (P1 - P0) and C'(1) = n (Pn - Pn-1): parallel to the end edges
    np.testing.assert_allclose(C.bezier_derivative(P, 0.0), 3 * (P[1] - P[0]), atol=1e-14)
    np.testing.assert_allclose(C.bezier_derivative(P, 1.0), 3 * (P[3] - P[2]), atol=1e-14)


@FAST
@given(seed=seeds, degree=st.integers(1, 9), dim=st.integers(2, 3))
def test_bezier_end_derivatives_parallel_to_end_edges(seed, degree, dim):
    P = rng(seed).normal(size=(degree + 1, dim))
    d0, d1 = C.bezier_derivative(P, [0.0, 1.0])
    for d, edge in ((d0, P[1] - P[0]), (d1, P[-1] - P[-2])):
        np.testing.assert_allclose(d, degree * edge, atol=1e-12)
    t0, t1 = C.bezier_tangent(P, [0.0, 1.0])
    np.testing.assert_allclose(t0, (P[1] - P[0]) / np.linalg.norm(P[1] - P[0]), atol=1e-9)
    np.testing.assert_allclose(t1, (P[-1] - P[-2]) / np.linalg.norm(P[-1] - P[-2]), atol=1e-9)


def test_bezier_tangent_is_normalised_derivative():
    gen = rng(11)
    P = gen.normal(size=(6, 3))
    t = gen.uniform(0, 1, 100)
    d = np.array([bezier_pkg.Curve(P.T, 5).evaluate_hodograph(x).ravel() for x in t])
    np.testing.assert_allclose(C.bezier_tangent(P, t), d / np.linalg.norm(d, axis=1)[:, None],
                               atol=1e-10)


def _direction_near(P, t):
    """Direction of the derivative (bezier package's hodograph) at t, just beside a point."""
    d = bezier_pkg.Curve(np.asarray(P, float).T, len(P) - 1).evaluate_hodograph(t).ravel()
    return d / np.linalg.norm(d)


def test_bezier_tangent_where_the_derivative_vanishes():
    # P0 = P1: at t = 0 the curve leaves towards P2 (C''(0) = n(n-1)(P2 - P0))
    P = np.array([[0.0, 0.0], [0.0, 0.0], [2.0, 1.0], [3.0, 0.0]])
    np.testing.assert_allclose(C.bezier_tangent(P, 0.0), np.array([2.0, 1.0]) / np.sqrt(5),
                               atol=1e-12)
    np.testing.assert_allclose(C.bezier_tangent(P, 0.0), _direction_near(P, 1e-7),
                               atol=1e-6)
    # P2 = P3: at t = 1 it arrives from P1, direction P3 - P1 (the limit from the left)
    Q = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 0.0], [3.0, 0.0]])
    np.testing.assert_allclose(C.bezier_tangent(Q, 1.0), np.array([2.0, -2.0]) / np.sqrt(8),
                               atol=1e-12)
    np.testing.assert_allclose(C.bezier_tangent(Q, 1.0),
                               _direction_near(Q, 1 - 1e-7), atol=1e-6)
    # an interior cusp: P3 + P2 = P1 + P0 makes C'(1/2) = 0; the limit from the right
    cusp = np.array([[0.0, 0.0], [2.0, 1.0], [0.0, 1.0], [2.0, 0.0]])
    np.testing.assert_allclose(C.bezier_derivative(cusp, 0.5), [0.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(C.bezier_tangent(cusp, 0.5),
                               _direction_near(cusp, 0.5 + 1e-7), atol=1e-6)
    # triple point at the start of a quartic: first non-zero derivative is the third
    R = np.array([[1.0, 1.0], [1.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 0.0]])
    np.testing.assert_allclose(C.bezier_tangent(R, 0.0), [0.0, 1.0], atol=1e-12)
    with pytest.raises(ValueError, match="single point"):
        C.bezier_tangent([[1, 2], [1, 2], [1, 2]], 0.5)


# ---------------------------------------------------------------------------------------------
# Bézier curves: subdivision, degree elevation
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("degree", [1, 2, 3, 5, 8])
@pytest.mark.parametrize("split", [0.0, 0.25, 0.5, 0.9, 1.0])
def test_bezier_subdivide_matches_bezier_package(degree, split):
    P = rng(300 + degree).normal(size=(degree + 1, 2))
    left, right = C.bezier_subdivide(P, split)
    curve = bezier_pkg.Curve(P.T, degree)
    np.testing.assert_allclose(left, curve.specialize(0.0, split).nodes.T, atol=1e-12)
    np.testing.assert_allclose(right, curve.specialize(split, 1.0).nodes.T, atol=1e-12)
    if split == 0.5:
        a, b = curve.subdivide()
        np.testing.assert_allclose(left, a.nodes.T, atol=1e-12)
        np.testing.assert_allclose(right, b.nodes.T, atol=1e-12)


@FAST
@given(seed=seeds, degree=st.integers(1, 9), dim=dims, split=unit_t)
def test_bezier_subdivision_reproduces_the_curve(seed, degree, dim, split):
    P = rng(seed).normal(size=(degree + 1, dim))
    left, right = C.bezier_subdivide(P, split)
    s = np.linspace(0, 1, 41)
    expected = bezier_as_bspline(P)
    np.testing.assert_allclose(C.bezier(left, s), expected(split * s), atol=1e-11)
    np.testing.assert_allclose(C.bezier(right, s), expected(split + (1 - split) * s), atol=1e-11)


@pytest.mark.parametrize("degree", [1, 2, 4, 7])
def test_bezier_elevate_matches_bezier_package(degree):
    P = rng(400 + degree).normal(size=(degree + 1, 3))
    expected = bezier_pkg.Curve(P.T, degree)
    once = C.bezier_elevate(P)
    np.testing.assert_allclose(once, expected.elevate().nodes.T, atol=1e-12)
    thrice = C.bezier_elevate(P, times=3)
    np.testing.assert_allclose(thrice, expected.elevate().elevate().elevate().nodes.T,
                               atol=1e-12)
    np.testing.assert_array_equal(C.bezier_elevate(P, times=0), P)


@FAST
@given(seed=seeds, degree=st.integers(1, 9), times=st.integers(1, 4))
def test_bezier_elevation_keeps_the_curve(seed, degree, times):
    P = rng(seed).normal(size=(degree + 1, 2))
    Q = C.bezier_elevate(P, times)
    assert Q.shape == (degree + 1 + times, 2)
    t = np.linspace(0, 1, 51)
    np.testing.assert_allclose(bezier_as_bspline(Q)(t), bezier_as_bspline(P)(t), atol=1e-12)


# ---------------------------------------------------------------------------------------------
# Bézier curves: the properties of the chapter
# ---------------------------------------------------------------------------------------------

@settings(max_examples=25, deadline=None, database=None)
@given(seed=seeds, degree=st.integers(1, 8), dim=st.integers(2, 3))
def test_bezier_convex_hull(seed, degree, dim):
    gen = rng(seed)
    P = gen.normal(size=(degree + 1, dim))
    for x in C.bezier(P, gen.uniform(0, 1, 6)):
        assert hull_distance(P, x) <= 1e-9


@FAST
@given(seed=seeds, degree=st.integers(1, 9), dim=dims)
def test_bezier_endpoint_interpolation_and_symmetry(seed, degree, dim):
    gen = rng(seed)
    P = gen.normal(size=(degree + 1, dim))
    np.testing.assert_allclose(C.bezier(P, [0.0, 1.0]), P[[0, -1]], atol=1e-14)
    t = gen.uniform(0, 1, 30)
    np.testing.assert_allclose(C.bezier(P[::-1], 1 - t), C.bezier(P, t), atol=1e-12)


@FAST
@given(seed=seeds, degree=st.integers(1, 9), dim=st.integers(1, 3))
def test_bezier_affine_invariance(seed, degree, dim):
    gen = rng(seed)
    P = gen.normal(size=(degree + 1, dim))
    A = gen.normal(size=(dim, dim))
    b = gen.normal(size=dim)
    t = gen.uniform(0, 1, 25)
    np.testing.assert_allclose(C.bezier(P @ A.T + b, t), C.bezier(P, t) @ A.T + b, atol=1e-11)


@FAST
@given(seed=seeds, degree=st.integers(1, 9))
def test_bezier_linear_precision(seed, degree):
    gen = rng(seed)
    a, b = gen.normal(size=(2, 3))
    t = np.linspace(0, 1, 33)
    # equally spaced points on a line: the curve is the line, uniformly parametrised
    P = a + np.linspace(0, 1, degree + 1)[:, None] * (b - a)
    np.testing.assert_allclose(C.bezier(P, t), a + t[:, None] * (b - a), atol=1e-12)
    # any points on the line: the curve stays on the line
    s = np.sort(gen.uniform(-1, 2, degree + 1))
    points = C.bezier(a + s[:, None] * (b - a), t)
    off = np.cross(points - a, b - a) / np.linalg.norm(b - a)
    assert np.abs(off).max() <= 1e-12 * (1 + np.abs(points).max())


@settings(max_examples=80, deadline=None, database=None)
@given(seed=seeds, degree=st.integers(2, 9))
def test_bezier_variation_diminishing(seed, degree):
    gen = rng(seed)
    P = gen.normal(size=(degree + 1, 2))
    t = np.linspace(0, 1, 4001)
    curve = C.bezier(P, t)
    through = curve[gen.integers(len(t))]          # a line through a point of the curve
    angle = gen.uniform(0, np.pi)
    normal = np.array([-np.sin(angle), np.cos(angle)])
    assert sign_changes((curve - through) @ normal) <= sign_changes((P - through) @ normal)


def test_variation_diminishing_check_can_fail():
    # the polygon itself (a zig-zag) crosses the x axis 3 times, a straight segment once
    zigzag = np.array([[0, -1], [1, 1], [2, -1], [3, 1]], float)
    assert sign_changes(zigzag[:, 1]) == 3
    assert sign_changes(np.linspace(-1, 1, 10)) == 1


def test_bezier_pseudo_local_control_closed_form():
    gen = rng(12)
    P = gen.normal(size=(6, 2))
    delta = np.array([0.3, -0.7])
    k = 2
    Q = P.copy()
    Q[k] += delta
    t = np.linspace(0, 1, 101)
    weight = math.comb(5, k) * t**k * (1 - t)**(5 - k)
    np.testing.assert_allclose(C.bezier(Q, t) - C.bezier(P, t), weight[:, None] * delta,
                               atol=1e-14)


# ---------------------------------------------------------------------------------------------
# B-spline knot vectors, spans, domains
# ---------------------------------------------------------------------------------------------

def test_clamped_and_uniform_knots_closed_forms():
    np.testing.assert_allclose(C.clamped_knots(6, 3), [0, 0, 0, 0, 1 / 3, 2 / 3, 1, 1, 1, 1],
                               atol=1e-15)
    np.testing.assert_allclose(C.clamped_knots(4, 3), [0, 0, 0, 0, 1, 1, 1, 1], atol=0)
    np.testing.assert_allclose(C.uniform_knots(5, 2), [-2 / 3, -1 / 3, 0, 1 / 3, 2 / 3, 1,
                                                       4 / 3, 5 / 3], atol=1e-15)
    for n, p in [(2, 1), (5, 2), (9, 3), (12, 7)]:
        for knots in (C.clamped_knots(n, p), C.uniform_knots(n, p)):
            assert len(knots) == n + p + 1
            assert C.domain(knots, p) == (0.0, 1.0)
            assert knots[p] == 0.0 and knots[n] == 1.0


def test_domain_closed_forms():
    assert C.domain([0, 1, 2, 3, 4, 5, 6, 7], 3) == (3.0, 4.0)
    assert C.domain([0, 0, 1, 2, 3, 3], 1) == (0.0, 3.0)
    assert C.domain([0, 0, 0, 0.2, 1, 1, 1], 2) == (0.0, 1.0)


def test_find_span_definition():
    gen = rng(13)
    for p in range(1, 6):
        for clamped in (True, False):
            u = random_knots(gen, 9, p, clamped, repeat=min(p, 2))
            a, b = bspline_domain(u, p)
            t = params_in(gen, a, b, 200, u)
            spans = C.find_span(u, p, t)
            for x, k in zip(t, spans):
                assert p <= k <= 8
                if x < b:
                    assert u[k] <= x < u[k + 1]
                else:                                   # the closed last span
                    assert u[k] < u[k + 1] == b
    assert isinstance(C.find_span([0, 0, 1, 1], 1, 0.5), int)


# ---------------------------------------------------------------------------------------------
# B-spline basis functions and curves against scipy and geomdl
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("degree", range(1, 8))
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
@pytest.mark.parametrize("repeat", [0, 2], ids=["simple", "double-knot"])
def test_bspline_basis_matches_scipy(degree, clamped, repeat):
    gen = rng(500 + 10 * degree + clamped + repeat)
    n = degree + 1 + gen.integers(0, 9)
    u = random_knots(gen, n, degree, clamped, repeat=min(repeat, degree))
    a, b = bspline_domain(u, degree)
    t = params_in(gen, a, b, 300, u)
    expected = BSpline.design_matrix(t, u, degree, extrapolate=False).toarray()
    got = C.bspline_basis(u, degree, t)
    assert got.shape == (len(t), n)
    np.testing.assert_allclose(got, expected, atol=1e-12)


@pytest.mark.parametrize("degree", range(1, 8))
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
def test_bspline_basis_derivatives_match_scipy(degree, clamped):
    gen = rng(600 + 10 * degree + clamped)
    n = degree + 1 + gen.integers(0, 9)
    u = random_knots(gen, n, degree, clamped, repeat=min(2, degree - 1))
    a, b = bspline_domain(u, degree)
    t = params_in(gen, a, b, 200, u)
    # scipy's BSpline.derivative refuses some orders across repeated knots: use the piecewise
    # polynomial form of each basis function (PPoly: the piece to the right at a breakpoint)
    pieces = [PPoly.from_spline(BSpline(u, np.eye(n)[i], degree)) for i in range(n)]
    for order in range(0, degree + 2):
        expected = np.stack([pp.derivative(order)(t) if order <= degree else 0 * t
                             for pp in pieces], axis=-1)
        got = C.bspline_basis_derivative(u, degree, t, order)
        scale = max(1.0, np.abs(expected).max())
        np.testing.assert_allclose(got, expected, atol=1e-10 * scale)


@pytest.mark.parametrize("degree", range(1, 8))
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
@pytest.mark.parametrize("dim", [1, 2, 3])
def test_bspline_matches_scipy(degree, clamped, dim):
    gen = rng(700 + 10 * degree + 3 * clamped + dim)
    n = degree + 1 + gen.integers(0, 12)
    u = random_knots(gen, n, degree, clamped, repeat=min(degree + 1, gen.integers(0, 3)))
    P = gen.normal(size=(n, dim))
    a, b = bspline_domain(u, degree)
    t = params_in(gen, a, b, 500, u)
    np.testing.assert_allclose(C.bspline(P, u, degree, t), scipy_curve(P, u, degree)(t),
                               atol=1e-12)
    # the same through the basis matrix
    np.testing.assert_allclose(C.bspline_basis(u, degree, t) @ P, scipy_curve(P, u, degree)(t),
                               atol=1e-12)
    for order in range(1, min(degree, 2) + 1):
        try:
            expected = scipy_curve(P, u, degree).derivative(order)(t)
        except ValueError:          # scipy refuses derivatives across a knot of multiplicity p+1
            continue
        np.testing.assert_allclose(C.bspline_derivative(P, u, degree, t, order), expected,
                                   rtol=1e-9, atol=1e-9)


def test_bspline_end_of_domain_with_a_repeated_knot_is_the_left_limit():
    # knots[n-1] == knots[n]: the last span before the domain end is empty; the value at the
    # end is the limit from the left (the curve is continuous there), as for any other t
    u = np.array([0, 0.1, 0.2, 0.3, 0.5, 0.7, 0.7, 0.8, 0.9, 1.0])
    P = rng(14).normal(size=(6, 2))
    b = u[6]
    end = C.bspline(P, u, 3, b)
    np.testing.assert_allclose(end, scipy_curve(P, u, 3)(b - 1e-12), atol=1e-9)


@pytest.mark.parametrize("degree", [1, 2, 3, 5])
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
def test_bspline_matches_geomdl(degree, clamped):
    gen = rng(800 + 10 * degree + clamped)
    n = degree + 1 + gen.integers(1, 8)
    u = random_knots(gen, n, degree, clamped)
    P = gen.normal(size=(n, 3))
    curve = GeomdlBSpline.Curve()
    curve.degree = degree
    curve.ctrlpts = P.tolist()
    curve.knotvector = u.tolist()
    a, b = bspline_domain(u, degree)
    t = params_in(gen, a, b, 60)
    expected = np.array([curve.evaluate_single(float(x)) for x in t])
    np.testing.assert_allclose(C.bspline(P, u, degree, t), expected, atol=1e-12)
    first = np.array([curve.derivatives(float(x), order=1)[1] for x in t])
    np.testing.assert_allclose(C.bspline_derivative(P, u, degree, t), first, rtol=1e-9,
                               atol=1e-9)


def test_bspline_full_range_basis_shows_whole_supports():
    # uniform cubic knots 0..7 (integers): each basis function is the same bell, shifted
    u = np.arange(8.0)
    t = np.linspace(0, 7, 701)
    N = C.bspline_basis(u, 3, t, full_range=True)
    for i in range(4):
        expected = np.nan_to_num(BSpline.basis_element(u[i:i + 5], extrapolate=False)(t))
        np.testing.assert_allclose(N[:, i], expected, atol=1e-12)
    np.testing.assert_allclose(N[:, 1], np.interp(t - 1, t, N[:, 0], left=0), atol=1e-12)
    # bell of the uniform cubic B-spline at its knots: 0, 1/6, 2/3, 1/6, 0
    np.testing.assert_allclose(N[[0, 100, 200, 300, 400], 0], [0, 1 / 6, 2 / 3, 1 / 6, 0],
                               atol=1e-15)
    with pytest.raises(ValueError, match="domain"):
        C.bspline_basis(u, 3, 1.0)                      # outside [3, 4] without full_range


def test_bezier_is_the_bspline_without_interior_knots():
    gen = rng(15)
    for degree in range(1, 8):
        P = gen.normal(size=(degree + 1, 2))
        t = gen.uniform(0, 1, 50)
        np.testing.assert_allclose(C.bspline(P, C.clamped_knots(degree + 1, degree), degree, t),
                                   C.bezier(P, t), atol=1e-12)


def test_de_boor_triangle_for_one_t():
    gen = rng(16)
    u = random_knots(gen, 8, 3, clamped=False)
    P = gen.normal(size=(8, 2))
    a, b = bspline_domain(u, 3)
    for x in np.r_[a, b, gen.uniform(a, b, 20)]:
        point, span, levels = C.de_boor(P, u, 3, x)
        np.testing.assert_allclose(point, scipy_curve(P, u, 3)(x), atol=1e-12)
        assert u[span] <= x and (x < u[span + 1] or x == b)
        np.testing.assert_array_equal(levels[0], P[span - 3:span + 1])
        assert [lv.shape for lv in levels] == [(4, 2), (3, 2), (2, 2), (1, 2)]
        np.testing.assert_allclose(levels[-1][0], point, atol=0)


# ---------------------------------------------------------------------------------------------
# B-spline properties
# ---------------------------------------------------------------------------------------------

bspline_case = st.tuples(seeds, degrees, st.booleans(), st.integers(0, 8))


def make_case(case, dim=2, repeat=0):
    seed, degree, clamped, extra = case
    gen = rng(seed)
    n = degree + 1 + extra
    u = random_knots(gen, n, degree, clamped, repeat=min(repeat, degree))
    return gen, u, degree, gen.normal(size=(n, dim))


@FAST
@given(case=bspline_case, repeat=st.integers(0, 3))
def test_bspline_basis_partition_of_unity_and_non_negativity(case, repeat):
    gen, u, p, _ = make_case(case, repeat=repeat)
    a, b = bspline_domain(u, p)
    N = C.bspline_basis(u, p, params_in(gen, a, b, 50, u))
    assert np.all(N >= 0)
    np.testing.assert_allclose(N.sum(axis=1), 1.0, atol=1e-12)
    # at most p + 1 of them are non-zero at any t (local support)
    assert np.count_nonzero(N > 0, axis=1).max() <= p + 1


@settings(max_examples=25, deadline=None, database=None)
@given(case=bspline_case)
def test_bspline_strong_convex_hull(case):
    gen, u, p, P = make_case(case, dim=3)
    a, b = bspline_domain(u, p)
    t = gen.uniform(a, b, 4)
    for x, point in zip(t, C.bspline(P, u, p, t)):
        k = max(i for i in range(len(u) - 1) if u[i] <= x and u[i] < u[i + 1])
        assert hull_distance(P[k - p:k + 1], point) <= 1e-9
    # and not always in the hull of another span's points (the check can fail)


def test_strong_convex_hull_check_can_fail():
    # a quadratic with control points on two sides: the point at t lies in its own span's hull
    # but not in the hull of the first span's points
    P = np.array([[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]], float)
    u = C.clamped_knots(5, 2)
    point = C.bspline(P, u, 2, 0.9)
    assert hull_distance(P[2:5], point) <= 1e-12
    assert hull_distance(P[0:3], point) > 0.1


@FAST
@given(case=bspline_case, dim=dims)
def test_bspline_affine_invariance(case, dim):
    gen, u, p, P = make_case(case, dim=dim)
    A = gen.normal(size=(dim, dim))
    shift = gen.normal(size=dim)
    a, b = bspline_domain(u, p)
    t = params_in(gen, a, b, 30, u)
    np.testing.assert_allclose(C.bspline(P @ A.T + shift, u, p, t),
                               C.bspline(P, u, p, t) @ A.T + shift, atol=1e-10)


@FAST
@given(case=bspline_case, scale=st.floats(0.01, 100), offset=st.floats(-100, 100))
def test_bspline_affine_reparametrisation(case, scale, offset):
    # scaling and shifting knots and parameters alike gives the same points
    gen, u, p, P = make_case(case)
    a, b = bspline_domain(u, p)
    t = gen.uniform(a, b, 30)
    np.testing.assert_allclose(C.bspline(P, scale * u + offset, p, scale * t + offset),
                               C.bspline(P, u, p, t), atol=1e-8)


@FAST
@given(case=bspline_case)
def test_bspline_local_control(case):
    gen, u, p, P = make_case(case)
    n = len(P)
    k = int(gen.integers(n))
    Q = P.copy()
    Q[k] += gen.normal(size=2) + 1.0
    a, b = bspline_domain(u, p)
    t = np.r_[np.linspace(a, b, 400), u[(u >= a) & (u <= b)]]
    before, after = C.bspline(P, u, p, t), C.bspline(Q, u, p, t)
    lo, hi = u[k], u[k + p + 1]
    outside = (t < lo) | (t >= hi)
    if hi == b:                               # the closed last span: t = b is inside
        outside &= t != b
    np.testing.assert_array_equal(after[outside], before[outside])     # exactly unchanged
    # inside, the change is N_k(t) times the move (N_k from scipy), non-zero where N_k > 0
    weight = BSpline.design_matrix(t, u, p, extrapolate=False).toarray()[:, k]
    np.testing.assert_allclose(after - before, weight[:, None] * (Q[k] - P[k]), atol=1e-12)
    assert np.all(weight[(t > lo) & (t < hi)] > 0)


@FAST
@given(seed=seeds, degree=degrees, extra=st.integers(0, 8))
def test_clamped_bspline_endpoint_interpolation_and_end_tangents(seed, degree, extra):
    gen = rng(seed)
    n = degree + 1 + extra
    u = random_knots(gen, n, degree, clamped=True)
    P = gen.normal(size=(n, 3))
    np.testing.assert_allclose(C.bspline(P, u, degree, [0.0, 1.0]), P[[0, -1]], atol=1e-12)
    d0, d1 = C.bspline_derivative(P, u, degree, [0.0, 1.0])
    # C'(0) = p / (u_{p+1} - u_1) (P1 - P0), C'(1) = p / (u_{n+p} - u_n) (Pn - Pn-1)
    np.testing.assert_allclose(d0, degree / (u[degree + 1] - u[1]) * (P[1] - P[0]), rtol=1e-9,
                               atol=1e-9)
    np.testing.assert_allclose(d1, degree / (u[n + degree - 1] - u[n - 1]) * (P[-1] - P[-2]),
                               rtol=1e-9, atol=1e-9)


@FAST
@given(case=bspline_case)
def test_bspline_symmetry(case):
    gen, u, p, P = make_case(case)
    a, b = bspline_domain(u, p)
    reflected = (a + b) - u[::-1]               # same domain, reversed direction
    t = gen.uniform(a, b, 30)
    np.testing.assert_allclose(C.bspline(P[::-1], reflected, p, a + b - t), C.bspline(P, u, p, t),
                               atol=1e-10)


@FAST
@given(case=bspline_case)
def test_bspline_linear_precision(case):
    # control points on a line at the Greville abscissae reproduce the line exactly
    gen, u, p, _ = make_case(case)
    n = len(u) - p - 1
    a_vec, b_vec = gen.normal(size=(2, 3))
    P = a_vec + greville(u, p, n)[:, None] * b_vec
    lo, hi = bspline_domain(u, p)
    t = params_in(gen, lo, hi, 40, u)
    np.testing.assert_allclose(C.bspline(P, u, p, t), a_vec + t[:, None] * b_vec, atol=1e-12)


@settings(max_examples=60, deadline=None, database=None)
@given(case=bspline_case)
def test_bspline_variation_diminishing(case):
    gen, u, p, P = make_case(case)
    a, b = bspline_domain(u, p)
    t = np.linspace(a, b, 4001)
    curve = C.bspline(P, u, p, t)
    through = curve[gen.integers(len(t))]
    angle = gen.uniform(0, np.pi)
    normal = np.array([-np.sin(angle), np.cos(angle)])
    assert sign_changes((curve - through) @ normal) <= sign_changes((P - through) @ normal)


# ---------------------------------------------------------------------------------------------
# knot insertion
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("degree", [1, 2, 3, 4, 6])
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
def test_insert_knot_matches_scipy_and_geomdl(degree, clamped):
    gen = rng(900 + 10 * degree + clamped)
    n = degree + 1 + gen.integers(1, 6)
    u = random_knots(gen, n, degree, clamped)
    P = gen.normal(size=(n, 2))
    a, b = bspline_domain(u, degree)
    x = float(gen.uniform(a, b))
    for times in range(1, degree + 1):
        Q, V = C.insert_knot(P, u, degree, x, times)
        assert Q.shape == (n + times, 2) and V.shape == (len(u) + times,)
        ref = insert(x, BSpline(u, P, degree), m=times)
        np.testing.assert_allclose(V, ref.t, atol=0)
        np.testing.assert_allclose(Q, ref.c[:n + times], atol=1e-12)
        curve = GeomdlBSpline.Curve()
        curve.degree = degree
        curve.ctrlpts = P.tolist()
        curve.knotvector = u.tolist()
        geomdl_operations.insert_knot(curve, [x], [times])
        np.testing.assert_allclose(Q, np.array(curve.ctrlpts), atol=1e-12)
        np.testing.assert_allclose(V, curve.knotvector, atol=1e-15)


@FAST
@given(case=bspline_case, where=unit_t, times=st.integers(1, 3))
def test_insert_knot_keeps_the_curve(case, where, times):
    gen, u, p, P = make_case(case)
    a, b = bspline_domain(u, p)
    x = a + where * (b - a)
    nearest = u[np.argmin(np.abs(u - x))]
    if abs(nearest - x) < 1e-9:         # on an existing knot, or clearly apart from all of them
        x = nearest                     # (a span of 1e-300 makes scipy's evaluation overflow)
    assume(np.count_nonzero(u == x) + times <= p + 1)
    Q, V = C.insert_knot(P, u, p, x, times)
    assert bspline_domain(V, p) == (a, b)
    t = params_in(gen, a, b, 100, u)
    expected = scipy_curve(P, u, p)(t)
    np.testing.assert_allclose(C.bspline(Q, V, p, t), expected, atol=1e-11)
    # scipy on the new curve too, except at t = b: when u = b was inserted the last span before
    # b is empty, and scipy then returns 0 there instead of the limit from the left
    inner = t < b
    np.testing.assert_allclose(scipy_curve(Q, V, p)(t[inner]), expected[inner], atol=1e-11)


def test_insert_knot_to_multiplicity_degree_interpolates_a_control_point():
    P = rng(17).normal(size=(6, 2))
    u = C.clamped_knots(6, 3)
    Q, V = C.insert_knot(P, u, 3, 0.4, times=3)
    point = scipy_curve(P, u, 3)(0.4)
    assert np.min(np.linalg.norm(Q - point, axis=1)) <= 1e-12
    with pytest.raises(ValueError, match="times"):
        C.insert_knot(Q, V, 3, 0.4, times=2)          # would make the multiplicity 5 > 4


# ---------------------------------------------------------------------------------------------
# rational curves
# ---------------------------------------------------------------------------------------------

def homogeneous_reference(P, w, u, p):
    """NURBS through scipy: the B-spline of (w P, w), divided by its last coordinate."""
    curve = scipy_curve(np.c_[P * w[:, None], w], u, p)
    return lambda t: curve(t)[..., :-1] / curve(t)[..., -1:]


@pytest.mark.parametrize("degree", range(1, 8))
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
def test_nurbs_matches_homogeneous_scipy(degree, clamped):
    gen = rng(1000 + 10 * degree + clamped)
    n = degree + 1 + gen.integers(0, 10)
    u = random_knots(gen, n, degree, clamped, repeat=min(degree, 2))
    P = gen.normal(size=(n, 3))
    w = 10.0 ** gen.uniform(-1, 1, n)
    a, b = bspline_domain(u, degree)
    t = params_in(gen, a, b, 300, u)
    np.testing.assert_allclose(C.nurbs(P, w, u, degree, t),
                               homogeneous_reference(P, w, u, degree)(t), atol=1e-11)


@pytest.mark.parametrize("degree", [1, 2, 3, 5])
def test_nurbs_and_rational_bezier_match_geomdl(degree):
    gen = rng(1100 + degree)
    n = degree + 3
    u = random_knots(gen, n, degree, clamped=bool(degree % 2))
    P = gen.normal(size=(n, 3))
    w = gen.uniform(0.2, 3.0, n)
    curve = GeomdlNURBS.Curve()
    curve.degree = degree
    curve.ctrlptsw = np.c_[P * w[:, None], w].tolist()
    curve.knotvector = u.tolist()
    a, b = bspline_domain(u, degree)
    t = params_in(gen, a, b, 50)
    expected = np.array([curve.evaluate_single(float(x)) for x in t])
    np.testing.assert_allclose(C.nurbs(P, w, u, degree, t), expected, atol=1e-12)
    # rational Bézier = NURBS with the Bézier knot vector
    Pb, wb = P[:degree + 1], w[:degree + 1]
    bez = GeomdlNURBS.Curve()
    bez.degree = degree
    bez.ctrlptsw = np.c_[Pb * wb[:, None], wb].tolist()
    bez.knotvector = [0.0] * (degree + 1) + [1.0] * (degree + 1)
    s = np.linspace(0, 1, 31)
    np.testing.assert_allclose(C.rational_bezier(Pb, wb, s),
                               np.array([bez.evaluate_single(float(x)) for x in s]), atol=1e-12)


@FAST
@given(seed=seeds, degree=st.integers(1, 9), dim=dims)
def test_rational_bezier_homogeneous_and_equal_weights(seed, degree, dim):
    gen = rng(seed)
    P = gen.normal(size=(degree + 1, dim))
    w = 10.0 ** gen.uniform(-1, 1, degree + 1)
    t = np.r_[0.0, 1.0, gen.uniform(0, 1, 30)]
    h = bezier_as_bspline(np.c_[P * w[:, None], w])(t)
    got = C.rational_bezier(P, w, t)
    np.testing.assert_allclose(got, h[:, :-1] / h[:, -1:], atol=1e-11)
    np.testing.assert_allclose(got[:2], P[[0, -1]], atol=1e-12)          # end points
    np.testing.assert_allclose(C.rational_bezier(P, 3.7 * w, t), got, atol=1e-12)
    np.testing.assert_allclose(C.rational_bezier(P, np.full(degree + 1, 2.5), t),
                               C.bezier(P, t), atol=1e-12)


@FAST
@given(case=bspline_case)
def test_nurbs_with_equal_weights_is_the_bspline(case):
    gen, u, p, P = make_case(case, dim=3)
    a, b = bspline_domain(u, p)
    t = params_in(gen, a, b, 30, u)
    np.testing.assert_allclose(C.nurbs(P, np.full(len(P), 0.7), u, p, t), C.bspline(P, u, p, t),
                               atol=1e-12)


@settings(max_examples=25, deadline=None, database=None)
@given(case=bspline_case)
def test_nurbs_convex_hull(case):
    gen, u, p, P = make_case(case, dim=3)
    w = 10.0 ** gen.uniform(-1, 1, len(P))
    a, b = bspline_domain(u, p)
    for x in C.nurbs(P, w, u, p, gen.uniform(a, b, 4)):
        assert hull_distance(P, x) <= 1e-9


@FAST
@given(case=bspline_case, seed=seeds)
def test_nurbs_projective_invariance(case, seed):
    # transform the homogeneous control points (w P, w) by a projective 3x3 matrix M: the new
    # NURBS is the old curve mapped by M (with the perspective divide)
    _, u, p, P = make_case(case)
    gen = rng(seed)
    w = 10.0 ** gen.uniform(-0.5, 0.5, len(P))
    M = np.eye(3) + 0.3 * gen.normal(size=(3, 3))
    M[2] = [0.2 * gen.normal(), 0.2 * gen.normal(), 1.0]
    H = np.c_[P * w[:, None], w] @ M.T
    assume(np.all(H[:, 2] > 0.05))
    assume(abs(np.linalg.det(M)) > 0.05)
    a, b = bspline_domain(u, p)
    t = gen.uniform(a, b, 30)
    curve = C.nurbs(P, w, u, p, t)
    mapped = np.c_[curve, np.ones(len(t))] @ M.T
    expected = mapped[:, :2] / mapped[:, 2:]
    np.testing.assert_allclose(C.nurbs(H[:, :2] / H[:, 2:], H[:, 2], u, p, t), expected,
                               rtol=1e-9, atol=1e-9)


def test_projective_invariance_needs_the_weights():
    # projecting only the control points (a non-rational curve) does not give the projected
    # curve: B-splines are affinely but not projectively invariant
    P = np.array([[0, 0], [1, 2], [2, -1], [3, 1], [4, 0]], float)
    u = C.clamped_knots(5, 3)
    M = np.array([[1.0, 0.2, 0.0], [0.0, 1.0, 0.0], [0.3, 0.1, 1.0]])
    t = np.linspace(0, 1, 21)
    mapped = np.c_[C.bspline(P, u, 3, t), np.ones(len(t))] @ M.T
    expected = mapped[:, :2] / mapped[:, 2:]
    H = np.c_[P, np.ones(5)] @ M.T
    assert np.abs(C.bspline(H[:, :2] / H[:, 2:], u, 3, t) - expected).max() > 0.01
    np.testing.assert_allclose(C.nurbs(H[:, :2] / H[:, 2:], H[:, 2], u, 3, t), expected,
                               atol=1e-12)


def test_nurbs_circle_is_exact():
    t = np.linspace(0, 1, 10001)
    for radius, center in [(1.0, (0.0, 0.0)), (2.5, (1.0, -3.0)), (1e-3, (0.0, 0.0))]:
        P, w, u, p = C.nurbs_circle(radius, center)
        assert p == 2 and P.shape == (9, 2) and w.shape == (9,) and u.shape == (12,)
        points = C.nurbs(P, w, u, p, t)
        distance = np.linalg.norm(points - center, axis=1)
        assert np.abs(distance - radius).max() <= 1e-12 * max(1.0, radius)
        angle = np.unwrap(np.arctan2(*(points - center).T[::-1]))
        assert angle[0] == pytest.approx(0.0, abs=1e-12)
        assert angle[-1] == pytest.approx(2 * np.pi, abs=1e-12)
        assert np.all(np.diff(angle) > 0)                    # counter-clockwise, once round
    # the quarter points are at 0, 90, 180, 270 degrees, and t = 1/8 at 45 degrees
    P, w, u, p = C.nurbs_circle()
    np.testing.assert_allclose(C.nurbs(P, w, u, p, [0.125, 0.25, 0.5, 0.75]),
                               [[np.sqrt(0.5), np.sqrt(0.5)], [0, 1], [-1, 0], [0, -1]],
                               atol=1e-15)
    # against geomdl's own evaluation of the same data
    curve = GeomdlNURBS.Curve()
    curve.degree = 2
    curve.ctrlptsw = np.c_[P * w[:, None], w].tolist()
    curve.knotvector = u.tolist()
    s = np.linspace(0, 1, 41)
    np.testing.assert_allclose(C.nurbs(P, w, u, p, s),
                               np.array([curve.evaluate_single(float(x)) for x in s]),
                               atol=1e-13)


def fit_conic(points):
    """Coefficients (A, B, C, D, E, F) of A x^2 + B xy + C y^2 + D x + E y + F = 0 (SVD)."""
    x, y = points.T
    design = np.c_[x * x, x * y, y * y, x, y, np.ones_like(x)]
    _, singular, vt = np.linalg.svd(design)
    return vt[-1], singular[-1] / singular[0]


@pytest.mark.parametrize("w, kind", [(0.2, "ellipse"), (np.sqrt(0.5), "ellipse"),
                                     (0.95, "ellipse"), (1.0, "parabola"),
                                     (1.05, "hyperbola"), (3.0, "hyperbola")])
def test_rational_quadratic_conic_type_by_weight(w, kind):
    gen = rng(int(100 * w))
    for _ in range(5):
        p0, p1, p2 = gen.uniform(-1, 1, size=(3, 2))
        e1, e2 = p1 - p0, p2 - p0
        area = abs(e1[0] * e2[1] - e1[1] * e2[0])
        if area < 0.2:
            continue
        t = np.linspace(0, 1, 60)
        points = C.rational_quadratic_conic(p0, p1, p2, w, t)
        coefficients, residual = fit_conic(points)
        assert residual <= 1e-10                          # all points on one conic
        a, b, c = coefficients[:3]
        discriminant = b * b - 4 * a * c
        assert C.conic_type(w) == kind
        if kind == "ellipse":
            assert discriminant < -1e-8
        elif kind == "hyperbola":
            assert discriminant > 1e-8
        else:
            assert abs(discriminant) <= 1e-9
        # barycentric form: tau_1^2 = 4 w^2 tau_0 tau_2
        T = np.vstack([np.stack([p0, p1, p2]).T, np.ones(3)])
        tau = np.linalg.solve(T, np.c_[points, np.ones(len(t))].T)
        np.testing.assert_allclose(tau[1]**2, 4 * w * w * tau[0] * tau[2], atol=1e-12)
        # ends and end tangents
        np.testing.assert_allclose(points[[0, -1]], [p0, p2], atol=1e-14)


def test_rational_quadratic_circular_arc():
    # the 90 degree arc: corner of the square with weight cos(45 degrees)
    t = np.linspace(0, 1, 101)
    arc = C.rational_quadratic_conic([1, 0], [1, 1], [0, 1], np.cos(np.pi / 4), t)
    np.testing.assert_allclose(np.linalg.norm(arc, axis=1), 1.0, atol=1e-15)
    # a 120 degree arc: control point at the tangent intersection, weight cos(60 degrees)
    a0, a2 = np.array([1.0, 0.0]), np.array([np.cos(2 * np.pi / 3), np.sin(2 * np.pi / 3)])
    corner = np.array([1.0, np.tan(np.pi / 3)])
    arc = C.rational_quadratic_conic(a0, corner, a2, 0.5, t)
    np.testing.assert_allclose(np.linalg.norm(arc, axis=1), 1.0, atol=1e-14)


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

P4 = [[0, 0], [1, 1], [2, 0], [3, 1]]
K4 = [0, 0, 0, 0.5, 1, 1, 1]            # 4 control points, degree 2


@pytest.mark.parametrize("call, error, pattern", [
    (lambda: C.bspline(P4, [0, 0, 0, 1, 1, 1], 2, 0.5), ValueError,
     r"knots must have n_control \+ degree \+ 1 = 4 \+ 2 \+ 1 = 7 values, got 6"),
    (lambda: C.bspline(P4, [0, 0, 0, 0.7, 0.5, 1, 1], 2, 0.5), ValueError,
     r"knots must be non-decreasing, but knots\[3\] = 0.7 > knots\[4\] = 0.5"),
    (lambda: C.bspline(P4, [0, 0, 0, 0, 1, 1, 1], 2, 0.5), ValueError,
     r"knots must not repeat a value more than degree \+ 1 = 3 times"),
    (lambda: C.bspline(P4, [0, 1, 1, 1, 2, 3], 1, 0.5), ValueError,
     r"knots must not repeat a value more than degree \+ 1 = 2 times, but 1.0 appears 3 times"),
    (lambda: C.bspline(P4[:3], [0, 0, 1, 1, 2, 2], 2, 0.5), ValueError,
     r"knots leave an empty domain"),
    (lambda: C.bspline(P4, [0, 0, 0, 0.5, 1, 1, 1], 0, 0.5), ValueError,
     r"degree must be at least 1"),
    (lambda: C.bspline(P4, [0, 0, 0, 0, 0, 1, 1, 1, 1], 4, 0.5), ValueError,
     r"degree must be less than the number of control points \(with n_control = 4"),
    (lambda: C.bspline(P4, K4, 2.5, 0.5), ValueError, r"degree must be a whole number"),
    (lambda: C.bspline(P4, K4, 2, 1.5), ValueError,
     r"t must lie in the domain \[0.0, 1.0\], got 1.5"),
    (lambda: C.bspline(P4, K4, 2, [0.2, -0.1]), ValueError, r"got -0.1 at index 1"),
    (lambda: C.bspline(P4, K4, 2, np.nan), ValueError, r"t must be finite"),
    (lambda: C.bspline([[0, 0], [np.nan, 1], [2, 0], [3, 1]], K4, 2, 0.5), ValueError,
     r"control_points must be finite"),
    (lambda: C.bspline([[0, 0]], [0, 0, 1], 1, 0.5), ValueError,
     r"control_points must hold at least 2 points"),
    (lambda: C.bspline([0, 1, 2, 3], K4, 2, 0.5), ValueError,
     r"control_points must be an array of points.*column"),
    (lambda: C.bspline(P4, "0 0 0 1 1 1", 2, 0.5), TypeError, r"knots must be numbers"),
    (lambda: C.nurbs(P4, [1, 1, 0, 1], K4, 2, 0.5), ValueError,
     r"weights must be positive .* weights\[2\] = 0"),
    (lambda: C.nurbs(P4, [1, 1, -2, 1], K4, 2, 0.5), ValueError, r"weights must be positive"),
    (lambda: C.nurbs(P4, [1, 1, 1], K4, 2, 0.5), ValueError,
     r"weights must be a 1D array with one weight per control point \(4\)"),
    (lambda: C.rational_bezier(P4, [1, 1, 1, -1], 0.5), ValueError, r"weights must be positive"),
    (lambda: C.bezier(P4, 1.2), ValueError, r"t must lie in the domain \[0.0, 1.0\]"),
    (lambda: C.bezier(P4, [[0.5, np.inf]]), ValueError, r"t must be finite"),
    (lambda: C.bezier([[1, 2]], 0.5), ValueError, r"at least 2 points"),
    (lambda: C.de_casteljau(P4, -0.5), ValueError, r"t must lie in the domain"),
    (lambda: C.bezier_derivative(P4, 0.5, order=-1), ValueError, r"order must be at least 0"),
    (lambda: C.bezier_elevate(P4, times=1.5), ValueError, r"times must be a whole number"),
    (lambda: C.bezier_subdivide(P4, [0.2, 0.4]), ValueError, r"t must be a single number"),
    (lambda: C.bernstein(3, 4, 0.5), ValueError, r"i must be whole numbers from 0 to n = 3"),
    (lambda: C.bernstein(-1, 0, 0.5), ValueError, r"n must be at least 0"),
    (lambda: C.bernstein(True, 0, 0.5), TypeError, r"n must be a whole number"),
    (lambda: C.insert_knot(P4, K4, 2, 1.5), ValueError, r"u must lie in the domain"),
    (lambda: C.insert_knot(P4, K4, 2, 0.0), ValueError, r"times = 1 is too many"),
    (lambda: C.clamped_knots(3, 3), ValueError, r"degree must be less than"),
    (lambda: C.uniform_knots(1, 1), ValueError, r"n_control must be at least 2"),
    (lambda: C.domain([0, 1, 2], 1), ValueError, r"knots must have at least 2 \* degree \+ 2 = 4"),
    (lambda: C.nurbs_circle(-1.0), ValueError, r"radius must be positive"),
    (lambda: C.nurbs_circle(1.0, (0, 0, 0)), ValueError, r"center must be a vector of 2"),
    (lambda: C.conic_type(0.0), ValueError, r"w must be positive"),
    (lambda: C.rational_quadratic_conic([0, 0], [1, 1], [2, 0, 0], 1.0, 0.5), ValueError,
     r"p2 must be a vector of 2 numbers"),
    (lambda: C.bspline_basis_derivative(K4, 2, 0.5, order=-2), ValueError,
     r"order must be at least 0"),
])
def test_bad_input_raises_with_a_clear_message(call, error, pattern):
    with pytest.raises(error, match=pattern):
        call()


def test_parameters_within_rounding_of_the_domain_are_accepted():
    u = C.clamped_knots(5, 3)
    P = rng(18).normal(size=(5, 2))
    np.testing.assert_allclose(C.bspline(P, u, 3, 1 + 1e-14), P[-1], atol=1e-12)
    np.testing.assert_allclose(C.bezier(P, -1e-14), P[0], atol=1e-12)
    with pytest.raises(ValueError, match="domain"):
        C.bspline(P, u, 3, 1 + 1e-9)
