"""Tests of the chapter 5 exercises (course_lib.exercises.ch05).

For every exercise and many seeds: the statement reads, the right answer (computed here
independently: shapely for 2D clipping, the slab method for 3D segments, an edge-function
rasterizer with plane-equation depths for the z-buffer, and closed forms typed out below, never
the course_lib or ch05 function the checker calls) is accepted, placeholders are "unanswered",
garbage is "invalid", and every anticipated mistake, rebuilt here from the question's
attributes, is named by its diagnosis.
"""
import math
from fractions import Fraction

import numpy as np
import pytest
from shapely.geometry import LineString, Polygon, box as shapely_box

from course_lib.exercises import ch05
import exercise_harness as harness
from exercise_harness import MIN_DIAGNOSED

SIDES = ("left", "right", "bottom", "top", "near", "far")


# ---------------------------------------------------------------------------------------------
# Independent computations
# ---------------------------------------------------------------------------------------------

def outcode(p, lo, hi, boundary_outside=False):
    """Bit 2k for below the minimum on axis k, bit 2k+1 for above the maximum."""
    code = 0
    for k in range(len(p)):
        below = p[k] <= lo[k] if boundary_outside else p[k] < lo[k]
        above = p[k] >= hi[k] if boundary_outside else p[k] > hi[k]
        code += (1 << (2 * k)) * int(below) + (1 << (2 * k + 1)) * int(above)
    return code


def rect(lo, hi):
    return shapely_box(lo[0], lo[1], hi[0], hi[1])


def shapely_clip(p0, p1, lo, hi):
    """The part of the segment inside the rectangle as (q0, q1) from p0's side, or None."""
    part = LineString([p0, p1]).intersection(rect(lo, hi))
    if part.is_empty or part.length == 0:
        return None
    a, b = (np.array(c) for c in part.coords)
    if np.linalg.norm(a - p0) > np.linalg.norm(b - p0):
        a, b = b, a
    return np.array([a, b])


def cohen_sutherland_by_hand(p0, p1, lo, hi):
    """Cohen-Sutherland typed out; returns (segment or None, number of intersections)."""
    p, q = np.array(p0, float), np.array(p1, float)
    cuts = 0
    while True:
        c0, c1 = outcode(p, lo, hi), outcode(q, lo, hi)
        if not c0 | c1:
            return np.array([p, q]), cuts
        if c0 & c1:
            return None, cuts
        if c0:
            bit = [k for k in range(4) if c0 >> k & 1][0]
            p = cut(p, q, bit, lo, hi)
        else:
            bit = [k for k in range(4) if c1 >> k & 1][0]
            q = cut(q, p, bit, lo, hi)
        cuts += 1


def cut(a, b, bit, lo, hi):
    axis = bit // 2
    value = (lo if bit % 2 == 0 else hi)[axis]
    t = (value - a[axis]) / (b[axis] - a[axis])
    point = a + t * (b - a)
    point[axis] = value                 # exactly on the side, or rounding could leave it outside
    return point


def liang_barsky_table(p0, p1, lo, hi):
    d = np.asarray(p1, float) - p0
    table = []
    for k in range(len(lo)):
        table.append([-d[k], p0[k] - lo[k]])
        table.append([d[k], hi[k] - p0[k]])
    return np.array([[p, q, q / p if p else math.nan] for p, q in table])


def slab_interval(p0, p1, lo, hi):
    """[t_in, t_out] of the segment inside the box by the slab method (None if empty)."""
    d = np.asarray(p1, float) - p0
    t_in, t_out = 0.0, 1.0
    for k in range(len(lo)):
        if d[k] == 0:
            if not lo[k] <= p0[k] <= hi[k]:
                return None
            continue
        ta, tb = sorted(((lo[k] - p0[k]) / d[k], (hi[k] - p0[k]) / d[k]))
        t_in, t_out = max(t_in, ta), min(t_out, tb)
    return (t_in, t_out) if t_in <= t_out else None


def interval_variant(table, swap=False, clamp=True, first=max, second=min):
    entering = [t for p, q, t in table if p != 0 and (p < 0) != swap]
    leaving = [t for p, q, t in table if p != 0 and (p > 0) != swap]
    t_in = first(entering) if entering else 0.0
    t_out = second(leaving) if leaving else 1.0
    return (max(0.0, t_in), min(1.0, t_out)) if clamp else (t_in, t_out)


def segment_at(p0, p1, interval):
    if interval is None or interval[0] > interval[1] + 1e-12:
        return "rejected"
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    return np.array([p0 + interval[0] * (p1 - p0), p0 + interval[1] * (p1 - p0)])


def half_plane_keep(point, side, value):
    axis = 0 if side in ("left", "right") else 1
    return point[axis] <= value if side in ("right", "top") else point[axis] >= value


def sutherland_hodgman_by_hand(polygon, side, value, keep_outside=False, swap_out_in=False,
                               skip=None):
    """One clipping stage typed out; `skip` leaves out the k-th intersection emitted."""
    out, emitted = [], 0
    axis = 0 if side in ("left", "right") else 1
    n = len(polygon)
    for i in range(n):
        s, e = np.asarray(polygon[i], float), np.asarray(polygon[(i + 1) % n], float)
        s_in = half_plane_keep(s, side, value) != keep_outside
        e_in = half_plane_keep(e, side, value) != keep_outside
        if s_in != e_in:
            t = (value - s[axis]) / (e[axis] - s[axis])
            hit = s + t * (e - s)
        if s_in and e_in:
            out.append(e)
        elif s_in:
            if emitted != skip:
                out.append(hit)
            emitted += 1
        elif e_in:
            pair = [hit, e]
            if emitted == skip:
                pair = [e]
            elif swap_out_in:
                pair = [e, hit]
            emitted += 1
            out.extend(pair)
    return np.array(out)


def plane_depth(triangle, x, y):
    """Depth at (x, y) from the plane z = a x + b y + c through the three vertices."""
    tri = np.asarray(triangle, float)
    a, b, c = np.linalg.solve(np.column_stack([tri[:, :2], np.ones(3)]), tri[:, 2])
    return a * x + b * y + c


def covers(triangle, x, y):
    """Edge functions: the point is inside when it is on the same side of all three edges."""
    tri = np.asarray(triangle, float)[:, :2]
    signs = []
    for i in range(3):
        a, b = tri[i], tri[(i + 1) % 3]
        signs.append((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]))
    return all(s > 0 for s in signs) or all(s < 0 for s in signs)


def rasterize(triangles, rule="nearest"):
    ids = -np.ones((4, 4), dtype=int)
    depth = np.full((4, 4), 1.0 if rule == "nearest" else -math.inf)
    writes = fragments = 0
    for k, tri in enumerate(triangles):
        for j in range(4):
            for i in range(4):
                if not covers(tri, i + 0.5, j + 0.5):
                    continue
                fragments += 1
                z = plane_depth(tri, i + 0.5, j + 0.5)
                wins = {"nearest": z < depth[j, i], "farthest": z > depth[j, i],
                        "last": True}[rule]
                if wins:
                    ids[j, i], depth[j, i] = k, z
                    writes += 1
    return ids, writes, fragments


def shoelace(points):
    p = np.asarray(points, float)
    return 0.5 * abs(np.dot(p[:, 0], np.roll(p[:, 1], -1)) - np.dot(p[:, 1], np.roll(p[:, 0], -1)))


# ---------------------------------------------------------------------------------------------
# Per exercise: the expected answer and the anticipated mistakes, from the attributes
# ---------------------------------------------------------------------------------------------

def back_faces(ex):
    back = [i for i, (p, n) in enumerate(zip(ex.points, ex.normals))
            if np.dot(n, np.asarray(p) - ex.eye) >= 0]
    front = [i for i in range(len(ex.points)) if i not in back]
    constant = [i for i, n in enumerate(ex.normals) if np.dot(n, ex.gaze) >= 0]
    return back, {"compendium sign": front, "constant view direction": constant}


def outcodes(ex):
    lo, hi, dim = ex.box_min, ex.box_max, ex.dim
    codes = [outcode(p, lo, hi) for p in ex.points]
    width = 2 * dim

    def swap(code):
        return sum(1 << (k ^ 1) for k in range(width) if code >> k & 1)

    mistakes = {
        "bit order reversed": [int(format(c, f"0{width}b")[::-1], 2) for c in codes],
        "min and max swapped": [swap(c) for c in codes],
    }
    boundary = [outcode(p, lo, hi, boundary_outside=True) for p in ex.points]
    if boundary != codes:
        mistakes["boundary counts as outside"] = boundary
    if dim == 3:
        mistakes["z bits missing"] = [c % 16 for c in codes]
    return codes, mistakes


def decide(c0, c1):
    return "accept" if not c0 | c1 else "reject" if c0 & c1 else "clip"


def cs_decision(ex):
    lo, hi = ex.box_min, ex.box_max
    right, both, swapped, final = [], [], [], []
    for p0, p1 in ex.segments:
        c0, c1 = outcode(p0, lo, hi), outcode(p1, lo, hi)
        right.append(decide(c0, c1))
        both.append("reject" if c0 and c1 else decide(c0, c1))
        swapped.append("accept" if not c0 & c1 else "reject")
        visible = shapely_clip(p0, p1, lo, hi) is not None
        final.append("reject" if not visible else decide(c0, c1))
    return right, {"both endpoints outside": both, "and/or swapped": swapped,
                   "final result instead of the test": final}


def cs_clip(ex):
    lo, hi = ex.box_min, ex.box_max
    right = shapely_clip(ex.p0, ex.p1, lo, hi)
    by_hand, _ = cohen_sutherland_by_hand(ex.p0, ex.p1, lo, hi)
    assert np.allclose(by_hand, right)
    return right, {
        "one clip per endpoint": one_clip_each(ex),
        "clamped": np.clip([ex.p0, ex.p1], lo, hi),
        "not clipped": np.array([ex.p0, ex.p1]),
    }


def one_clip_each(ex):
    lo, hi = ex.box_min, ex.box_max
    ends = []
    for a, b in ((ex.p0, ex.p1), (ex.p1, ex.p0)):
        code = outcode(a, lo, hi)
        if code:
            bit = [k for k in range(4) if code >> k & 1][0]
            a = cut(np.asarray(a, float), np.asarray(b, float), bit, lo, hi)
        ends.append(a)
    return np.array(ends)


def cs_intersections(ex):
    lo, hi = ex.box_min, ex.box_max
    _, cuts = cohen_sutherland_by_hand(ex.p0, ex.p1, lo, hi)
    c0, c1 = outcode(ex.p0, lo, hi), outcode(ex.p1, lo, hi)
    return cuts, {
        "one per endpoint": int(c0 != 0) + int(c1 != 0),
        "one per bit": bin(c0).count("1") + bin(c1).count("1"),
        "counted the final test": cuts + 1,
    }


def lb_table(ex):
    table = liang_barsky_table(ex.p0, ex.p1, ex.box_min, ex.box_max)
    return table, {
        "sign of p": table * [-1, 1, -1],
        "sign of q": table * [1, -1, -1],
        "p and q negated": table * [-1, -1, 1],
    }


def lb_interval(ex):
    table = liang_barsky_table(ex.p0, ex.p1, ex.box_min, ex.box_max)
    clipped = shapely_clip(ex.p0, ex.p1, ex.box_min, ex.box_max)
    d = np.asarray(ex.p1, float) - ex.p0
    right = [float(np.dot(q - ex.p0, d) / np.dot(d, d)) for q in clipped]
    return np.array(right), {
        "entering/leaving swapped": interval_variant(table, swap=True),
        "not clamped": interval_variant(table, clamp=False),
        "min and max swapped": interval_variant(table, first=min, second=max),
    }


def lb_clip_3d(ex):
    table = liang_barsky_table(ex.p0, ex.p1, ex.box_min, ex.box_max)
    right = segment_at(ex.p0, ex.p1, slab_interval(ex.p0, ex.p1, ex.box_min, ex.box_max))
    parallel_out = any(p == 0 and q < 0 for p, q, _ in table)
    t_in, t_out = interval_variant(table)
    p0, p1 = np.asarray(ex.p0, float), np.asarray(ex.p1, float)
    return right, {
        "empty interval not noticed": np.array([p0 + t_in * (p1 - p0), p0 + t_out * (p1 - p0)]),
        "entering/leaving swapped": "rejected" if parallel_out else
        segment_at(ex.p0, ex.p1, interval_variant(table, swap=True)),
        "not clamped": "rejected" if parallel_out else
        segment_at(ex.p0, ex.p1, interval_variant(table, clamp=False)),
    }


def sh_one_side(ex):
    right = sutherland_hodgman_by_hand(ex.polygon, ex.side, ex.value)
    axis = 0 if ex.side in ("left", "right") else 1
    lo_hi = [-99, -99, 99, 99]
    lo_hi[axis + (2 if ex.side in ("right", "top") else 0)] = ex.value
    kept = shapely_box(*lo_hi)
    assert math.isclose(shoelace(right), Polygon(ex.polygon).intersection(kept).area)
    crossings = sum(half_plane_keep(ex.polygon[i], ex.side, ex.value)
                    != half_plane_keep(ex.polygon[i - 1], ex.side, ex.value)
                    for i in range(len(ex.polygon)))
    assert crossings == 2
    mistakes = {
        "reversed order": right[::-1],
        "kept the outside part": sutherland_hodgman_by_hand(ex.polygon, ex.side, ex.value,
                                                            keep_outside=True),
        "out-in order": sutherland_hodgman_by_hand(ex.polygon, ex.side, ex.value,
                                                   swap_out_in=True),
    }
    variants = [sutherland_hodgman_by_hand(ex.polygon, ex.side, ex.value, skip=k)
                for k in range(2)]
    return right, mistakes, {"missing intersection vertex": variants}


def sh_area(ex):
    lo, hi = ex.box_min, ex.box_max
    clipped = Polygon(ex.triangle).intersection(rect(lo, hi))
    vertices = np.array(clipped.exterior.coords[:-1])
    corners = [np.array([x, y]) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]
    without = [v for v in vertices if not any(np.allclose(v, c) for c in corners)]
    tri_area = Polygon(ex.triangle).area
    return np.array([len(vertices), clipped.area]), {
        "box corner missing": [len(without), shoelace(without)],
        "unclipped area": [len(vertices), tri_area],
    }


def zbuffer_ids(ex):
    ids, _, _ = rasterize(ex.triangles)
    return ids, {
        "no depth test": rasterize(ex.triangles, "last")[0],
        "depth test reversed": rasterize(ex.triangles, "farthest")[0],
        "rows upside down": ids[::-1],
        "transposed": ids.T,
        "numbered from 1": [[v + 1 if v >= 0 else -1 for v in row] for row in ids],
    }


def zbuffer_writes(ex):
    ids, writes, fragments = rasterize(ex.triangles)
    return writes, {
        "counted final pixels": int(np.sum(ids >= 0)),
        "counted all fragments": fragments,
        "counted the failures": fragments - writes,
    }


def painters_order(ex):
    depths = [np.asarray(d, float) for d in ex.depths]
    n = len(depths)
    order = sorted(range(n), key=lambda k: depths[k].min())
    return order, {
        "nearest first": order[::-1],
        "sorted by nearest vertex": sorted(range(n), key=lambda k: depths[k].max()),
        "sorted by average depth": sorted(range(n), key=lambda k: depths[k].mean()),
        "counted from 1": [k + 1 for k in order],
    }


def painter_failure(ex):
    def depth_at(seg, x):
        x0, d0, x1, d1 = seg
        return d0 + (d1 - d0) * (x - x0) / (x1 - x0)

    def covering(i):
        x = i + 0.5
        return {k: depth_at(s, x) for k, s in enumerate(ex.segments)
                if min(s[0], s[2]) < x < max(s[0], s[2])}

    order = sorted(range(3), key=lambda k: -max(ex.segments[k][1], ex.segments[k][3]))
    truth = [min(c, key=c.get) if c else -1 for c in map(covering, range(8))]

    def wrong_pixels(drawing_order):
        return sorted(i for i in range(8)
                      if ([k for k in drawing_order if k in covering(i)] or [-1])[-1]
                      != truth[i])

    return wrong_pixels(order), {
        "no failure": [],
        "all overlaps": [i for i in range(8) if len(covering(i)) >= 2],
        "nearest first": wrong_pixels(order[::-1]),
    }


def ray_counts(ex):
    p = ex.width * ex.height
    P, k = ex.triangles, ex.hits
    right = np.array([p * sum(P), sum(a * b for a, b in zip(k, P)), p * len(P)], float)
    return right, {
        "added instead of multiplied": [p + sum(P), right[1], right[2]],
        "all triangles per hit ray": [right[0], sum(k) * sum(P), right[2]],
        "one test per object": [right[0], right[1], len(P)],
    }


# ---------------------------------------------------------------------------------------------
# Specs
# ---------------------------------------------------------------------------------------------

SET_GARBAGE = ["all", {"a": 1}, [0.5], ["a"], 3.5, [True, 2]]
CODES_GARBAGE = ["1001", {"a": 1}, [1, 2], ["2", "0", "0", "0", "0"], [1.5] * 5,
                 ["1111111"] * 5, [True] * 5, [5.5, 0, 0, 0, 0], ["x1", "0", "0", "0", "0"]]
WORDS_GARBAGE = ["accept", {"a": 1}, ["accept"], ["yes"] * 5, [1, 2, 3, 4, 5]]
SEGMENT_GARBAGE = ["maybe", {"a": 1}, [1, 2], [[1, 2, 3]], [[math.nan] * 4] * 2, [[1, 2]] * 3]
TABLE_GARBAGE = ["t", {"a": 1}, np.eye(4), [1, 2, 3], [[math.nan] * 3] * 4]
NUMBERS_GARBAGE = ["t", {"a": 1}, [1], [[1, 2], [3, 4]], [math.nan] * 5, 1.0]
POLYGON_GARBAGE = ["poly", {"a": 1}, [1, 2, 3], [[1, 2, 3]], [[math.inf, 0]]]
GRID_GARBAGE = ["ids", {"a": 1}, np.zeros((3, 4)), np.full((4, 4), 0.5), [1, 2]]
ORDER_GARBAGE = ["0123", {"a": 1}, [0, 1, 2], [0.5, 1, 2, 3, 4], [True] * 4]
NUMBER_GARBAGE = ["v", {"v": 1}, [1, 2], [[1], [2, 3]], math.nan]

# class name: (independent answer and mistakes, answer form)
SPECS = {
    "BackFaceCulling": (back_faces, "set"),
    "Outcodes": (outcodes, "codes"),
    "CohenSutherlandDecision": (cs_decision, "words"),
    "CohenSutherlandClip": (cs_clip, "segment"),
    "CohenSutherlandIntersections": (cs_intersections, "number"),
    "LiangBarskyTable": (lb_table, "table"),
    "LiangBarskyInterval": (lb_interval, "numbers"),
    "LiangBarskyClip3D": (lb_clip_3d, "segment"),
    "SutherlandHodgmanOneSide": (sh_one_side, "polygon"),
    "SutherlandHodgmanArea": (sh_area, "numbers"),
    "ZBufferIds": (zbuffer_ids, "grid"),
    "ZBufferWrites": (zbuffer_writes, "number"),
    "PaintersOrder": (painters_order, "order"),
    "PainterFailure": (painter_failure, "set"),
    "RayCastingCount": (ray_counts, "numbers"),
}
GARBAGE = {"set": SET_GARBAGE, "codes": CODES_GARBAGE, "words": WORDS_GARBAGE,
           "segment": SEGMENT_GARBAGE, "number": NUMBER_GARBAGE, "table": TABLE_GARBAGE,
           "numbers": NUMBERS_GARBAGE, "polygon": POLYGON_GARBAGE, "grid": GRID_GARBAGE,
           "order": ORDER_GARBAGE}


#: This file tests the chapter's older topics (SPECS); tests/test_exercises_ch05_*.py the others,
#: and test_every_exercise_is_tested_in_one_file holds the union to the chapter's list.
TOPIC = harness.topic(ch05, SPECS)
exercises = harness.variants(TOPIC)


def solve(name, ex):
    """(right, {key: [values]}): every mistake as a list of the answers that make it."""
    result = SPECS[name][0](ex)
    right, mistakes = result[0], {k: [v] for k, v in result[1].items()}
    if len(result) == 3:
        for key, values in result[2].items():
            mistakes.setdefault(key, []).extend(values)
    return right, mistakes


def same(form, a, b):
    """Whether two answers of the given form are the same answer."""
    if form in ("set",):
        return set(a) == set(b)
    if form in ("codes", "words", "order"):
        return list(a) == list(b)
    if form == "segment":
        if isinstance(a, str) or isinstance(b, str):
            return isinstance(a, str) and isinstance(b, str)
        a, b = np.asarray(a, float), np.asarray(b, float)
        return np.allclose(a, b, atol=1e-6) or np.allclose(a[::-1], b, atol=1e-6)
    if form == "polygon":
        a, b = np.asarray(a, float), np.asarray(b, float)
        return a.shape == b.shape and any(np.allclose(np.roll(a, s, axis=0), b, atol=1e-6)
                                          for s in range(len(a)))
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a.shape == b.shape and np.allclose(a, b, atol=1e-6)


def as_answer(form, value):
    if form == "set":
        return sorted(value)
    return value


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(
    TOPIC, SPECS, GARBAGE, exercises, at_least=10, distinct=(20, 15), words=r"nan|inf",
    newlines=r"\\neq", odd=harness.ODD + [[1, "a"]]))


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    form = SPECS[name][1]
    for ex in exercises(name):
        right, _ = solve(name, ex)
        fb = ex.check(as_answer(form, right))
        assert fb.status == "correct", (ex, right, fb)
        assert bool(fb)
        if form in ("segment", "table", "numbers", "polygon") and not isinstance(right, str):
            assert ex.check(np.round(right, 3)).status == "correct", ex
            assert ex.check(np.asarray(right).tolist()).status == "correct", ex


def test_answers_in_other_spellings_are_accepted():
    for ex in exercises("BackFaceCulling", range(30)):
        right, _ = back_faces(ex)
        mask = [i in right for i in range(len(ex.points))]
        assert ex.check(mask).status == "correct"
        assert ex.check(set(right)).status == "correct"
        assert ex.check(tuple(reversed(right))).status == "correct"
    for ex in exercises("Outcodes", range(30)):
        codes, _ = outcodes(ex)
        width = 2 * ex.dim
        assert ex.check([format(c, f"0{width}b") for c in codes]).status == "correct"
        assert ex.check([f"0b{c:b}" for c in codes]).status == "correct"
        assert ex.check(np.array(codes)).status == "correct"
    for ex in exercises("CohenSutherlandDecision", range(30)):
        words, _ = cs_decision(ex)
        assert ex.check([w.upper() for w in words]).status == "correct"
        assert ex.check(["trivially " + w + "ed" if w != "clip" else w
                         for w in words]).status == "correct"
    for ex in exercises("CohenSutherlandClip", range(30)):
        right, _ = cs_clip(ex)
        assert ex.check(right[::-1]).status == "correct"
    for ex in exercises("SutherlandHodgmanOneSide", range(30)):
        right, _, _ = sh_one_side(ex)
        for shift in range(len(right)):
            assert ex.check(np.roll(right, shift, axis=0)).status == "correct"


def test_rejected_segments_occur_and_are_answered_with_a_word():
    rejected = [ex for ex in exercises("LiangBarskyClip3D") if ex.expected is None]
    assert 20 <= len(rejected) <= 150
    for ex in rejected[:20]:
        assert ex.check("rejected").status == "correct"
        assert ex.check([]).status == "correct"
        fb = ex.check([[0, 0, 0], [1, 1, 1]])
        assert fb.status == "wrong"
    visible = [ex for ex in exercises("LiangBarskyClip3D") if ex.expected is not None]
    for ex in visible[:20]:
        fb = ex.check("rejected")
        assert fb.status == "wrong" and fb.diagnosis in ("rejected a visible segment",
                                                          "entering/leaving swapped",
                                                          "not clamped")


@pytest.mark.parametrize("name", SPECS)
def test_mistakes_are_diagnosed(name):
    form = SPECS[name][1]
    diagnosed = {}
    for ex in exercises(name):
        right, mistakes = solve(name, ex)
        for key, values in mistakes.items():
            for value in values:
                fb = ex.check(as_answer(form, value))
                if same(form, value, right):      # the slip gives the right answer here
                    assert fb.status == "correct", (ex, key, fb)
                    continue
                assert fb.status == "wrong", (ex, key, value, fb)
                clashes = [other for other, vs in mistakes.items() if other != key
                           and any(same(form, value, v) for v in vs)]
                if clashes:          # two slips give this answer: it names one or neither
                    assert fb.diagnosis not in set(mistakes) - {key, *clashes}, (ex, key, fb)
                    continue
                assert fb.diagnosis == key, (ex, key, value, fb.diagnosis, fb.message)
                assert len(fb.message) > 40
                diagnosed[key] = diagnosed.get(key, 0) + 1
    keys = set().union(*(solve(name, ex)[1] for ex in exercises(name, range(30))))
    for key in keys:
        assert diagnosed.get(key, 0) >= MIN_DIAGNOSED, (key, diagnosed)


def test_zbuffer_scenes_need_the_depth_test():
    for ex in exercises("ZBufferIds"):
        ids, _, _ = rasterize(ex.triangles)
        assert not np.array_equal(ids, rasterize(ex.triangles, "last")[0])
        assert np.all(ex.triangles[0][:, 2] > 0) and np.all(np.asarray(ex.triangles)[:, :, 2] < 1)


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("CohenSutherlandClip"):
        assert np.all(ex.p0 == np.round(ex.p0)) and np.all(ex.p1 == np.round(ex.p1))
    for ex in exercises("ZBufferIds"):
        for tri in ex.triangles:
            assert np.all(tri[:, :2] == np.round(tri[:, :2]))
            assert np.allclose(tri[:, 2] * 10, np.round(tri[:, 2] * 10))
    for ex in exercises("RayCastingCount"):
        assert all(k == int(k) for k in ex.hits)


# ---------------------------------------------------------------------------------------------
# Whole numbers, variety, boundary cases
# ---------------------------------------------------------------------------------------------

def one_off(right):
    """Every answer that is `right` (whole numbers) with one entry one larger or smaller."""
    flat = [int(v) for v in np.ravel(right)]
    for i in range(len(flat)):
        for step in (-1, 1):
            wrong = list(flat)
            wrong[i] += step
            yield np.reshape(wrong, np.shape(right)).tolist() if np.ndim(right) else wrong[0]


#: Exercises answered in whole numbers: the answer as the solver gives it, the whole part of it
#: (the vertex count of SutherlandHodgmanArea), and whether its parts are counts (off by one is
#: then diagnosed as such) rather than indices, codes or ids.
WHOLE = {
    "RayCastingCount": (lambda r: r, True),
    "ZBufferWrites": (lambda r: r, True),
    "CohenSutherlandIntersections": (lambda r: r, True),
    "ZBufferIds": (lambda r: r, False),
    "Outcodes": (lambda r: r, False),
    "PaintersOrder": (lambda r: r, False),
    "BackFaceCulling": (lambda r: r, False),
    "PainterFailure": (lambda r: r, False),
    "SutherlandHodgmanArea": (lambda r: r[0], True),
}


@pytest.mark.parametrize("name", WHOLE)
def test_whole_numbers_are_exact_and_may_be_given_as_floats(name):
    form = SPECS[name][1]
    whole_part, counts = WHOLE[name]
    off_by_one = 0
    for ex in exercises(name):
        right, mistakes = solve(name, ex)
        right = as_answer(form, right)
        as_floats = np.asarray(right, dtype=float)
        for answer in (as_floats, as_floats.tolist()):
            assert ex.check(answer).status == "correct", (ex, answer)
        if name == "SutherlandHodgmanArea":
            wrongs = [[n, float(right[1])] for n in one_off(whole_part(right))]
        elif form == "set" and not right:
            wrongs = [[0]]
        else:
            wrongs = list(one_off(right))
        for wrong in wrongs:
            fb = ex.check(wrong)
            assert fb.status == "wrong", (ex, wrong, fb)
            if counts and fb.diagnosis not in mistakes:
                assert fb.diagnosis == "off by one", (ex, wrong, fb)
                assert "Components" not in fb.message, fb.message        # a single number
                off_by_one += 1
    assert not counts or off_by_one >= MIN_DIAGNOSED


def test_outcodes_read_integral_floats_and_refuse_the_rest():
    for ex in exercises("Outcodes"):
        codes, _ = outcodes(ex)
        assert ex.check([float(c) for c in codes]).status == "correct", ex
        assert ex.check(np.array(codes, dtype=float)).status == "correct", ex
        assert ex.check([np.float64(c) for c in codes]).status == "correct", ex
        for bad in (5.5, True, "21", "x"):
            fb = ex.check([bad] + [float(c) for c in codes[1:]])
            assert fb.status == "invalid", (ex, bad, fb)
        fb = ex.check([4 ** ex.dim] + codes[1:])
        assert (fb.status, fb.diagnosis) == ("wrong", "not an outcode"), (ex, fb)


def test_indices_out_of_range_or_counted_from_one_are_named():
    for ex in exercises("PaintersOrder", range(30)):
        order, _ = painters_order(ex)
        n = len(order)
        assert ex.check([k + 1 for k in order]).diagnosis == "counted from 1"
        twice = [order[0]] + order[:-1]
        fb = ex.check(twice)
        assert (fb.status, fb.diagnosis) == ("wrong", "not a permutation"), (ex, fb)
        assert ex.check(order[:-1] + [n + 2]).status == "wrong"
    for ex in exercises("BackFaceCulling", range(30)):
        back, _ = back_faces(ex)
        fb = ex.check(back + [len(ex.points)])
        assert (fb.status, fb.diagnosis) == ("wrong", "out of range"), (ex, fb)
        fb = ex.check([i + 1 for i in back])
        assert fb.status == "wrong" and fb.diagnosis in ("counted from 1", "compendium sign",
                                                         "constant view direction"), (ex, fb)
    for ex in exercises("ZBufferIds", range(30)):
        ids, _ = zbuffer_ids(ex)
        assert ex.check(np.where(ids >= 0, ids + 1, -1)).diagnosis == "numbered from 1"


#: The fewest distinct answers among 300 seeds: 30, unless the answer has few values in itself:
#: the number of Cohen-Sutherland intersections of one segment (1 to 4) and the number of
#: z-buffer writes on a 4 x 4 screen (a count of at most 16 pixels per triangle, in practice
#: from 7 to 25). Their scenes differ from seed to seed all the same.
FEWEST_ANSWERS = {"CohenSutherlandIntersections": 4, "ZBufferWrites": 15}


@pytest.mark.parametrize("name", SPECS)
def test_seeds_give_many_different_answers(name):
    cls = getattr(ch05, name)
    answers = {harness.answer_key(cls(seed=seed).expected) for seed in range(300)}
    assert len(answers) >= FEWEST_ANSWERS.get(name, 30), (name, len(answers))


def passes_through(p0, p1, lo, hi):
    """Whether the open segment meets the box's boundary at a point on two sides at once."""
    p0, p1 = [Fraction(float(v)) for v in p0], [Fraction(float(v)) for v in p1]
    lo, hi = [Fraction(float(v)) for v in lo], [Fraction(float(v)) for v in hi]
    dim = len(p0)
    for i in range(dim):
        for j in range(dim):
            if i == j or p1[i] == p0[i] or p1[j] == p0[j]:
                continue
            for a in (lo[i], hi[i]):
                for b in (lo[j], hi[j]):
                    t = (a - p0[i]) / (p1[i] - p0[i])
                    if t != (b - p0[j]) / (p1[j] - p0[j]) or not 0 < t < 1:
                        continue
                    point = [u + t * (w - u) for u, w in zip(p0, p1)]
                    if all(lo[k] <= point[k] <= hi[k] for k in range(dim)):
                        return True
    return False


def boundary_found(name, ex):
    """The boundary cases of a variant, found here from its attributes."""
    lo, hi = np.asarray(ex.box_min), np.asarray(ex.box_max)
    if name == "Outcodes":
        ends = [ex.points]
    elif name == "CohenSutherlandDecision":
        ends = [ex.segments.reshape(-1, 2)]
    else:
        ends = [np.array([ex.p0, ex.p1])]
    found = []
    if any(np.any((e == lo) | (e == hi)) for e in ends):
        found.append("point on a side")
    if name not in ("Outcodes", "CohenSutherlandDecision", "LiangBarskyTable") and \
            passes_through(ex.p0, ex.p1, lo, hi):
        found.append("through a corner" if len(lo) == 2 else "through an edge or corner")
    if name == "LiangBarskyClip3D" and np.any(np.asarray(ex.p0) == ex.p1):
        found.append("parallel to a side")
    return found


BOUNDARY = ("Outcodes", "CohenSutherlandDecision", "CohenSutherlandClip",
            "CohenSutherlandIntersections", "LiangBarskyTable", "LiangBarskyInterval",
            "LiangBarskyClip3D")


@pytest.mark.parametrize("name", BOUNDARY)
def test_boundary_cases_are_a_labelled_tenth_to_a_fifth_of_the_seeds(name):
    cls = getattr(ch05, name)
    labelled = 0
    seeds = range(300)
    for seed in seeds:
        ex = cls(seed=seed)
        found = boundary_found(name, ex)
        assert found == ([] if ex.boundary is None else [ex.boundary]), (ex, found, ex.boundary)
        said = "boundary case" in ex.worked().markdown()
        assert said == (ex.boundary is not None), (ex, ex.boundary)
        labelled += ex.boundary is not None
    assert 0.10 <= labelled / len(seeds) <= 0.22, (name, labelled)
    kinds = {cls(seed=seed).boundary for seed in range(300)} - {None}
    assert kinds == set(cls.boundary_kinds), (name, kinds)


def test_other_exercises_never_land_on_a_boundary_case():
    for ex in exercises("BackFaceCulling"):                        # no face seen edge-on
        assert all(np.dot(n, p - ex.eye) != 0 for p, n in zip(ex.points, ex.normals))
    for ex in exercises("SutherlandHodgmanOneSide"):               # no vertex on the line
        axis = 0 if ex.side in ("left", "right") else 1
        assert np.all(ex.polygon[:, axis] != ex.value)
    for name in ("ZBufferIds", "ZBufferWrites"):                   # no depth ties
        for ex in exercises(name):
            for j in range(4):
                for i in range(4):
                    depths = sorted(plane_depth(t, i + 0.5, j + 0.5) for t in ex.triangles
                                    if covers(t, i + 0.5, j + 0.5))
                    assert all(b - a > 1e-3 for a, b in zip(depths, depths[1:]))
    for ex in exercises("PaintersOrder"):                          # no ties in the keys
        keys = [min(d) for d in ex.depths]
        assert len(set(keys)) == len(keys)


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch05, SPECS, at_least=10)
