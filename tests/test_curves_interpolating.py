"""course_lib.curves.interpolating against scipy.interpolate and closed forms typed here."""
import numpy as np
import pytest
from scipy import interpolate as si

from course_lib import curves
from course_lib.curves import interpolating as ip

RNG = np.random.default_rng(7)
POINTS = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5], [6.0, 1.0], [7.0, 3.0]])


def test_parameterizations_closed_form():
    p = [[0, 0], [3, 4], [3, 5], [0, 9]]           # steps 5, 1, 5
    assert np.allclose(ip.parameterize(p, "uniform"), [0, 1, 2, 3])
    assert np.allclose(ip.parameterize(p, "chord"), [0, 5, 6, 11])
    assert np.allclose(ip.parameterize(p, "centripetal"), [0, 5 ** .5, 5 ** .5 + 1, 2 * 5 ** .5 + 1])
    assert np.allclose(ip.parameterize(p, "chord", normalize=True), np.array([0, 5, 6, 11]) / 11)


@pytest.mark.parametrize("kind", ["uniform", "chord", "centripetal"])
def test_polynomial_curve_matches_scipy_barycentric(kind):
    nodes = ip.parameterize(POINTS, kind)
    t = np.linspace(nodes[0], nodes[-1], 57)
    ours = ip.polynomial_curve(POINTS, t, kind)
    assert np.allclose(ours, si.BarycentricInterpolator(nodes, POINTS)(t))
    lag = si.lagrange(nodes, POINTS[:, 1])
    assert np.allclose(ours[:, 1], lag(t), atol=1e-8)


def test_lagrange_basis_is_a_partition_of_unity_and_kronecker_at_nodes():
    nodes = np.sort(RNG.uniform(0, 5, 6))
    assert np.allclose(ip.lagrange_basis(nodes, nodes), np.eye(6))
    assert np.allclose(ip.lagrange_basis(nodes, np.linspace(0, 5, 11)).sum(-1), 1)


def test_runge_oscillation_grows_with_the_degree():
    f = lambda x: 1 / (1 + 25 * x ** 2)                               # noqa: E731
    x = np.linspace(-1, 1, 1001)
    errors = []
    for n in (5, 9, 13):
        nodes = np.linspace(-1, 1, n)
        pts = np.column_stack([nodes, f(nodes)])
        y = ip.polynomial_curve(pts, x, nodes)[:, 1]
        errors.append(np.abs(y - f(x)).max())
    assert errors[0] < errors[1] < errors[2] and errors[2] > 1


def test_hermite_basis_closed_form_and_end_conditions():
    t = np.linspace(0, 1, 9)
    h = ip.hermite_basis(t)
    assert np.allclose(h[:, 0], 1 - 3 * t ** 2 + 2 * t ** 3)
    assert np.allclose(h[:, 3], t ** 3 - t ** 2)
    assert np.allclose(ip.hermite_basis([0, 1]), [[1, 0, 0, 0], [0, 1, 0, 0]])
    assert np.allclose(ip.hermite_basis([0, 1], 1), [[0, 0, 1, 0], [0, 0, 0, 1]])
    eps = 1e-6                                           # derivatives by central differences
    num = (ip.hermite_basis(0.3 + eps) - ip.hermite_basis(0.3 - eps)) / (2 * eps)
    assert np.allclose(ip.hermite_basis(0.3, 1), num, atol=1e-6)
    num2 = (ip.hermite_basis(0.3, 1) - ip.hermite_basis(0.3 - 2 * eps, 1)) / (2 * eps)
    assert np.allclose(ip.hermite_basis(0.3 - eps, 2), num2, atol=1e-4)


@pytest.mark.parametrize("kind", ["uniform", "chord", "centripetal"])
def test_hermite_curve_matches_scipy_cubic_hermite_spline(kind):
    tangents = RNG.normal(size=POINTS.shape)
    nodes = ip.parameterize(POINTS, kind)
    t = np.linspace(nodes[0], nodes[-1], 101)
    ref = si.CubicHermiteSpline(nodes, POINTS, tangents)(t)
    assert np.allclose(ip.hermite_curve(POINTS, tangents, t, kind), ref)


def test_hermite_segment_by_hand():
    # P0=(0,0), P1=(2,0), T0=(0,2), T1=(0,-2), t=1/2: H=(1/2,1/2,1/8,-1/8) -> (1, 0.5)
    assert np.allclose(ip.hermite_segment([0, 0], [2, 0], [0, 2], [0, -2], 0.5), [1, 0.5])


@pytest.mark.parametrize("kind", ["uniform", "chord", "centripetal"])
def test_natural_spline_matches_scipy(kind):
    nodes = ip.parameterize(POINTS, kind)
    t = np.linspace(nodes[0], nodes[-1], 203)
    ref = si.CubicSpline(nodes, POINTS, bc_type="natural")
    assert np.allclose(ip.cubic_spline(POINTS, t, kind, "natural"), ref(t))
    assert np.allclose(ip.spline_tangents(POINTS, kind), ref(nodes, 1))
    assert np.allclose(ip.spline_tangents(POINTS, kind, second=True), ref(nodes, 2))


def test_clamped_spline_matches_scipy_and_make_interp_spline():
    nodes = ip.parameterize(POINTS, "chord")
    ends = np.array([[1.0, -1.0], [0.5, 2.0]])
    t = np.linspace(nodes[0], nodes[-1], 203)
    ref = si.CubicSpline(nodes, POINTS, bc_type=((1, ends[0]), (1, ends[1])))
    ours = ip.cubic_spline(POINTS, t, "chord", "clamped", ends)
    assert np.allclose(ours, ref(t))
    bsp = si.make_interp_spline(nodes, POINTS, k=3, bc_type=([(1, ends[0])], [(1, ends[1])]))
    assert np.allclose(ours, bsp(t))


@pytest.mark.parametrize("kind", ["uniform", "chord", "centripetal"])
@pytest.mark.parametrize("count", [4, 5, 6])
def test_not_a_knot_spline_matches_scipy(kind, count):
    pts = POINTS[:count]
    nodes = ip.parameterize(pts, kind)
    t = np.linspace(nodes[0], nodes[-1], 151)
    ref = si.CubicSpline(nodes, pts, bc_type="not-a-knot")
    assert np.allclose(ip.cubic_spline(pts, t, kind, "not-a-knot"), ref(t))
    a, b = ip.spline_system(pts, kind, "not-a-knot")
    assert np.allclose(a @ ref(nodes, 2), b)                  # scipy's M solve our system
    assert np.count_nonzero(a[0]) == 3                        # not tridiagonal


def test_spline_system_by_hand_and_dense_solution():
    # 3 points, uniform: natural rows M0 = 0, M2 = 0; middle 1*M0 + 4*M1 + 1*M2 = 6*(-1 - 1)
    a, b = ip.spline_system([[0.0], [1.0], [0.0]])
    assert np.allclose(a, [[1, 0, 0], [1, 4, 1], [0, 0, 1]]) and np.allclose(b, [[0], [-12], [0]])
    a, b = ip.spline_system([[0.0], [1.0], [0.0]], end="clamped", end_tangents=[[0.0], [0.0]])
    assert np.allclose(a, [[2, 1, 0], [1, 4, 1], [0, 1, 2]]) and np.allclose(b, [[6], [-12], [6]])
    assert np.allclose(np.linalg.solve(a, b).ravel(), [6, -6, 6])
    a, b = ip.spline_system(POINTS, "chord", "clamped", [[1, 0], [0, 1]])
    m = ip.spline_tangents(POINTS, "chord", "clamped", [[1, 0], [0, 1]], second=True)
    assert np.allclose(a @ m, b)


def test_thomas_against_dense_solve():
    n = 40
    sub, sup = RNG.uniform(-1, 1, n), RNG.uniform(-1, 1, n)
    diag = 3 + RNG.uniform(0, 1, n)
    rhs = RNG.normal(size=(n, 3))
    a = np.diag(diag) + np.diag(sub[1:], -1) + np.diag(sup[:-1], 1)
    assert np.allclose(ip.thomas_solve(sub, diag, sup, rhs), np.linalg.solve(a, rhs))
    assert np.allclose(ip.thomas_solve(sub, diag, sup, rhs[:, 0]), np.linalg.solve(a, rhs[:, 0]))


def test_catmull_rom_uniform_tangents_and_scipy():
    tan = ip.cardinal_tangents(POINTS)
    assert np.allclose(tan[1:-1], (POINTS[2:] - POINTS[:-2]) / 2)
    assert np.allclose(tan[[0, -1]], [POINTS[1] - POINTS[0], POINTS[-1] - POINTS[-2]])
    t = np.linspace(0, 5, 99)
    ref = si.CubicHermiteSpline(np.arange(6.0), POINTS, tan)(t)
    assert np.allclose(ip.catmull_rom(POINTS, t), ref)
    assert np.allclose(ip.cardinal_tangents(POINTS, 0.2)[1:-1], 0.2 * (POINTS[2:] - POINTS[:-2]))
    assert np.allclose(ip.catmull_rom(POINTS, [0, 1, 2, 3, 4, 5], tension=0), POINTS)


def _barry_goldman(p, knots, t):
    """Centripetal Catmull-Rom by the Barry-Goldman pyramid (independent of the Hermite form)."""
    p0, p1, p2, p3 = p
    t0, t1, t2, t3 = knots

    def lerp(a, b, ta, tb):
        return ((tb - t) * a + (t - ta) * b) / (tb - ta)
    a1, a2, a3 = lerp(p0, p1, t0, t1), lerp(p1, p2, t1, t2), lerp(p2, p3, t2, t3)
    b1, b2 = lerp(a1, a2, t0, t2), lerp(a2, a3, t1, t3)
    return lerp(b1, b2, t1, t2)


@pytest.mark.parametrize("kind", ["uniform", "chord", "centripetal"])
def test_catmull_rom_matches_barry_goldman_pyramid(kind):
    nodes = ip.parameterize(POINTS, kind)
    for i in (1, 2, 3):
        t = np.linspace(nodes[i], nodes[i + 1], 7)
        ours = ip.catmull_rom(POINTS, t, kind)
        ref = np.array([_barry_goldman(POINTS[i - 1:i + 3], nodes[i - 1:i + 3], tt) for tt in t])
        assert np.allclose(ours, ref)


def test_passes_through_tells_interpolation_from_approximation():
    nodes = ip.parameterize(POINTS, "chord")
    f = lambda t: ip.cubic_spline(POINTS, t, "chord")                 # noqa: E731
    assert ip.passes_through(f, POINTS, nodes).all()
    samples = curves.bezier(POINTS, np.linspace(0, 1, 400))
    hit = ip.passes_through(samples, POINTS, atol=1e-6)
    assert hit[0] and hit[-1] and not hit[1:-1].any()
    dense = f(np.sort(np.concatenate([np.linspace(nodes[0], nodes[-1], 200), nodes])))
    assert ip.passes_through(dense, POINTS, atol=1e-9).all()       # the samples include t_i


@pytest.mark.parametrize("call, match", [
    (lambda: ip.parameterize([[0, 0], [0, 0], [1, 1]], "chord"), "points must not repeat"),
    (lambda: ip.parameterize([[0, 0], [1, 1]], "arc"), "kind must be one of"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1], [1, 1]], 0.5), "points must not repeat"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1]], 0.5, end="natural"), "at least 3"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1], [2, 0]], 0.5, end="not-a-knot"), "at least 4"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1], [2, 0]], 0.5, [0, 2, 1]), "strictly increasing"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1], [2, 0]], 0.5, [0, 1]), "one parameter value"),
    (lambda: ip.cubic_spline([[0, 0], [1, np.nan], [2, 0]], 0.5), "points must be finite"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1], [2, 0]], 9.0, "uniform"), "t must lie"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1], [2, 0]], 1, "uniform", "clamped"), "end_tangents"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1], [2, 0]], 1, "uniform", "clamped", [1, 0]),
     "end_tangents must be the two"),
    (lambda: ip.cubic_spline([[0, 0], [1, 1], [2, 0]], 1, "uniform", "free"), "end must be one"),
    (lambda: ip.hermite_curve([[0, 0], [1, 1]], [[1, 0]], 0.5), "tangents must have"),
    (lambda: ip.hermite_segment([0, 0], [1, 1], [1, 0, 0], [0, 1], 0.5), "t0 must have"),
    (lambda: ip.hermite_basis(1.5), "t must lie"),
    (lambda: ip.cardinal_tangents([[0, 0], [1, 1]], -1), "tension must be >= 0"),
    (lambda: ip.polynomial_curve([[0, 0]], 0.0), "at least 2"),
    (lambda: ip.lagrange_basis([0, 0, 1], 0.5), "strictly increasing"),
    (lambda: ip.thomas_solve([0, 0], [0, 1], [0, 0], [1, 1]), "singular"),
    (lambda: ip.passes_through(lambda t: t, [[0, 0]]), "params must be given"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises(ValueError, match=match):
        call()
