"""Chapter 7 curve basics: continuity, curvature, matrix form, and bspline_basis on short knots.

Cross-checks: closed forms typed here (circle 1/r, parabola), numpy finite differences,
scipy.interpolate (BSpline.basis_element, CubicHermiteSpline, BSpline curves), and
course_lib.curves.bezier / bezier_derivative.
"""
import numpy as np
import pytest
from scipy.interpolate import BSpline, CubicHermiteSpline

from course_lib import curves as C
from course_lib.curves import continuity as K
from course_lib.curves import matrix_form as MF


def rng(seed):
    return np.random.default_rng(seed)


# --------------------------------------------------------------------------- implicit/parametric

def test_circle_forms_agree():
    t = np.linspace(0, 2 * np.pi, 37)
    pts = K.circle_parametric(t, 2.5, (1, -1))
    np.testing.assert_allclose(K.circle_implicit(pts, 2.5, (1, -1)), 0, atol=1e-12)
    s = np.linspace(-3, 3, 41)
    rat = K.circle_rational(s, 2.5, (1, -1))
    np.testing.assert_allclose(np.hypot(*(rat - [1, -1]).T), 2.5)
    # s = tan(theta / 2) gives the angle theta (half-angle substitution)
    theta = 2 * np.arctan(s)
    np.testing.assert_allclose(rat, K.circle_parametric(theta, 2.5, (1, -1)), atol=1e-12)
    assert K.circle_implicit([0, 0]) == -1.0


# --------------------------------------------------------------------------------- curvature

@pytest.mark.parametrize("r", [0.5, 1.0, 3.0])
def test_circle_curvature_is_one_over_radius(r):
    t = np.linspace(0, 6, 13)
    d1 = r * np.stack([-np.sin(t), np.cos(t)], -1)
    d2 = r * np.stack([-np.cos(t), -np.sin(t)], -1)
    np.testing.assert_allclose(C.curvature(d1, d2), 1 / r)
    np.testing.assert_allclose(C.curvature(d1 * 3, d2 * 9), 1 / r)     # speed does not matter
    # 3D: a tilted circle
    d13 = np.concatenate([d1, np.zeros_like(t)[:, None]], -1) @ _rot_x(0.7).T
    d23 = np.concatenate([d2, np.zeros_like(t)[:, None]], -1) @ _rot_x(0.7).T
    np.testing.assert_allclose(C.curvature(d13, d23), 1 / r)
    kv = C.curvature_vector(d13, d23)
    np.testing.assert_allclose(np.linalg.norm(kv, axis=-1), 1 / r)


def _rot_x(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def test_parabola_curvature_closed_form():
    # y = a x^2 as (x, a x^2): kappa = 2|a| / (1 + 4 a^2 x^2)^(3/2)
    a, x = -0.7, np.linspace(-2, 2, 21)
    d1 = np.stack([np.ones_like(x), 2 * a * x], -1)
    d2 = np.stack([np.zeros_like(x), np.full_like(x, 2 * a)], -1)
    np.testing.assert_allclose(C.curvature(d1, d2), 2 * abs(a) / (1 + 4 * a * a * x * x) ** 1.5)
    assert np.all(C.curvature(d1, d2, signed=True) < 0)                 # turns right


def test_bezier_curvature_against_finite_differences_and_end_formula():
    P = rng(1).normal(size=(4, 2))
    t = np.linspace(0.1, 0.9, 9)
    h = 1e-4
    d1 = (C.bezier(P, t + h) - C.bezier(P, t - h)) / (2 * h)
    d2 = (C.bezier(P, t + h) - 2 * C.bezier(P, t) + C.bezier(P, t - h)) / h ** 2
    np.testing.assert_allclose(d1, C.bezier_derivative(P, t), rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(C.bezier_curvature(P, t), C.curvature(d1, d2), rtol=1e-4)
    a, b = P[1] - P[0], P[2] - P[1]
    n = 3
    expected = (n - 1) / n * abs(a[0] * b[1] - a[1] * b[0]) / np.linalg.norm(a) ** 3
    assert C.bezier_curvature(P, 0.0) == pytest.approx(expected)


def test_curvature_comb_teeth():
    # a quarter circle approximation: teeth point away from the centre, length scale * kappa
    P = np.array([[1, 0], [1, 0.55], [0.55, 1], [0, 1]])
    t = np.linspace(0, 1, 11)
    base, tips = C.curvature_comb(P, t, scale=0.5)
    teeth = tips - base
    np.testing.assert_allclose(np.linalg.norm(teeth, axis=1), 0.5 * C.bezier_curvature(P, t))
    assert np.all(np.sum(teeth * base, axis=1) > 0)                    # outward
    base, tips = C.curvature_comb([[0, 0], [1, 1], [2, 2], [3, 3]], t)  # a line: no teeth
    np.testing.assert_allclose(base, tips)


# --------------------------------------------------------------------------------- joins

A = np.array([[0, 0], [1, 0], [2, 0], [3, 1]], float)


def test_join_continuity_levels():
    assert C.join_continuity(A, A + [5, 5])[:2] == (-1, -1)
    assert C.join_continuity(A, [[3, 1], [3, 3], [4, 4], [5, 4]])[:2] == (0, 0)   # corner
    assert C.join_continuity(A, [[3, 1], [2, 0], [1, 1], [0, 2]])[:2] == (0, 0)   # cusp: opposite
    assert C.join_continuity(A, [[3, 1], [5, 3], [6, 3], [7, 2]])[:2] == (0, 1)
    assert C.join_continuity(A, [[3, 1], [4, 2], [5, 3], [6, 3]])[:2] == (1, 1)
    # C2: Q2 = 2 Q1 - Q0 + (P3 - 2 P2 + P1) = (8, 4) - (3, 1) + (0, 1) = (5, 4)
    assert C.join_continuity(A, [[3, 1], [4, 2], [5, 4], [7, 4]])[:2] == (2, 2)


def test_g2_not_c2_and_c1_implies_g1_and_callables():
    Q = C.join_points(A, "G2", ratio=2.0, beta2=1.5)
    B = np.vstack([Q, [[9, 9]]])
    res = C.join_continuity(A, B)
    assert res[:2] == (0, 2)
    assert res.curvatures[0] == pytest.approx(res.curvatures[1])
    # the same join with callables f(t, order)
    fa = lambda t, k: C.bezier_derivative(A, t, k)   # noqa: E731
    fb = lambda t, k: C.bezier_derivative(B, t, k)   # noqa: E731
    assert C.join_continuity(fa, fb)[:2] == (0, 2)


def test_join_at_the_origin_with_callables():
    # a circle arc (cos, sin) shifted to start at the origin, then its continuation: C2, G2
    def arc(offset):
        def f(t, k):
            a = t + offset
            v = [np.cos(a + k * np.pi / 2), np.sin(a + k * np.pi / 2)]
            return np.array(v) - (np.array([np.cos(1.0), np.sin(1.0)]) if k == 0 else 0)
        return f
    assert C.join_continuity(arc(0.0), arc(1.0))[:2] == (2, 2)
    # the same arc traversed twice as fast afterwards: G2, only C0
    fast = lambda t, k: 2.0 ** k * arc(1.0)(2 * t, k) if k else arc(1.0)(2 * t, 0)  # noqa: E731
    assert C.join_continuity(arc(0.0), fast)[:2] == (0, 2)


def test_join_points_formulas_match_derivatives():
    gen = rng(3)
    for _ in range(5):
        P = gen.normal(size=(4, 2))
        for m, r in [(3, 1.0), (2, 1.0), (4, 0.5), (3, 2.0)]:
            Q = np.vstack([C.join_points(P, "C2", degree=m, ratio=r), gen.normal(size=(m - 2, 2))])
            # global parameter: A on [0, h0], B on [h0, h0 + h1]; derivatives divide by h
            h0, h1 = 1.0, r
            for k in (0, 1, 2):
                np.testing.assert_allclose(C.bezier_derivative(P, 1.0, k) / h0 ** k,
                                           C.bezier_derivative(Q, 0.0, k) / h1 ** k, atol=1e-9)
    P = np.array([[0, 0], [1, 1], [2, 1], [3, 0]], float)
    np.testing.assert_allclose(C.join_points(P, "C1")[1], [4, -1])
    np.testing.assert_allclose(C.join_points(P, "G1", ratio=0.5)[1], [3.5, -0.5])


def test_constrain_join_reaches_each_continuity():
    gen = rng(4)
    for cont, want in [("C0", (0, 0)), ("G1", (0, 1)), ("C1", (1, 1)), ("G2", (0, 2)),
                       ("C2", (2, 2))]:
        P = gen.normal(size=(4, 2))
        Q = gen.normal(size=(4, 2)) + 3
        new = C.constrain_join(P, Q, cont)
        got = C.join_continuity(P, new)
        assert got.C >= want[0] and got.G >= want[1], cont
        k = int(cont[1])
        np.testing.assert_array_equal(new[k + 1:], Q[k + 1:])          # the rest untouched
    # G1 keeps the first leg's length
    new = C.constrain_join(A, [[3, 1], [3, 3], [5, 1], [6, 0]], "G1")
    assert np.linalg.norm(new[1] - new[0]) == pytest.approx(2.0)


@pytest.mark.parametrize("call, error, pattern", [
    (lambda: C.curvature([1, 0], [0, 1, 0]), ValueError, "d2 must have the shape of d1"),
    (lambda: C.curvature([1, 0, 0], [0, 1, 0], signed=True), ValueError, "signed=True"),
    (lambda: C.curvature([1], [0]), ValueError, "d1 must hold 2D or 3D"),
    (lambda: C.circle_parametric(0, -1), ValueError, "radius must be positive"),
    (lambda: C.circle_implicit([1, 2, 3]), ValueError, "points must have 2 coordinates"),
    (lambda: C.join_continuity(A, "abc"), TypeError, "b must be numbers"),
    (lambda: C.join_continuity(A, np.zeros((4, 3))), ValueError, "same dimension"),
    (lambda: C.join_points(A, "C3"), ValueError, "continuity must be one of"),
    (lambda: C.join_points(A, "C2", degree=1), ValueError, "degree must be at least"),
    (lambda: C.join_points([[0, 0], [1, 1]], "C2"), ValueError, "at least 3 points"),
    (lambda: C.join_points([[0, 0], [1, 1], [1, 1]], "G1"), ValueError, "tangent vanishes"),
    (lambda: C.join_points(A, "C1", beta2=1), ValueError, "beta2"),
    (lambda: C.constrain_join(A, [[0, 0, 0], [1, 1, 1]], "C0"), ValueError, "dimension of P"),
    (lambda: C.curvature_comb(A, [[0.5]]), ValueError, "t must be a 1D"),
    (lambda: C.basis_matrix("nurbs"), ValueError, "name must be one of"),
    (lambda: C.cubic_matrix_eval("bezier", A[:3], 0.5), ValueError, r"shape \(4, d\)"),
    (lambda: C.cubic_matrix_eval(np.eye(3), A, 0.5), ValueError, "4x4 matrix"),
    (lambda: C.convert_geometry(A, "bezier", np.zeros((4, 4))), ValueError, "invertible"),
    (lambda: C.power_row(0.5, order=-1), ValueError, "order must be at least 0"),
])
def test_bad_input(call, error, pattern):
    with pytest.raises(error, match=pattern):
        call()


# --------------------------------------------------------------------------------- matrix form

def test_bezier_matrix_form_equals_bernstein_evaluation():
    G = rng(5).normal(size=(4, 3))
    t = np.linspace(0, 1, 17)
    np.testing.assert_allclose(C.cubic_matrix_eval("bezier", G, t), C.bezier(G, t), atol=1e-12)
    for k in (1, 2, 3):
        np.testing.assert_allclose(C.cubic_matrix_eval("bezier", G, t, k),
                                   C.bezier_derivative(G, t, k), atol=1e-10)


def test_uniform_bspline_matrix_form_equals_bspline_curve():
    P = rng(6).normal(size=(7, 2))
    u = np.arange(11.0)                                  # uniform cubic knots, domain [3, 7]
    for i in range(1, 5):                                # span [u_{i+2}, u_{i+3}]
        t = np.linspace(0, 1, 9)
        got = C.cubic_matrix_eval("bspline", P[i - 1:i + 3], t)
        np.testing.assert_allclose(got, C.bspline(P, u, 3, i + 2 + t), atol=1e-12)
        np.testing.assert_allclose(got, BSpline(u, P, 3)(i + 2 + t), atol=1e-12)


def test_hermite_matrix_form_equals_scipy():
    gen = rng(7)
    p0, p1, d0, d1 = gen.normal(size=(4, 2))
    spline = CubicHermiteSpline([0, 1], np.array([p0, p1]), np.array([d0, d1]))
    t = np.linspace(0, 1, 11)
    G = np.array([p0, p1, d0, d1])
    np.testing.assert_allclose(C.cubic_matrix_eval("hermite", G, t), spline(t), atol=1e-12)
    np.testing.assert_allclose(C.cubic_matrix_eval("hermite", G, t, 1), spline(t, 1), atol=1e-12)


def test_catmull_rom_interpolates_with_central_tangents():
    G = rng(8).normal(size=(4, 2))
    np.testing.assert_allclose(C.cubic_matrix_eval("catmull-rom", G, [0, 1]), G[1:3], atol=1e-12)
    np.testing.assert_allclose(C.cubic_matrix_eval("catmull-rom", G, [0, 1], 1),
                               [(G[2] - G[0]) / 2, (G[3] - G[1]) / 2], atol=1e-12)


@pytest.mark.parametrize("a", MF.BASIS_NAMES)
@pytest.mark.parametrize("b", MF.BASIS_NAMES)
def test_convert_geometry_keeps_the_curve(a, b):
    G = rng(9).normal(size=(4, 2))
    t = np.linspace(0, 1, 7)
    H = C.convert_geometry(G, a, b)
    np.testing.assert_allclose(C.cubic_matrix_eval(b, H, t), C.cubic_matrix_eval(a, G, t),
                               atol=1e-10)


def test_known_conversions_typed_by_hand():
    G = rng(10).normal(size=(4, 2))
    p0, p1, d0, d1 = G
    np.testing.assert_allclose(C.convert_geometry(G, "hermite", "bezier"),
                               [p0, p0 + d0 / 3, p1 - d1 / 3, p1], atol=1e-12)
    P0, P1, P2, P3 = G
    np.testing.assert_allclose(C.convert_geometry(G, "bspline", "bezier"),
                               [(P0 + 4 * P1 + P2) / 6, (2 * P1 + P2) / 3, (P1 + 2 * P2) / 3,
                                (P1 + 4 * P2 + P3) / 6], atol=1e-12)


def test_basis_functions_partition_of_unity_and_power_row():
    t = np.linspace(0, 1, 11)
    for name in MF.BASIS_NAMES:
        if name != "hermite":
            np.testing.assert_allclose(C.basis_functions(name, t).sum(-1), 1, atol=1e-12)
    h = 1e-5
    np.testing.assert_allclose(C.power_row(t, 1), (C.power_row(t + h) - C.power_row(t - h)) / (2 * h),
                               atol=1e-8)
    np.testing.assert_allclose(C.power_row(0.3, 3), [6, 0, 0, 0])
    np.testing.assert_allclose(C.power_row(0.3, 4), [0, 0, 0, 0])


# --------------------------------------------------------------------------------- bspline_basis

def test_bspline_basis_of_the_textbook_short_knot_vector():
    u = [0, 1, 2, 3, 4]
    t = np.linspace(0, 4, 401)
    N = C.bspline_basis(u, 2, t)
    assert N.shape == (401, 2)
    x = t
    bell = np.select([x < 1, x < 2, x < 3, x <= 4],
                     [x ** 2 / 2, (-2 * x ** 2 + 6 * x - 3) / 2, (3 - x) ** 2 / 2, 0 * x])
    np.testing.assert_allclose(N[:, 0], bell, atol=1e-12)
    for i in range(2):
        expected = np.nan_to_num(BSpline.basis_element(u[i:i + 4], extrapolate=False)(t))
        np.testing.assert_allclose(N[:, i], expected, atol=1e-12)
    # derivative of the bell: t, -2t + 3, t - 3 on the three spans
    d = C.bspline_basis_derivative(u, 2, [0.5, 1.5, 2.5])[:, 0]
    np.testing.assert_allclose(d, [0.5, 0.0, -0.5])


def test_bspline_basis_single_function_and_repeated_knots():
    # degree + 2 knots: exactly one basis function (here the Bernstein-like bell on [0, 2])
    t = np.linspace(0, 2, 21)
    np.testing.assert_allclose(C.bspline_basis([0, 1, 2], 1, t)[:, 0], 1 - abs(t - 1), atol=1e-12)
    u = [0, 0, 1, 3]
    expected = np.nan_to_num(BSpline.basis_element(u, extrapolate=False)(np.linspace(0, 3, 31)))
    np.testing.assert_allclose(C.bspline_basis(u, 2, np.linspace(0, 3, 31))[:, 0], expected,
                               atol=1e-12)
    with pytest.raises(ValueError, match="at least degree \\+ 2 = 4"):
        C.bspline_basis([0, 1, 2], 2, 0.5)
    with pytest.raises(ValueError, match="non-decreasing"):
        C.bspline_basis([0, 2, 1, 3], 2, 0.5)
    with pytest.raises(ValueError, match="more than degree \\+ 1"):
        C.bspline_basis([1, 1, 1, 1], 2, 1.0)
    with pytest.raises(ValueError, match="domain"):
        C.bspline_basis([0, 1, 2, 3, 4], 2, 4.5)
    with pytest.raises(ValueError, match="at least 2 \\* degree \\+ 2"):
        C.domain([0, 1, 2, 3, 4], 2)                     # a curve still needs more knots
