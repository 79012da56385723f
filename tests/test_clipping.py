"""Tests of course_lib.clipping (back faces, outcodes, Cohen-Sutherland, Liang-Barsky,
Sutherland-Hodgman, clipping against arbitrary half-spaces and view volumes).

Expected values come from shapely (2D), VTK's vtkBox (3D), scipy (convex hulls, half-space
intersections), closed forms typed out below, or mathematical properties. Nothing here is copied
from the output of the code under test.

Conventions of the references, worked out once:

* Our clip region is the *closed* box: its boundary counts as inside, so a segment that only
  touches the box at a point comes out as a degenerate segment ``(q, q)``, and a segment lying on
  a side is kept whole.
* ``shapely.intersection(line, box(...))`` (GEOS overlay) is closed-set intersection too: a
  segment on a side comes back as that LINESTRING, a touching segment as a POINT. Zero-length
  segments however are degenerate LineStrings to GEOS and always give an empty result, so those
  are checked against the closed form instead.
* ``shapely.clip_by_rect`` (GEOS rectangle intersection) differs on degenerate cases: it drops
  everything lying *on* the rectangle's boundary (a segment along a side, a touching point, a
  zero-length segment on the boundary: all GEOMETRYCOLLECTION EMPTY), but keeps a zero-length
  segment strictly inside. For generic random segments it agrees with the overlay; it is the
  reference there, and the degenerate differences are tested explicitly below. For *polygons*
  the reference is the overlay: clip_by_rect (shapely 2.2) returns the wrong piece for some
  polygons with vertices on the rectangle's corners (see the closed-form test with
  (1, 2), (0, 1), (0, 0), (0.25, 0.25), (1, -0.25): true area 0.921875, clip_by_rect 0.078125).
* ``vtk.vtkBox.IntersectWithLine(bounds, p0, p1, t0, t1, x0, x1, plane0, plane1)`` with
  ``bounds = (xmin, xmax, ymin, ymax, zmin, zmax)`` returns 1 when the segment meets the closed
  box, with the entry/exit parameters t0 <= t1 clamped to [0, 1] and the points x0, x1 in the
  order of the segment (from p0 towards p1); plane0/plane1 are -1 for an end point that is inside
  (both inside: returns 1 with t = (0, 1), x = (p0, p1)). It returns 0 when the segment misses
  the box. Boundary inclusive, like ours; a zero-length segment inside or on the boundary gives 1.
"""
import numpy as np
import pytest
import shapely
import vtk
from scipy.spatial import ConvexHull, HalfspaceIntersection
from scipy.spatial.transform import Rotation
from shapely.geometry import LineString, Polygon, box as shapely_box

from course_lib import clipping as C
from course_lib import transforms
from course_lib import viewing as V

BIT_NAMES = ("left", "right", "bottom", "top", "near", "far")   # the module's table, typed


# ---------------------------------------------------------------------------------------------
# helpers (independent of the code under test)
# ---------------------------------------------------------------------------------------------

def rng(seed):
    return np.random.default_rng(seed)


def outcode_closed_form(points, lo, hi):
    """The module's table: bit 2k for coordinate k below the box, bit 2k+1 for above."""
    p = np.asarray(points, dtype=float)
    code = np.zeros(p.shape[:-1], dtype=np.int64)
    for k in range(len(lo)):
        code = code + (p[..., k] < lo[k]) * 2 ** (2 * k) + (p[..., k] > hi[k]) * 2 ** (2 * k + 1)
    return code


def random_box(gen, dim):
    lo = gen.uniform(-3, 1, dim)
    return lo, lo + gen.uniform(0.2, 4, dim)


def random_segments(gen, n, lo, hi):
    """End points in the box widened by its size on every side."""
    size = hi - lo
    return (gen.uniform(lo - size, hi + size, (n, len(lo))),
            gen.uniform(lo - size, hi + size, (n, len(lo))))


def same_segment_unordered(got, expected, atol):
    (a, b), (c, d) = np.asarray(got, float), np.asarray(expected, float)
    err = min(max(np.abs(a - c).max(), np.abs(b - d).max()),
              max(np.abs(a - d).max(), np.abs(b - c).max()))
    return err <= atol


def shapely_segment(geom):
    """A shapely clip result -> None (empty) or its two end points (a POINT: twice)."""
    if geom.is_empty:
        return None
    assert geom.geom_type in ("LineString", "Point"), geom.wkt
    coords = np.asarray(geom.coords)
    return coords[0], coords[-1]


def vtk_clip(lo, hi, p0, p1):
    bounds = (lo[0], hi[0], lo[1], hi[1], lo[2], hi[2])
    t0, t1 = vtk.reference(0.0), vtk.reference(0.0)
    x0, x1 = [0.0] * 3, [0.0] * 3
    plane0, plane1 = vtk.reference(0), vtk.reference(0)
    hit = vtk.vtkBox.IntersectWithLine(bounds, list(map(float, p0)), list(map(float, p1)),
                                       t0, t1, x0, x1, plane0, plane1)
    return (np.array(x0), np.array(x1)) if hit else None


def shoelace(poly):
    p = np.asarray(poly, dtype=float)
    if len(p) < 3:
        return 0.0
    x, y = p[:, 0], p[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def area_3d(poly):
    p = np.asarray(poly, dtype=float)
    if len(p) < 3:
        return 0.0
    return 0.5 * np.linalg.norm(np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0))


def star_polygon(gen, centre, r_min, r_max, k):
    """A simple polygon with k vertices, counter-clockwise, star-shaped about `centre` (vertices
    by angle around it; redrawn until shapely finds it valid, as an angular gap over pi can
    make the closing edge cross the others)."""
    while True:
        ang = np.sort(gen.uniform(0, 2 * np.pi, k))
        rad = gen.uniform(r_min, r_max, k)
        poly = np.asarray(centre) + np.column_stack([rad * np.cos(ang), rad * np.sin(ang)])
        if Polygon(poly).is_valid:
            return poly


def convex_polygon(gen, centre, spread, k):
    pts = np.asarray(centre) + gen.normal(size=(k, 2)) * spread
    return pts[ConvexHull(pts).vertices]


# ---------------------------------------------------------------------------------------------
# outcodes
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("dim", [2, 3])
def test_outcode_matches_the_table(dim):
    gen = rng(1)
    for _ in range(50):
        lo, hi = random_box(gen, dim)
        pts = gen.uniform(lo - 1, hi + 1, (200, dim))
        # some coordinates exactly on the box's sides: on the boundary means inside
        mask = gen.random((200, dim)) < 0.2
        pts[mask] = np.where(gen.random(mask.sum()) < 0.5, np.broadcast_to(lo, pts.shape)[mask],
                             np.broadcast_to(hi, pts.shape)[mask])
        np.testing.assert_array_equal(C.outcode(pts, lo, hi), outcode_closed_form(pts, lo, hi))
    # a single point gives a Python int
    assert C.outcode([2.0, -1.0], [0, 0], [1, 1]) == 2 + 4
    assert isinstance(C.outcode([2.0, -1.0], [0, 0], [1, 1]), int)
    assert C.outcode([-1.0, 0.5, 5.0], [0, 0, 0], [1, 1, 1]) == 1 + 32
    assert C.outcode(np.zeros((2, 3, dim)), -np.ones(dim), np.ones(dim)).shape == (2, 3)


def test_describe_outcode_closed_forms():
    assert C.describe_outcode(0) == "0000 (inside)"
    assert C.describe_outcode(9) == "1001 (top, left)"
    assert C.describe_outcode(6) == "0110 (bottom, right)"
    assert C.describe_outcode(0, dim=3) == "000000 (inside)"
    assert C.describe_outcode(0b100010, dim=3) == "100010 (far, right)"
    assert C.describe_outcode(63, dim=3) == "111111 (far, near, top, bottom, right, left)"
    for dim in (2, 3):
        for code in range(2 ** (2 * dim)):
            text = C.describe_outcode(code, dim=dim)
            bits, sides = text.split(" ", 1)
            assert bits == bin(code)[2:].zfill(2 * dim)
            names = [BIT_NAMES[k] for k in range(2 * dim) if code & (1 << k)][::-1]
            assert sides == "(" + (", ".join(names) if names else "inside") + ")"


def test_describe_outcode_rejects_codes_that_do_not_exist():
    # BUG: describe_outcode does not check its code: describe_outcode(16) gives '10000 (inside)'
    # (5 bits, and the 'near' bit silently dropped in 2D), describe_outcode(-1) gives
    # '-001 (top, bottom, right, left)'. A code outside [0, 2**(2 dim)) should be a ValueError.
    failures = []
    for code, dim in [(16, 2), (64, 3), (-1, 2), (255, 2)]:
        try:
            failures.append(f"describe_outcode({code}, dim={dim}) = "
                            f"{C.describe_outcode(code, dim=dim)!r}")
        except ValueError as exc:
            if "code" not in str(exc):
                failures.append(f"{code}: {exc}")
    assert not failures, "\n".join(failures)


# ---------------------------------------------------------------------------------------------
# 2D segments against shapely
# ---------------------------------------------------------------------------------------------

ALGORITHMS = {"cohen_sutherland": (C.cohen_sutherland, C.cohen_sutherland_many),
              "liang_barsky": (C.liang_barsky, C.liang_barsky_many)}


@pytest.mark.parametrize("name", list(ALGORITHMS))
def test_2d_random_segments_match_shapely(name):
    single, many = ALGORITHMS[name]
    gen = rng(2)
    visible_total = 0
    for trial in range(6):
        lo, hi = (np.zeros(2), np.ones(2)) if trial == 0 else random_box(gen, 2)
        p0, p1 = random_segments(gen, 500, lo, hi)
        lines = shapely.linestrings(np.stack([p0, p1], axis=1))
        by_rect = shapely.clip_by_rect(lines, lo[0], lo[1], hi[0], hi[1])
        overlay = shapely.intersection(lines, shapely_box(lo[0], lo[1], hi[0], hi[1]))
        q0, q1, visible = many(p0, p1, lo, hi)
        for i in range(len(p0)):
            expected = shapely_segment(by_rect[i])
            assert (shapely_segment(overlay[i]) is None) == (expected is None)   # generic case
            assert bool(visible[i]) == (expected is not None), (p0[i], p1[i])
            got = single(p0[i], p1[i], lo, hi)
            assert (got is not None) == (expected is not None), (p0[i], p1[i])
            if expected is not None:
                assert same_segment_unordered(got, expected, 1e-9), (got, expected)
                assert same_segment_unordered((q0[i], q1[i]), expected, 1e-9)
                visible_total += 1
    assert 600 < visible_total < 2400                    # both outcomes well represented


def _special_segments():
    """(p0, p1) on the box [0, 1]^2, and what the closed box gives: None, or the segment."""
    return [
        # along a side, longer than it, and inside it
        (((-1, 0), (2, 0)), ((0, 0), (1, 0))),
        (((0.5, 1), (3, 1)), ((0.5, 1), (1, 1))),
        (((0, 0.2), (0, 0.8)), ((0, 0.2), (0, 0.8))),
        (((1, -1), (1, 2)), ((1, 0), (1, 1))),
        (((0, -5), (0, -1)), None),                                  # on the line, off the side
        # touching a corner, or a side, at one point
        (((-1, 1), (1, -1)), ((0, 0), (0, 0))),
        (((0, 2), (2, 0)), ((1, 1), (1, 1))),
        (((-1, 0.5), (0, 0.5)), ((0, 0.5), (0, 0.5))),
        (((1, 0.5), (3, 0.5)), ((1, 0.5), (1, 0.5))),
        (((0.5, 1), (0.7, 2)), ((0.5, 1), (0.5, 1))),
        (((-1, 0), (0, -1)), None),                                  # misses the corner
        # end points exactly on the sides
        (((0, 0.5), (1, 0.5)), ((0, 0.5), (1, 0.5))),
        (((0, 0.3), (0.5, 1)), ((0, 0.3), (0.5, 1))),
        (((0.5, 0), (2, 2)), ((0.5, 0), (1, 2 / 3))),
        (((0, 0), (1, 1)), ((0, 0), (1, 1))),
        # vertical and horizontal
        (((0.25, -3), (0.25, 3)), ((0.25, 0), (0.25, 1))),
        (((-3, 0.75), (3, 0.75)), ((0, 0.75), (1, 0.75))),
        (((1.5, -3), (1.5, 3)), None),
        (((-3, -0.1), (3, -0.1)), None),
        (((0.6, 0.2), (0.6, 0.9)), ((0.6, 0.2), (0.6, 0.9))),
        # zero length: inside, outside, on a side, at a corner
        (((0.5, 0.5), (0.5, 0.5)), ((0.5, 0.5), (0.5, 0.5))),
        (((2, 0.5), (2, 0.5)), None),
        (((0, 0.5), (0, 0.5)), ((0, 0.5), (0, 0.5))),
        (((1, 1), (1, 1)), ((1, 1), (1, 1))),
        (((-1e-300, 0.5), (-1e-300, 0.5)), None),
        # crossing the whole box
        (((-1, -1), (2, 2)), ((0, 0), (1, 1))),
        (((-1, 0.5), (2, 0.5)), ((0, 0.5), (1, 0.5))),
    ]


@pytest.mark.parametrize("segment, expected", _special_segments(),
                         ids=[str(s) for s, _ in _special_segments()])
def test_2d_special_segments(segment, expected):
    p0, p1 = map(np.array, segment)
    lo, hi = np.zeros(2), np.ones(2)
    for single, many in ALGORITHMS.values():
        got = single(p0, p1, lo, hi)
        q0, q1, visible = many(p0[None], p1[None], lo, hi)
        assert (got is None) == (expected is None) == (not visible[0]), (single.__name__, got)
        if expected is not None:
            assert same_segment_unordered(got, expected, 1e-12), (single.__name__, got)
            assert same_segment_unordered((q0[0], q1[0]), expected, 1e-12)
    # shapely's overlay agrees wherever it has a non-degenerate answer (not zero-length input)
    if np.any(p0 != p1):
        ref = shapely_segment(LineString([p0, p1]).intersection(shapely_box(0, 0, 1, 1)))
        assert (ref is None) == (expected is None)
        if ref is not None:
            assert same_segment_unordered(ref, expected, 1e-12)


def test_shapely_convention_differences_on_degenerate_segments():
    """Where shapely and we differ, by convention (boundary inside, zero-length segments)."""
    clip = lambda a, b: shapely.clip_by_rect(LineString([a, b]), 0, 0, 1, 1)   # noqa: E731
    over = lambda a, b: LineString([a, b]).intersection(shapely_box(0, 0, 1, 1))  # noqa: E731
    # a segment on a side: clip_by_rect drops it, the overlay and we keep it
    assert clip((-1, 0), (2, 0)).is_empty
    assert over((-1, 0), (2, 0)).equals(LineString([(0, 0), (1, 0)]))
    assert C.liang_barsky([-1, 0], [2, 0], [0, 0], [1, 1]) is not None
    # touching a corner: clip_by_rect empty, the overlay a POINT, we a degenerate segment
    assert clip((-1, 1), (1, -1)).is_empty
    assert over((-1, 1), (1, -1)).geom_type == "Point"
    q0, q1 = C.cohen_sutherland([-1, 1], [1, -1], [0, 0], [1, 1])
    np.testing.assert_array_equal(q0, q1)
    np.testing.assert_allclose(q0, [0, 0], atol=1e-15)
    # a zero-length segment inside: clip_by_rect keeps it, the overlay drops it, we keep it
    assert not clip((0.5, 0.5), (0.5, 0.5)).is_empty
    assert over((0.5, 0.5), (0.5, 0.5)).is_empty
    assert C.liang_barsky([0.5, 0.5], [0.5, 0.5], [0, 0], [1, 1]) is not None
    # a zero-length segment on the boundary: both shapely functions drop it, we keep it
    assert clip((0, 0.5), (0, 0.5)).is_empty and over((0, 0.5), (0, 0.5)).is_empty
    assert C.cohen_sutherland([0, 0.5], [0, 0.5], [0, 0], [1, 1]) is not None


@pytest.mark.parametrize("dim", [2, 3])
def test_single_and_many_agree_and_algorithms_agree(dim):
    gen = rng(3)
    for _ in range(4):
        lo, hi = random_box(gen, dim)
        p0, p1 = random_segments(gen, 500, lo, hi)
        results = {}
        for name, (single, many) in ALGORITHMS.items():
            q0, q1, visible = many(p0, p1, lo, hi)
            assert q0.shape == q1.shape == p0.shape and visible.shape == (len(p0),)
            singles = [single(a, b, lo, hi) for a, b in zip(p0, p1)]
            np.testing.assert_array_equal([g is not None for g in singles], visible)
            got = np.array([g for g in singles if g is not None])      # (visible, 2, d)
            np.testing.assert_allclose(got[:, 0], q0[visible], rtol=0, atol=1e-12)
            np.testing.assert_allclose(got[:, 1], q1[visible], rtol=0, atol=1e-12)
            # the clipped points are in the box, and on the original segment, in its order
            tol = 1e-12 * max(1.0, np.abs(np.concatenate([lo, hi])).max())
            assert np.all(q0[visible] >= lo - tol) and np.all(q0[visible] <= hi + tol)
            assert np.all(q1[visible] >= lo - tol) and np.all(q1[visible] <= hi + tol)
            d = p1 - p0
            s0 = np.einsum("ij,ij->i", q0 - p0, d) / np.einsum("ij,ij->i", d, d)
            s1 = np.einsum("ij,ij->i", q1 - p0, d) / np.einsum("ij,ij->i", d, d)
            assert np.all(s0[visible] >= -1e-12) and np.all(s1[visible] <= 1 + 1e-12)
            assert np.all(s0[visible] <= s1[visible] + 1e-12)
            results[name] = (q0, q1, visible)
        (a0, a1, av), (b0, b1, bv) = results.values()
        np.testing.assert_array_equal(av, bv)
        np.testing.assert_allclose(a0[av], b0[av], rtol=0, atol=1e-12)
        np.testing.assert_allclose(a1[av], b1[av], rtol=0, atol=1e-12)


def test_cohen_sutherland_many_accepts_what_liang_barsky_many_accepts():
    # BUG: cohen_sutherland_many validates p0/p1 with as_points (any (..., d) shape), like
    # liang_barsky_many, but only works for (n, d): one (d,) segment crashes with
    # "AttributeError: 'bool' object has no attribute 'any'" (outcode returns a Python int), a
    # stacked (k, m, d) array with an IndexError (flat indices used on the first axis).
    # liang_barsky_many handles both. Either work the same, or raise a ValueError naming p0.
    gen = rng(4)
    lo, hi = np.zeros(3), np.ones(3)
    failures = []
    for shape in [(3,), (2, 3, 3)]:
        p0, p1 = gen.uniform(-1, 2, shape), gen.uniform(-1, 2, shape)
        try:
            got = C.cohen_sutherland_many(p0, p1, lo, hi)
        except ValueError as exc:
            if "p0" not in str(exc):
                failures.append(f"{shape}: {exc}")
            continue
        except Exception as exc:                      # noqa: BLE001 - the wrong kind of error
            failures.append(f"shape {shape}: {type(exc).__name__}: {exc}")
            continue
        expected = C.liang_barsky_many(p0, p1, lo, hi)
        if not np.array_equal(got[2], expected[2]):
            failures.append(f"shape {shape}: visibility differs from liang_barsky_many")
    assert not failures, "\n".join(failures)


def test_cohen_sutherland_many_returns_rejected_segments_unchanged():
    # BUG (code or docstring): cohen_sutherland_many documents q0, q1 as "The clipped end points
    # (unchanged where a segment is rejected)", but a segment rejected only after a clip comes
    # back half clipped: cohen_sutherland_many([[-1, 0.9]], [[0.5, 3]], [0, 0], [1, 1]) gives
    # q0 = [[0, 2.3]] (p0 moved onto x = 0, then the segment is rejected as above the box).
    q0, q1, visible = C.cohen_sutherland_many([[-1, 0.9]], [[0.5, 3]], [0, 0], [1, 1])
    assert not visible[0]
    np.testing.assert_array_equal(q0, [[-1, 0.9]])
    np.testing.assert_array_equal(q1, [[0.5, 3]])
    gen = rng(41)
    p0, p1 = random_segments(gen, 1000, np.zeros(2), np.ones(2))
    q0, q1, visible = C.cohen_sutherland_many(p0, p1, [0, 0], [1, 1])
    np.testing.assert_array_equal(q0[~visible], p0[~visible])
    np.testing.assert_array_equal(q1[~visible], p1[~visible])


def test_many_with_no_segments():
    for _, many in ALGORITHMS.values():
        q0, q1, visible = many(np.zeros((0, 2)), np.zeros((0, 2)), [0, 0], [1, 1])
        assert q0.shape == (0, 2) and q1.shape == (0, 2) and visible.shape == (0,)


# ---------------------------------------------------------------------------------------------
# 3D segments against VTK
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", list(ALGORITHMS))
def test_3d_random_segments_match_vtk_box(name):
    single, many = ALGORITHMS[name]
    gen = rng(5)
    visible_total = 0
    for trial in range(5):
        lo, hi = (-np.ones(3), np.ones(3)) if trial == 0 else random_box(gen, 3)
        p0, p1 = random_segments(gen, 600, lo, hi)
        # a few end points inside, and a few with coordinates exactly on the sides
        p0[:60] = gen.uniform(lo, hi, (60, 3))
        p1[60:80, 0] = hi[0]
        q0, q1, visible = many(p0, p1, lo, hi)
        for i in range(len(p0)):
            expected = vtk_clip(lo, hi, p0[i], p1[i])
            got = single(p0[i], p1[i], lo, hi)
            assert (got is not None) == (expected is not None) == bool(visible[i]), (p0[i], p1[i])
            if expected is not None:
                # VTK keeps the segment's direction: compare in order
                np.testing.assert_allclose(got, expected, rtol=0, atol=1e-9)
                np.testing.assert_allclose((q0[i], q1[i]), expected, rtol=0, atol=1e-9)
                visible_total += 1
    assert 300 < visible_total < 2700


@pytest.mark.parametrize("segment", [
    ((-1, 0, 0), (2, 0, 0)),             # along an edge of the unit box
    ((0, -1, 0.5), (0, 2, 0.5)),          # in a face
    ((0, 0.2, 0.3), (0, 0.6, 0.9)),       # inside a face
    ((-1, -1, -1), (0, 0, 0)),            # touches a corner
    ((-1, 0.5, 0.5), (0, 0.5, 0.5)),      # touches a face
    ((0.5, 0.5, 0.5), (0.5, 0.5, 0.5)),   # zero length, inside
    ((0, 0, 1), (0, 0, 1)),               # zero length, at a corner
    ((0.5, 0.5, 1), (0.5, 0.5, 1)),       # zero length, on a face
    ((-1, 0.5, 0.5), (-1, 0.5, 0.5)),     # zero length, outside
    ((-1, 1.5, 0.5), (1.5, -1, 0.5)),     # misses an edge... just
    ((0.5, 0.5, -2), (0.5, 0.5, 3)),      # along z through the middle
    ((2, 2, 2), (3, -1, 0.5)),            # outside
], ids=str)
def test_3d_special_segments_match_vtk(segment):
    p0, p1 = map(np.array, segment)
    lo, hi = np.zeros(3), np.ones(3)
    expected = vtk_clip(lo, hi, p0, p1)
    for single, many in ALGORITHMS.values():
        got = single(p0, p1, lo, hi)
        q0, q1, visible = many(p0[None], p1[None], lo, hi)
        assert (got is None) == (expected is None) == (not visible[0]), single.__name__
        if expected is not None:
            np.testing.assert_allclose(got, expected, atol=1e-12)
            np.testing.assert_allclose((q0[0], q1[0]), expected, atol=1e-12)


def test_clip_segment_with_box_planes_matches_vtk():
    gen = rng(6)
    lo, hi = random_box(gen, 3)
    p0, p1 = random_segments(gen, 1000, lo, hi)
    planes = C.box_planes(lo, hi)
    for a, b in zip(p0, p1):
        expected = vtk_clip(lo, hi, a, b)
        got = C.clip_segment(a, b, planes)
        assert (got is None) == (expected is None)
        if expected is not None:
            np.testing.assert_allclose(got, expected, atol=1e-9)


def test_box_planes_closed_form():
    planes = C.box_planes([-1, 0, 2], [1, 3, 5])
    assert [name for name, _, _ in planes] == list(BIT_NAMES)
    expected = [([-1, 0, 0], 1), ([1, 0, 0], 1), ([0, -1, 0], 0), ([0, 1, 0], 3),
                ([0, 0, -1], -2), ([0, 0, 1], 5)]
    for (_, n, c), (n_exp, c_exp) in zip(planes, expected):
        np.testing.assert_array_equal(n, n_exp)
        assert c == c_exp


# ---------------------------------------------------------------------------------------------
# the step-by-step versions
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("dim", [2, 3])
def test_cohen_sutherland_steps(dim):
    gen = rng(7)
    max_clips = 0
    for _ in range(12):
        lo, hi = random_box(gen, dim)
        p0, p1 = random_segments(gen, 100, lo, hi)
        for a, b in zip(p0, p1):
            result, steps = C.cohen_sutherland_steps(a, b, lo, hi)
            assert steps[-1]["action"] in ("accept", "reject")
            assert all(s["action"] == "clip" for s in steps[:-1])
            clips = len(steps) - 1
            assert clips <= 2 * dim
            max_clips = max(max_clips, clips)
            assert np.array_equal(steps[0]["p0"], a) and np.array_equal(steps[0]["p1"], b)
            for k, s in enumerate(steps):
                c0, c1 = outcode_closed_form(s["p0"], lo, hi), outcode_closed_form(s["p1"], lo, hi)
                assert (s["code0"], s["code1"]) == (c0, c1)
                if s["action"] == "accept":
                    assert c0 == 0 and c1 == 0
                elif s["action"] == "reject":
                    assert c0 & c1 != 0
                else:
                    assert c0 | c1 != 0 and c0 & c1 == 0
                    e = s["endpoint"]
                    assert e == (0 if c0 else 1)                     # the outside end first
                    code = (c0, c1)[e]
                    bit = BIT_NAMES.index(s["side"])
                    assert code & (1 << bit)
                    assert code & ((1 << bit) - 1) == 0              # the lowest bit
                    nxt = steps[k + 1]
                    assert np.array_equal(nxt[f"p{e}"], s["new_point"])
                    assert np.array_equal(nxt[f"p{1 - e}"], s[f"p{1 - e}"])
                    assert not nxt[f"code{e}"] & (1 << bit)          # that bit is gone
                    # the new point is on the side's line / plane, and on the segment
                    axis, limit = bit // 2, (lo, hi)[bit % 2][bit // 2]
                    assert s["new_point"][axis] == limit
                    d = s["p1"] - s["p0"]
                    off = s["new_point"] - s["p0"]
                    assert np.linalg.norm(np.cross(off, d) if dim == 3 else
                                          off[0] * d[1] - off[1] * d[0]) <= 1e-9 * (d @ d + 1)
            if steps[-1]["action"] == "accept":
                assert np.array_equal(result[0], steps[-1]["p0"])
                assert np.array_equal(result[1], steps[-1]["p1"])
            else:
                assert result is None
    assert max_clips >= 3                       # the long cases were exercised


@pytest.mark.parametrize("dim", [2, 3])
def test_liang_barsky_steps(dim):
    gen = rng(8)
    for _ in range(20):
        lo, hi = random_box(gen, dim)
        p0, p1 = random_segments(gen, 100, lo, hi)
        p1[:10, 0] = p0[:10, 0]                 # some parallel to a side
        for a, b in zip(p0, p1):
            result, steps = C.liang_barsky_steps(a, b, lo, hi)
            d = b - a
            t_in, t_out = 0.0, 1.0
            for k, s in enumerate(steps):
                assert s["side"] == BIT_NAMES[k]
                axis = k // 2
                if k % 2 == 0:
                    p, q = -d[axis], a[axis] - lo[axis]
                else:
                    p, q = d[axis], hi[axis] - a[axis]
                assert s["p"] == p and s["q"] == q
                if p == 0:
                    assert s["t"] is None
                    assert s["kind"] == ("parallel inside" if q >= 0 else "parallel outside")
                else:
                    assert s["t"] == q / p
                    assert s["kind"] == ("entering" if p < 0 else "leaving")
                assert s["t_in"] >= t_in and s["t_out"] <= t_out
                t_in, t_out = s["t_in"], s["t_out"]
            empty = t_in > t_out
            assert len(steps) == 2 * dim or empty        # stops early only when empty
            assert all(s["t_in"] <= s["t_out"] for s in steps[:-1])
            if empty:
                assert result is None
            else:
                assert len(steps) == 2 * dim
                np.testing.assert_allclose(result[0], a + t_in * d, atol=1e-15)
                np.testing.assert_allclose(result[1], a + t_out * d, atol=1e-15)


def test_steps_closed_form_examples():
    result, steps = C.liang_barsky_steps([-1, 0.5], [3, 0.5], [0, 0], [2, 1])
    assert [(s["side"], s["kind"], s["t"]) for s in steps] == [
        ("left", "entering", 0.25), ("right", "leaving", 0.75),
        ("bottom", "parallel inside", None), ("top", "parallel inside", None)]
    np.testing.assert_allclose(result, [[0, 0.5], [2, 0.5]])
    result, steps = C.cohen_sutherland_steps([-1, 0.5], [2, 0.5], [0, 0], [1, 1])
    assert [(s["action"], s.get("side")) for s in steps] == [("clip", "left"), ("clip", "right"),
                                                             ("accept", None)]
    # left and then top: (-1, 0) -> (3, 4) on [0, 2]^2 enters at (0, 1), leaves at (1, 2)
    result, steps = C.cohen_sutherland_steps([-1, 0], [3, 4], [0, 0], [2, 2])
    np.testing.assert_allclose(result, [[0, 1], [1, 2]], atol=1e-15)
    assert [s.get("side") for s in steps] == ["left", "right", "top", None]


# ---------------------------------------------------------------------------------------------
# polygons: Sutherland-Hodgman against shapely
# ---------------------------------------------------------------------------------------------

def _random_polygons(gen, lo, hi, n):
    size = hi - lo
    out = []
    for i in range(n):
        centre = gen.uniform(lo - size / 2, hi + size / 2)
        kind = i % 3
        if kind == 0:
            poly = convex_polygon(gen, centre, size.mean() * gen.uniform(0.2, 1), 12)
        elif kind == 1:
            poly = star_polygon(gen, centre, 0.1 * size.mean(), size.mean(), gen.integers(3, 25))
        else:
            # vertices snapped exactly onto the clip lines: edges along the box's sides
            poly = star_polygon(gen, centre, 0.2 * size.mean(), size.mean(), gen.integers(5, 25))
            for k in range(2):
                for v in (lo[k], hi[k]):
                    near = np.abs(poly[:, k] - v) < 0.15 * size[k]
                    poly[near, k] = v
        if Polygon(poly).is_valid:                      # keep simple polygons only
            out.append(poly)
    return out


def test_sutherland_hodgman_area_matches_shapely():
    gen = rng(9)
    count = nonempty = on_lines = 0
    for trial in range(8):
        lo, hi = (np.zeros(2), np.ones(2)) if trial == 0 else random_box(gen, 2)
        polys = _random_polygons(gen, lo, hi, 300)
        # the overlay, not clip_by_rect: see the test with vertices on box corners below
        ref = shapely.area(shapely.intersection([Polygon(p) for p in polys],
                                                shapely_box(*lo, *hi)))
        for poly, expected in zip(polys, ref):
            got = C.sutherland_hodgman(poly, lo, hi)
            assert got.ndim == 2 and got.shape[1] == 2
            assert shoelace(got) == pytest.approx(expected, rel=1e-9, abs=1e-12)
            if len(got):
                assert np.all(got >= lo - 1e-12) and np.all(got <= hi + 1e-12)
                nonempty += expected > 0
            on_lines += np.any(np.isin(poly, np.concatenate([lo, hi])))
            count += 1
    assert count > 2000 and nonempty > 800 and on_lines > 300


def test_sutherland_hodgman_polygon_missing_the_box_gives_nothing():
    gen = rng(10)
    lo, hi = np.zeros(2), np.ones(2)
    for _ in range(300):
        poly = star_polygon(gen, [0, 0], 0.1, 1, 8)
        side = gen.integers(4)
        k, beyond = side // 2, side % 2
        # shift the whole polygon beyond one side
        shift = np.zeros(2)
        shift[k] = (poly[:, k].max() - lo[k] + gen.uniform(0, 1) if beyond == 0
                    else hi[k] - poly[:, k].min() + gen.uniform(0, 1))
        moved = poly - shift if beyond == 0 else poly + shift
        got = C.sutherland_hodgman(moved, lo, hi)
        assert got.shape == (0, 2)


def test_sutherland_hodgman_polygon_wrapped_around_the_box_encloses_no_area():
    # a C shape around the unit box: it misses the box, but Sutherland-Hodgman (which clips the
    # closed outline, not the region) leaves a degenerate polygon along the boundary, as its
    # docstring says for non-convex polygons; what matters is that it encloses no area
    c_shape = [(-1, -1), (2, -1), (2, -0.5), (-0.5, -0.5), (-0.5, 1.5), (2, 1.5), (2, 2), (-1, 2)]
    assert shapely.clip_by_rect(Polygon(c_shape), 0, 0, 1, 1).is_empty
    got = C.sutherland_hodgman(c_shape, [0, 0], [1, 1])
    assert shoelace(got) == 0.0
    assert np.all((got >= 0) & (got <= 1))


def test_sutherland_hodgman_polygon_containing_the_box_gives_the_box():
    gen = rng(11)
    for _ in range(200):
        lo, hi = random_box(gen, 2)
        centre = (lo + hi) / 2
        radius = np.linalg.norm(hi - lo)               # every vertex beyond the box's corners
        poly = star_polygon(gen, centre, 1.5 * radius, 3 * radius, 3)
        if not Polygon(poly).contains(shapely_box(*lo, *hi)):
            continue
        got = C.sutherland_hodgman(poly, lo, hi)
        corners = {(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])}
        assert {tuple(v) for v in np.round(got, 12)} == {tuple(np.round(c, 12)) for c in corners}
        assert shoelace(got) == pytest.approx(np.prod(hi - lo), rel=1e-12)


def test_sutherland_hodgman_steps_one_per_side_in_order():
    gen = rng(12)
    for dim in (2, 3):
        for _ in range(100):
            lo, hi = random_box(gen, dim)
            if dim == 2:
                poly = star_polygon(gen, (lo + hi) / 2, 0.3, 3, 10)
            else:
                poly = _planar_polygon_3d(gen, (lo + hi) / 2)[0]
            steps = C.sutherland_hodgman_steps(poly, lo, hi)
            assert [name for name, _ in steps] == list(BIT_NAMES[:2 * dim])
            for k, (_, p) in enumerate(steps):
                if len(p) == 0:
                    continue
                for j in range(k + 1):                  # inside this and every earlier side
                    axis = j // 2
                    if j % 2 == 0:
                        assert np.all(p[:, axis] >= lo[axis] - 1e-12)
                    else:
                        assert np.all(p[:, axis] <= hi[axis] + 1e-12)
            np.testing.assert_array_equal(steps[-1][1], C.sutherland_hodgman(poly, lo, hi))


def test_sutherland_hodgman_polygon_with_vertices_on_box_corners_closed_form():
    # vertices on two corners of the unit box; inside the box the polygon is the box minus the
    # notch (0, 0), (0.625, 0), (0.25, 0.25) (the edge (0.25, 0.25) -> (1, -0.25) meets y = 0 at
    # x = 0.625): area 1 - 0.5 * 0.625 * 0.25. (shapely.clip_by_rect, GEOS's rectangle
    # intersection, gets this one wrong in the installed shapely 2.2 / GEOS: it returns the
    # notch, area 0.078125; the overlay shapely.intersection gets 0.921875. That is why the
    # polygon comparisons use the overlay.)
    poly = [(1, 2), (0, 1), (0, 0), (0.25, 0.25), (1, -0.25)]
    expected = 1 - 0.5 * 0.625 * 0.25
    assert Polygon(poly).intersection(shapely_box(0, 0, 1, 1)).area == pytest.approx(expected)
    assert shoelace(C.sutherland_hodgman(poly, [0, 0], [1, 1])) == pytest.approx(expected,
                                                                                 rel=1e-14)


def test_sutherland_hodgman_closed_form_triangle():
    # the triangle (-1, -1), (3, -1), (1, 3) on [0, 2]^2: closed-form area by hand.
    # The triangle minus the box: its part below y = 0 is a trapezoid... compute it as
    # box area minus the two corner triangles cut off at the top: the sides x = 1 -+ (3 - y) / 2
    # meet y = 2 at x = 0.5 and 1.5 and x = 0 / 2 at y = 1; each cut corner is 0.5 * 0.5 * 1.
    got = C.sutherland_hodgman([[-1, -1], [3, -1], [1, 3]], [0, 0], [2, 2])
    assert shoelace(got) == pytest.approx(4 - 2 * 0.25, rel=1e-14)


# 3D planar polygons

def _planar_polygon_3d(gen, centre):
    rot = Rotation.random(rng=gen).as_matrix()
    e1, e2 = rot[:, 0], rot[:, 1]
    uv = star_polygon(gen, [0, 0], 0.3, 2.5, gen.integers(3, 16))
    return centre + uv[:, :1] * e1 + uv[:, 1:] * e2, uv, e1, e2


def _box_cross_section(lo, hi, centre, e1, e2):
    """The plane's cross-section of the box, in the plane's (u, v) coordinates (scipy)."""
    basis = np.column_stack([e1, e2])                   # x = centre + basis @ (u, v)
    # lo <= centre + basis (u, v) <= hi as rows [A, b] with A (u, v) + b <= 0
    rows = np.vstack([np.column_stack([-basis, lo - centre]),
                      np.column_stack([basis, centre - hi])])
    hs = HalfspaceIntersection(rows, np.zeros(2))
    pts = hs.intersections
    return Polygon(pts[ConvexHull(pts).vertices])


def test_sutherland_hodgman_3d_planar_polygon():
    gen = rng(13)
    checked = 0
    for _ in range(300):
        lo, hi = random_box(gen, 3)
        centre = gen.uniform(lo + 0.05 * (hi - lo), hi - 0.05 * (hi - lo))   # inside the box
        poly, uv, e1, e2 = _planar_polygon_3d(gen, centre)
        if not Polygon(uv).is_valid:
            continue
        got = C.sutherland_hodgman(poly, lo, hi)
        expected = Polygon(uv).intersection(_box_cross_section(lo, hi, centre, e1, e2)).area
        assert area_3d(got) == pytest.approx(expected, rel=1e-9, abs=1e-12)
        if len(got):
            normal = np.cross(e1, e2)
            np.testing.assert_allclose((got - centre) @ normal, 0, atol=1e-12)   # in the plane
            assert np.all(got >= lo - 1e-12) and np.all(got <= hi + 1e-12)
            back = np.column_stack([(got - centre) @ e1, (got - centre) @ e2])
            assert shoelace(back) == pytest.approx(expected, rel=1e-9, abs=1e-12)
            checked += 1
    assert checked > 200


# ---------------------------------------------------------------------------------------------
# arbitrary half-spaces and view volumes
# ---------------------------------------------------------------------------------------------

def test_clip_polygon_with_arbitrary_half_planes_matches_shapely():
    gen = rng(14)
    for _ in range(300):
        k = gen.integers(3, 8)
        ang = gen.uniform(0, 2 * np.pi, k)
        normals = np.column_stack([np.cos(ang), np.sin(ang)]) * gen.uniform(0.5, 2, (k, 1))
        offsets = gen.uniform(0.3, 2, k)                   # the origin is inside every one
        planes = list(zip(normals, offsets))
        # the region n . x <= c, bounded by a big square, built by scipy
        big = [(np.array(n), 50.0) for n in ([1, 0], [-1, 0], [0, 1], [0, -1])]
        rows = np.array([[*n, -c] for n, c in planes + big])
        hs = HalfspaceIntersection(rows, np.zeros(2))
        region = Polygon(hs.intersections[ConvexHull(hs.intersections).vertices])
        poly = star_polygon(gen, gen.uniform(-1, 1, 2), 0.2, 3, gen.integers(3, 20))
        got = C.clip_polygon(poly, planes)
        expected = Polygon(poly).intersection(region).area
        assert shoelace(got) == pytest.approx(expected, rel=1e-9, abs=1e-12)
        if len(got):
            assert np.all(got @ normals.T <= offsets + 1e-12)
    steps = C.clip_polygon_steps([[0, 0], [2, 0], [0, 2]], [([1, 0], 1), ("named", [0, 1], 1)])
    assert [name for name, _ in steps] == ["0", "named"]


def test_view_volume_planes_agree_with_the_canonical_cube():
    gen = rng(15)
    inside_total = outside_total = 0
    for _ in range(50):
        eye = gen.uniform(-5, 5, 3)
        gaze = gen.normal(size=3)
        up = gen.normal(size=3)
        near = gen.uniform(0.1, 1)
        m = V.perspective(gen.uniform(0.3, 2.5), gen.uniform(0.5, 2), near,
                          near + gen.uniform(1, 20)) @ V.look_at(eye, gaze, up)
        planes = C.view_volume_planes(m)
        assert [name for name, _, _ in planes] == list(BIT_NAMES)
        g = gaze / np.linalg.norm(gaze)
        pts = eye + gen.uniform(-3, 25, (400, 1)) * g + gen.normal(size=(400, 3)) * 5
        w = np.concatenate([pts, np.ones((400, 1))], axis=1) @ m[3]
        pts = pts[np.abs(w) > 1e-3]
        ndc = transforms.apply(m, pts)
        in_cube = np.all(np.abs(ndc) <= 1, axis=1)
        in_planes = np.all([pts @ n <= c for _, n, c in planes], axis=0)
        clear = np.all(np.abs(np.abs(ndc) - 1) > 1e-9, axis=1)
        np.testing.assert_array_equal(in_planes[clear], in_cube[clear])
        inside_total += in_cube[clear].sum()
        outside_total += (~in_cube[clear]).sum()
    assert inside_total > 500 and outside_total > 500


def test_view_volume_planes_of_an_orthographic_matrix_are_the_box():
    planes = C.view_volume_planes(V.orthographic(-2, 3, -1, 4, 1, 10))
    # eye-space box [-2, 3] x [-1, 4] x [-10, -1]: unit normals and offsets typed out
    expected = [([-1, 0, 0], 2), ([1, 0, 0], 3), ([0, -1, 0], 1), ([0, 1, 0], 4),
                ([0, 0, 1], -1), ([0, 0, -1], 10)]
    for (_, n, c), (n_exp, c_exp) in zip(planes, expected):
        length = np.linalg.norm(n)
        np.testing.assert_allclose(n / length, n_exp, atol=1e-15)
        assert c / length == pytest.approx(c_exp, rel=1e-12)


def test_clip_segment_against_a_frustum():
    gen = rng(16)
    m = V.perspective(1.2, 1.5, 0.5, 30) @ V.look_at([1, 2, 3], [-1, -2, -3], [0, 1, 0])
    planes = C.view_volume_planes(m)
    for _ in range(500):
        a, b = gen.normal(size=(2, 3)) * 6
        got = C.clip_segment(a, b, planes)
        s = np.linspace(0, 1, 201)
        line = a + s[:, None] * (b - a)
        inside = np.all([line @ n <= c + 1e-12 for _, n, c in planes], axis=0)
        if got is None:
            assert not inside.any()
        else:
            for q in got:                          # the end points are in the view volume
                assert all(q @ n <= c + 1e-9 * (1 + abs(c)) for _, n, c in planes)
            # samples of the segment inside the volume lie between the clipped end points
            d = b - a
            t0, t1 = ((np.array(got) - a) @ d) / (d @ d)
            assert np.all((s[inside] >= t0 - 1e-9) & (s[inside] <= t1 + 1e-9))


# ---------------------------------------------------------------------------------------------
# back faces
# ---------------------------------------------------------------------------------------------

def test_is_back_face_is_the_sign_of_the_dot_product():
    gen = rng(17)
    n = gen.normal(size=(1000, 3))
    v = gen.normal(size=(1000, 3))
    v[:50] = np.cross(n[:50], gen.normal(size=(50, 3)))     # (nearly) edge-on ones
    n[50:60] = [[0, 0, 2], [1, 0, 0], [0, -3, 0], [1, 1, 0], [0, 0, 1]] * 2
    v[50:60] = [[1, 1, 0], [0, 5, 1], [2, 0, 7], [1, -1, 3], [0, 0, 0]] * 2   # exactly edge-on
    expected = np.einsum("ij,ij->i", n, v) >= 0
    np.testing.assert_array_equal(C.is_back_face(n, v), expected)
    # broadcasting: one view vector for all normals, and stacks
    np.testing.assert_array_equal(C.is_back_face(n, v[0]), n @ v[0] >= 0)
    stack = n.reshape(10, 100, 3)
    assert C.is_back_face(stack, v[:100]).shape == (10, 100)
    np.testing.assert_array_equal(C.is_back_face(stack, v[:100]),
                                  np.einsum("kij,ij->ki", stack, v[:100]) >= 0)
    # single vectors give a Python bool; edge-on counts as a back face
    assert C.is_back_face([0, 0, 1], [0, 0, -1]) is False
    assert C.is_back_face([0, 0, -1], [0, 0, -1]) is True
    assert C.is_back_face([1, 0, 0], [0, 0, -1]) is True


def _oriented_hull(points):
    """A convex mesh from scipy's hull, triangles turned counter-clockwise seen from outside."""
    hull = ConvexHull(points)
    faces = hull.simplices.copy()
    for i, (a, b, c) in enumerate(faces):
        if np.cross(points[b] - points[a], points[c] - points[a]) @ hull.equations[i, :3] < 0:
            faces[i] = [a, c, b]
    return faces, hull.equations


def _meshes():
    phi = (1 + 5 ** 0.5) / 2
    ico = np.array([[0, s1, s2 * phi] for s1 in (-1, 1) for s2 in (-1, 1)]
                   + [[s1, s2 * phi, 0] for s1 in (-1, 1) for s2 in (-1, 1)]
                   + [[s2 * phi, 0, s1] for s1 in (-1, 1) for s2 in (-1, 1)], dtype=float)
    tet = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float)
    sphere = rng(18).normal(size=(200, 3))
    sphere /= np.linalg.norm(sphere, axis=1, keepdims=True)
    out = {}
    for name, pts in (("tetrahedron", tet), ("icosahedron", ico), ("sphere", sphere)):
        faces, eq = _oriented_hull(pts)
        out[name] = (pts, faces, eq[:, :3], eq[:, 3])
    # the cube with quads, counter-clockwise from outside (checked: normal . outward axis > 0)
    cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], float) - 0.5
    quads = np.array([[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4],
                      [1, 5, 7, 3]])
    axes = np.array([[-1, 0, 0], [1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, -1], [0, 0, 1]], float)
    for q, axis in zip(quads, axes):
        a, b, c = cube[q[:3]]
        assert np.cross(b - a, c - a) @ axis > 0
    out["cube"] = (cube, quads, axes, -0.5 * np.ones(6))
    return out


MESHES = _meshes()


@pytest.mark.parametrize("mesh", list(MESHES))
def test_back_faces_from_an_eye_outside_a_convex_mesh(mesh):
    pts, faces, normals, offsets = MESHES[mesh]          # inside: normal . x + offset <= 0
    gen = rng(19)
    for _ in range(200):
        eye = gen.normal(size=3)
        eye *= gen.uniform(1.8, 20) / np.linalg.norm(eye)
        dist = normals @ eye + offsets                    # > 0: the eye is beyond the face
        if np.abs(dist).min() < 1e-9:
            continue
        # a face is seen exactly when its plane separates the eye from the interior
        np.testing.assert_array_equal(C.back_faces(pts, faces, eye=eye), dist <= 0)


@pytest.mark.parametrize("mesh", list(MESHES))
def test_back_faces_with_a_view_direction(mesh):
    pts, faces, normals, _ = MESHES[mesh]
    gen = rng(20)
    for _ in range(200):
        d = gen.normal(size=3) * gen.uniform(0.1, 10)
        culled = C.back_faces(pts, faces, direction=d)
        np.testing.assert_array_equal(~culled, normals @ d < 0)
        # the seen faces' projected areas add up to the silhouette's area (a convex mesh)
        dh = d / np.linalg.norm(d)
        tri = pts[faces]
        area_vectors = 0.5 * np.cross(tri, np.roll(tri, -1, axis=1)).sum(axis=1)
        projected = -(area_vectors[~culled] @ dh)
        basis = np.linalg.svd(dh[None])[2][1:]           # two unit vectors across d
        silhouette = ConvexHull(pts @ basis.T).volume    # "volume" of a 2D hull is its area
        assert projected.sum() == pytest.approx(silhouette, rel=1e-9)


def test_back_faces_edge_on_faces_are_culled():
    pts, faces, _, _ = MESHES["cube"]
    # looking along +x: only the -x face (normal -x) is seen; the four side faces are edge-on
    np.testing.assert_array_equal(C.back_faces(pts, faces, direction=[1, 0, 0]),
                                  [False, True, True, True, True, True])


def test_back_faces_in_css_need_direction_0_0_minus_1():
    """The projection to CSS mirrors z (CSS is left-handed, det < 0), which reverses the winding
    of every face: normals computed from CSS coordinates point inwards. The documented recipe,
    direction (0, 0, -1) in CSS, agrees with the world-space test from the eye; (0, 0, 1), the
    viewing direction itself, gives exactly the complement."""
    pts, faces, _, _ = MESHES["cube"]
    gen = rng(21)
    for _ in range(20):
        eye = gen.normal(size=3)
        eye *= gen.uniform(3, 10) / np.linalg.norm(eye)
        m = V.perspective(1.0, 1.0, 0.5, 50) @ V.look_at(eye, -eye, [0.3, 1, 0.2])
        css = transforms.apply(m, pts)
        world = C.back_faces(pts, faces, eye=eye)
        np.testing.assert_array_equal(C.back_faces(css, faces, direction=[0, 0, -1]), world)
        np.testing.assert_array_equal(C.back_faces(css, faces, direction=[0, 0, 1]), ~world)


@pytest.mark.filterwarnings("ignore:clipping.face_normals is deprecated")
def test_face_normals_closed_form():
    # Newell: twice the area vector; a 2 x 3 rectangle in the xy plane, counter-clockwise
    np.testing.assert_allclose(C.face_normals([[0, 0, 0], [2, 0, 0], [2, 3, 0], [0, 3, 0]],
                                              [[0, 1, 2, 3]]), [[0, 0, 12]])
    # a non-convex (L-shaped) face, area 3, in the plane x = 1, counter-clockwise seen from +x
    ell = [[1, 0, 0], [1, 2, 0], [1, 2, 1], [1, 1, 1], [1, 1, 2], [1, 0, 2]]
    np.testing.assert_allclose(C.face_normals(ell, [list(range(6))]), [[6, 0, 0]], atol=1e-15)



def test_face_cross_products_are_the_old_face_normals_and_mesh_normals_their_direction():
    # one function for each concept: clipping.face_cross_products is mesh's, clipping's old
    # name still works but warns (it is not unit length), mesh.face_normals is its direction
    from course_lib import draw, mesh, shading
    assert C.face_cross_products is mesh.face_cross_products
    assert shading.face_normals is mesh.face_normals is draw.face_normals
    rng = np.random.default_rng(5)
    v = rng.normal(size=(30, 3)) + [1e3, 0, 0]           # far from the origin
    f = rng.permuted(np.tile(np.arange(30), (12, 1)), axis=1)[:, :5]
    with pytest.warns(DeprecationWarning, match="face_cross_products"):
        old = C.face_normals(v, f)
    c = C.face_cross_products(v, f)
    np.testing.assert_array_equal(old, c)
    p = v[f]                                              # Newell about the origin, by hand
    np.testing.assert_allclose(c, np.cross(p, np.roll(p, -1, axis=1)).sum(axis=1), atol=1e-8)
    np.testing.assert_allclose(mesh.face_normals(v, f),
                               c / np.linalg.norm(c, axis=1, keepdims=True), atol=1e-14)
    np.testing.assert_allclose(mesh.face_areas(v, f), np.linalg.norm(c, axis=1) / 2)

# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

SQUARE = [[0, 0], [1, 0], [1, 1], [0, 1]]
TRI_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]


def _box_calls(lo, hi):
    return [
        lambda: C.cohen_sutherland([0, 0], [1, 1], lo, hi),
        lambda: C.cohen_sutherland_many([[0, 0]], [[1, 1]], lo, hi),
        lambda: C.liang_barsky([0, 0], [1, 1], lo, hi),
        lambda: C.liang_barsky_many([[0, 0]], [[1, 1]], lo, hi),
        lambda: C.sutherland_hodgman(SQUARE, lo, hi),
        lambda: C.outcode([0.5, 0.5], lo, hi),
        lambda: C.box_planes(lo, hi),
        lambda: C.cohen_sutherland_steps([0, 0], [1, 1], lo, hi),
        lambda: C.liang_barsky_steps([0, 0], [1, 1], lo, hi),
        lambda: C.sutherland_hodgman_steps(SQUARE, lo, hi),
    ]


@pytest.mark.parametrize("lo, hi", [([0, 0], [0, 1]), ([0, 1], [1, 1]), ([2, 0], [1, 1]),
                                    ([0, 0], [1, -1])], ids=str)
@pytest.mark.parametrize("k", range(10))
def test_empty_boxes_raise(lo, hi, k):
    with pytest.raises(ValueError, match="box_min"):
        _box_calls(lo, hi)[k]()


BAD = [
    ("box of 3D, points 2D", lambda: C.cohen_sutherland([0, 0], [1, 1], [0, 0, 0], [1, 1, 1]),
     r"p0|box"),
    ("box of 2D, points 3D", lambda: C.liang_barsky_many(np.zeros((2, 3)), np.ones((2, 3)),
                                                         [0, 0], [1, 1]), r"p0|box"),
    ("box_min 2D, box_max 3D", lambda: C.outcode([0, 0], [0, 0], [1, 1, 1]), "box"),
    ("polygon 3D, box 2D", lambda: C.sutherland_hodgman(np.zeros((3, 3)), [0, 0], [1, 1]),
     "polygon"),
    ("box 4D", lambda: C.outcode([0, 0, 0, 0], [0, 0, 0, 0], [1, 1, 1, 1]), "box_min"),
    ("polygon of 2 vertices", lambda: C.sutherland_hodgman([[0, 0], [1, 1]], [0, 0], [1, 1]),
     "polygon"),
    ("polygon of 1 vertex", lambda: C.clip_polygon([[0, 0]], [([1, 0], 1)]), "polygon"),
    ("polygon flat", lambda: C.sutherland_hodgman([0, 0, 1, 1, 2, 2], [0, 0], [1, 1]),
     "polygon"),
    ("polygon, no planes, 2 vertices", lambda: C.clip_polygon([[0, 0], [1, 1]], []), "polygon"),
    ("faces index too big", lambda: C.back_faces(TRI_V, [[0, 1, 3]], eye=[0, 0, 1]), "faces"),
    ("faces index negative", lambda: C.back_faces(TRI_V, [[0, 1, -1]], eye=[0, 0, 1]), "faces"),
    ("faces of 2 vertices", lambda: C.back_faces(TRI_V, [[0, 1]], eye=[0, 0, 1]), "faces"),
    ("faces not integers", lambda: C.back_faces(TRI_V, [[0.0, 1.0, 2.0]], eye=[0, 0, 1]),
     "faces"),
    ("faces ragged", lambda: C.face_normals(TRI_V, [[0, 1, 2], [0, 1]]), "faces"),
    ("eye and direction", lambda: C.back_faces(TRI_V, [[0, 1, 2]], eye=[0, 0, 1],
                                               direction=[0, 0, 1]), r"eye.*direction"),
    ("neither eye nor direction", lambda: C.back_faces(TRI_V, [[0, 1, 2]]), r"eye.*direction"),
    ("eye 2D", lambda: C.back_faces(TRI_V, [[0, 1, 2]], eye=[0, 1]), "eye"),
    ("direction 2D", lambda: C.back_faces(TRI_V, [[0, 1, 2]], direction=[0, 1]), "direction"),
    ("vertices 2D", lambda: C.back_faces([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], eye=[0, 0, 1]),
     "vertices"),
    ("p0 and p1 of different lengths", lambda: C.liang_barsky_many(np.zeros((3, 2)),
                                                                   np.zeros((4, 2)), [0, 0],
                                                                   [1, 1]), r"p0.*p1"),
    ("p0 and p1 of different lengths, CS",
     lambda: C.cohen_sutherland_many(np.zeros((3, 2)), np.zeros((4, 2)), [0, 0], [1, 1]),
     r"p0.*p1"),
    ("p0 2D, p1 3D", lambda: C.clip_segment([0, 0], [0, 0, 0], [([1, 0], 1)]), r"p0|p1"),
    ("arrays to the single form", lambda: C.liang_barsky(np.zeros((2, 2)), np.ones((2, 2)),
                                                         [0, 0], [1, 1]), "p0"),
    ("arrays to the single CS form", lambda: C.cohen_sutherland(np.zeros((2, 2)),
                                                                np.ones((2, 2)), [0, 0],
                                                                [1, 1]), "p0"),
    ("plane of another dimension", lambda: C.clip_polygon(SQUARE, [([1, 0, 0], 1)]), "normal"),
    ("view volume of a 3x3", lambda: C.view_volume_planes(np.eye(3)), "matrix"),
    ("NaN in p0", lambda: C.liang_barsky([np.nan, 0], [1, 1], [0, 0], [1, 1]), r"p0.*finite"),
    ("inf in p1", lambda: C.cohen_sutherland_many([[0, 0]], [[np.inf, 1]], [0, 0], [1, 1]),
     r"p1.*finite"),
    ("NaN in box_max", lambda: C.outcode([0, 0], [0, 0], [1, np.nan]), r"box_max.*finite"),
    ("NaN in polygon", lambda: C.sutherland_hodgman([[0, 0], [1, np.nan], [0, 1]], [0, 0],
                                                    [1, 1]), r"polygon.*finite"),
    ("inf in normal", lambda: C.is_back_face([0, 0, np.inf], [0, 0, 1]), r"normal.*finite"),
    ("NaN in eye", lambda: C.back_faces(TRI_V, [[0, 1, 2]], eye=[0, np.nan, 1]), r"eye.*finite"),
]


@pytest.mark.parametrize("call, pattern", [(c, p) for _, c, p in BAD], ids=[n for n, _, _ in BAD])
def test_bad_input_raises_value_error_naming_the_argument(call, pattern):
    with pytest.raises(ValueError, match=pattern):
        call()


@pytest.mark.parametrize("call", [
    lambda: C.cohen_sutherland("ab", [1, 1], [0, 0], [1, 1]),
    lambda: C.liang_barsky_many([[0, 0]], [[1, 1]], "lo", [1, 1]),
    lambda: C.sutherland_hodgman("polygon", [0, 0], [1, 1]),
    lambda: C.outcode(None, [0, 0], [1, 1]),
    lambda: C.is_back_face("n", [0, 0, 1]),
    lambda: C.back_faces(TRI_V, [[0, 1, 2]], eye="eye"),
    lambda: C.view_volume_planes("M"),
], ids=["cohen_sutherland", "liang_barsky_many", "sutherland_hodgman", "outcode", "is_back_face",
        "back_faces", "view_volume_planes"])
def test_strings_and_none_raise_type_error(call):
    with pytest.raises(TypeError):
        call()


def test_is_back_face_mismatched_stacks_are_reported_by_name():
    # BUG: is_back_face lets numpy broadcast normal against view_vector, so stacks that cannot
    # pair up end in numpy's "operands could not be broadcast together with remapped shapes"
    # instead of an error naming the two arguments (as _validate.broadcast_stacks gives).
    with pytest.raises(ValueError) as info:
        C.is_back_face(np.ones((3, 3)), np.ones((2, 3)))
    message = str(info.value)
    assert "normal" in message and "view_vector" in message


@pytest.mark.parametrize("polygon", [[[0, 0], [1, 0], [2, 1], [0, 2]],     # S on the plane, E out
                                     [[2, 1], [1, 0], [0, 0], [0, 2]],     # E on the plane, S out
                                     [[1, -1], [1, 1], [0, 1], [0, -1]]])  # an edge along it
def test_vertices_on_the_clip_plane_are_not_duplicated(polygon):
    clipped = C.clip_polygon(polygon, [([1, 0], 1)])                  # keep x <= 1
    rolled = np.roll(clipped, -1, axis=0)
    assert not np.any(np.all(np.isclose(clipped, rolled), axis=1)), clipped
    expected = shapely.Polygon(polygon).intersection(shapely.box(-5, -5, 1, 5)).area
    x, y = clipped.T
    assert 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) == \
        pytest.approx(expected)
