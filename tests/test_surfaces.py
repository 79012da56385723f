"""Tests of course_lib.surfaces (tensor-product Bézier, B-spline and NURBS surfaces).

Expected values come from scipy.interpolate.NdBSpline, geomdl, the `bezier` package, closed
forms typed out below, or the surfaces' mathematical properties. Nothing is copied from the
output of the code under test. Random inputs use seeded numpy generators.
"""
import math

import bezier as bezier_pkg             # test-only references: `bezier` and geomdl
import numpy as np
import pytest
from geomdl import BSpline as GeomdlBSpline
from geomdl import NURBS as GeomdlNURBS
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline, NdBSpline
from scipy.optimize import linprog

from course_lib import curves as C
from course_lib import surfaces as S

FAST = settings(max_examples=40, deadline=None, database=None)


# ---------------------------------------------------------------------------------------------
# helpers (independent of the code under test)
# ---------------------------------------------------------------------------------------------

def rng(seed):
    return np.random.default_rng(seed)


def random_knots(gen, n_control, degree, clamped):
    """Random knots on [0, 1] (first 0, last 1): distinct, or clamped at both ends."""
    m = n_control + degree + 1
    u = np.concatenate([[0.0], np.cumsum(gen.uniform(0.2, 1.0, m - 1))])
    u /= u[-1]
    if clamped:
        u[:degree + 1] = 0.0
        u[-degree - 1:] = 1.0
    return u


def knot_domain(u, p):
    return u[p], u[len(u) - p - 1]


def grid_params(gen, a, b, count, knots=()):
    inside = [k for k in knots if a < k < b]
    return np.sort(np.concatenate([gen.uniform(a, b, count), [a, b], inside]))


def nd_reference(grid, ku, kv, p, q, u, v, nu=(0, 0)):
    """scipy's NdBSpline on the grid of u and v: shape (len(u), len(v), d)."""
    spline = NdBSpline((ku, kv), grid, (p, q), extrapolate=False)
    uu, vv = np.meshgrid(u, v, indexing="ij")
    return spline(np.stack([uu, vv], axis=-1), nu=nu)


def bezier_knots(n):
    return np.r_[np.zeros(n + 1), np.ones(n + 1)]


def bernstein_closed(n, i, t):
    return math.comb(n, i) * t**i * (1 - t)**(n - i)


def hull_distance(points, x):
    points = np.asarray(points, float)
    n, d = points.shape
    cost = np.r_[np.zeros(n), 1.0]
    a_ub = np.block([[points.T, -np.ones((d, 1))], [-points.T, -np.ones((d, 1))]])
    b_ub = np.r_[x, -np.asarray(x)]
    result = linprog(cost, A_ub=a_ub, b_ub=b_ub, A_eq=np.r_[np.ones(n), 0.0][None],
                     b_eq=[1.0], bounds=[(0, None)] * (n + 1), method="highs")
    assert result.status == 0, result.message
    return result.fun


def geomdl_surface(grid, ku, kv, p, q, weights=None):
    nu, nv, _ = grid.shape
    surface = GeomdlBSpline.Surface() if weights is None else GeomdlNURBS.Surface()
    surface.degree_u, surface.degree_v = p, q
    surface.ctrlpts_size_u, surface.ctrlpts_size_v = nu, nv
    if weights is None:
        surface.ctrlpts = grid.reshape(-1, grid.shape[-1]).tolist()     # v runs fastest
    else:
        h = np.concatenate([grid * weights[..., None], weights[..., None]], axis=-1)
        surface.ctrlptsw = h.reshape(-1, h.shape[-1]).tolist()
    surface.knotvector_u = ku.tolist()
    surface.knotvector_v = kv.tolist()
    return surface


def random_surface(seed, p, q, clamped_u, clamped_v, dim=3):
    gen = rng(seed)
    nu = p + 1 + int(gen.integers(0, 5))
    nv = q + 1 + int(gen.integers(0, 5))
    ku = random_knots(gen, nu, p, clamped_u)
    kv = random_knots(gen, nv, q, clamped_v)
    return gen, gen.normal(size=(nu, nv, dim)), ku, kv


# ---------------------------------------------------------------------------------------------
# Bézier patches
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("m, n", [(1, 1), (2, 3), (3, 3), (5, 2), (6, 6)])
def test_bezier_surface_closed_form_and_ndbspline(m, n):
    gen = rng(10 * m + n)
    grid = gen.normal(size=(m + 1, n + 1, 3))
    u = np.r_[0.0, 1.0, gen.uniform(0, 1, 9)]
    v = np.r_[gen.uniform(0, 1, 7), 1.0]
    expected = np.zeros((len(u), len(v), 3))
    for a, x in enumerate(u):
        for b, y in enumerate(v):
            expected[a, b] = sum(bernstein_closed(m, i, x) * bernstein_closed(n, j, y) * grid[i, j]
                                 for i in range(m + 1) for j in range(n + 1))
    got = S.bezier_surface(grid, u, v)
    assert got.shape == (len(u), len(v), 3)
    np.testing.assert_allclose(got, expected, atol=1e-12)
    np.testing.assert_allclose(got, nd_reference(grid, bezier_knots(m), bezier_knots(n), m, n,
                                                 u, v), atol=1e-12)


def test_bezier_surface_shapes_for_numbers_and_arrays():
    grid = S.hill_grid(3, 4)
    assert S.bezier_surface(grid, 0.5, 0.5).shape == (3,)
    assert S.bezier_surface(grid, [0.5], 0.5).shape == (1, 3)
    assert S.bezier_surface(grid, 0.5, [0.1, 0.2]).shape == (2, 3)
    assert S.bezier_surface(grid, np.linspace(0, 1, 5), np.linspace(0, 1, 6)).shape == (5, 6, 3)


@FAST
@given(seed=st.integers(0, 2**32 - 1), m=st.integers(1, 6), n=st.integers(1, 6))
def test_bezier_patch_corners_boundaries_and_isoparametric_curves(seed, m, n):
    gen = rng(seed)
    grid = gen.normal(size=(m + 1, n + 1, 3))
    s = np.linspace(0, 1, 17)
    corners = S.bezier_surface(grid, [0.0, 1.0], [0.0, 1.0])
    np.testing.assert_allclose(corners, grid[[0, -1]][:, [0, -1]], atol=1e-13)
    # boundary curves: the Bézier curves of the boundary rows and columns (bezier package)
    row = bezier_pkg.Curve(grid[0].T, n).evaluate_multi(s).T
    np.testing.assert_allclose(S.bezier_surface(grid, 0.0, s), row, atol=1e-12)
    column = bezier_pkg.Curve(grid[:, -1].T, m).evaluate_multi(s).T
    np.testing.assert_allclose(S.bezier_surface(grid, s, 1.0), column, atol=1e-12)
    # an inner u = const curve: the Bézier curve of the columns' points at u
    x = float(gen.uniform())
    blended = np.array([bezier_pkg.Curve(grid[:, j].T, m).evaluate(x).ravel()
                        for j in range(n + 1)])
    np.testing.assert_allclose(S.bezier_surface(grid, x, s),
                               bezier_pkg.Curve(blended.T, n).evaluate_multi(s).T, atol=1e-12)


def test_bezier_surface_partials_closed_form_and_ndbspline():
    gen = rng(3)
    grid = gen.normal(size=(4, 3, 3))
    u, v = gen.uniform(0, 1, 6), gen.uniform(0, 1, 5)
    surface, su, sv = S.bezier_surface_partials(grid, u, v)
    ku, kv = bezier_knots(3), bezier_knots(2)
    np.testing.assert_allclose(surface, nd_reference(grid, ku, kv, 3, 2, u, v), atol=1e-12)
    np.testing.assert_allclose(su, nd_reference(grid, ku, kv, 3, 2, u, v, (1, 0)), atol=1e-11)
    np.testing.assert_allclose(sv, nd_reference(grid, ku, kv, 3, 2, u, v, (0, 1)), atol=1e-11)
    # the bilinear patch z = u v: S_u = (1, 0, v), S_v = (0, 1, u)
    bilinear = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    _, su, sv = S.bezier_surface_partials(bilinear, 0.3, 0.8)
    np.testing.assert_allclose(su, [1, 0, 0.8], atol=1e-15)
    np.testing.assert_allclose(sv, [0, 1, 0.3], atol=1e-15)


# ---------------------------------------------------------------------------------------------
# B-spline and NURBS surfaces against scipy NdBSpline and geomdl
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("p, q", [(1, 1), (2, 3), (3, 3), (4, 2), (5, 5), (7, 1)])
@pytest.mark.parametrize("clamped", [(True, True), (False, False), (True, False)],
                         ids=["clamped", "unclamped", "mixed"])
def test_bspline_surface_matches_ndbspline(p, q, clamped):
    gen, grid, ku, kv = random_surface(100 * p + 10 * q + clamped[0] + 2 * clamped[1], p, q,
                                       *clamped)
    u = grid_params(gen, *knot_domain(ku, p), 20, ku)
    v = grid_params(gen, *knot_domain(kv, q), 15, kv)
    got = S.bspline_surface(grid, ku, kv, p, q, u, v)
    assert got.shape == (len(u), len(v), 3)
    np.testing.assert_allclose(got, nd_reference(grid, ku, kv, p, q, u, v), atol=1e-12)
    surface, su, sv = S.bspline_surface_partials(grid, ku, kv, p, q, u, v)
    np.testing.assert_allclose(surface, got, atol=1e-15)
    scale = max(1.0, np.abs(su).max(), np.abs(sv).max())
    np.testing.assert_allclose(su, nd_reference(grid, ku, kv, p, q, u, v, (1, 0)),
                               atol=1e-10 * scale)
    np.testing.assert_allclose(sv, nd_reference(grid, ku, kv, p, q, u, v, (0, 1)),
                               atol=1e-10 * scale)


@pytest.mark.parametrize("p, q", [(1, 2), (2, 2), (3, 3)])
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
def test_bspline_surface_matches_geomdl(p, q, clamped):
    gen, grid, ku, kv = random_surface(200 + 10 * p + q + clamped, p, q, clamped, clamped)
    u = grid_params(gen, *knot_domain(ku, p), 6)
    v = grid_params(gen, *knot_domain(kv, q), 5)
    reference = geomdl_surface(grid, ku, kv, p, q)
    expected = np.array([[reference.evaluate_single((float(x), float(y))) for y in v] for x in u])
    np.testing.assert_allclose(S.bspline_surface(grid, ku, kv, p, q, u, v), expected, atol=1e-12)


@pytest.mark.parametrize("p, q", [(1, 1), (2, 3), (3, 3), (5, 2)])
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
def test_nurbs_surface_matches_homogeneous_ndbspline(p, q, clamped):
    gen, grid, ku, kv = random_surface(300 + 10 * p + q + clamped, p, q, clamped, clamped)
    weights = 10.0 ** gen.uniform(-1, 1, grid.shape[:2])
    u = grid_params(gen, *knot_domain(ku, p), 12, ku)
    v = grid_params(gen, *knot_domain(kv, q), 10, kv)
    h = nd_reference(np.concatenate([grid * weights[..., None], weights[..., None]], axis=-1),
                     ku, kv, p, q, u, v)
    np.testing.assert_allclose(S.nurbs_surface(grid, weights, ku, kv, p, q, u, v),
                               h[..., :3] / h[..., 3:], atol=1e-11)


@pytest.mark.parametrize("p, q", [(1, 2), (2, 2), (3, 2)])
@pytest.mark.parametrize("clamped", [True, False], ids=["clamped", "unclamped"])
def test_nurbs_surface_and_partials_match_geomdl(p, q, clamped):
    gen, grid, ku, kv = random_surface(400 + 10 * p + q + clamped, p, q, clamped, clamped)
    weights = gen.uniform(0.3, 3.0, grid.shape[:2])
    u = grid_params(gen, *knot_domain(ku, p), 4)
    v = grid_params(gen, *knot_domain(kv, q), 4)
    reference = geomdl_surface(grid, ku, kv, p, q, weights)
    surface, su, sv = S.nurbs_surface_partials(grid, weights, ku, kv, p, q, u, v)
    np.testing.assert_allclose(S.nurbs_surface(grid, weights, ku, kv, p, q, u, v), surface,
                               atol=1e-14)
    for a, x in enumerate(u):
        for b, y in enumerate(v):
            np.testing.assert_allclose(surface[a, b],
                                       reference.evaluate_single((float(x), float(y))),
                                       atol=1e-12)
            d = reference.derivatives(float(x), float(y), order=1)     # d[k][l]: d^(k+l) S
            np.testing.assert_allclose(su[a, b], d[1][0], rtol=1e-9, atol=1e-9)
            np.testing.assert_allclose(sv[a, b], d[0][1], rtol=1e-9, atol=1e-9)


def test_nurbs_surface_partials_finite_differences():
    sphere = S.nurbs_sphere(1.5, (1, 2, 3))
    u = np.array([0.1, 0.37, 0.6, 0.93])
    v = np.array([0.2, 0.45, 0.77])
    _, su, sv = S.nurbs_surface_partials(*sphere, u, v)
    h = 1e-6
    fd_u = (S.nurbs_surface(*sphere, u + h, v) - S.nurbs_surface(*sphere, u - h, v)) / (2 * h)
    fd_v = (S.nurbs_surface(*sphere, u, v + h) - S.nurbs_surface(*sphere, u, v - h)) / (2 * h)
    np.testing.assert_allclose(su, fd_u, atol=1e-6)
    np.testing.assert_allclose(sv, fd_v, atol=1e-6)


def test_nurbs_with_equal_weights_is_the_bspline_surface():
    gen, grid, ku, kv = random_surface(5, 3, 2, True, False)
    u = grid_params(gen, *knot_domain(ku, 3), 8)
    v = grid_params(gen, *knot_domain(kv, 2), 8)
    np.testing.assert_allclose(S.nurbs_surface(grid, np.full(grid.shape[:2], 2.0), ku, kv, 3, 2,
                                               u, v),
                               S.bspline_surface(grid, ku, kv, 3, 2, u, v), atol=1e-12)


# ---------------------------------------------------------------------------------------------
# properties
# ---------------------------------------------------------------------------------------------

surface_case = st.tuples(st.integers(0, 2**32 - 1), st.integers(1, 4), st.integers(1, 4),
                         st.booleans(), st.booleans())


@settings(max_examples=15, deadline=None, database=None)
@given(case=surface_case)
def test_surface_convex_hull(case):
    seed, p, q, cu, cv = case
    gen, grid, ku, kv = random_surface(seed, p, q, cu, cv)
    weights = 10.0 ** gen.uniform(-1, 1, grid.shape[:2])
    u = gen.uniform(*knot_domain(ku, p), 2)
    v = gen.uniform(*knot_domain(kv, q), 2)
    points = grid.reshape(-1, 3)
    for x in S.bspline_surface(grid, ku, kv, p, q, u, v).reshape(-1, 3):
        assert hull_distance(points, x) <= 1e-9
    for x in S.nurbs_surface(grid, weights, ku, kv, p, q, u, v).reshape(-1, 3):
        assert hull_distance(points, x) <= 1e-9


@FAST
@given(case=surface_case)
def test_surface_affine_invariance(case):
    seed, p, q, cu, cv = case
    gen, grid, ku, kv = random_surface(seed, p, q, cu, cv)
    A, shift = gen.normal(size=(3, 3)), gen.normal(size=3)
    weights = 10.0 ** gen.uniform(-1, 1, grid.shape[:2])
    u = gen.uniform(*knot_domain(ku, p), 5)
    v = gen.uniform(*knot_domain(kv, q), 4)
    moved = grid @ A.T + shift
    np.testing.assert_allclose(S.bspline_surface(moved, ku, kv, p, q, u, v),
                               S.bspline_surface(grid, ku, kv, p, q, u, v) @ A.T + shift,
                               atol=1e-10)
    np.testing.assert_allclose(S.nurbs_surface(moved, weights, ku, kv, p, q, u, v),
                               S.nurbs_surface(grid, weights, ku, kv, p, q, u, v) @ A.T + shift,
                               atol=1e-10)


@FAST
@given(case=surface_case)
def test_nurbs_surface_projective_invariance(case):
    seed, p, q, cu, cv = case
    gen, grid, ku, kv = random_surface(seed, p, q, cu, cv)
    weights = 10.0 ** gen.uniform(-0.3, 0.3, grid.shape[:2])
    M = np.eye(4) + 0.2 * gen.normal(size=(4, 4))
    M[3] = [0.1 * gen.normal(), 0.1 * gen.normal(), 0.1 * gen.normal(), 1.0]
    h = np.concatenate([grid * weights[..., None], weights[..., None]], axis=-1) @ M.T
    if np.any(h[..., 3] <= 0.05) or abs(np.linalg.det(M)) < 0.05:
        return
    u = gen.uniform(*knot_domain(ku, p), 4)
    v = gen.uniform(*knot_domain(kv, q), 3)
    surface = S.nurbs_surface(grid, weights, ku, kv, p, q, u, v)
    mapped = np.concatenate([surface, np.ones(surface.shape[:2] + (1,))], axis=-1) @ M.T
    np.testing.assert_allclose(S.nurbs_surface(h[..., :3] / h[..., 3:], h[..., 3], ku, kv, p, q,
                                               u, v),
                               mapped[..., :3] / mapped[..., 3:], rtol=1e-9, atol=1e-9)


@FAST
@given(case=surface_case)
def test_bspline_surface_local_control(case):
    seed, p, q, cu, cv = case
    gen, grid, ku, kv = random_surface(seed, p, q, cu, cv)
    i, j = int(gen.integers(grid.shape[0])), int(gen.integers(grid.shape[1]))
    moved = grid.copy()
    moved[i, j] += 1.0 + gen.normal(size=3)
    (a, b), (c, d) = knot_domain(ku, p), knot_domain(kv, q)
    u, v = np.linspace(a, b, 41), np.linspace(c, d, 37)
    before = S.bspline_surface(grid, ku, kv, p, q, u, v)
    after = S.bspline_surface(moved, ku, kv, p, q, u, v)
    in_u = (u >= ku[i]) & ((u < ku[i + p + 1]) | ((u == b) & (ku[i + p + 1] == b)))
    in_v = (v >= kv[j]) & ((v < kv[j + q + 1]) | ((v == d) & (kv[j + q + 1] == d)))
    outside = ~(in_u[:, None] & in_v[None, :])
    np.testing.assert_array_equal(after[outside], before[outside])        # exactly unchanged
    # inside: the change is N_i(u) N_j(v) times the move (basis values from scipy)
    nu = BSpline.design_matrix(u, ku, p, extrapolate=False).toarray()[:, i]
    nv = BSpline.design_matrix(v, kv, q, extrapolate=False).toarray()[:, j]
    np.testing.assert_allclose(after - before, np.multiply.outer(np.outer(nu, nv),
                                                                 moved[i, j] - grid[i, j]),
                               atol=1e-12)


def test_clamped_bspline_surface_interpolates_corners_and_boundary_curves():
    gen, grid, ku, kv = random_surface(7, 3, 2, True, True)
    s = np.linspace(0, 1, 21)
    corners = S.bspline_surface(grid, ku, kv, 3, 2, [0.0, 1.0], [0.0, 1.0])
    np.testing.assert_allclose(corners, grid[[0, -1]][:, [0, -1]], atol=1e-13)
    np.testing.assert_allclose(S.bspline_surface(grid, ku, kv, 3, 2, 0.0, s),
                               BSpline(kv, grid[0], 2)(s), atol=1e-12)
    np.testing.assert_allclose(S.bspline_surface(grid, ku, kv, 3, 2, s, 1.0),
                               BSpline(ku, grid[:, -1], 3)(s), atol=1e-12)


# ---------------------------------------------------------------------------------------------
# normals, the sphere, drawing helpers, example grids
# ---------------------------------------------------------------------------------------------

def test_nurbs_sphere_is_exact_and_its_normals_point_outwards():
    center = np.array([1.0, -2.0, 0.5])
    sphere = S.nurbs_sphere(2.0, center)
    assert sphere.control_grid.shape == (9, 5, 3) and sphere.weights.shape == (9, 5)
    u, v = np.linspace(0, 1, 101), np.linspace(0, 1, 51)
    points = S.nurbs_surface(*sphere, u, v)
    np.testing.assert_allclose(np.linalg.norm(points - center, axis=-1), 2.0, rtol=0, atol=1e-12)
    # it covers the sphere: poles at v = 0 and 1, the equator at v = 1/2
    np.testing.assert_allclose(points[:, 0], np.broadcast_to(center - [0, 0, 2], (101, 3)),
                               atol=1e-12)
    np.testing.assert_allclose(points[:, -1], np.broadcast_to(center + [0, 0, 2], (101, 3)),
                               atol=1e-12)
    np.testing.assert_allclose(points[:, 25, 2], center[2], atol=1e-12)
    # against geomdl
    reference = geomdl_surface(sphere.control_grid, sphere.knots_u, sphere.knots_v, 2, 2,
                               sphere.weights)
    for x, y in [(0.1, 0.3), (0.55, 0.8), (0.9, 0.5)]:
        np.testing.assert_allclose(S.nurbs_surface(*sphere, x, y),
                                   reference.evaluate_single((x, y)), atol=1e-13)
    # normals: outward unit vectors (S - c) / r, zero at the poles
    surface, su, sv = S.nurbs_surface_partials(*sphere, u, v)
    normals = S.surface_normals(su, sv)
    np.testing.assert_allclose(normals[:, 1:-1], (surface[:, 1:-1] - center) / 2.0, atol=1e-9)
    np.testing.assert_array_equal(normals[:, [0, -1]], 0.0)


@FAST
@given(seed=st.integers(0, 2**32 - 1))
def test_surface_normals_are_unit_and_orthogonal(seed):
    gen = rng(seed)
    su, sv = gen.normal(size=(2, 20, 3))
    n = S.surface_normals(su, sv)
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, atol=1e-12)
    np.testing.assert_allclose(np.einsum("...i,...i", n, su), 0.0, atol=1e-10)
    np.testing.assert_allclose(np.einsum("...i,...i", n, sv), 0.0, atol=1e-10)
    # right-handed: det[S_u, S_v, n] > 0
    assert np.all(np.linalg.det(np.stack([su, sv, n], axis=-2)) > 0)


def test_surface_normals_of_a_plane_and_degenerate_cases():
    np.testing.assert_allclose(S.surface_normals([1, 0, 0], [0, 2, 0]), [0, 0, 1])
    np.testing.assert_allclose(S.surface_normals([0, 2, 0], [1, 0, 0]), [0, 0, -1])
    np.testing.assert_array_equal(S.surface_normals([[0, 0, 0], [1, 1, 0]],
                                                    [[1, 0, 0], [2, 2, 0]]), 0.0)
    # the wave: normals of the graph z = f(x, y) are (-f_x, -f_y, 1) normalised
    grid = S.wave_grid(7, 7)
    ku = kv = C.clamped_knots(7, 3)
    u = v = np.linspace(0, 1, 9)
    surface, su, sv = S.bspline_surface_partials(grid, ku, kv, 3, 3, u, v)
    n = S.surface_normals(su, sv)
    assert np.all(n[..., 2] > 0)
    np.testing.assert_allclose(np.einsum("...i,...i", n, su), 0.0, atol=1e-12)


def test_isoparametric_lines_lie_on_the_surface():
    grid = S.wave_grid(6, 5)
    ku, kv = C.uniform_knots(6, 3), C.clamped_knots(5, 2)
    du, dv = C.domain(ku, 3), C.domain(kv, 2)

    def evaluate(u, v):
        return S.bspline_surface(grid, ku, kv, 3, 2, u, v)

    along_v, along_u = S.isoparametric_lines(evaluate, 4, [0.25, 0.5], samples=30,
                                             domain_u=du, domain_v=dv)
    assert along_v.shape == (4, 30, 3) and along_u.shape == (2, 30, 3)
    us, s = np.linspace(*du, 4), np.linspace(*dv, 30)
    for a, x in enumerate(us):
        np.testing.assert_allclose(along_v[a], evaluate(np.array([x]), s)[0], atol=1e-15)
    s = np.linspace(*du, 30)
    for b, y in enumerate([0.25, 0.5]):
        np.testing.assert_allclose(along_u[b], evaluate(s, np.array([y]))[:, 0], atol=1e-15)
    with pytest.raises(ValueError, match="v_lines must lie in the domain"):
        S.isoparametric_lines(evaluate, 3, [2.0], domain_u=du, domain_v=dv)
    with pytest.raises(TypeError, match="evaluate must be a function"):
        S.isoparametric_lines(grid)


def test_example_grids_closed_forms():
    hill = S.hill_grid(5, 3, height=2.0)
    assert hill.shape == (5, 3, 3)
    np.testing.assert_allclose(hill[:, 0, 0], [-1, -0.5, 0, 0.5, 1])
    np.testing.assert_allclose(hill[0, :, 1], [-1, 0, 1])
    expected = 2.0 * np.outer(np.sin(np.pi * np.arange(5) / 4), np.sin(np.pi * np.arange(3) / 2))
    np.testing.assert_allclose(hill[..., 2], expected, atol=1e-15)
    wave = S.wave_grid(9, 4, amplitude=0.5, waves=2.0)
    x, y = wave[..., 0], wave[..., 1]
    np.testing.assert_allclose(wave[..., 2],
                               0.5 * np.sin(2 * np.pi * (x + 1)) * np.cos(np.pi * y / 2),
                               atol=1e-15)


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

G = S.hill_grid(4, 3)
KU, KV = C.clamped_knots(4, 2), C.clamped_knots(3, 1)


@pytest.mark.parametrize("call, error, pattern", [
    (lambda: S.bezier_surface(G[0], 0.5, 0.5), ValueError,
     r"control_grid must be a grid of points of shape \(nu, nv, d\)"),
    (lambda: S.bezier_surface(G[:1], 0.5, 0.5), ValueError, r"nu >= 2"),
    (lambda: S.bezier_surface(G, 1.5, 0.5), ValueError, r"u must lie in the domain \[0.0, 1.0\]"),
    (lambda: S.bezier_surface(G, 0.5, [[0.5]]), ValueError, r"v must be a number or a 1D array"),
    (lambda: S.bezier_surface(G, np.nan, 0.5), ValueError, r"u must be finite"),
    (lambda: S.bspline_surface(G, KU[:-1], KV, 2, 1, 0.5, 0.5), ValueError,
     r"knots_u must have n_control \+ degree \+ 1 = 4 \+ 2 \+ 1 = 7 values, got 6"),
    (lambda: S.bspline_surface(G, KU, KV[::-1], 2, 1, 0.5, 0.5), ValueError,
     r"knots_v must be non-decreasing"),
    (lambda: S.bspline_surface(G, KU, KV, 2, 0, 0.5, 0.5), ValueError,
     r"degree_v must be at least 1"),
    (lambda: S.bspline_surface(G, KU, KV, 4, 1, 0.5, 0.5), ValueError,
     r"degree_u must be less than the number of control points"),
    (lambda: S.bspline_surface(G, KU, KV, 2, 1, 0.5, -0.5), ValueError,
     r"v must lie in the domain"),
    (lambda: S.nurbs_surface(G, np.ones((4, 2)), KU, KV, 2, 1, 0.5, 0.5), ValueError,
     r"weights must have one weight per control point, shape \(4, 3\)"),
    (lambda: S.nurbs_surface(G, -np.ones((4, 3)), KU, KV, 2, 1, 0.5, 0.5), ValueError,
     r"weights must be positive .* weights\[\(0, 0\)\] = -1.0"),
    (lambda: S.surface_normals([1, 0], [0, 1]), ValueError, r"partial_u must be 3D vectors"),
    (lambda: S.surface_normals(np.ones((2, 3)), np.ones((3, 3))), ValueError, r"same shape"),
    (lambda: S.hill_grid(1, 3), ValueError, r"nu must be at least 2"),
    (lambda: S.nurbs_sphere(0.0), ValueError, r"radius must be positive"),
    (lambda: S.isoparametric_lines(lambda u, v: 0, samples=1), ValueError,
     r"samples must be at least 2"),
    (lambda: S.isoparametric_lines(lambda u, v: 0, domain_u=(1, 0)), ValueError,
     r"domain_u must be an interval"),
])
def test_bad_input_raises_with_a_clear_message(call, error, pattern):
    with pytest.raises(error, match=pattern):
        call()
