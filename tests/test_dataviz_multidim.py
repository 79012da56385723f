"""Tests of course_lib.dataviz.multidim and .projection (textbook 10.7): parallel coordinates,
the point-line duality, the polyline raster, scatterplot matrices, brushing, glyphs and PCA.

Independent references: the duality against the intersection of two of the dual lines solved
with numpy.linalg.solve; the raster against a dense sampling of the segments; histograms,
brushes and normalisation against plain Python loops; PCA against numpy's SVD, numpy.cov,
numpy.corrcoef and scipy.linalg.eigh (and scikit-learn's PCA when it is installed)."""
import math

import numpy as np
import pytest
import scipy.linalg

from course_lib.dataviz import multidim as md
from course_lib.dataviz import projection as pj

RNG = np.random.default_rng(1907)


# ---------------------------------------------------------------------------------------------
# Data sets
# ---------------------------------------------------------------------------------------------

def test_data_sets_are_seeded_and_shaped():
    a, b = md.cars_table(seed=3), md.cars_table(seed=3)
    assert np.array_equal(a.data, b.data) and a.names == b.names
    assert not np.array_equal(a.data, md.cars_table(seed=4).data)
    assert set(np.unique(a.data[:, 1])) <= {4.0, 6.0, 8.0}
    assert a.data[:, 5].min() >= 70 and a.data[:, 5].max() <= 82
    w = md.weather_table()
    assert w.data.shape == (10_000, 5) and len(w.names) == 5
    assert np.isfinite(w.data).all() and (w.data[:, 4] >= 0).all()
    gallery = md.correlation_gallery()
    assert tuple(gallery) == md.GALLERY
    assert all(t.data.shape == (200, 2) and t.names == ("x", "y") for t in gallery.values())


def test_gallery_relations():
    g = md.correlation_gallery(n=2000, seed=5)
    r = {k: np.corrcoef(t.data.T)[0, 1] for k, t in g.items()}
    assert r["positive"] > 0.85 and r["negative"] < -0.85 and abs(r["none"]) < 0.1
    assert abs(r["non-linear"]) < 0.1
    x, y = g["non-linear"].data.T
    assert np.corrcoef(x * x, y)[0, 1] > 0.9            # a strong relation, not linear


# ---------------------------------------------------------------------------------------------
# Parallel coordinates
# ---------------------------------------------------------------------------------------------

def test_normalise_columns_against_a_loop():
    data = RNG.normal(size=(30, 4)) * [1, 10, 100, 0.1] + [0, 5, -50, 2]
    out = md.normalise_columns(data)
    for i in range(30):
        for k in range(4):
            lo, hi = min(data[:, k]), max(data[:, k])
            assert math.isclose(out[i, k], (data[i, k] - lo) / (hi - lo), abs_tol=1e-12)
    const = md.normalise_columns([[1.0, 2.0], [1.0, 3.0]])
    assert const[:, 0].tolist() == [0.5, 0.5]
    assert md.column_ranges(data).tolist() == [[min(c), max(c)] for c in data.T]


def test_parallel_coordinates_layout_order_and_flip():
    data = np.array([[1.0, 10.0, 100.0], [3.0, 30.0, 300.0], [2.0, 40.0, 200.0]])
    names = ("a", "b", "c")
    lines = md.parallel_coordinates(data, order=["c", "a", "b"], flip=["a"], names=names)
    assert lines.shape == (3, 3, 2)
    assert np.array_equal(lines[..., 0], np.tile([0.0, 1.0, 2.0], (3, 1)))
    # record 1: c = 300 -> 1; a = 3 -> 1, flipped 0; b = 30 -> 2/3
    assert np.allclose(lines[1, :, 1], [1.0, 0.0, 2 / 3])
    assert np.allclose(lines[2, :, 1], [0.5, 0.5, 1.0])
    with pytest.raises(ValueError, match="exactly once"):
        md.parallel_coordinates(data, order=[0, 0, 1])
    with pytest.raises(ValueError, match="not an attribute"):
        md.parallel_coordinates(data, order=["c", "a", "x"], names=names)


@pytest.mark.parametrize("m, c", [(-2.0, 5.0), (-0.3, 1.0), (0.5, 2.0), (2.5, -1.0), (1.7, 0.3)])
def test_dual_point_is_where_the_dual_lines_meet(m, c):
    x_range, y_range = (-1.0, 4.0), (-6.0, 9.0)
    xs = np.array([-0.5, 0.7, 2.9])
    slopes, intercepts = md.dual_line(np.column_stack([xs, m * xs + c]), x_range, y_range)
    # intersect the first two lines: v = i0 + s0 u = i1 + s1 u, solved independently
    u, v = np.linalg.solve([[slopes[0], -1.0], [slopes[1], -1.0]], [-intercepts[0], -intercepts[1]])
    assert (u, v) == pytest.approx(md.dual_point(m, c, x_range, y_range))
    assert intercepts[2] + slopes[2] * u == pytest.approx(v)          # the third line too
    # the closed form 1 / (1 - m') with m' = m * 5 / 15
    m_n = m * 5.0 / 15.0
    assert md.normalised_slope(m, x_range, y_range) == pytest.approx(m_n)
    assert u == pytest.approx(1 / (1 - m_n))
    assert (0 < u < 1) == (m < 0)                      # between the axes exactly when negative


def test_dual_line_passes_through_the_two_axis_values():
    s, i = md.dual_line([3.0, 7.0], (1.0, 5.0), (5.0, 9.0))
    assert i == pytest.approx(0.5) and i + s == pytest.approx(0.5)
    with pytest.raises(ValueError, match="parallel"):
        md.dual_point(1.0, 0.0)
    with pytest.raises(ValueError, match="low < high"):
        md.dual_line([0, 0], x_range=(1, 1))
    with pytest.raises(TypeError, match="m must be a number"):
        md.dual_point("1", 0)


# ---------------------------------------------------------------------------------------------
# The polyline raster
# ---------------------------------------------------------------------------------------------

def _dense_pixels(p, q, w, h):
    """Pixels a segment passes through, by sampling it a million times."""
    t = np.linspace(0, 1, 1_000_001)
    x = p[0] + (q[0] - p[0]) * t
    y = p[1] + (q[1] - p[1]) * t
    col = np.clip(np.floor(x * w), 0, w - 1).astype(int)
    row = np.clip(np.floor(y * h), 0, h - 1).astype(int)
    return set(zip(row.tolist(), col.tolist()))


def test_raster_matches_dense_sampling():
    w, h = 37, 23
    for _ in range(20):
        y0, y1 = RNG.uniform(0.001, 0.999, 2)
        counts = md.rasterize_polylines([[[0.0, y0], [1.0, y1]]], w, h)
        ours = {(int(r), int(c)) for r, c in np.argwhere(counts)}
        dense = _dense_pixels((0.0, y0), (1.0, y1), w, h)
        assert counts.max() == 1
        assert len(ours ^ dense) <= 2, (y0, y1, ours ^ dense)    # at most the corner cases


def test_raster_of_polylines_masks_and_complement():
    data = RNG.normal(size=(301, 4))
    lines = md.parallel_coordinates(data)
    raster = md.PolylineRaster(lines, 60, 40)
    total = raster.counts()
    per_line = [md.rasterize_polylines(lines[i:i + 1], 60, 40) for i in range(301)]
    assert np.array_equal(total, np.sum(per_line, axis=0))
    for share in (0.1, 0.7):                    # few selected, and most (the complement path)
        mask = RNG.uniform(size=301) < share
        expected = np.sum([per_line[i] for i in np.flatnonzero(mask)], axis=0)
        assert np.array_equal(raster.counts(mask), expected)
    # every polyline crosses every column once at least: a connected, gap-free line
    assert (per_line[0].sum(axis=0) >= 1).all()
    with pytest.raises(ValueError, match="mask must be 301 booleans"):
        raster.counts(np.ones(3, bool))
    with pytest.raises(ValueError, match="share their x"):
        md.PolylineRaster([[[0, 0], [1, 1]], [[0, 0], [2, 1]]], 4, 4)


# ---------------------------------------------------------------------------------------------
# Scatterplot matrix
# ---------------------------------------------------------------------------------------------

def test_scatterplot_matrix_panels():
    cars = md.Table(RNG.uniform(size=(40, 4)) * [1, 10, 100, 3], ("a", "b", "c", "d"))
    panels = md.scatterplot_matrix(cars.data, cars.names, bins=5)
    d = len(cars.names)
    assert len(panels) == d * d
    y = md.normalise_columns(cars.data)
    for p in panels:
        r, c = p["row"], p["col"]
        if r == c:
            column = cars.data[:, r]
            lo, hi = column.min(), column.max()
            width = (hi - lo) / 5
            expected = [0] * 5
            for v in column:
                expected[min(int((v - lo) / width), 4)] += 1
            assert p["kind"] == "histogram" and p["counts"].tolist() == expected
            assert p["name"] == cars.names[r]
        else:
            assert p["kind"] == "scatter"
            assert np.allclose(p["points"], np.column_stack([y[:, c], y[:, r]]))
    named = md.scatterplot_matrix(cars.data, cars.names, diagonal="names")
    assert [p["name"] for p in named if p["kind"] == "name"] == list(cars.names)
    with pytest.raises(ValueError, match="diagonal must be one of"):
        md.scatterplot_matrix(cars.data, diagonal="boxes")


# ---------------------------------------------------------------------------------------------
# Brushing
# ---------------------------------------------------------------------------------------------

def test_brushes_against_loops():
    cars = md.cars_table(n=80, seed=7)
    names = cars.names
    brushes = [{"weight": (1500, 1900)}, {"mpg": (25, 40), "year": (78, 82)}]
    both = md.brush_mask(cars.data, brushes, "and", names)
    either = md.brush_mask(cars.data, brushes, "OR", names)
    for i, row in enumerate(cars.data):
        first = 1500 <= row[3] <= 1900
        second = 25 <= row[0] <= 40 and 78 <= row[5] <= 82
        assert both[i] == (first and second) and either[i] == (first or second)
    assert md.brush_mask(cars.data, [], names=names).all()
    rect = md.rectangle_brush(cars.data, "weight", "mpg", (1500, 1900), (20, 30), names)
    assert np.array_equal(rect, md.range_brush(cars.data, 3, 1500, 1900)
                          & md.range_brush(cars.data, 0, 20, 30))


def test_brush_bounds_are_included():
    data = [[1.0], [2.0], [3.0]]
    assert md.range_brush(data, 0, 1.0, 2.0).tolist() == [True, True, False]


@pytest.mark.parametrize("call, error, words", [
    (lambda d: md.range_brush(d, "mass", 0, 1, names=("a", "b")), ValueError, "not an attribute"),
    (lambda d: md.range_brush(d, 5, 0, 1), ValueError, "out of range"),
    (lambda d: md.range_brush(d, 1.0, 0, 1), TypeError, "whole-number index"),
    (lambda d: md.range_brush(d, True, 0, 1), TypeError, "whole-number index"),
    (lambda d: md.range_brush(d, 0, 2, 2), ValueError, "empty"),
    (lambda d: md.range_brush(d, 0, 3, 1), ValueError, "reversed"),
    (lambda d: md.range_brush(d, 0, 0, np.nan), ValueError, "finite"),
    (lambda d: md.range_brush(np.array([[1.0, np.nan]]), 0, 0, 1), ValueError, "NaN"),
    (lambda d: md.range_brush("table", 0, 0, 1), TypeError, "table of numbers"),
    (lambda d: md.brush_mask(d, [{}]), TypeError, "non-empty mapping"),
    (lambda d: md.brush_mask(d, [{0: (1, 2)}], how="xor"), ValueError, "how must be one of"),
    (lambda d: md.combine_brushes([[True], [True, False]]), ValueError, "one length"),
    (lambda d: md.rectangle_brush(d, 0, 1, (0, 1), (2, 1)), ValueError, "y_range is reversed"),
])
def test_brush_errors(call, error, words):
    with pytest.raises(error, match=words):
        call(np.array([[0.5, 1.5], [1.0, 2.0]]))


# ---------------------------------------------------------------------------------------------
# Glyphs
# ---------------------------------------------------------------------------------------------

def test_star_glyph_vertices_and_area():
    v = RNG.uniform(size=(5, 7))
    poly = md.star_glyph(v)
    for i in range(5):
        for k in range(7):
            a = math.pi / 2 + 2 * math.pi * k / 7
            assert poly[i, k] == pytest.approx([v[i, k] * math.cos(a), v[i, k] * math.sin(a)])
        x, y = poly[i].T
        shoelace = 0.5 * abs(x @ np.roll(y, -1) - y @ np.roll(x, -1))
        closed_form = 0.5 * math.sin(2 * math.pi / 7) * float(v[i] @ np.roll(v[i], -1))
        assert shoelace == pytest.approx(closed_form)
    with pytest.raises(ValueError, match="normalised"):
        md.star_glyph([0.2, 1.5, 0.3])
    with pytest.raises(ValueError, match="d >= 3"):
        md.star_glyph([0.2, 0.5])


def test_chernoff_mapping_and_face():
    cars = md.cars_table(n=10, seed=1)
    mapping = {"mouth curve": "mpg", "face width": "weight", "eye size": 2}
    p = md.chernoff_parameters(cars.data, cars.names, mapping)
    y = md.normalise_columns(cars.data)
    f = md.CHERNOFF_FEATURES
    assert np.allclose(p[:, f.index("mouth curve")], y[:, 0])
    assert np.allclose(p[:, f.index("face width")], y[:, 3])
    assert np.allclose(p[:, f.index("eye size")], y[:, 2])
    assert np.allclose(p[:, f.index("nose length")], 0.5)
    default = md.chernoff_parameters(cars.data)
    assert np.allclose(default[:, :6], y)
    narrow, wide = md.chernoff_face(np.r_[0.0, [0.5] * 7]), md.chernoff_face(np.r_[1.0, [0.5] * 7])
    assert np.ptp(wide["face"][:, 0]) > np.ptp(narrow["face"][:, 0])
    with pytest.raises(ValueError, match="feature must be one of"):
        md.chernoff_parameters(cars.data, cars.names, {"ears": 0})
    with pytest.raises(ValueError, match="params must be 8 numbers"):
        md.chernoff_face([0.5] * 3)


# ---------------------------------------------------------------------------------------------
# PCA
# ---------------------------------------------------------------------------------------------

def _table(n=60, d=4, seed=3):
    rng = np.random.default_rng(seed)
    mixing = rng.normal(size=(d, d)) * np.linspace(3, 0.5, d)
    return rng.normal(size=(n, d)) @ mixing.T + rng.normal(size=d) * 10


@pytest.mark.parametrize("ddof", [0, 1])
def test_covariance_against_numpy(ddof):
    data = _table()
    assert np.allclose(pj.covariance_matrix(data, ddof), np.cov(data.T, ddof=ddof))


def test_pca_against_svd_and_scipy():
    data = _table()
    r = pj.pca(data)
    centred = data - data.mean(axis=0)
    _, s, vt = np.linalg.svd(centred, full_matrices=False)
    assert np.allclose(r.eigenvalues, s ** 2 / (len(data) - 1))
    for j in range(data.shape[1]):                    # the same axes up to sign
        assert abs(abs(r.components[:, j] @ vt[j]) - 1) < 1e-9
    w, v = scipy.linalg.eigh(np.cov(data.T))
    assert np.allclose(r.eigenvalues, w[::-1])
    assert np.allclose(np.abs(r.components), np.abs(v[:, ::-1]))
    assert np.allclose(r.explained_variance_ratio, w[::-1] / w.sum())
    # orthonormal axes, scores reconstruct the data, projection agrees
    assert np.allclose(r.components.T @ r.components, np.eye(4))
    assert np.allclose(r.scores @ r.components.T + r.mean, data)
    assert np.allclose(pj.pca_project(data, r), r.scores)
    # the scores' variances are the eigenvalues, uncorrelated
    assert np.allclose(np.cov(r.scores.T), np.diag(r.eigenvalues))


def test_pca_signs_are_deterministic():
    data = _table(seed=8)
    r = pj.pca(data, k=2)
    for j in range(2):
        col = r.components[:, j]
        assert col[np.argmax(np.abs(col))] > 0
    flipped = pj.pca(-data, k=2)                      # the same axes, the same signs
    assert np.allclose(flipped.components, r.components)
    assert np.allclose(flipped.scores, -r.scores)


def test_pca_standardised_is_pca_of_correlations():
    data = _table(seed=11) * [1, 100, 0.01, 5]
    r = pj.pca(data, standardise=True)
    w = np.linalg.eigvalsh(np.corrcoef(data.T))[::-1]
    assert np.allclose(r.eigenvalues, w)
    assert np.allclose(r.scale, data.std(axis=0, ddof=1))


def test_pca_ddof_changes_eigenvalues_only():
    data = _table(n=12)
    a, b = pj.pca(data, ddof=1), pj.pca(data, ddof=0)
    assert np.allclose(a.eigenvalues * 11 / 12, b.eigenvalues)
    assert np.allclose(a.components, b.components)
    assert np.allclose(a.explained_variance_ratio, b.explained_variance_ratio)


def test_pca_by_hand():
    # x = 1..5, y = (1, 3, 2, 4, 5): centred sums Sxx = Syy = 10, Sxy = 9, covariance over 4
    r = pj.pca([[1, 1], [2, 3], [3, 2], [4, 4], [5, 5]], k=1)
    assert r.eigenvalues.tolist() == pytest.approx([19 / 4, 1 / 4])
    assert r.components[:, 0] == pytest.approx([1 / math.sqrt(2)] * 2)
    assert r.scores[0, 0] == pytest.approx(-4 / math.sqrt(2))


def test_pca_against_scikit_learn():
    sklearn = pytest.importorskip("sklearn.decomposition")
    data = _table()
    ours = pj.pca(data, k=3)
    theirs = sklearn.PCA(n_components=3).fit(data)
    assert np.allclose(ours.eigenvalues[:3], theirs.explained_variance_)
    assert np.allclose(np.abs(ours.components.T), np.abs(theirs.components_))


def test_pca_errors():
    with pytest.raises(ValueError, match="k must be at most"):
        pj.pca(_table(), k=5)
    with pytest.raises(ValueError, match="attribute 1 is constant"):
        pj.pca([[1, 2], [2, 2], [3, 2]], standardise=True)
    with pytest.raises(ValueError, match="ddof = 1 needs more than 1 records"):
        pj.covariance_matrix([[1, 2]])
    with pytest.raises(ValueError, match="NaN"):
        pj.pca([[1, 2], [np.nan, 2]])
    with pytest.raises(ValueError, match="symmetric"):
        pj.principal_axes([[1, 2], [0, 1]])
    with pytest.raises(ValueError, match="positive semi-definite"):
        pj.principal_axes([[1, 2], [2, 1]])
    with pytest.raises(ValueError, match="the 4 attributes"):
        pj.pca_project([[1, 2]], pj.pca(_table()))
