"""Tests of course_lib.scivis (chapter 18: contours, isosurfaces, volume rendering, streamlines).

References used: scikit-image (``measure.find_contours``, ``measure.marching_cubes`` with the
Lewiner and Lorensen methods, ``measure.mesh_surface_area``), scipy (``ndimage.map_coordinates``,
``interpolate.RegularGridInterpolator``, ``integrate.solve_ivp``, ``spatial.transform.Rotation``),
shapely (ray lengths through a box), numpy's ``np.gradient`` and ``np.interp``, closed forms
derived in the comments, and mesh invariants (watertightness, orientation, Euler
characteristic). Nothing is copied from the output of the code under test.

Array convention under test: ``field[i, j]`` is at (x = j, y = i); ``volume[k, j, i]`` at
(x = i, y = j, z = k); scikit-image works in (row, col[, plane]) order, so its points are
reversed before comparing.
"""
import subprocess
import sys
import warnings

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.interpolate import RegularGridInterpolator
from scipy.ndimage import map_coordinates
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation
from shapely.geometry import LineString, box
from skimage import measure

from course_lib import colormaps as CM
from course_lib import scivis as S


def rng(seed):
    return np.random.default_rng(seed)


# ---------------------------------------------------------------------------------------------
# helpers: mesh invariants, written independently of the module
# ---------------------------------------------------------------------------------------------

def directed_edges(tris):
    return np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])


def assert_watertight_and_oriented(tris):
    """Every edge in exactly two triangles, traversed once in each direction."""
    d = directed_edges(tris)
    _, undirected = np.unique(np.sort(d, axis=1), axis=0, return_counts=True)
    assert undirected.min() == 2 and undirected.max() == 2, "an edge is not shared by exactly 2"
    _, directed = np.unique(d, axis=0, return_counts=True)
    assert directed.max() == 1, "two triangles run along an edge in the same direction"


def euler_characteristic(verts, tris):
    n_edges = len(np.unique(np.sort(directed_edges(tris), axis=1), axis=0))
    return len(verts) - n_edges + len(tris)


def signed_volume(verts, tris):
    a, b, c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
    return float(np.sum(a * np.cross(b, c)) / 6.0)


def skimage_mesh(volume, level, spacing, origin, method="lewiner"):
    verts, faces, _, _ = measure.marching_cubes(volume, level, spacing=tuple(spacing[::-1]),
                                                method=method)
    return verts[:, ::-1] + np.asarray(origin), faces


def trilinear_scipy(volume, points, spacing, origin):
    """Trilinear interpolation at (x, y, z) points with scipy (array order z, y, x)."""
    idx = (np.asarray(points) - np.asarray(origin)) / np.asarray(spacing)
    return map_coordinates(volume, idx[:, ::-1].T, order=1, mode="nearest")


# ---------------------------------------------------------------------------------------------
# marching squares
# ---------------------------------------------------------------------------------------------

# the edge midpoints of the unit cell (x, y): bottom, right, top, left
B, R, T, L = (0.5, 0.0), (1.0, 0.5), (0.5, 1.0), (0.0, 0.5)
# crossed edges for each case, worked out by hand from "which corners are cut off"
# (corner 0 bottom left, 1 bottom right, 2 top right, 3 top left; bit k = corner k above)
HAND_TABLE = {
    0: [], 15: [],
    1: [{B, L}], 14: [{B, L}],            # one corner alone
    2: [{B, R}], 13: [{B, R}],
    4: [{R, T}], 11: [{R, T}],
    8: [{T, L}], 7: [{T, L}],
    3: [{L, R}], 12: [{L, R}],            # two neighbouring corners: a straight cut
    6: [{B, T}], 9: [{B, T}],
}


def unit_cell(case, above=1.0, below=0.0):
    corners = [above if (case >> k) & 1 else below for k in range(4)]
    # field[i, j]: corner 0 = [0, 0], 1 = [0, 1], 2 = [1, 1], 3 = [1, 0]
    return np.array([[corners[0], corners[1]], [corners[3], corners[2]]])


def as_point_sets(segments):
    return sorted([{tuple(np.round(p, 12) + 0.0) for p in seg} for seg in segments],
                  key=lambda s: sorted(s))


@pytest.mark.parametrize("case", sorted(HAND_TABLE))
def test_marching_squares_16_cases_against_a_hand_table(case):
    segs = S.marching_squares(unit_cell(case), 0.5)
    expected = sorted(HAND_TABLE[case], key=lambda s: sorted(s))
    assert as_point_sets(segs) == expected
    assert S.marching_squares_cases(unit_cell(case), 0.5)[0, 0] == case


@pytest.mark.parametrize("case", range(16))
def test_marching_squares_segments_keep_the_above_corners_on_their_left(case):
    field = unit_cell(case)
    corners = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    is_above = np.array([(case >> k) & 1 for k in range(4)], bool)
    for start, end in S.marching_squares(field, 0.5):
        d = end - start
        # the corner nearest to the segment's midpoint is the one it cuts off (or one of two)
        side = d[0] * (corners[:, 1] - start[1]) - d[1] * (corners[:, 0] - start[0])
        nearest = np.argmin(np.linalg.norm(corners - (start + end) / 2, axis=1))
        assert (side[nearest] > 0) == is_above[nearest]
        if case not in (5, 10):                   # one segment: every corner on its side
            assert np.all((side > 0) == is_above)


def test_saddles_are_resolved_by_the_midpoint_decider():
    # case 5 (corners 0 and 2 above). Above value 1, below 0: the mean 0.5 >= 0.5, centre
    # above, the above corners are joined and the below corners 1 and 3 are cut off.
    segs = S.marching_squares(unit_cell(5, above=1.0), 0.5)
    assert as_point_sets(segs) == sorted([{B, R}, {T, L}], key=lambda s: sorted(s))
    # above value 0.9: mean 0.45 < 0.5, centre below: corners 0 and 2 are cut off. The
    # crossings lie (0.9 - 0.5) / 0.9 = 4/9 of an edge away from the above corner.
    segs = S.marching_squares(unit_cell(5, above=0.9), 0.5)
    t = 4 / 9
    expected = [{(t, 0.0), (0.0, t)}, {(1.0, 1 - t), (1 - t, 1.0)}]
    assert as_point_sets(segs) == as_point_sets([list(s) for s in expected])
    # case 10 (corners 1 and 3 above), centre above: corners 0 and 2 are cut off
    segs = S.marching_squares(unit_cell(10, above=1.0), 0.5)
    assert as_point_sets(segs) == sorted([{B, L}, {R, T}], key=lambda s: sorted(s))
    segs = S.marching_squares(unit_cell(10, above=0.9), 0.5)
    assert as_point_sets(segs) == as_point_sets([[(1 - t, 0.0), (1.0, t)],
                                                 [(0.0, 1 - t), (t, 1.0)]])
    # the decider itself: the mean of the four corners
    assert S.saddle_centre_above(unit_cell(5, 1.0), 0.5)[0, 0]
    assert not S.saddle_centre_above(unit_cell(5, 0.9), 0.5)[0, 0]


def test_marching_squares_cases_against_a_plain_loop():
    field = rng(10).random((9, 12))
    cases = S.marching_squares_cases(field, 0.4)
    assert cases.shape == (8, 11)
    for i in range(8):
        for j in range(11):
            corners = [field[i, j], field[i, j + 1], field[i + 1, j + 1], field[i + 1, j]]
            assert cases[i, j] == sum(1 << k for k, v in enumerate(corners) if v >= 0.4)


def _segments_by_cell(segs):
    """Unordered segments (rounded end points) grouped by the cell holding their midpoint."""
    cells = {}
    for seg in segs:
        x, y = seg.mean(axis=0)
        key = (int(np.floor(y)), int(np.floor(x)))
        cells.setdefault(key, []).append(tuple(sorted(map(tuple, np.round(seg, 9) + 0.0))))
    return {k: sorted(v) for k, v in cells.items()}


def _skimage_segments(field, level, fully_connected):
    contours = measure.find_contours(field, level, fully_connected=fully_connected)
    segs = np.concatenate([np.stack([c[:-1], c[1:]], axis=1) for c in contours if len(c) > 1])
    keep = np.linalg.norm(segs[:, 1] - segs[:, 0], axis=1) > 0
    return segs[keep][..., ::-1]                    # (row, col) -> (x, y)


@pytest.mark.parametrize("seed", [11, 12, 13])
def test_marching_squares_matches_skimage_find_contours_cell_by_cell(seed):
    """Same segments in every cell. In the saddle cells skimage does not decide by the centre
    value but by a fixed rule (fully_connected="low" or "high"): there we compare with the
    skimage run whose rule agrees with our midpoint decider in that cell."""
    field = rng(seed).random((25, 35))
    level = 0.5
    ours = _segments_by_cell(S.marching_squares(field, level))
    low = _segments_by_cell(_skimage_segments(field, level, "low"))
    high = _segments_by_cell(_skimage_segments(field, level, "high"))
    cases = S.marching_squares_cases(field, level)
    centre_above = S.saddle_centre_above(field, level)
    saddles = 0
    assert set(ours) == set(low) == set(high)
    for cell, segs in ours.items():
        if cases[cell] in (5, 10):
            saddles += 1
            assert segs == (high[cell] if centre_above[cell] else low[cell]), cell
        else:
            assert segs == low[cell] == high[cell], cell
    assert saddles > 10                               # the test really met ambiguous cells


def test_marching_squares_circle_length_and_join():
    f = S.example_field_2d("circle", size=201)
    segs = S.marching_squares(f.values, f.level, f.spacing, f.origin)
    length = np.linalg.norm(segs[:, 1] - segs[:, 0], axis=1).sum()
    assert length == pytest.approx(2 * np.pi * 0.6, rel=2e-4)      # chords: slightly short
    lines = S.isolines(f.values, f.level, f.spacing, f.origin)
    assert len(lines) == 1 and len(lines[0]) == len(segs) + 1
    np.testing.assert_array_equal(lines[0][0], lines[0][-1])       # closed, bit for bit
    np.testing.assert_allclose(np.hypot(*lines[0].T), 0.6, atol=1e-3)
    # the distance grows outwards: higher values on the left means clockwise (negative area)
    x, y = lines[0].T
    assert 0.5 * np.sum(x[:-1] * y[1:] - x[1:] * y[:-1]) == pytest.approx(-np.pi * 0.36,
                                                                          rel=1e-3)


def test_isolines_around_maxima_run_counter_clockwise():
    f = S.example_field_2d("hills", size=80)
    lines = S.isolines(f.values, f.level, f.spacing, f.origin)
    assert len(lines) == 2                                          # one around each hill
    for line in lines:
        x, y = line.T
        assert np.array_equal(line[0], line[-1])
        assert 0.5 * np.sum(x[:-1] * y[1:] - x[1:] * y[:-1]) > 0


def test_join_segments_open_lines_and_skimage_count():
    f = S.example_field_2d("saddle", size=40)        # the two diagonals, ending at the border
    lines = S.isolines(f.values, 0.3, f.spacing, f.origin)
    sk = measure.find_contours(f.values, 0.3)
    assert len(lines) == len(sk) == 2
    assert sorted(map(len, lines)) == sorted(map(len, sk))


def test_marching_squares_spacing_and_origin_are_an_affine_map():
    field = rng(14).random((12, 9))
    unit = S.marching_squares(field, 0.5)
    moved = S.marching_squares(field, 0.5, spacing=(2.0, 0.5), origin=(-3.0, 4.0))
    np.testing.assert_allclose(moved, unit * [2.0, 0.5] + [-3.0, 4.0], atol=1e-12)


@pytest.mark.parametrize("level", [-0.1, 1.5])
def test_level_outside_the_data_range_gives_an_empty_result_without_warnings(level):
    field = rng(15).random((10, 10))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        segs = S.marching_squares(field, level)
        verts, tris = S.marching_cubes(rng(15).random((6, 6, 6)), level)
    assert segs.shape == (0, 2, 2) and S.join_segments(segs) == []
    assert verts.shape == (0, 3) and tris.shape == (0, 3)


@pytest.mark.parametrize("kwargs, match", [
    ({"field": np.ones(5)}, "field must be a 2D field"),
    ({"field": np.ones((3, 3, 3))}, "field must be a 2D field"),
    ({"field": np.ones((1, 5))}, "at least 2 samples"),
    ({"field": [[0, 1], [np.nan, 1]]}, "field must be finite"),
    ({"field": np.array([[0, 1], [np.nan, 1]])}, "field contains NaN"),
    ({"spacing": (1, 0)}, "spacing must be positive"),
    ({"spacing": (-1, 1)}, "spacing must be positive"),
    ({"level": np.nan}, "level must be finite"),
    ({"origin": (0, 0, 0)}, "origin must be a vector of 2"),
])
def test_marching_squares_bad_input(kwargs, match):
    args = {"field": np.eye(3), "level": 0.5, **kwargs}
    with pytest.raises(ValueError, match=match):
        S.marching_squares(**args)


def test_opposite_saddles_take_the_pairing_the_decider_rejects():
    # case 5, above 1: the decider joins corners 0 and 2 (cuts off 1 and 3); the other
    # reading cuts off corners 0 and 2 instead, and the other way round for above 0.9
    opposite = S.marching_squares(unit_cell(5, above=1.0), 0.5, saddles="opposite")
    assert as_point_sets(opposite) == sorted([{B, L}, {R, T}], key=lambda s: sorted(s))
    for case in (5, 10):
        for above in (1.0, 0.9):
            cell = unit_cell(case, above=above)
            chosen = S.marching_squares(cell, 0.5)
            other = S.marching_squares(cell, 0.5, saddles="opposite")
            points = {p for seg in as_point_sets(chosen) for p in seg}
            assert points == {p for seg in as_point_sets(other) for p in seg}
            assert not any(seg in as_point_sets(chosen) for seg in as_point_sets(other))
    # cells without a saddle read the same either way
    for case in HAND_TABLE:
        np.testing.assert_array_equal(S.marching_squares(unit_cell(case), 0.5, saddles="opposite"),
                                      S.marching_squares(unit_cell(case), 0.5))


@pytest.mark.parametrize("seed", [3, 4])
def test_marching_squares_cells_mask_marches_a_subset(seed):
    field = rng(seed).uniform(-1, 1, (9, 11))
    cases = S.marching_squares_cases(field, 0.1)
    saddle = np.isin(cases, (5, 10))
    assert saddle.any()

    def rows(segments):
        return sorted(map(tuple, np.round(segments.reshape(len(segments), -1), 12)))
    full = S.marching_squares(field, 0.1, (0.5, 2.0), (1.0, -1.0))
    parts = [S.marching_squares(field, 0.1, (0.5, 2.0), (1.0, -1.0), cells=m)
             for m in (saddle, ~saddle)]
    assert rows(np.concatenate(parts)) == rows(full)
    assert len(parts[0]) == 2 * int(saddle.sum())
    # the rejected pairings of the saddle cells alone: the same crossings, other segments
    other = S.marching_squares(field, 0.1, (0.5, 2.0), (1.0, -1.0), saddles="opposite",
                               cells=saddle)
    assert sorted(map(tuple, np.round(other.reshape(-1, 2), 12))) == \
        sorted(map(tuple, np.round(parts[0].reshape(-1, 2), 12)))
    assert not set(rows(other)) & set(rows(parts[0]))
    assert len(S.marching_squares(field, 0.1, cells=np.zeros_like(saddle))) == 0


@pytest.mark.parametrize("kwargs, match", [
    ({"saddles": "asymptotic"}, "saddles must be one of"),
    ({"cells": np.ones((3, 3), bool)}, "cells must be a boolean mask of shape"),
    ({"cells": np.ones((2, 2))}, "cells must be a boolean mask of shape"),
])
def test_marching_squares_options_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        S.marching_squares(np.eye(3), 0.5, **kwargs)


# ---------------------------------------------------------------------------------------------
# marching cubes
# ---------------------------------------------------------------------------------------------

def test_sphere_is_closed_outward_and_matches_skimage_and_the_analytic_sphere():
    f = S.example_volume("sphere", size=64)
    verts, tris = S.marching_cubes(f.values, f.level, f.spacing, f.origin)
    assert_watertight_and_oriented(tris)
    assert euler_characteristic(verts, tris) == 2
    area, volume = S.surface_area(verts, tris), S.enclosed_volume(verts, tris)
    assert volume > 0                                       # normals point outwards
    assert volume == pytest.approx(signed_volume(verts, tris), rel=1e-12)
    assert volume == pytest.approx(4 / 3 * np.pi * 0.6 ** 3, rel=0.01)
    assert area == pytest.approx(4 * np.pi * 0.6 ** 2, rel=0.01)
    for method in ("lewiner", "lorensen"):
        sv, sf = skimage_mesh(f.values, f.level, f.spacing, f.origin, method)
        assert area == pytest.approx(measure.mesh_surface_area(sv, sf), rel=0.01)
        assert volume == pytest.approx(abs(signed_volume(sv, sf)), rel=0.01)
    # every vertex lies on the isosurface of the trilinear interpolant (exact on grid edges)
    np.testing.assert_allclose(trilinear_scipy(f.values, verts, f.spacing, f.origin), f.level,
                               atol=1e-12)
    # all normals point to lower values, i.e. away from the centre for this field
    a, b, c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
    assert np.all(np.einsum("ij,ij->i", np.cross(b - a, c - a), (a + b + c) / 3) > 0)


def test_vertices_are_the_same_as_skimage_lorensen():
    """One vertex per crossed grid edge, by linear interpolation: the same point sets."""
    f = S.example_volume("blobs", size=40)
    verts, _ = S.marching_cubes(f.values, f.level, f.spacing, f.origin)
    sv, _ = skimage_mesh(f.values, f.level, f.spacing, f.origin, "lorensen")
    assert len(verts) == len(sv)
    # scikit-image computes in float32: match each vertex to the nearest of the other set
    for a, b in ((verts, sv), (sv, verts)):
        distance, _ = cKDTree(b).query(a)
        assert distance.max() < 1e-6
    # and as many vertices as grid edges whose ends lie on different sides of the level
    above = f.values >= f.level
    crossed = sum(int((np.diff(above, axis=a) != 0).sum()) for a in range(3))
    assert len(verts) == crossed


def test_torus_has_euler_characteristic_zero_and_the_analytic_volume():
    f = S.example_volume("torus", size=72)
    verts, tris = S.marching_cubes(f.values, f.level, f.spacing, f.origin)
    assert_watertight_and_oriented(tris)
    assert euler_characteristic(verts, tris) == 0
    big, small = 0.55, 0.2
    assert S.enclosed_volume(verts, tris) == pytest.approx(2 * np.pi ** 2 * big * small ** 2,
                                                           rel=0.02)
    assert S.surface_area(verts, tris) == pytest.approx(4 * np.pi ** 2 * big * small, rel=0.02)
    sv, sf = skimage_mesh(f.values, f.level, f.spacing, f.origin)
    assert S.surface_area(verts, tris) == pytest.approx(measure.mesh_surface_area(sv, sf),
                                                        rel=0.01)


def test_two_blobs_give_two_spheres():
    f = S.example_volume("blobs", size=48)
    verts, tris = S.marching_cubes(f.values, f.level, f.spacing, f.origin)
    assert_watertight_and_oriented(tris)
    assert euler_characteristic(verts, tris) == 4           # two components of genus 0
    # at a lower level they merge into one
    verts, tris = S.marching_cubes(f.values, 0.15, f.spacing, f.origin)
    assert euler_characteristic(verts, tris) == 2


def test_anisotropic_spacing_and_origin_scale_the_mesh():
    f = S.example_volume("blobs", size=24)
    v1, t1 = S.marching_cubes(f.values, f.level)
    v2, t2 = S.marching_cubes(f.values, f.level, spacing=(0.5, 2.0, 3.0), origin=(1, 2, 3))
    np.testing.assert_array_equal(t1, t2)
    np.testing.assert_allclose(v2, v1 * [0.5, 2.0, 3.0] + [1, 2, 3], atol=1e-12)
    sv, sf = skimage_mesh(f.values, f.level, (0.5, 2.0, 3.0), (1, 2, 3))
    assert S.surface_area(v2, t2) == pytest.approx(measure.mesh_surface_area(sv, sf), rel=0.01)


def test_random_volumes_give_watertight_oriented_meshes_for_all_256_cases():
    """Noise makes every case, and ambiguous faces of all kinds, appear; padding the volume
    with low values closes every surface. The table must never leave a hole."""
    seen = set()
    ambiguous_cells = 0
    for seed in range(30):
        vol = np.full((11, 11, 11), -1.0)
        vol[1:-1, 1:-1, 1:-1] = rng(100 + seed).uniform(-1, 1, (9, 9, 9))
        cases = S.marching_cubes_cases(vol, 0.0)
        seen.update(np.unique(cases).tolist())
        ambiguous_cells += int(np.isin(cases, [5, 10, 65, 130, 195]).sum())
        verts, tris = S.marching_cubes(vol, 0.0)
        assert_watertight_and_oriented(tris)
        assert euler_characteristic(verts, tris) % 2 == 0
        assert S.enclosed_volume(verts, tris) > 0
        # the vertices on grid edges lie on the trilinear isosurface
        on_edge = (np.abs(verts - np.round(verts)) < 1e-12).sum(axis=1) >= 2
        assert on_edge.mean() > 0.95              # the rest: centres of long loops
        np.testing.assert_allclose(trilinear_scipy(vol, verts[on_edge], (1, 1, 1), (0, 0, 0)),
                                   0.0, atol=1e-12)
    assert seen == set(range(256))
    assert ambiguous_cells > 100


def _face_connects(f0, f1, f2, f3, level, n=151):
    """Do the above corners 0 and 2 of a face touch, for the bilinear interpolant? Decided by
    sampling it densely and labelling the above region (4-connected)."""
    from scipy.ndimage import label

    s = np.linspace(0, 1, n)
    u, v = np.meshgrid(s, s)                 # u along edge 0 -> 1, v along edge 0 -> 3
    f = f0 * (1 - u) * (1 - v) + f1 * u * (1 - v) + f2 * u * v + f3 * (1 - u) * v
    labels, _ = label(f >= level)
    return labels[0, 0] == labels[-1, -1]


def test_ambiguous_faces_follow_the_bilinear_interpolant():
    """A 2 x 2 x 2 volume whose bottom face has corners 0 and 2 above (case 5) and the top all
    below: if the above corners are joined on the face, the surface is one hexagon (4
    triangles), otherwise two corner triangles. The midpoint decider would disagree with the
    bilinear interpolant in some of these; the asymptotic decider must not."""
    gen = rng(70)
    checked = disagree_with_midpoint = 0
    for k in range(150):
        if k % 2:                              # anywhere
            f0, f2 = gen.uniform(0.5, 1.0, 2)
            f1, f3 = gen.uniform(0.0, 0.5, 2)
        else:                                  # where the two deciders tend to disagree
            f0, f2 = gen.uniform(0.9, 1.0), gen.uniform(0.5, 0.58)
            f1, f3 = gen.uniform(0.25, 0.4, 2)
        if _face_connects(f0, f1, f2, f3, 0.49) != _face_connects(f0, f1, f2, f3, 0.51):
            continue                           # too close to call by sampling
        joined = _face_connects(f0, f1, f2, f3, 0.5)
        vol = np.zeros((2, 2, 2))              # volume[z, y, x]
        vol[0, 0, 0], vol[0, 0, 1], vol[0, 1, 1], vol[0, 1, 0] = f0, f1, f2, f3
        verts, tris = S.marching_cubes(vol, 0.5)
        assert len(tris) == (4 if joined else 2)
        checked += 1
        disagree_with_midpoint += joined != ((f0 + f1 + f2 + f3) / 4 >= 0.5)
    assert checked > 100 and disagree_with_midpoint > 20


@pytest.mark.parametrize("case", [1, 3, 7, 15, 24, 60, 90, 105, 129, 165, 195, 254])
def test_cube_triangles_use_exactly_the_crossed_edges(case):
    crossed = {e for e, (a, b) in enumerate(S.CUBE_EDGES) if ((case >> a) ^ (case >> b)) & 1}
    for connected in range(64):
        tris = S.cube_triangles(case, connected)
        used = set(tris.ravel().tolist()) - {S.CENTRE}
        assert used == crossed
    # a case and its complement cut the same edges
    assert set(S.cube_triangles(255 - case).ravel().tolist()) - {S.CENTRE} == crossed


def test_cube_triangles_bad_input():
    with pytest.raises(ValueError, match="case must be a whole number in 0-255"):
        S.cube_triangles(256)
    with pytest.raises(ValueError, match="connected_faces must be a 6-bit mask"):
        S.cube_triangles(5, connected_faces=64)


@pytest.mark.parametrize("kwargs, match", [
    ({"volume": np.ones((4, 4))}, "volume must be a 3D volume"),
    ({"volume": np.ones((4, 4, 1))}, "at least 2 samples"),
    ({"volume": np.where(np.eye(3)[None] > 0, np.nan, 0.0).repeat(3, 0)}, "contains NaN"),
    ({"spacing": (1, 1, 0)}, "spacing must be positive"),
    ({"spacing": (1, 1)}, "spacing must be a vector of 3"),
    ({"level": None}, "level must be a number"),
])
def test_marching_cubes_bad_input(kwargs, match):
    args = {"volume": np.ones((3, 3, 3)), "level": 0.5, **kwargs}
    with pytest.raises((ValueError, TypeError), match=match):
        S.marching_cubes(**args)


def rim_edges(tris):
    """Edges of one triangle only (the rims of holes), sorted vertex pairs."""
    edges, uses = np.unique(np.sort(directed_edges(tris), axis=1), axis=0, return_counts=True)
    return edges[uses == 1]


def test_classic_table_equals_the_consistent_one_without_ambiguous_faces():
    for kind, size in (("sphere", 40), ("blobs", 32), ("torus", 40)):
        f = S.example_volume(kind, size=size)
        classic = S.marching_cubes(f.values, f.level, f.spacing, f.origin, table="classic")
        consistent = S.marching_cubes(f.values, f.level, f.spacing, f.origin)
        for a, b in zip(classic, consistent):
            np.testing.assert_array_equal(a, b)
        sv, sf = skimage_mesh(f.values, f.level, f.spacing, f.origin, "lorensen")
        assert S.surface_area(*classic) == pytest.approx(measure.mesh_surface_area(sv, sf),
                                                         rel=1e-3)


def test_classic_table_leaves_holes_only_on_ambiguous_faces():
    f = S.example_volume("noise", size=24)
    v, t = S.marching_cubes(f.values, 0.1, f.spacing, f.origin, table="classic")
    v2, t2 = S.marching_cubes(f.values, 0.1, f.spacing, f.origin)
    assert_watertight_and_oriented(t2)
    rims = rim_edges(t)
    assert len(rims) > 0
    # the same crossed grid edges, the same vertices (the consistent table may add centres)
    np.testing.assert_array_equal(v, v2[:len(v)])
    # each rim edge joins two crossings on one cell face whose corners alternate above/below
    idx = (v - np.asarray(f.origin)) / np.asarray(f.spacing)       # index coordinates
    for a, b in rims:
        pa, pb = idx[a], idx[b]
        shared = [k for k in range(3) if abs(pa[k] - round(pa[k])) < 1e-9
                  and abs(pb[k] - round(pb[k])) < 1e-9 and round(pa[k]) == round(pb[k])]
        assert shared, "a rim edge inside a cube"
        k = shared[0]
        lo = np.floor(np.minimum(pa, pb) + 1e-9).astype(int)
        others = [m for m in range(3) if m != k]
        corner = lambda du, dv: f.values[tuple(np.array(  # noqa: E731  (z, y, x) order
            [lo[m] + (du if m == others[0] else dv if m == others[1] else 0)
             if m != k else int(round(pa[k])) for m in range(3)])[::-1])]
        above = [corner(0, 0) >= 0.1, corner(1, 0) >= 0.1, corner(1, 1) >= 0.1,
                 corner(0, 1) >= 0.1]
        assert above[0] == above[2] != above[1] == above[3], "a hole on a plain face"
    # holes cost a little area; otherwise the same surface as scikit-image's
    sv, sf = skimage_mesh(f.values, 0.1, f.spacing, f.origin, "lewiner")
    assert S.surface_area(v, t) == pytest.approx(measure.mesh_surface_area(sv, sf), rel=0.02)


def test_classic_table_decides_each_cube_by_its_corner_count():
    gen = rng(81)
    for case in range(256):
        values = np.where((case >> np.arange(8)) & 1, gen.uniform(0.6, 1.0, 8),
                          gen.uniform(0.0, 0.4, 8))
        vol = np.zeros((2, 2, 2))
        for k, (x, y, z) in enumerate(S.CUBE_CORNERS):
            vol[z, y, x] = values[k]
        _, tris = S.marching_cubes(vol, 0.5, table="classic")
        many = bin(case).count("1") > 4
        assert len(tris) == len(S.cube_triangles(case, 63 if many else 0))


def test_marching_cubes_table_bad_input():
    with pytest.raises(ValueError, match="table must be one of"):
        S.marching_cubes(np.ones((3, 3, 3)), 0.5, table="lewiner")


def test_noise_volume_is_smoothed_seeded_noise_with_a_low_border():
    from scipy.ndimage import uniform_filter1d

    f = S.example_volume("noise", size=20)
    raw = np.random.default_rng(18).normal(size=(20, 20, 20))
    for axis in range(3):
        for _ in range(3):
            raw = uniform_filter1d(raw, 3, axis=axis, mode="wrap")
    expected = 2 * (raw - raw.min()) / (raw.max() - raw.min()) - 1
    inner = (slice(1, -1),) * 3
    np.testing.assert_allclose(f.values[inner], expected[inner], atol=1e-12)
    border = np.ones(f.values.shape, bool)
    border[inner] = False
    assert (f.values[border] == -2.0).all()
    assert f.level == 0.3 and f.spacing == (2 / 19,) * 3 and f.origin == (-1.0,) * 3
    np.testing.assert_array_equal(S.example_volume("noise", size=20).values, f.values)
    assert_watertight_and_oriented(S.marching_cubes(f.values, f.level)[1])


# ---------------------------------------------------------------------------------------------
# interpolation and gradients
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("dim", [2, 3])
def test_interpolate_matches_scipy_and_clamps_outside(dim):
    gen = rng(20 + dim)
    shape = (5, 7, 6)[:dim]                               # array order: (z,) y, x
    grid = gen.normal(size=shape)
    spacing, origin = (0.5, 2.0, 1.5)[:dim], (-1.0, 3.0, 0.5)[:dim]
    axes = [o + s * np.arange(n) for o, s, n in zip(origin, spacing, shape[::-1])]
    ref = RegularGridInterpolator(axes[::-1], grid)       # scipy wants array axis order
    lo = np.array(origin)
    hi = lo + np.array(spacing) * (np.array(shape[::-1]) - 1)
    points = lo + gen.random((200, dim)) * (hi - lo)
    ours = S.interpolate(grid, points, spacing, origin)
    np.testing.assert_allclose(ours, ref(points[:, ::-1]), atol=1e-12)
    outside = points + (hi - lo) * 3
    np.testing.assert_allclose(S.interpolate(grid, outside, spacing, origin),
                               ref(np.clip(outside, lo, hi)[:, ::-1]), atol=1e-12)
    vectors = np.stack([grid, 2 * grid], axis=-1)
    np.testing.assert_allclose(S.interpolate(vectors, points, spacing, origin),
                               np.stack([ours, 2 * ours], axis=-1), atol=1e-12)


@pytest.mark.parametrize("dim", [2, 3])
def test_gradient_matches_np_gradient(dim):
    field = rng(30).normal(size=(6, 7, 8)[:dim])
    spacing = (0.5, 2.0, 3.0)[:dim]
    ours = S.gradient(field, spacing)
    ref = np.gradient(field, *spacing[::-1])              # per array axis: (z,) y, x
    for c in range(dim):
        np.testing.assert_allclose(ours[..., c], ref[dim - 1 - c], atol=1e-12)


def test_gradient_is_exact_inside_for_a_quadratic():
    f = S.example_field_2d("saddle", size=11)             # x^2 - y^2: gradient (2x, -2y)
    g = S.gradient(f.values, f.spacing)
    x, y = np.meshgrid(*f.axes)
    np.testing.assert_allclose(g[1:-1, 1:-1, 0], 2 * x[1:-1, 1:-1], atol=1e-12)
    np.testing.assert_allclose(g[1:-1, 1:-1, 1], -2 * y[1:-1, 1:-1], atol=1e-12)


# ---------------------------------------------------------------------------------------------
# volume rendering
# ---------------------------------------------------------------------------------------------

def constant_tf(alpha, rgb=(1.0, 1.0, 1.0)):
    row = list(rgb) + [alpha]
    return CM.TransferFunction([0.0, 1.0], [row, row])


def test_view_rotation_matches_scipy():
    expected = (Rotation.from_euler("x", -0.4) * Rotation.from_euler("y", 1.1)).as_matrix()
    np.testing.assert_allclose(S.view_rotation(1.1, -0.4), expected, atol=1e-15)


@pytest.mark.parametrize("step", [1.0, 0.3, 0.07])
def test_beer_lambert_transmittance_of_a_uniform_block(step):
    # a 6 x 5 x 9 block (path length 8 along z) of opacity 0.2 per unit length:
    # transmittance (1 - 0.2)^8, whatever the step
    img = S.volume_render(np.ones((9, 5, 6)), constant_tf(0.2), step=step,
                          early_termination=None)
    assert img.alpha.shape == (5, 6)
    np.testing.assert_allclose(1 - img.alpha, 0.8 ** 8, rtol=1e-10)
    np.testing.assert_allclose(img.rgb, np.repeat(img.alpha[..., None], 3, axis=2), rtol=1e-12)


@pytest.mark.parametrize("elevation", [0.3, np.pi / 4, 1.2])
def test_beer_lambert_on_tilted_rays_against_shapely_path_lengths(elevation):
    # turning about x keeps each ray in a plane x = const: its path through the box is the
    # intersection of a line with the (y, z) rectangle, measured by shapely
    ny, nz = 7, 10
    spacing = (1.0, 0.5, 0.8)
    rot = S.view_rotation(0.0, elevation)
    extent = (-1.5, 1.5, -5.0, 5.0)
    img = S.volume_render(np.ones((nz, ny, 4)), constant_tf(0.3), rotation=rot, step=0.05,
                          spacing=spacing, extent=extent, image_size=(41, 3),
                          early_termination=None, unit_length=0.7)
    centre = np.array([(ny - 1) * spacing[1], (nz - 1) * spacing[2]]) / 2
    up, forward = rot[1, 1:], -rot[2, 1:]               # (y, z) parts of view y and view -z
    rect = box(0, 0, (ny - 1) * spacing[1], (nz - 1) * spacing[2])
    for row, v in enumerate(np.linspace(extent[2], extent[3], 41)):
        p = centre + v * up
        length = LineString([p - 50 * forward, p + 50 * forward]).intersection(rect).length
        np.testing.assert_allclose(1 - img.alpha[row], 0.7 ** (length / 0.7), atol=1e-9)


def test_volume_render_equals_compositing_the_samples_by_hand():
    """Default view: the ray of pixel (i, j) runs down the column volume[:, i, j] from the top
    (z = nz - 1) to z = 0; along it, trilinear interpolation is linear interpolation in z."""
    gen = rng(40)
    vol = gen.random((5, 3, 4))
    points = [0.0, 0.3, 0.6, 1.0]
    colors = gen.random((4, 3))
    alphas = gen.uniform(0, 0.6, 4)
    tf = CM.TransferFunction(points, np.column_stack([colors, alphas]))
    h = 0.25
    img = S.volume_render(vol, tf, step=h, early_termination=None)
    z = 4.0 - h * np.arange(int(4 / h) + 1)               # front to back, both ends included
    length = np.full(len(z), h)
    length[-1] = 0.0                                      # the last sample covers nothing
    for i in range(3):
        for j in range(4):
            s = np.interp(z, np.arange(5), vol[:, i, j])
            c = np.column_stack([np.interp(s, points, colors[:, k]) for k in range(3)])
            a = 1 - (1 - np.interp(s, points, alphas)) ** length
            color, alpha = np.zeros(3), 0.0
            for k in range(len(z) - 1, -1, -1):           # back to front, plain "over"
                color = a[k] * c[k] + (1 - a[k]) * color
                alpha = a[k] + (1 - a[k]) * alpha
            # (1e-10: the ray box is grown by 1e-12 to keep rays grazing its faces)
            np.testing.assert_allclose(img.rgb[i, j], color, atol=1e-10)
            assert img.alpha[i, j] == pytest.approx(alpha, abs=1e-10)


def test_front_to_back_equals_back_to_front_compositing():
    gen = rng(41)
    colors = gen.random((7, 5, 12, 3))
    alphas = gen.random((7, 5, 12))
    c1, a1 = S.composite(colors, alphas)
    c2, a2 = S.composite(colors, alphas, order="back-to-front")
    np.testing.assert_allclose(c1, c2, atol=1e-14)
    np.testing.assert_allclose(a1, a2, atol=1e-14)
    # closed form: transparency is the product of the (1 - alpha_i)
    np.testing.assert_allclose(1 - a1, np.prod(1 - alphas, axis=-1), atol=1e-14)
    # grey samples and the running values
    grey_c, grey_a = S.composite(colors[..., 0], alphas, cumulative=True)
    assert grey_c.shape == (7, 5, 12)
    np.testing.assert_allclose(grey_c[..., -1], c1[..., 0], atol=1e-14)
    np.testing.assert_allclose(1 - grey_a, np.cumprod(1 - alphas, axis=-1), atol=1e-14)


def test_composite_by_hand():
    # white (opacity 0.5) in front of red (opacity 1): C = 0.5 white + 0.5 * 1 * red
    color, alpha = S.composite([[1, 1, 1], [1, 0, 0]], [0.5, 1.0])
    np.testing.assert_allclose(color, [1.0, 0.5, 0.5])
    assert alpha == 1.0
    with pytest.raises(ValueError, match="opacities must lie in \\[0, 1\\]"):
        S.composite([0.5, 0.5], [0.5, 1.5])
    with pytest.raises(ValueError, match="colors must have shape"):
        S.composite([[1, 1], [1, 0]], [0.5, 1.0])
    with pytest.raises(ValueError, match="order must be one of"):
        S.composite([1.0], [0.5], order="sideways")


def test_early_termination_changes_the_image_by_less_than_one_minus_threshold():
    f = S.example_volume("ct", size=40)
    common = dict(transfer="bone", spacing=f.spacing, origin=f.origin,
                  rotation=S.view_rotation(0.4, 0.2), extent="sphere", image_size=(48, 48))
    full = S.volume_render(f.values, early_termination=None, **common)
    for threshold in (0.9, 0.99):
        early = S.volume_render(f.values, early_termination=threshold, **common)
        assert np.abs(early.rgb - full.rgb).max() <= 1 - threshold + 1e-12
        assert np.abs(early.alpha - full.alpha).max() <= 1 - threshold + 1e-12
        assert early.samples_saved > 0.1 * full.samples
        assert early.samples + early.samples_saved == full.samples
    assert full.samples_saved == 0


def test_step_size_barely_changes_a_smooth_rendering():
    f = S.example_volume("blobs", size=32)
    tf = CM.rgba_transfer("magma", CM.opacity_transfer([0.0, 0.3, 1.2], [0.0, 0.05, 0.4]))
    fine = S.volume_render(f.values, tf, spacing=f.spacing, step=0.25 * f.spacing[0],
                           early_termination=None)
    coarse = S.volume_render(f.values, tf, spacing=f.spacing, step=0.5 * f.spacing[0],
                             early_termination=None)
    assert np.abs(fine.rgb - coarse.rgb).max() < 0.02


def test_background_shows_through_where_alpha_is_low():
    img = S.volume_render(np.zeros((3, 3, 3)), constant_tf(0.0), background=(0.2, 0.4, 0.6))
    np.testing.assert_allclose(img.rgb, np.broadcast_to([0.2, 0.4, 0.6], img.rgb.shape))
    # a view window larger than the volume: the rays that miss it show the background
    img = S.volume_render(np.ones((3, 3, 3)), constant_tf(1.0, (1, 0, 0)),
                          extent=(-5, 5, -5, 5), image_size=(5, 5), background=(0, 0, 1))
    np.testing.assert_allclose(img.rgb[0, 0], [0, 0, 1])
    np.testing.assert_allclose(img.rgb[2, 2], [1, 0, 0])


def test_mip_equals_the_maximum_along_the_viewing_axis():
    vol = rng(42).random((6, 5, 7))
    for step in (1.0, 0.5, 0.25):
        np.testing.assert_allclose(S.mip(vol, step=step), vol.max(axis=0), atol=1e-12)
    cube = rng(43).random((6, 6, 6))
    # turned by 90 degrees about y, the view's x is the volume's z: rays run along x
    side = S.mip(cube, rotation=S.view_rotation(np.pi / 2), step=1.0)
    np.testing.assert_allclose(side, cube.max(axis=2).T, atol=1e-9)
    # finer steps only add interpolated samples, which never exceed the grid's maximum
    tilted = S.mip(cube, rotation=S.view_rotation(0.3, 0.5), extent="sphere", fill=-1.0)
    assert tilted.max() <= cube.max() + 1e-12 and tilted.min() == -1.0


@pytest.mark.parametrize("kwargs, error, match", [
    ({"volume": np.ones((3, 3))}, ValueError, "volume must be a 3D volume"),
    ({"volume": np.full((3, 3, 3), np.nan)}, ValueError, "volume contains NaN"),
    ({"step": 0.0}, ValueError, "step must be positive"),
    ({"step": -0.5}, ValueError, "step must be positive"),
    ({"spacing": (1, -1, 1)}, ValueError, "spacing must be positive"),
    ({"transfer": constant_tf(1.5)}, ValueError, "opacities in \\[0, 1\\]"),
    ({"transfer": "lungs"}, ValueError, "name must be one of"),
    ({"transfer": CM.TransferFunction([0, 1], [0, 1])}, TypeError, "4-channel"),
    ({"early_termination": 0.0}, ValueError, "early_termination must lie in \\(0, 1\\]"),
    ({"early_termination": 1.5}, ValueError, "early_termination must lie in \\(0, 1\\]"),
    ({"rotation": np.diag([1.0, 1.0, -1.0])}, ValueError, "rotation is not a rotation"),
    ({"image_size": (0, 4)}, ValueError, "image_size must be"),
    ({"extent": (1, 0, 0, 1)}, ValueError, "extent must be"),
    ({"extent": "wide"}, ValueError, "extent must be one of"),
    ({"unit_length": 0}, ValueError, "unit_length must be positive"),
])
def test_volume_render_bad_input(kwargs, error, match):
    args = {"volume": np.ones((3, 3, 3)), "transfer": "ramp", **kwargs}
    with pytest.raises(error, match=match):
        S.volume_render(**args)


# --- ray samples: the rays of one view sampled once, classified and composited later ---------

@pytest.mark.parametrize("alpha", [0.05, 0.2, 0.6])
def test_ray_samples_obey_beer_lambert_through_a_uniform_block(alpha):
    # a 9 x 9 x 9 block seen along z: the central ray's path is 8 long; samples every h on
    # common depth planes, each standing for h: (1 - alpha)^(count h), count h within a step
    # of 8, and the colour of white over black is the opacity
    rays = S.RaySamples(np.ones((9, 9, 9)), image_size=(5, 5), step=0.5, value_range=(0, 1))
    img = rays.composite(constant_tf(alpha))
    count = int(rays.inside.sum(axis=1)[12])
    # (the table is single precision)
    np.testing.assert_allclose(1 - img.alpha[2, 2], (1 - alpha) ** (count * 0.5), rtol=1e-4)
    assert abs(count * 0.5 - 8) <= 0.5
    np.testing.assert_allclose(img.rgb[2, 2], img.alpha[2, 2], rtol=1e-6)


def test_ray_samples_composite_like_composite_of_the_classified_samples():
    f = S.example_volume("ct", size=24)
    tf = CM.transfer_preset("skin")
    rotation = S.view_rotation(0.4, -0.3)
    rays = S.RaySamples(f.values, rotation, (10, 12), 0.05, f.spacing, f.origin, "sphere",
                        value_range=(0.0, 1.0))
    assert rays.samples.shape == rays.inside.shape and rays.hit.shape == (120,)
    # the samples are trilinear interpolations (scipy) at the common depth planes
    inside = rays.inside
    img = rays.composite(tf, background=(0.2, 0.3, 0.4))
    # classify exactly (no table) and composite with the loop of scivis.composite
    rgba = np.where(inside[..., None], tf(np.nan_to_num(rays.samples)), 0.0)
    opacity = 1 - (1 - rgba[..., 3]) ** (rays.step / rays.unit)
    color, alpha = S.composite(rgba[..., :3], np.clip(opacity, 0, 1))
    got = np.column_stack([img.rgb.reshape(-1, 3), img.alpha.ravel()])[rays.hit]
    expected = np.column_stack([color + (1 - alpha)[:, None] * [0.2, 0.3, 0.4], alpha])
    assert np.abs(got - expected).max() < 5e-3                      # the 1024-entry table
    assert (img.alpha.ravel()[~rays.hit] == 0).all()
    assert img.samples + img.samples_saved == int(inside.sum())
    # and the picture of the full ray caster, whose samples start where each ray enters
    full = S.volume_render(f.values, tf, rotation, (10, 12), 0.05, f.spacing, f.origin,
                           "sphere", early_termination=None, background=(0.2, 0.3, 0.4))
    assert np.abs(img.rgb - full.rgb).mean() < 0.01
    assert np.abs(img.alpha - full.alpha).mean() < 0.01


def test_ray_samples_are_trilinear_samples_on_depth_planes():
    vol = rng(12).uniform(0, 1, (6, 7, 8))
    rot = S.view_rotation(0.3, 0.2)
    rays = S.RaySamples(vol, rot, (6, 6), 0.4, (1.0, 0.5, 2.0), (1.0, 2.0, 3.0), "sphere")
    lo, hi = np.array([1.0, 2.0, 3.0]), np.array([1.0, 2.0, 3.0]) + [7.0, 3.0, 10.0]
    centre, radius = (lo + hi) / 2, np.linalg.norm(hi - lo) / 2
    u, v = np.meshgrid(np.linspace(-radius, radius, 6), np.linspace(-radius, radius, 6))
    pixel = np.flatnonzero(rays.hit)[7]
    ray = centre + u.ravel()[pixel] * rot[0] + v.ravel()[pixel] * rot[1]
    values = rays.samples[7][rays.inside[7]]
    depths = [d for d in np.arange(radius, -radius - 1e-9, -0.4)
              if np.all((ray + d * rot[2] >= lo - 1e-9) & (ray + d * rot[2] <= hi + 1e-9))]
    points = ray + np.array(depths)[:, None] * rot[2]
    np.testing.assert_allclose(values, trilinear_scipy(vol, points, (1.0, 0.5, 2.0),
                                                       (1.0, 2.0, 3.0)), atol=1e-12)


@pytest.mark.parametrize("kwargs, match", [
    ({"step": 0.0}, "step must be positive"),
    ({"value_range": (1, 1)}, "value_range must be \\(low, high\\) with low < high"),
    ({"lut_size": 1}, "lut_size must be a whole number >= 2"),
    ({"extent": "wide"}, "extent must be one of"),
    ({"volume": np.ones((3, 3))}, "volume must be a 3D volume"),
])
def test_ray_samples_bad_input(kwargs, match):
    args = {"volume": np.ones((3, 3, 3)), **kwargs}
    with pytest.raises(ValueError, match=match):
        S.RaySamples(**args)
    with pytest.raises(ValueError, match="termination must lie in"):
        S.RaySamples(np.ones((3, 3, 3))).composite("ramp", termination=0.0)


def test_transfer_pair_and_colormap_name():
    vol = S.example_volume("blobs", size=16).values
    pair = (CM.color_transfer([0, 1], [[0, 0, 1], [1, 0, 0]]),
            CM.opacity_transfer([0, 1], [0.0, 0.5]))
    img = S.volume_render(vol, pair)
    joined = S.volume_render(vol, CM.rgba_transfer(*pair))
    np.testing.assert_allclose(img.rgb, joined.rgb)
    named = S.volume_render(vol, ("viridis", pair[1]))
    assert named.rgb.shape == img.rgb.shape and named.alpha.max() > 0


# ---------------------------------------------------------------------------------------------
# streamlines
# ---------------------------------------------------------------------------------------------

VORTEX = S.example_vector_field("vortex")


def radii(line):
    return np.linalg.norm(line, axis=-1)


def test_euler_on_a_circular_flow_spirals_out_by_the_closed_form():
    # x_{n+1} = (I + hA) x_n with A the 90-degree rotation: |I + hA| = sqrt(1 + h^2), and each
    # step turns by atan(h). So x_n = (1 + h^2)^(n/2) (cos(n atan h), sin(n atan h)).
    h, n = 0.05, 400
    line = S.streamline(VORTEX, [1.0, 0.0], h, n, method="euler")
    k = np.arange(n + 1)
    expected = (1 + h * h) ** (k / 2)[:, None] * np.stack([np.cos(k * np.arctan(h)),
                                                           np.sin(k * np.arctan(h))], axis=1)
    np.testing.assert_allclose(line, expected, rtol=1e-10, atol=1e-12)


def test_rk2_and_rk4_radius_closed_forms():
    # midpoint RK2: x_{n+1} = (I + hA + h^2 A^2 / 2) x_n = ((1 - h^2/2) I + h A) x_n, whose norm
    # factor is sqrt(1 + h^4/4). RK4: ((1 - h^2/2 + h^4/24) I + (h - h^3/6) A), whose norm
    # factor squared is 1 - h^6/72 + h^8/576: a very slow inward drift.
    h, n = 0.1, 600
    k = np.arange(n + 1)
    rk2 = S.streamline(VORTEX, [0.0, 2.0], h, n, method="rk2")
    np.testing.assert_allclose(radii(rk2), 2 * (1 + h ** 4 / 4) ** (k / 2), rtol=1e-10)
    rk4 = S.streamline(VORTEX, [0.0, 2.0], h, n, method="rk4")
    np.testing.assert_allclose(radii(rk4), 2 * (1 - h ** 6 / 72 + h ** 8 / 576) ** (k / 2),
                               rtol=1e-10)
    euler = S.streamline(VORTEX, [0.0, 2.0], h, n, method="euler")
    drift = [abs(radii(line)[-1] - 2.0) for line in (euler, rk2, rk4)]
    assert drift[0] > 100 * drift[1] > 100 * drift[2] and drift[2] < 1e-4


def test_rk4_matches_scipy_solve_ivp_on_a_nonlinear_field():
    def flow(p):
        x, y = p[..., 0], p[..., 1]
        return np.stack([np.sin(y) + 0.3 * x * y, np.cos(x) - 0.2 * y], axis=-1)

    h, n = 0.02, 150
    ours = S.streamline(flow, [0.2, -0.4], h, n, method="rk4")
    ref = solve_ivp(lambda t, p: flow(p), (0, h * n), [0.2, -0.4], method="DOP853",
                    t_eval=h * np.arange(n + 1), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(ours, ref.y.T, atol=1e-8)
    euler = S.streamline(flow, [0.2, -0.4], h, n, method="euler")
    assert np.abs(euler - ref.y.T).max() > 1e-3                  # first order: visibly off


def test_3d_helix():
    helix = S.example_vector_field("helix", dim=3)
    h, n = 0.05, 500
    line = S.streamline(helix, [0.5, 0.0, 0.0], h, n)
    t = h * np.arange(n + 1)
    np.testing.assert_allclose(line[:, 2], 0.2 * t, atol=1e-12)       # constant rise
    np.testing.assert_allclose(np.hypot(line[:, 0], line[:, 1]), 0.5, rtol=1e-6)
    np.testing.assert_allclose(line[:, 0], 0.5 * np.cos(t), atol=1e-6)
    np.testing.assert_allclose(line[:, 1], 0.5 * np.sin(t), atol=1e-6)


def test_sampled_grid_of_a_linear_field_gives_the_same_lines():
    # bilinear interpolation reproduces a linear field exactly
    grid = S.sample_vector_field(VORTEX, size=21)
    seeds = rng(50).uniform(-0.4, 0.4, (10, 2))
    from_grid = S.streamline(grid.values, seeds, 0.05, 40, spacing=grid.spacing,
                             origin=grid.origin)
    exact = S.streamline(VORTEX, seeds, 0.05, 40)
    np.testing.assert_allclose(from_grid, exact, atol=1e-12)
    grid3 = S.sample_vector_field(S.example_vector_field("helix", 3), size=9, dim=3)
    seeds3 = [[0.3, 0.0, -0.9], [0.0, 0.2, -0.5]]
    np.testing.assert_allclose(
        S.streamline(grid3.values, seeds3, 0.1, 30, spacing=grid3.spacing, origin=grid3.origin),
        S.streamline(S.example_vector_field("helix", 3), seeds3, 0.1, 30), atol=1e-12)


def test_many_seeds_equal_one_at_a_time():
    spiral = S.example_vector_field("spiral")
    seeds = rng(51).uniform(-1, 1, (25, 2))
    together = S.streamline(spiral, seeds, 0.1, 30, method="rk2")
    for seed, line in zip(seeds, together):
        np.testing.assert_allclose(S.streamline(spiral, seed, 0.1, 30, method="rk2"), line,
                                   atol=1e-14)


def test_lines_stop_at_the_domain_boundary_and_at_zero_velocity():
    source = S.example_vector_field("source")
    lines = S.streamline(source, [[0.1, 0.0], [0.0, 0.0], [2.0, 2.0]], 0.1, 100,
                         bounds=[[-1, -1], [1, 1]])
    first = lines[0][np.isfinite(lines[0, :, 0])]
    # x grows by the factor 1.1 per Euler... RK4 step: exp-like growth, stopping inside
    assert np.all(np.abs(first) <= 1.0) and first[-1, 0] > 0.8
    assert np.isnan(lines[0, len(first):]).all()
    next_point = first[-1] * (1 + 0.1 + 0.1 ** 2 / 2 + 0.1 ** 3 / 6 + 0.1 ** 4 / 24)
    assert next_point[0] > 1.0                                    # the step that would leave
    # the origin is a critical point: the line is just its seed
    np.testing.assert_array_equal(lines[1, 0], [0.0, 0.0])
    assert np.isnan(lines[1, 1:]).all()
    # a seed outside the domain is kept, nothing else
    np.testing.assert_array_equal(lines[2, 0], [2.0, 2.0])
    assert np.isnan(lines[2, 1:]).all()
    # a grid's extent is its domain
    grid = S.sample_vector_field(source, size=11)
    line = S.streamline(grid.values, [0.5, 0.5], 0.1, 100, spacing=grid.spacing,
                        origin=grid.origin)
    valid = line[np.isfinite(line[:, 0])]
    assert 1 < len(valid) < 101 and np.all(valid <= 1.0)


def test_negative_step_traces_upstream():
    forward = S.streamline(VORTEX, [1.0, 0.0], 0.1, 20)
    back = S.streamline(VORTEX, forward[-1], -0.1, 20)
    np.testing.assert_allclose(back[-1], [1.0, 0.0], atol=1e-6)


@pytest.mark.parametrize("kwargs, error, match", [
    ({"step": 0.0}, ValueError, "step must not be zero"),
    ({"method": "rk3"}, ValueError, "method must be one of"),
    ({"n_steps": 0}, ValueError, "n_steps must be a whole number >= 1"),
    ({"seeds": [1.0]}, ValueError, "seeds must have 2 or 3 coordinates"),
    ({"velocity": np.zeros((4, 4, 3))}, ValueError, "velocity must be a function or a grid"),
    ({"velocity": lambda p: p[:, :1]}, ValueError, "velocity must return one 2-vector"),
    ({"velocity": lambda p: p * np.nan}, ValueError, "velocity returned NaN"),
    ({"bounds": [[1, 1], [0, 0]]}, ValueError, "bounds must be"),
])
def test_streamline_bad_input(kwargs, error, match):
    args = {"velocity": VORTEX, "seeds": [0.5, 0.0], "step": 0.1, "n_steps": 5, **kwargs}
    with pytest.raises(error, match=match):
        S.streamline(**args)


# ---------------------------------------------------------------------------------------------
# glyphs and example data
# ---------------------------------------------------------------------------------------------

def test_hedgehog_segments():
    gen = rng(60)
    p, v = gen.normal(size=(30, 3)), gen.normal(size=(30, 3))
    segs = S.hedgehog(p, v, scale=0.3)
    assert segs.shape == (30, 2, 3)
    np.testing.assert_allclose(segs[:, 0], p)
    np.testing.assert_allclose(segs[:, 1], p + 0.3 * v)
    unit = S.hedgehog(p, v, scale=0.3, normalize=True)
    np.testing.assert_allclose(np.linalg.norm(unit[:, 1] - unit[:, 0], axis=1), 0.3)
    np.testing.assert_array_equal(S.hedgehog([1, 2], [0, 0], normalize=True), [[1, 2], [1, 2]])


def test_arrow_shapes_closed_form():
    gen = rng(61)
    p, v = gen.normal(size=(20, 2)), gen.normal(size=(20, 2))
    shapes = S.arrows(p, v, scale=0.5, head_length=0.3, head_width=0.4, shaft_width=0.1)
    assert shapes.shape == (20, 7, 2)
    np.testing.assert_allclose(shapes[:, 3], p + 0.5 * v)                     # the tip
    length = 0.5 * np.linalg.norm(v, axis=1)
    x, y = shapes[..., 0], shapes[..., 1]
    area = 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
    # shaft rectangle 0.1 L x 0.7 L plus head triangle 0.4 L wide, 0.3 L long, counter-clockwise
    np.testing.assert_allclose(area, 0.1 * 0.7 * length ** 2 + 0.5 * 0.4 * 0.3 * length ** 2)
    np.testing.assert_allclose(S.arrows([1, 1], [0, 0]), np.ones((7, 2)))
    with pytest.raises(ValueError, match="head_length must be at most 1"):
        S.arrows([0, 0], [1, 0], head_length=1.5)
    with pytest.raises(ValueError, match="points must have 2 coordinates"):
        S.arrows([0, 0, 0], [1, 0, 0])


def test_example_fields_and_volumes():
    circle = S.example_field_2d("circle", size=9)
    x, y = np.meshgrid(*circle.axes)
    np.testing.assert_allclose(circle.values, np.hypot(x, y))
    assert circle.values.shape == (9, 9)
    sphere = S.example_volume("sphere", size=9)
    xs, ys, zs = sphere.axes
    # volume[k, j, i] is at (x_i, y_j, z_k)
    assert sphere.values[1, 3, 8] == pytest.approx(0.6 - np.sqrt(xs[8] ** 2 + ys[3] ** 2
                                                                 + zs[1] ** 2))
    ct = S.example_volume("ct", size=64)
    assert ct.values.min() >= 0 and ct.values.max() <= 1 and ct.values.max() > 0.9
    for kind in ("hills", "saddle", "ripple"):
        assert S.example_field_2d(kind, size=7).values.shape == (7, 7)
    for kind in ("blobs", "torus"):
        assert S.example_volume(kind, size=7).values.shape == (7, 7, 7)
    with pytest.raises(ValueError, match="kind must be one of"):
        S.example_volume("cube")
    with pytest.raises(ValueError, match="size must be a whole number >= 2"):
        S.example_field_2d("circle", size=1)


def test_example_vector_fields_closed_forms():
    p = rng(62).normal(size=(10, 2))
    x, y = p.T
    np.testing.assert_allclose(S.example_vector_field("saddle")(p), np.stack([x, -y], 1))
    np.testing.assert_allclose(S.example_vector_field("sink")(p), -p)
    q = rng(63).normal(size=(10, 3))
    np.testing.assert_allclose(S.example_vector_field("saddle", 3)(q), q * [1, 1, -2])
    with pytest.raises(ValueError, match="kind must be one of"):
        S.example_vector_field("helix", dim=2)


# ---------------------------------------------------------------------------------------------
# the module's promises
# ---------------------------------------------------------------------------------------------

def test_module_imports_numpy_only():
    code = ("import sys, course_lib.scivis\n"
            "print(sorted(m for m in ('matplotlib', 'pyvista', 'vtk', 'ipywidgets', 'scipy', "
            "'skimage') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_interpolate_is_multilinear_interpolate_under_its_old_name():
    assert S.interpolate is S.multilinear_interpolate
    assert "interpolate" not in S.__all__ and "multilinear_interpolate" in S.__all__
    np.testing.assert_allclose(S.multilinear_interpolate([[0, 1], [2, 3]], [[0.25, 0.5]]), [1.25])


def test_the_isosurface_of_a_level_the_data_never_takes_has_area_and_volume_zero():
    # a slider may sweep past the data range: the empty surface is measured, not an error
    volume = S.example_volume("sphere", size=12)
    v, t = S.marching_cubes(volume.values, float(volume.values.max()) + 1.0,
                                 volume.spacing, volume.origin)
    assert t.shape == (0, 3)
    assert S.surface_area(v, t) == 0.0
    assert S.enclosed_volume(v, t) == 0.0
    with pytest.raises(ValueError, match="triangles refers to vertex 3"):
        S.surface_area([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 3]])
