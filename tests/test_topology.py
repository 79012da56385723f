"""Tests of course_lib/scivis/topology.py: critical points, classes, separatrices, gridded
integration.

Cross-checks: numpy.linalg.eigvals with the classification rules typed below; the zeros of
linear fields (closed form); scipy.interpolate.RegularGridInterpolator for the bilinear
interpolation; scipy.integrate.solve_ivp on the same interpolant for the streamlines; the matrix
exponential (scipy.linalg.expm) for linear fields as the grid refines.
"""
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.interpolate import RegularGridInterpolator
from scipy.linalg import expm

from course_lib.scivis import Field
from course_lib.scivis.topology import (CRITICAL_CLASSES, bilinear_velocity,
                                        classify_critical_point, critical_points,
                                        gridded_field, integrate_gridded, jacobian_at,
                                        preset_field, separatrices)

RNG = np.random.default_rng(18)


def typed_class(j):
    """The class from numpy's eigenvalues, by the textbook rules."""
    lam = np.linalg.eigvals(j)
    re, im = lam.real, lam.imag
    if np.abs(lam).min() < 1e-9:
        return "degenerate"
    # a repeated eigenvalue of a defective matrix comes out of eigvals only to ~sqrt(eps)
    if np.abs(im).max() > 1e-6:                      # complex pair
        if abs(re[0]) < 1e-9:
            return "centre"
        return "attracting focus" if re[0] < 0 else "repelling focus"
    if re.min() < 0 < re.max():
        return "saddle"
    if (re < 0).all():
        return "attracting node"
    if (re > 0).all():
        return "repelling node"
    return "degenerate"


def linear_grid(a, c, lo=-2.0, hi=2.0, n=21):
    """v = A (x - c) sampled on [lo, hi]^2 with n nodes per side."""
    axis = np.linspace(lo, hi, n)
    x, y = np.meshgrid(axis, axis)
    u = a[0, 0] * (x - c[0]) + a[0, 1] * (y - c[1])
    v = a[1, 0] * (x - c[0]) + a[1, 1] * (y - c[1])
    return gridded_field(u, v, axis[1] - axis[0], (lo, lo)), axis


def test_classes_agree_with_numpy_eigenvalues():
    seen = set()
    for _ in range(3000):
        j = RNG.integers(-4, 5, size=(2, 2)).astype(float) / 2
        c = classify_critical_point(j)
        assert c.kind == typed_class(j), j
        assert np.allclose(np.sort_complex(c.eigenvalues), np.sort_complex(np.linalg.eigvals(j)))
        seen.add(c.kind)
    assert seen == set(CRITICAL_CLASSES)


def test_random_real_jacobians():
    for _ in range(2000):
        j = RNG.normal(size=(2, 2))
        assert classify_critical_point(j).kind == typed_class(j)


def test_reasons_name_the_evidence():
    assert "negative" in classify_critical_point([[2, 0], [0, -3]]).reason
    assert "complex" in classify_critical_point([[0, -1], [1, 0]]).reason


@pytest.mark.parametrize("bad", [[[np.nan, 0], [0, 1]], [[np.inf, 0], [0, 1]]])
def test_non_finite_jacobian_is_rejected(bad):
    with pytest.raises(ValueError, match="finite"):
        classify_critical_point(bad)


def test_wrong_jacobian_shape():
    with pytest.raises(ValueError, match="2 x 2"):
        classify_critical_point([1, 2, 3])


def test_linear_fields_critical_point_located_exactly():
    for _ in range(40):
        a = RNG.normal(size=(2, 2))
        if abs(np.linalg.det(a)) < 0.2:
            continue
        c = RNG.uniform(-1.5, 1.5, 2)
        f, _ = linear_grid(a, c)
        cps = critical_points(f)
        assert len(cps) == 1
        assert np.allclose(cps[0].position, c, atol=1e-9)
        assert np.allclose(cps[0].jacobian, a, atol=1e-9)     # bilinear of a linear field
        assert cps[0].kind == typed_class(a)


def test_zero_on_a_node_is_reported_once():
    a = np.array([[1.0, 2.0], [-3.0, 0.5]])
    f, axis = linear_grid(a, [axis_value := 0.4, -0.8], n=11)   # 0.4, -0.8 are nodes
    assert np.isclose(axis, axis_value).any()
    cps = critical_points(f)
    assert len(cps) == 1 and np.allclose(cps[0].position, [0.4, -0.8])


def test_bilinear_zeros_of_a_nonlinear_cell():
    # u = x y - 0.1, v = x - y on the unit square: zero at x = y = sqrt(0.1)
    u = np.array([[-0.1, -0.1], [-0.1, 0.9]])
    v = np.array([[0.0, 1.0], [-1.0, 0.0]])
    cps = critical_points(gridded_field(u, v))
    r = np.sqrt(0.1)
    assert len(cps) == 1 and np.allclose(cps[0].position, [r, r])
    assert np.allclose(cps[0].jacobian, [[r, r], [1, -1]])


def test_duffing_preset_has_a_saddle_and_two_foci():
    cps = critical_points(preset_field("saddle and two foci", 1.0, 0.5, n=65))
    kinds = [c.kind for c in cps]
    assert kinds == ["attracting focus", "saddle", "attracting focus"]
    assert np.allclose([c.position[0] for c in cps], [-1, 0, 1], atol=0.01)


def test_double_gyre_centres():
    cps = critical_points(preset_field("double gyre", 0.0, 0.25))
    centres = [c.position for c in cps if c.kind == "centre"]
    assert np.allclose(centres, [[0.5, 0.5], [1.5, 0.5]])


def test_bilinear_matches_scipy():
    nx, ny = 7, 5
    u, v = RNG.normal(size=(ny, nx)), RNG.normal(size=(ny, nx))
    sp, org = (0.5, 0.25), (-1.0, 2.0)
    xs, ys = org[0] + sp[0] * np.arange(nx), org[1] + sp[1] * np.arange(ny)
    x = RNG.uniform(xs[0], xs[-1], 200)
    y = RNG.uniform(ys[0], ys[-1], 200)
    got = bilinear_velocity(u, v, x, y, sp, org)
    for k, comp in enumerate((u, v)):
        ref = RegularGridInterpolator((ys, xs), comp)(np.column_stack([y, x]))
        assert np.allclose(got[:, k], ref)
    # nodes are reproduced
    assert np.allclose(bilinear_velocity(u, v, xs[3], ys[2], sp, org), [u[2, 3], v[2, 3]])


@pytest.mark.parametrize("method", ["euler", "rk2", "rk4"])
def test_gridded_integration_against_solve_ivp(method):
    f = preset_field("saddle and two foci", 1.0, 0.5, n=17)
    g = f.values
    xs = f.origin[0] + f.spacing[0] * np.arange(g.shape[1])
    ys = f.origin[1] + f.spacing[1] * np.arange(g.shape[0])
    interp = [RegularGridInterpolator((ys, xs), g[..., k]) for k in range(2)]

    def rhs(t, p):
        q = [[p[1], p[0]]]
        return [float(interp[0](q)[0]), float(interp[1](q)[0])]

    seed, h, n = np.array([-1.6, 0.9]), 0.01, 100
    line = integrate_gridded(f, seed, h, n, method=method)
    assert line.shape == (n + 1, 2)
    ref = solve_ivp(rhs, (0, n * h), seed, t_eval=h * np.arange(n + 1), rtol=1e-10,
                    atol=1e-12, max_step=0.002)
    err = np.abs(line - ref.y.T).max()
    assert err < {"euler": 2e-2, "rk2": 1e-3, "rk4": 1e-3}[method]
    if method == "euler":
        assert err > 1e-4                           # first order: visibly off


def test_gridded_rk4_converges_to_the_analytic_linear_streamline():
    a = np.array([[-0.5, 1.0], [-1.0, -0.5]])
    seed, t_end = np.array([1.2, 0.3]), 1.0
    exact = expm(a * t_end) @ seed
    errors = []
    for n in (5, 9, 17, 33):
        f, _ = linear_grid(a, [0.0, 0.0], n=n)
        line = integrate_gridded(f, seed, 0.01, 100, method="rk4")
        errors.append(np.linalg.norm(line[-1] - exact))
    assert errors[-1] < 1e-6 and errors[0] < 1e-6        # linear fields are bilinear: exact


def test_integration_stops_at_the_border_and_at_a_critical_point():
    f = gridded_field(np.ones((3, 3)), np.zeros((3, 3)))
    line = integrate_gridded(f, [0.0, 1.0], 0.3, 50, method="euler")
    assert line[-1, 0] <= 2.0 and line[-1, 0] > 1.6 and len(line) == 7
    g, _ = linear_grid(-np.eye(2), [0.0, 0.0], n=5)
    line = integrate_gridded(g, [0.0, 0.0], 0.1, 10)
    assert len(line) == 1                                 # seed at a zero: no motion
    outside = integrate_gridded(f, [5.0, 5.0], 0.1, 10)
    assert len(outside) == 1


def test_backward_integration_reverses_the_flow():
    f, _ = linear_grid(-np.eye(2), [0.0, 0.0])
    fwd = integrate_gridded(f, [1.0, 0.5], 0.05, 10, method="rk4")
    back = integrate_gridded(f, [1.0, 0.5], 0.05, 10, method="rk4", backward=True)
    assert np.linalg.norm(fwd[-1]) < np.linalg.norm(fwd[0]) < np.linalg.norm(back[-1])
    assert np.allclose(fwd[-1], np.exp(-0.5) * np.array([1.0, 0.5]), atol=1e-6)


def test_separatrices_of_a_linear_saddle_follow_its_eigenvectors():
    a = np.array([[1.0, 2.0], [1.5, -0.5]])
    f, _ = linear_grid(a, [0.2, -0.1], n=41)
    (saddle,) = critical_points(f)
    assert saddle.kind == "saddle"
    lam, vec = np.linalg.eig(a)
    e_u, e_s = vec[:, np.argmax(lam)], vec[:, np.argmin(lam)]
    sep = separatrices(f, saddle, n=1500)
    for name, e in (("unstable", e_u), ("stable", e_s)):
        lines = sep[name]
        assert len(lines) == 2
        for line in lines:
            d = line[1:] - saddle.position
            cross = d[:, 0] * e[1] - d[:, 1] * e[0]
            assert np.abs(cross).max() < 1e-6          # on the eigenvector's line
            assert np.linalg.norm(d[-1]) > 1.0            # reaches far out
        ends = [line[-1] - saddle.position for line in lines]
        assert ends[0] @ ends[1] < 0                      # the two opposite branches


def test_separatrices_need_a_saddle():
    f, _ = linear_grid(-np.eye(2), [0.0, 0.0])
    with pytest.raises(ValueError, match="saddle"):
        separatrices(f, [0.0, 0.0])


def test_jacobian_at_matches_finite_differences():
    f = preset_field("double gyre", 3.0, 0.25, n=65)
    p, d = np.array([0.61, 0.37]), 1e-6
    g = f.values
    num = np.column_stack([
        (bilinear_velocity(g[..., 0], g[..., 1], p[0] + d, p[1], f.spacing, f.origin)
         - bilinear_velocity(g[..., 0], g[..., 1], p[0] - d, p[1], f.spacing, f.origin)) / (2 * d),
        (bilinear_velocity(g[..., 0], g[..., 1], p[0], p[1] + d, f.spacing, f.origin)
         - bilinear_velocity(g[..., 0], g[..., 1], p[0], p[1] - d, f.spacing, f.origin)) / (2 * d)])
    assert np.allclose(jacobian_at(f, p), num, atol=1e-6)


def test_errors():
    f = preset_field("linear")
    with pytest.raises(ValueError, match="step"):
        integrate_gridded(f, [0.1, 0.1], 0.0, 10)
    with pytest.raises(ValueError, match="step"):
        integrate_gridded(f, [0.1, 0.1], -0.1, 10)
    with pytest.raises(ValueError, match="n"):
        integrate_gridded(f, [0.1, 0.1], 0.1, 0)
    with pytest.raises(ValueError, match="method"):
        integrate_gridded(f, [0.1, 0.1], 0.1, 5, method="rk3")
    with pytest.raises(ValueError, match="same shape"):
        gridded_field(np.zeros((3, 3)), np.zeros((3, 4)))
    with pytest.raises(ValueError, match="shape"):
        gridded_field(np.zeros(3), np.zeros(3))
    with pytest.raises(ValueError, match="finite"):
        gridded_field([[0, np.nan], [0, 0]], np.zeros((2, 2)))
    bad = Field(np.full((3, 3, 2), np.inf), (1.0, 1.0), (0.0, 0.0))
    with pytest.raises(ValueError, match="finite"):
        critical_points(bad)
    with pytest.raises(ValueError, match="finite"):
        jacobian_at(bad, [0.5, 0.5])
    with pytest.raises(ValueError, match="shape"):
        critical_points(Field(np.zeros((3, 3)), (1.0, 1.0), (0.0, 0.0)))
    with pytest.raises(TypeError, match="Field"):
        critical_points(np.zeros((3, 3, 2)))
    with pytest.raises(ValueError, match="spacing"):
        bilinear_velocity(np.zeros((2, 2)), np.zeros((2, 2)), 0.0, 0.0, spacing=0)
    with pytest.raises(ValueError, match="same shape"):
        bilinear_velocity(np.zeros((2, 2)), np.zeros((2, 2)), [0.0, 1.0], 0.0)
    with pytest.raises(ValueError, match="name"):
        preset_field("tornado")


def test_gridded_streamline_converges_to_the_analytic_one_as_the_grid_refines():
    def analytic(t, p):                         # the oscillator of preset "saddle and two foci"
        return [p[1], p[0] - p[0] ** 3 - 0.5 * p[1]]

    seed, h, n = np.array([-0.5, 1.45]), 0.01, 400
    ref = solve_ivp(analytic, (0, n * h), seed, rtol=1e-11, atol=1e-12).y[:, -1]
    errors = []
    for size in (9, 17, 33, 65):
        f = preset_field("saddle and two foci", 1.0, 0.5, n=size)
        errors.append(np.linalg.norm(integrate_gridded(f, seed, h, n)[-1] - ref))
    assert all(b < a for a, b in zip(errors, errors[1:]))
    assert errors[-1] < 0.05 * errors[0]


def test_critical_points_match_newton_per_cell():
    """scipy.optimize.fsolve on every candidate cell's bilinear pair finds the same zeros."""
    from scipy.optimize import fsolve

    axis = np.linspace(0.0, 1.0, 48)
    x, y = np.meshgrid(axis, axis)
    u = np.sin(20 * x + 1) * np.cos(15 * y) + 0.2 * np.sin(5 * y)
    v = np.cos(17 * x) * np.sin(19 * y + 0.5) - 0.1 * x
    f = gridded_field(u, v, axis[1] - axis[0], (0.0, 0.0))
    ours = np.array([c.position for c in critical_points(f)])
    g, h, found = f.values, axis[1] - axis[0], []
    for j in range(len(axis) - 1):
        for i in range(len(axis) - 1):
            c = [g[j, i], g[j, i + 1], g[j + 1, i], g[j + 1, i + 1]]
            if (np.min(c, axis=0) > 0).any() or (np.max(c, axis=0) < 0).any():
                continue                       # a component keeps its sign: no zero here

            def residual(st):
                s, t = st
                return ((1 - s) * (1 - t) * c[0] + s * (1 - t) * c[1] + (1 - s) * t * c[2]
                        + s * t * c[3])
            for start in ([0.5, 0.5], [0.1, 0.1], [0.9, 0.9], [0.1, 0.9], [0.9, 0.1]):
                st, _, ok, _ = fsolve(residual, start, full_output=True, xtol=1e-13)
                if ok == 1 and (st > -1e-9).all() and (st < 1 + 1e-9).all() and \
                        np.abs(residual(st)).max() < 1e-10:
                    p = [axis[i] + h * st[0], axis[j] + h * st[1]]
                    if not any(np.hypot(*(np.subtract(p, q))) < 1e-7 for q in found):
                        found.append(p)
    found = np.array(found)
    assert len(ours) == len(found) > 20
    dist = np.linalg.norm(ours[:, None] - found[None], axis=-1)
    assert dist.min(axis=1).max() < 1e-8 and dist.min(axis=0).max() < 1e-8
