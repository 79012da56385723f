"""Tests of chapter 10.3's data modules: levels of measurement, grids, scattered data.

The expected values come from outside the code under test: Stevens' table and the closed forms
typed here, scipy (Delaunay, griddata, RBFInterpolator, RegularGridInterpolator, ConvexHull),
matplotlib's triangle interpolator, numpy's gradient, and plain loops over the formulas.
"""
import math

import numpy as np
import pytest
from scipy.interpolate import RBFInterpolator, RegularGridInterpolator, griddata
from scipy.spatial import ConvexHull, Delaunay

from course_lib.dataviz import _buckets, data_types as D, grids as G, scattered as S

RNG = np.random.default_rng(2024)


# ---------------------------------------------------------------------------------------------
# Levels of measurement
# ---------------------------------------------------------------------------------------------

STEVENS = {   # level -> what it permits (typed from Stevens' table)
    "nominal": {"equality", "count", "mode"},
    "ordinal": {"equality", "count", "mode", "order", "median", "percentile"},
    "interval": {"equality", "count", "mode", "order", "median", "percentile", "difference",
                 "mean", "standard deviation"},
    "ratio": {"equality", "count", "mode", "order", "median", "percentile", "difference",
              "mean", "standard deviation", "ratio", "geometric mean", "harmonic mean",
              "coefficient of variation"},
}


@pytest.mark.parametrize("level", STEVENS)
def test_permits_follows_stevens(level):
    for what in D.OPERATIONS + D.STATISTICS:
        assert D.permits(level, what) == (what in STEVENS[level]), (level, what)
    row = D.LEVELS[level]
    assert set(row.operations) | set(row.statistics) == STEVENS[level]
    assert row.kind == ("qualitative" if level in ("nominal", "ordinal") else "quantitative")


def test_permits_symbols_and_errors():
    assert D.permits("ordinal", "<") and not D.permits("nominal", "<")
    assert D.permits("interval", "-") and not D.permits("interval", "/")
    assert D.permits(" Ratio ", "/") and D.permits(D.LEVELS["ratio"], "*")
    with pytest.raises(ValueError, match="level must be one of"):
        D.permits("cardinal", "mean")
    with pytest.raises(ValueError, match="what must be an operation"):
        D.permits("ratio", "variance")
    with pytest.raises(ValueError, match="what must be"):
        D.permits("ratio", 3)


def test_measurement_level_questions():
    assert D.measurement_level(ordered=False) == "nominal"
    assert D.measurement_level(ordered=True) == "ordinal"
    assert D.measurement_level(ordered=True, equal_intervals=True) == "interval"
    assert D.measurement_level(ordered=True, equal_intervals=True, true_zero=True) == "ratio"
    with pytest.raises(ValueError, match="needs ordered=True"):
        D.measurement_level(ordered=False, equal_intervals=True)
    with pytest.raises(ValueError, match="needs equal_intervals=True"):
        D.measurement_level(ordered=True, true_zero=True)
    with pytest.raises(TypeError, match="ordered must be True or False"):
        D.measurement_level(ordered="yes")


def test_admissible_transformations():
    c = np.array([-40.0, 0.0, 10.0, 20.0, 37.0, 100.0])
    f = c * 9 / 5 + 32
    k = c + 273.15
    rankine = k * 9 / 5
    assert D.is_admissible_transform("interval", c, f)
    assert not D.is_admissible_transform("ratio", c, f)        # °C is no ratio scale
    assert D.is_admissible_transform("ratio", k, rankine)
    assert D.is_admissible_transform("ordinal", k, np.log(k))   # increasing
    assert not D.is_admissible_transform("interval", k, np.log(k))
    assert not D.is_admissible_transform("ordinal", c, -c)       # order reversed
    assert D.is_admissible_transform("nominal", [1, 2, 3, 1], [7, 5, 6, 7])
    assert not D.is_admissible_transform("nominal", [1, 2, 3], [7, 7, 6])   # merges two codes
    assert not D.is_admissible_transform("ratio", [1, 1, 2], [2, 3, 4])     # not a function
    # ratios survive a ratio transformation, and fail under an interval one
    assert math.isclose(rankine[3] / rankine[2], k[3] / k[2])
    assert not math.isclose(f[3] / f[2], c[3] / c[2])
    with pytest.raises(ValueError, match="same length"):
        D.is_admissible_transform("ratio", [1, 2], [1, 2, 3])
    with pytest.raises(ValueError, match="2 distinct"):
        D.is_admissible_transform("ratio", [1, 1], [2, 2])
    with pytest.raises(ValueError, match="finite"):
        D.is_admissible_transform("ratio", [1, np.nan], [2, 3])


def test_attribute_examples_cover_every_level():
    levels = [level for level, _ in D.ATTRIBUTE_EXAMPLES.values()]
    assert set(levels) == set(D.LEVELS)
    assert D.ATTRIBUTE_EXAMPLES["postcode"][0] == "nominal"
    assert D.ATTRIBUTE_EXAMPLES["temperature in °C"][0] == "interval"
    assert D.ATTRIBUTE_EXAMPLES["temperature in kelvin"][0] == "ratio"
    for example in (e for row in D.LEVELS.values() for e in row.examples):
        assert isinstance(example, str) and example


@pytest.mark.parametrize("shape, dim, kind, comps, samples, signature", [
    ((64, 64), 2, "scalar", 1, 4096, "f: R^2 -> R"),
    ((30, 40, 2), 2, "vector", 2, 1200, "f: R^2 -> R^2"),
    ((8, 9, 10, 3), 3, "vector", 3, 720, "f: R^3 -> R^3"),
    ((8, 9, 10), 3, "scalar", 1, 720, "f: R^3 -> R"),
    ((10, 10, 3), 2, "multivariate", 3, 100, "f: R^2 -> R^3"),
    ((5, 6, 7, 3, 3), 3, "tensor", 9, 210, "f: R^3 -> R^(3x3)"),
    ((100,), 1, "scalar", 1, 100, "f: R -> R"),
    ((100, 4), 1, "multivariate", 4, 100, "f: R -> R^4"),
])
def test_dimensionality_of_gridded_data(shape, dim, kind, comps, samples, signature):
    d = D.data_dimensionality(np.zeros(shape), dim)
    assert d == (dim, kind, comps, samples, signature)


def test_dimensionality_of_scattered_data_and_errors():
    d = D.data_dimensionality(np.zeros((50, 3)), points=np.zeros((50, 3)))
    assert (d.domain_dim, d.value_kind, d.samples) == (3, "vector", 50)
    d = D.data_dimensionality(np.zeros((50, 3)), points=np.zeros((50, 3)), kind="multivariate")
    assert d.value_kind == "multivariate"
    assert D.data_dimensionality(np.zeros((10, 10, 3)), 2, kind="vector").value_kind == "vector"
    with pytest.raises(ValueError, match="domain_dim is needed"):
        D.data_dimensionality(np.zeros((4, 4)))
    with pytest.raises(ValueError, match="one row per point"):
        D.data_dimensionality(np.zeros(49), points=np.zeros((50, 2)))
    with pytest.raises(ValueError, match="fit no kind"):
        D.data_dimensionality(np.zeros((4, 4, 2, 3)), 2)
    with pytest.raises(ValueError, match="does not fit"):
        D.data_dimensionality(np.zeros((4, 4)), 2, kind="vector")
    with pytest.raises(ValueError, match="disagrees"):
        D.data_dimensionality(np.zeros(5), 3, points=np.zeros((5, 2)))
    with pytest.raises(ValueError, match="domain_dim must be 1, 2 or 3"):
        D.data_dimensionality(np.zeros((2, 2, 2, 2)), 4)


# ---------------------------------------------------------------------------------------------
# Grids
# ---------------------------------------------------------------------------------------------

def test_constructors_give_the_lattice_positions():
    g = G.uniform_grid((3, 4), spacing=(0.5, 2.0), origin=(1.0, -1.0))
    X, Y = np.meshgrid(1.0 + 0.5 * np.arange(4), -1.0 + 2.0 * np.arange(3))
    assert np.array_equal(g.nodes, np.column_stack([X.ravel(), Y.ravel()]))
    assert g.cells.shape == (2 * 3, 4)
    corners = g.nodes[g.cells]                       # every quad counter-clockwise
    x, y = corners[..., 0], corners[..., 1]
    area = 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
    assert np.allclose(area, 0.5 * 2.0)
    r = G.rectilinear_grid([0, 1, 5], [0, 2], [0, 0.5, 1, 3])
    assert r.shape == (4, 2, 3) and r.cells.shape == (3 * 1 * 2, 8)
    Z, Y, X = np.meshgrid([0, 0.5, 1, 3], [0, 2], [0, 1, 5], indexing="ij")
    assert np.array_equal(r.nodes, np.column_stack([X.ravel(), Y.ravel(), Z.ravel()]))
    hexa = r.nodes[r.cells[0]]                      # the first hexahedron: 8 distinct corners
    assert len(np.unique(hexa, axis=0)) == 8
    c = G.curvilinear_grid(np.stack([X[0], Y[0]], axis=-1))
    assert c.kind == "curvilinear" and c.nodes.shape == (6, 2)
    with pytest.raises(ValueError, match="strictly increasing"):
        G.rectilinear_grid([0, 2, 1], [0, 1])
    with pytest.raises(ValueError, match="spacing must be positive"):
        G.uniform_grid((2, 2), spacing=(1, 0))
    with pytest.raises(ValueError, match="only 3 nodes"):
        G.unstructured_grid([[0, 0], [1, 0], [0, 1]], [[0, 1, 3]])
    with pytest.raises(ValueError, match="shape"):
        G.curvilinear_grid(np.zeros((3, 4, 3)))


def test_grid_kind_from_coordinates():
    assert G.grid_kind([0, 1, 2], [5, 6]) == "uniform"
    kind, why = G.grid_kind([0, 1, 2], [0, 1, 2], explain=True)
    assert kind == "uniform" and "Cartesian" in why
    assert "Cartesian" not in G.grid_kind([0, 1, 2], [0, 2, 4], explain=True)[1]
    assert G.grid_kind([0, 1, 3], [0, 1]) == "rectilinear"
    assert G.grid_kind([0, 1, 2], [0, 1], [0, 1, 3]) == "rectilinear"
    for indexing in ("xy", "ij"):
        X, Y = np.meshgrid([0.0, 0.5, 1.0, 1.5], [2.0, 3.0, 4.0], indexing=indexing)
        assert G.grid_kind(X, Y) == "uniform"
        X, Y = np.meshgrid([0.0, 0.5, 2.0], [2.0, 3.0, 4.0], indexing=indexing)
        assert G.grid_kind(X, Y) == "rectilinear"
    r, t = np.meshgrid([1.0, 2.0, 3.0], np.linspace(0, 1, 5))
    assert G.grid_kind(r * np.cos(t), r * np.sin(t)) == "curvilinear"
    X, Y = np.meshgrid([0.0, 1.0, 2.0], [0.0, 1.0])
    assert G.grid_kind(X + 0.1 * Y, Y) == "curvilinear"                  # sheared
    assert G.grid_kind(X, X) == "curvilinear"                            # degenerate
    pts = RNG.uniform(size=(20, 2))
    assert G.grid_kind(pts) == "scattered"
    assert G.grid_kind(pts, cells=Delaunay(pts).simplices) == "unstructured"
    with pytest.raises(ValueError, match="cells belong"):
        G.grid_kind([0, 1], [0, 1], cells=[[0, 1, 2]])
    with pytest.raises(ValueError, match="1D arrays"):
        G.grid_kind(np.zeros((2, 3)), np.zeros((3, 2)))
    with pytest.raises(ValueError, match="strictly increasing"):
        G.grid_kind([0, 2, 1], [0, 1])


@pytest.mark.parametrize("shape", [(50, 100), (4, 5, 6)])
def test_grid_memory_closed_forms(shape):
    d, n = len(shape), int(np.prod(shape))
    cells = int(np.prod([s - 1 for s in shape]))
    expect = {"uniform": (2 * d, d), "rectilinear": (sum(shape), d),
              "curvilinear": (d * n, d), "scattered": (d * n, 0),
              "unstructured": (d * n, (2 * cells * 3) if d == 2 else (6 * cells * 4))}
    for kind, (geometry, topology) in expect.items():
        m = G.grid_memory(kind, shape, components=3, bytes_per_number=8)
        assert (m["geometry"], m["topology"], m["values"]) == (geometry, topology, 3 * n)
        assert m["bytes"] == 8 * (geometry + topology + 3 * n)
    whole = "quad" if d == 2 else "hexahedron"
    assert G.grid_memory("unstructured", shape, cell=whole)["topology"] == cells * 2 ** d
    with pytest.raises(ValueError, match="cell applies"):
        G.grid_memory("uniform", shape, cell="triangle")
    with pytest.raises(ValueError, match="kind must be one of"):
        G.grid_memory("regular", shape)


def test_grid_memory_agrees_with_what_the_grids_store():
    shape = (4, 6)
    X, Y = np.meshgrid(np.arange(6.0), np.arange(4.0) ** 1.5)
    uni = G.uniform_grid(shape)
    grids = {"uniform": uni,
             "rectilinear": G.rectilinear_grid(np.arange(6.0), np.arange(4.0) ** 1.5),
             "curvilinear": G.curvilinear_grid(np.stack([X + 0.2 * Y, Y], axis=-1)),
             "unstructured": G.unstructured_grid(uni.nodes, np.concatenate(
                 [uni.cells[:, [0, 1, 2]], uni.cells[:, [0, 2, 3]]])),
             "scattered": G.scattered_points(uni.nodes)}
    for kind, grid in grids.items():
        stored = sum(a.size for a in grid.stored.values())
        m = G.grid_memory(kind, shape)
        assert stored == m["geometry"] + m["topology"], kind


def test_rectilinear_interpolation_against_scipy():
    x = np.sort(RNG.uniform(0, 5, 7))
    y = np.sort(RNG.uniform(-1, 2, 5))
    z = np.sort(RNG.uniform(0, 1, 4))
    v2 = RNG.normal(size=(5, 7))
    q2 = np.column_stack([RNG.uniform(x[0], x[-1], 200), RNG.uniform(y[0], y[-1], 200)])
    ref = RegularGridInterpolator((y, x), v2)(q2[:, ::-1])
    assert np.allclose(G.rectilinear_interpolate(v2, (x, y), q2), ref, atol=1e-12)
    v3 = RNG.normal(size=(4, 5, 7, 2))                       # a 2-vector per sample
    q3 = np.column_stack([RNG.uniform(x[0], x[-1], 100), RNG.uniform(y[0], y[-1], 100),
                          RNG.uniform(z[0], z[-1], 100)])
    ref = RegularGridInterpolator((z, y, x), v3)(q3[:, ::-1])
    assert np.allclose(G.rectilinear_interpolate(v3, (x, y, z), q3), ref, atol=1e-12)
    # at the samples themselves: the samples
    X, Y = np.meshgrid(x, y)
    assert np.allclose(G.rectilinear_interpolate(v2, (x, y), np.stack([X, Y], -1)), v2)
    far = [[x[-1] + 1.0, y[0]]]
    with pytest.raises(ValueError, match="1 of the points lie outside"):
        G.rectilinear_interpolate(v2, (x, y), far)
    assert np.allclose(G.rectilinear_interpolate(v2, (x, y), far, outside="clamp"), v2[0, -1])
    assert np.isnan(G.rectilinear_interpolate(v2, (x, y), far, outside=np.nan)[0])
    with pytest.raises(ValueError, match="values must have shape"):
        G.rectilinear_interpolate(v2.T, (x, y), q2)
    with pytest.raises(ValueError, match="NaN"):
        G.rectilinear_interpolate(np.where(v2 > 0, np.nan, v2), (x, y), q2)
    with pytest.raises(TypeError, match="outside"):
        G.rectilinear_interpolate(v2, (x, y), q2, outside=[1])


def test_grid_interpolate_uniform_matches_scivis_and_scipy():
    g = G.uniform_grid((4, 6), spacing=(0.5, 2.0), origin=(1.0, -2.0))
    v = RNG.normal(size=(4, 6))
    xs, ys = 1.0 + 0.5 * np.arange(6), -2.0 + 2.0 * np.arange(4)
    q = np.column_stack([RNG.uniform(1, 3.5, 50), RNG.uniform(-2, 4, 50)])
    ref = RegularGridInterpolator((ys, xs), v)(q[:, ::-1])
    assert np.allclose(G.grid_interpolate(g, v, q), ref)
    with pytest.raises(ValueError, match="no cells"):
        G.grid_interpolate(G.scattered_points(q), v, q)
    with pytest.raises(TypeError, match="Grid"):
        G.grid_interpolate("grid", v, q)


def _closed_form_inverse(quad, p):
    """(u, v) of p in the quad by the quadratic in v (typed from the derivation)."""
    p00, p10, p11, p01 = (np.asarray(c, float) for c in quad)
    e, f, g, h = p10 - p00, p01 - p00, p00 - p10 + p11 - p01, np.asarray(p, float) - p00

    def cross(a, b):
        return a[0] * b[1] - a[1] * b[0]
    k2, k1, k0 = cross(g, f), cross(e, f) + cross(h, g), cross(h, e)
    if abs(k2) < 1e-14:
        vs = [-k0 / k1]
    else:
        disc = math.sqrt(k1 * k1 - 4 * k0 * k2)
        vs = [(-k1 + disc) / (2 * k2), (-k1 - disc) / (2 * k2)]
    for v in vs:
        den = e + g * v
        u = (h[0] - f[0] * v) / den[0] if abs(den[0]) > abs(den[1]) else (h[1] - f[1] * v) / den[1]
        if -1e-9 <= u <= 1 + 1e-9 and -1e-9 <= v <= 1 + 1e-9:
            return u, v
    raise AssertionError("no root inside")


def test_inverse_bilinear_against_the_closed_form():
    quad = [[0.0, 0.0], [3.0, 0.5], [3.5, 2.5], [0.5, 2.0]]
    uv = RNG.uniform(size=(50, 2))
    p00, p10, p11, p01 = (np.array(c) for c in quad)
    u, v = uv[:, :1], uv[:, 1:]
    pts = (1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + u * v * p11 + (1 - u) * v * p01
    got = G.inverse_bilinear(quad, pts)
    assert np.allclose(got, uv, atol=1e-10)
    for p, (a, b) in zip(pts[:10], got[:10]):
        assert np.allclose(_closed_form_inverse(quad, p), (a, b), atol=1e-9)
    # one quad per point (broadcast) and a parallelogram (g = 0)
    quads = np.repeat(np.array(quad)[None], 3, axis=0)
    assert np.allclose(G.inverse_bilinear(quads, pts[:3]), uv[:3])
    assert np.allclose(G.inverse_bilinear([[0, 0], [2, 0], [3, 1], [1, 1]], [[1.5, 0.5]]),
                       [[0.5, 0.5]])
    with pytest.raises(ValueError, match="could not be inverted"):
        G.inverse_bilinear([[0, 0], [1, 0], [1, 0], [0, 0]], [[0.5, 0.5]])
    with pytest.raises(ValueError, match="shape"):
        G.inverse_bilinear([[0, 0], [1, 0], [1, 1]], [[0.5, 0.5]])


def _polar(nr=6, nt=9):
    r, t = np.meshgrid(np.linspace(1, 3, nr), np.linspace(0, np.pi / 2, nt))
    return np.stack([r * np.cos(t), r * np.sin(t)], axis=-1)


def test_curvilinear_interpolation_reproduces_linear_functions():
    xy = _polar()
    f = 2.0 * xy[..., 0] - 3.0 * xy[..., 1] + 1.0
    # points inside the polygonal grid: random (u, v) in random cells
    cells = G.curvilinear_grid(xy).cells
    which = RNG.integers(len(cells), size=300)
    corners = xy.reshape(-1, 2)[cells[which]]
    u, v = RNG.uniform(size=(2, 300, 1))
    pts = ((1 - u) * (1 - v) * corners[:, 0] + u * (1 - v) * corners[:, 1]
           + u * v * corners[:, 2] + (1 - u) * v * corners[:, 3])
    exact = 2.0 * pts[:, 0] - 3.0 * pts[:, 1] + 1.0
    for method in ("bilinear", "triangles"):
        got = G.curvilinear_interpolate(xy, f, pts, method=method)
        assert np.allclose(got, exact, atol=1e-9), method
    # a nonlinear function: the bilinear blend of the cell's corner values with weights (u, v)
    g = xy[..., 0] ** 2
    got = G.curvilinear_interpolate(xy, g, pts)
    gc = g.ravel()[cells[which]]
    blend = ((1 - u[:, 0]) * (1 - v[:, 0]) * gc[:, 0] + u[:, 0] * (1 - v[:, 0]) * gc[:, 1]
             + u[:, 0] * v[:, 0] * gc[:, 2] + (1 - u[:, 0]) * v[:, 0] * gc[:, 3])
    assert np.allclose(got, blend, atol=1e-9)
    with pytest.raises(ValueError, match="outside every cell"):
        G.curvilinear_interpolate(xy, f, [[0.0, 0.0]])
    assert np.isnan(G.curvilinear_interpolate(xy, f, [[0.0, 0.0]], outside=np.nan)[0])


def test_curvilinear_triangles_against_matplotlib():
    from matplotlib.tri import LinearTriInterpolator, Triangulation

    xy = _polar(5, 7)
    values = RNG.normal(size=xy.shape[:2])
    quads = G.curvilinear_grid(xy).cells
    tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    nodes = xy.reshape(-1, 2)
    tri = Triangulation(nodes[:, 0], nodes[:, 1], tris)
    q = np.column_stack([RNG.uniform(0, 3, 400), RNG.uniform(0, 3, 400)])
    ref = np.ma.filled(LinearTriInterpolator(tri, values.ravel())(q[:, 0], q[:, 1]), np.nan)
    got = G.curvilinear_interpolate(xy, values, q, method="triangles", outside=np.nan)
    assert np.array_equal(np.isnan(got), np.isnan(ref))
    assert np.allclose(got[~np.isnan(got)], ref[~np.isnan(ref)], atol=1e-10)
    got2 = G.triangle_interpolate(nodes, tris, values.ravel(), q, outside=np.nan)
    assert np.allclose(got2, got, equal_nan=True)


def test_curvilinear_bilinear_on_an_axis_parallel_lattice_is_scipys():
    x, y = np.array([0.0, 1.0, 3.0, 4.0]), np.array([0.0, 2.0, 2.5])
    X, Y = np.meshgrid(x, y)
    v = RNG.normal(size=(3, 4, 2))
    q = np.column_stack([RNG.uniform(0, 4, 100), RNG.uniform(0, 2.5, 100)])
    ref = RegularGridInterpolator((y, x), v)(q[:, ::-1])
    got = G.curvilinear_interpolate(np.stack([X, Y], -1), v, q)
    assert np.allclose(got, ref, atol=1e-10)


# ---------------------------------------------------------------------------------------------
# Scattered data
# ---------------------------------------------------------------------------------------------

def _franke(x, y):
    return (0.75 * np.exp(-((9 * x - 2) ** 2 + (9 * y - 2) ** 2) / 4)
            + 0.75 * np.exp(-(9 * x + 1) ** 2 / 49 - (9 * y + 1) / 10)
            + 0.5 * np.exp(-((9 * x - 7) ** 2 + (9 * y - 3) ** 2) / 4)
            - 0.2 * np.exp(-(9 * x - 4) ** 2 - (9 * y - 7) ** 2))


def _sample(n, seed=0):
    rng = np.random.default_rng(seed)
    p = rng.uniform(size=(n, 2))
    return p, _franke(p[:, 0], p[:, 1])


def test_scattered_data_rules():
    p, v = S.scattered_data([[0, 0], [1, 1], [0, 0], [2, 0], [1, 1]], [1, 2, 1, 3, 2])
    assert p.tolist() == [[0, 0], [1, 1], [2, 0]] and v.tolist() == [1, 2, 3]
    with pytest.raises(ValueError, match="points 1 and 4 are the same position"):
        S.scattered_data([[0, 0], [1, 1], [0, 0], [2, 0], [1, 1]], [1, 2, 1, 3, 9])
    with pytest.raises(ValueError, match=r"values contains NaN .* at index \(1,\)"):
        S.scattered_data([[0, 0], [1, 1]], [1.0, np.nan])
    with pytest.raises(ValueError, match="points contains NaN"):
        S.scattered_data([[0, 0], [np.nan, 1]], [1.0, 2.0])
    with pytest.raises(ValueError, match="one entry .* per point: 2 points"):
        S.scattered_data([[0, 0], [1, 1]], [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"shape \(n, 2\) or \(n, 3\)"):
        S.scattered_data([1.0, 2.0], [1.0, 2.0])
    with pytest.raises(TypeError, match="values must be numbers"):
        S.scattered_data([[0, 0]], "a")
    # every method applies the rule
    for method in S.SCATTERED_METHODS:
        with pytest.raises(ValueError, match="same position"):
            S.scattered_interpolate([[0, 0], [1, 0], [0, 1], [0, 0]], [1, 2, 3, 4], [[0.2, 0.2]],
                                    method)


@pytest.mark.parametrize("seed", range(4))
def test_delaunay_matches_scipy(seed):
    p, _ = _sample(60 + 40 * seed, seed)
    ours = S.delaunay_triangulation(p)
    ref = Delaunay(p).simplices
    assert {tuple(sorted(t)) for t in ours.tolist()} == {tuple(sorted(t)) for t in ref.tolist()}
    a, b, c = p[ours[:, 0]], p[ours[:, 1]], p[ours[:, 2]]
    cross = (b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0]
    assert np.all(cross > 0)                                   # counter-clockwise


def _area(p, tris):
    a, b, c = p[tris[:, 0]], p[tris[:, 1]], p[tris[:, 2]]
    return 0.5 * np.abs((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])


def test_delaunay_of_cocircular_grid_points_is_a_delaunay_triangulation():
    X, Y = np.meshgrid(np.arange(5.0), np.arange(4.0))
    p = np.column_stack([X.ravel(), Y.ravel()])
    p = p[RNG.permutation(len(p))]
    tris = S.delaunay_triangulation(p)
    area = _area(p, tris)
    assert np.all(area > 0) and math.isclose(area.sum(), ConvexHull(p).volume)
    for a, b, c in p[tris]:                          # no point strictly inside a circumcircle
        lifted = np.stack([np.c_[x - p, np.sum((x - p) ** 2, axis=1)] for x in (a, b, c)],
                          axis=1)                    # (n, 3, 3): the incircle determinant
        assert np.all(np.linalg.det(lifted) <= 1e-9)
    with pytest.raises(ValueError, match="one line"):
        S.delaunay_triangulation([[0, 0], [1, 1], [2, 2], [3, 3]])
    with pytest.raises(ValueError, match="distinct"):
        S.delaunay_triangulation([[0, 0], [1, 0], [0, 1], [0, 0]])
    with pytest.raises(ValueError, match="n >= 3"):
        S.delaunay_triangulation([[0, 0], [1, 0]])


def test_delaunay_with_collinear_points_on_the_hull():
    p = np.array([[0, 0], [1, 0], [2, 0], [3, 0], [1.5, 2], [0.5, 1], [2.5, 1]], float)
    tris = S.delaunay_triangulation(p)
    area = _area(p, tris)
    assert np.all(area > 1e-12) and math.isclose(area.sum(), ConvexHull(p).volume)
    assert set(np.unique(tris)) == set(range(len(p)))


def test_linear_and_nearest_against_griddata():
    p, f = _sample(200, 5)
    q = RNG.uniform(-0.2, 1.2, size=(1500, 2))
    ours = S.linear_interpolate(p, f, q, outside=np.nan)
    ref = griddata(p, f, q, method="linear")
    assert np.array_equal(np.isnan(ours), np.isnan(ref))
    assert np.allclose(ours[~np.isnan(ours)], ref[~np.isnan(ref)], atol=1e-12)
    assert np.array_equal(S.nearest_interpolate(p, f, q), griddata(p, f, q, method="nearest"))
    with pytest.raises(ValueError, match="outside every triangle"):
        S.linear_interpolate(p, f, q)
    # vector values and a given triangulation
    vec = np.column_stack([f, 2 * f])
    inside = q[~np.isnan(ref)]
    got = S.linear_interpolate(p, vec, inside, triangles=Delaunay(p).simplices)
    assert np.allclose(got[:, 1], 2 * got[:, 0]) and np.allclose(got[:, 0], ref[~np.isnan(ref)])
    # nearest: a tie goes to the point given first
    assert S.nearest_interpolate([[0, 0], [2, 0]], [5.0, 7.0], [[1, 0]])[0] == 5.0
    assert S.nearest_interpolate([[2, 0], [0, 0]], [7.0, 5.0], [[1, 0]])[0] == 7.0


def _shepard_loop(p, f, q, power, radius=None):
    """Shepard by the formula, one query at a time."""
    out = []
    for x in q:
        d = np.sqrt(np.sum((p - x) ** 2, axis=1))
        if np.any(d == 0):
            out.append(f[np.argmin(d)])
            continue
        if radius is None:
            w = 1.0 / d ** power
        else:
            w = (np.maximum(radius - d, 0) / (radius * d)) ** power
        out.append(np.sum(w * f) / np.sum(w))
    return np.array(out)


@pytest.mark.parametrize("power", [0.5, 1.0, 2.0, 3.0, 8.0])
def test_shepard_global_against_the_formula(power):
    p, f = _sample(150, 6)
    q = np.vstack([RNG.uniform(-0.3, 1.3, size=(300, 2)), p[:5]])
    got = S.shepard_interpolate(p, f, q, power=power)
    assert np.allclose(got, _shepard_loop(p, f, q, power), rtol=1e-12, atol=1e-12)
    assert np.allclose(got[-5:], f[:5])                        # interpolates
    assert f.min() - 1e-12 <= got.min() and got.max() <= f.max() + 1e-12


def test_shepard_by_hand_and_limits(monkeypatch):
    # d = 1, 2, 4 and power 2: weights 1, 1/4, 1/16
    got = S.shepard_interpolate([[1, 0], [0, 2], [-4, 0]], [7.0, 3.0, 1.0], [[0, 0]], power=2)
    assert math.isclose(got[0], (7 + 3 / 4 + 1 / 16) / (1 + 1 / 4 + 1 / 16))
    p, f = _sample(100, 7)
    q = RNG.uniform(size=(200, 2))
    # a large power approaches nearest neighbour; huge powers do not overflow
    sharp = S.shepard_interpolate(p, f, q, power=400)
    d = np.sort(np.sqrt(np.sum((q[:, None] - p[None]) ** 2, axis=2)), axis=1)
    clear = d[:, 1] > 1.1 * d[:, 0]                     # (d1/d2)^400 < 1e-16
    assert np.isfinite(sharp).all() and clear.sum() > 150
    assert np.allclose(sharp[clear], griddata(p, f, q[clear], "nearest"), atol=1e-9)
    # the chunked distance matrix gives the same result as one chunk
    whole = S.shepard_interpolate(p, f, q)
    monkeypatch.setattr(S, "_CHUNK", 250)
    assert np.allclose(S.shepard_interpolate(p, f, q), whole, rtol=1e-13)
    # vector values: per component
    two = S.shepard_interpolate(p, np.column_stack([f, -f]), q)
    assert np.allclose(two[:, 0], whole) and np.allclose(two[:, 1], -whole)
    for bad in (0, -1, np.nan):
        with pytest.raises(ValueError, match="power must be positive|power must be finite"):
            S.shepard_interpolate(p, f, q, power=bad)


def test_shepard_local_against_the_formula():
    p, f = _sample(300, 8)
    q = RNG.uniform(size=(400, 2))
    for power in (1.0, 2.0):
        got = S.shepard_interpolate(p, f, q, power=power, radius=0.2)
        assert np.allclose(got, _shepard_loop(p, f, q, power, radius=0.2), atol=1e-12)
    at = S.shepard_interpolate(p, f, p[:4], radius=0.1)
    assert np.allclose(at, f[:4])
    far = [[5.0, 5.0]]
    with pytest.raises(ValueError, match="no data point within radius"):
        S.shepard_interpolate(p, f, far, radius=0.1)
    assert S.shepard_interpolate(p, f, far, radius=0.1, outside=-9.0)[0] == -9.0
    with pytest.raises(ValueError, match="radius must be positive"):
        S.shepard_interpolate(p, f, q, radius=0)


@pytest.mark.parametrize("kernel, eps, degree", [
    ("gaussian", 12.0, -1), ("gaussian", 12.0, 0), ("gaussian", 12.0, 1),
    ("multiquadric", 4.0, -1), ("multiquadric", 4.0, 1),
    ("inverse_multiquadric", 6.0, -1), ("inverse_multiquadric", 6.0, 0),
    ("thin_plate_spline", 1.0, 1),
])
def test_rbf_global_against_scipy(kernel, eps, degree):
    p, f = _sample(80, 9)
    q = RNG.uniform(size=(300, 2))
    ref = RBFInterpolator(p, f, kernel=kernel, epsilon=eps, degree=degree)(q)
    got = S.rbf_interpolate(p, f, q, kernel, eps, degree)
    assert np.allclose(got, ref, atol=1e-8)
    assert np.allclose(S.rbf_interpolate(p, f, p, kernel, eps, degree), f, atol=1e-8)


@pytest.mark.parametrize("kernel, eps, degree", [
    ("gaussian", 30.0, -1), ("multiquadric", 10.0, 0), ("inverse_multiquadric", 15.0, 1),
    ("thin_plate_spline", 1.0, 1),
])
def test_rbf_local_against_scipy_neighbors(kernel, eps, degree):
    p, f = _sample(400, 10)
    q = RNG.uniform(size=(500, 2))
    ref = RBFInterpolator(p, f, kernel=kernel, epsilon=eps, degree=degree, neighbors=15)(q)
    got = S.rbf_interpolate(p, f, q, kernel, eps, degree, neighbors=15)
    assert np.allclose(got, ref, atol=1e-7)


def test_rbf_system_by_hand_and_properties():
    # two centres, Gaussian with eps = 1 at distance 1: A = [[1, a], [a, 1]], a = e^-1
    a = math.exp(-1)
    m = S.rbf_fit([[0, 0], [1, 0]], [2.0, 5.0], "gaussian", 1.0)
    lam = np.linalg.solve([[1, a], [a, 1]], [2.0, 5.0])
    assert np.allclose(m.weights[:, 0], lam)
    assert math.isclose(S.rbf_evaluate(m, [[0.5, 0]])[0], (lam[0] + lam[1]) * math.exp(-0.25))
    # the thin-plate spline with its linear term reproduces planes and ignores epsilon
    p, _ = _sample(30, 11)
    plane = 3 * p[:, 0] - 2 * p[:, 1] + 0.5
    q = RNG.uniform(size=(50, 2))
    for eps in (0.5, 3.0):
        got = S.rbf_interpolate(p, plane, q, "thin_plate_spline", eps)
        assert np.allclose(got, 3 * q[:, 0] - 2 * q[:, 1] + 0.5, atol=1e-9)
    # kernels typed from their definitions
    r = np.array([0.0, 0.3, 1.0, 2.5])
    s = 2.0 * r
    expect = {"gaussian": np.exp(-s ** 2), "multiquadric": np.sqrt(1 + s ** 2),
              "inverse_multiquadric": 1 / np.sqrt(1 + s ** 2),
              "thin_plate_spline": np.r_[0.0, s[1:] ** 2 * np.log(s[1:])]}
    for name, values in expect.items():
        assert np.allclose(S.rbf_kernel(r, name, 2.0), values)
    # vector values keep their axis
    two = S.rbf_interpolate(p, np.column_stack([plane, plane]), q[:3], "thin_plate_spline")
    assert two.shape == (3, 2)


def test_rbf_errors():
    p, f = _sample(40, 12)
    q = [[0.5, 0.5]]
    with pytest.raises(ValueError, match="kernel must be one of"):
        S.rbf_interpolate(p, f, q, "cubic")
    with pytest.raises(ValueError, match="epsilon must be positive"):
        S.rbf_interpolate(p, f, q, "gaussian", 0.0)
    with pytest.raises(ValueError, match="needs the linear polynomial term"):
        S.rbf_interpolate(p, f, q, "thin_plate_spline", degree=0)
    with pytest.raises(ValueError, match="degree must be -1"):
        S.rbf_interpolate(p, f, q, "gaussian", degree=2)
    with pytest.raises(TypeError, match="degree"):
        S.rbf_interpolate(p, f, q, "gaussian", degree=True)
    with pytest.raises(ValueError, match="ill-conditioned"):
        S.rbf_interpolate(p, f, q, "gaussian", 0.01)          # nearly flat bumps
    with pytest.raises(ValueError, match="neighbors must be between 3"):
        S.rbf_interpolate(p, f, q, "thin_plate_spline", neighbors=2)
    with pytest.raises(ValueError, match="not all lie on a line|ill-conditioned"):
        S.rbf_interpolate([[0, 0], [1, 1], [2, 2], [3, 3]], [0, 1, 2, 3], q,
                          "thin_plate_spline")
    many = np.random.default_rng(0).uniform(size=(S.MAX_GLOBAL_RBF_CENTRES + 1, 2))
    with pytest.raises(ValueError, match="Pass neighbors=k"):
        S.rbf_fit(many, many[:, 0])
    with pytest.raises(TypeError, match="RBFModel"):
        S.rbf_evaluate("model", q)


def test_resample_to_grid_and_gradient_magnitude():
    p, f = _sample(250, 13)
    grid_values, grid = S.resample_to_grid(p, f, (30, 40), extent=(0, 1, 0, 1), method="linear",
                                           outside=np.nan)
    X, Y = np.meshgrid(np.linspace(0, 1, 40), np.linspace(0, 1, 30))
    ref = griddata(p, f, (X, Y), method="linear")
    assert np.allclose(grid_values, ref, equal_nan=True)
    assert np.allclose(grid.stored["spacing"], [1 / 39, 1 / 29])
    g, grid = S.resample_to_grid(p, f, (20, 20), method="nearest")
    assert np.allclose(grid.stored["origin"], p.min(axis=0))
    with pytest.raises(ValueError, match="NaN .* convex hull"):
        S.gradient_magnitude(grid_values, (1 / 39, 1 / 29))
    # gradient of a smooth field against numpy and against the exact derivative
    x, y = np.linspace(0, 1, 81), np.linspace(0, 1, 61)
    X, Y = np.meshgrid(x, y)
    F = np.sin(3 * X) * np.cos(2 * Y)
    gy, gx = np.gradient(F, y, x)
    got = S.gradient_magnitude(F, (x[1] - x[0], y[1] - y[0]))
    assert np.allclose(got, np.hypot(gx, gy), atol=1e-12)
    exact = np.hypot(3 * np.cos(3 * X) * np.cos(2 * Y), -2 * np.sin(3 * X) * np.sin(2 * Y))
    assert np.abs(got - exact)[1:-1, 1:-1].max() < 2e-3
    with pytest.raises(ValueError, match="extent"):
        S.resample_to_grid(p, f, (4, 4), extent=(1, 0, 0, 1))
    with pytest.raises(TypeError, match="takes the options"):
        S.resample_to_grid(p, f, (4, 4), method="nearest", power=2)
    with pytest.raises(ValueError, match="method must be one of"):
        S.resample_to_grid(p, f, (4, 4), method="kriging")


def test_searches_against_brute_force():
    data = RNG.uniform(size=(500, 3))
    query = RNG.uniform(-0.1, 1.1, size=(200, 3))
    full = np.sum((query[:, None] - data[None]) ** 2, axis=2)
    idx, d2 = _buckets._k_nearest(data, query, 6)
    assert np.array_equal(idx, np.argsort(full, axis=1, kind="stable")[:, :6])
    qi, pj, _ = _buckets._pairs_within(data, query, 0.15)
    assert len(qi) == np.count_nonzero(full <= 0.15 ** 2) and np.all(full[qi, pj] <= 0.0225)
    # 3D data through the public functions
    f = data.sum(axis=1)
    assert np.array_equal(S.nearest_interpolate(data, f, query), f[idx[:, 0]])
    got = S.shepard_interpolate(data, f, query, power=2)
    assert np.allclose(got, _shepard_loop(data, f, query, 2.0))
