"""Tests of the 2D BSP tree of segments (course_lib/visibility/bsp2d.py).

The painting order is checked without the tree: rays shot from the eye in many directions
(ray-segment intersections typed below with numpy) must meet, among the fragments they hit,
the later-painted one first. Splits are compared with shapely intersections and the parts'
union with the original segment; a worked exam example is typed by hand; and the order agrees
with the 3D tree of visibility.build_bsp on the segments extruded into vertical quads.
"""
import numpy as np
import pytest
import shapely

from course_lib import visibility as vis
from course_lib.visibility import bsp2d

# the lesson's worked example: a splits b; eye (1, 4) above a and left of b
HAND = [[[0, 2], [6, 2]], [[2, 0], [2, 4]], [[4, 3], [5, 5]], [[5, 0], [3, 1]]]


def random_segments(rng, n):
    a = rng.uniform(-5, 5, (n, 2))
    ang = rng.uniform(0, 2 * np.pi, n)
    length = rng.uniform(1, 4, n)
    b = a + length[:, None] * np.c_[np.cos(ang), np.sin(ang)]
    return np.stack([a, b], axis=1)


def ray_hits(eye, directions, frags):
    """t of every ray (rows) against every fragment (columns), inf where missed."""
    p0 = np.array([f.start for f in frags])
    e = np.array([f.end for f in frags]) - p0
    d = directions[:, None, :]
    den = d[..., 0] * e[None, :, 1] - d[..., 1] * e[None, :, 0]
    w = p0[None] - eye
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (w[..., 0] * e[None, :, 1] - w[..., 1] * e[None, :, 0]) / den
        u = (w[..., 0] * d[..., 1] - w[..., 1] * d[..., 0]) / den
    hit = (np.abs(den) > 1e-12) & (t > 1e-9) & (u >= 0) & (u <= 1)
    return np.where(hit, t, np.inf)


def assert_painter_order(frags, eye, n_rays=3000):
    ang = np.linspace(0, 2 * np.pi, n_rays, endpoint=False) + 1e-4
    t = ray_hits(np.asarray(eye, float), np.c_[np.cos(ang), np.sin(ang)], frags)
    pairs = 0
    for row in t:
        hit = np.flatnonzero(np.isfinite(row))      # in painting order
        pairs += max(len(hit) - 1, 0)
        # each one painted later must be nearer (or touch at the same point)
        assert np.all(np.diff(row[hit]) <= 1e-9), (eye, hit, row[hit])
    return pairs


def test_worked_example_by_hand():
    tree = vis.build_bsp_2d(HAND)
    assert str(tree) == ("a\n├─ front: b2\n│  └─ back: c\n└─ back: b1\n   └─ back: d")
    assert tree.children() == {"a": ("b2", "b1"), "b2": (None, "c"), "c": (None, None),
                               "b1": (None, "d"), "d": (None, None)}
    assert (tree.n_nodes, tree.n_splits, tree.depth) == (5, 1, 3)
    assert tree.split_segments() == ["b"]
    b1 = next(f for f in tree.fragments if f.label == "b1")
    assert b1.start.tolist() == [2, 0] and b1.end.tolist() == [2, 2]
    out = vis.bsp2d_back_to_front(tree, [1, 4])
    assert out.labels == ["d", "b1", "a", "c", "b2"]
    assert [(s.node, s.side) for s in out.steps] == [("a", 1), ("b1", 1), ("d", -1), ("b2", 1),
                                                     ("c", 1)]
    assert vis.bsp2d_back_to_front(tree, [4, 1]).labels == ["b2", "c", "a", "b1", "d"]
    assert vis.bsp2d_front_to_back(tree, [4, 1]).labels == ["d", "b1", "a", "c", "b2"]
    assert_painter_order(out.fragments, [1, 4])


def test_front_is_the_left_side():
    # typed: s = (b - a) x (p - a)
    assert bsp2d.segment_side([[0, 0], [0, 2]], [[-1, 1], [1, 1]]).tolist() == [2.0, -2.0]
    tree = vis.build_bsp_2d([[[0, 0], [0, 2]], [[-3, 0], [-3, 1]], [[3, 0], [3, 1]]])
    assert tree.children()["a"] == ("b", "c")
    assert np.allclose(tree.root.normal, [-1, 0])


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("choose", ["order", "fewest_splits"])
def test_order_never_paints_a_nearer_fragment_first(seed, choose):
    rng = np.random.default_rng(seed)
    segs = random_segments(rng, 12)
    tree = vis.build_bsp_2d(segs, order=rng.permutation(12).tolist(), choose=choose)
    pairs = 0
    for eye in rng.uniform(-6, 6, (4, 2)):
        out = vis.bsp2d_back_to_front(tree, eye)
        assert sorted(out.labels) == sorted(f.label for f in tree.fragments)
        pairs += assert_painter_order(out.fragments, eye)
        back = vis.bsp2d_front_to_back(tree, eye)
        assert back.labels == out.labels[::-1]
    assert pairs > 100


def test_the_check_can_fail():
    tree = vis.build_bsp_2d(HAND)
    wrong = vis.bsp2d_front_to_back(tree, [1, 4]).fragments
    with pytest.raises(AssertionError):
        assert_painter_order(wrong, [1, 4])


@pytest.mark.parametrize("seed", range(4))
def test_splits_agree_with_shapely(seed):
    rng = np.random.default_rng(10 + seed)
    segs = random_segments(rng, 10)
    tree = vis.build_bsp_2d(segs)
    assert tree.n_splits == len(tree.fragments) - len(segs)
    lines = [shapely.LineString(s) for s in segs]
    for k, seg in enumerate(segs):
        parts = [f for f in tree.fragments if f.source == k]
        union = shapely.unary_union([shapely.LineString([f.start, f.end]) for f in parts])
        assert abs(union.length - lines[k].length) < 1e-9
        assert abs(sum(np.hypot(*(f.end - f.start)) for f in parts) - lines[k].length) < 1e-9
        assert union.difference(lines[k].buffer(1e-9)).length < 1e-9
        assert lines[k].difference(union.buffer(1e-9)).length < 1e-9
        # every cut point is where another segment's (extended) line crosses this one
        cuts = {tuple(np.round(f.end, 7)) for f in parts} - {tuple(np.round(seg[1], 7))}
        crossings = []
        for j, other in enumerate(segs):
            if j != k:
                d = other[1] - other[0]
                far = shapely.LineString([other[0] - 100 * d, other[1] + 100 * d])
                x = lines[k].intersection(far)
                if x.geom_type == "Point":
                    crossings.append(np.array(x.coords[0]))
        for c in cuts:
            assert min(np.abs(np.array(c) - x).max() for x in crossings) < 1e-6
    assert tree.n_splits > 0


def test_collinear_segments_stay_in_the_node():
    tree = vis.build_bsp_2d([[[0, 0], [2, 0]], [[0, 1], [1, 1]], [[5, 0], [3, 0]]])
    assert tree.preorder() == ["a+c", "b"]
    assert tree.n_nodes == 2


def test_eye_on_a_partition_line():
    tree = vis.build_bsp_2d(HAND)
    out = vis.bsp2d_back_to_front(tree, [8, 2])             # on a's line
    assert out.steps[0].side == 0 and "either order" in out.steps[0].text
    assert_painter_order(out.fragments, [8, 2])


def test_fewest_splits_cuts_less():
    # a's line x = 0 cuts b (c's line would cut b too); b's line y = 2 cuts nothing
    segs = [[[0, -1], [0, 1]], [[-5, 2], [5, 2]], [[3, -1], [3, 1]]]
    assert vis.build_bsp_2d(segs).n_splits == 1
    assert vis.build_bsp_2d(segs, choose="fewest_splits").n_splits == 0


def test_order_by_labels_and_deeper_split_names():
    segs = [[[0, 0], [4, 0]], [[2, -2], [2, 2]], [[0, 1], [4, -1]]]
    tree = vis.build_bsp_2d(segs, order="bac")
    labels = sorted(f.label for f in tree.fragments)
    assert "c1" in labels or "c2" in labels
    tree2 = vis.build_bsp_2d([[[1, 1], [3, 1]], [[0, 0], [4, 0]], [[2, -2], [2, 2]]],
                             labels=["x", "y", "z"], order=[1, 0, 2])
    assert tree2.root.label == "y"


def extrude(segs):
    """Two triangles per segment, a vertical quad z in [0, 1] whose normal is the 2D left."""
    tris = []
    for a, b in np.asarray(segs, float):
        a0, a1, b0, b1 = [np.append(p, z) for p, z in ((a, 0), (a, 1), (b, 0), (b, 1))]
        tris += [[a0, a1, b1], [a0, b1, b0]]
    return np.array(tris)


def no_split_sets(count):
    """Random sets of 6 short segments where no segment straddles another's line (the 3D tree
    puts the parts of a split triangle at the end of its lists, so with splits the partitions
    taken differ; without, both take the segments in input order)."""
    rng = np.random.default_rng(40)
    found = []
    while len(found) < count:
        segs = random_segments(rng, 6) * np.array([2.0, 2.0])
        segs = segs[:, [0, 0]] + 0.3 * (segs - segs[:, [0, 0]])
        if vis.build_bsp_2d(segs).n_splits == 0:
            found.append(segs)
    return found


@pytest.mark.parametrize("segs", no_split_sets(4))
def test_same_order_as_the_3d_tree_of_extruded_quads(segs):
    rng = np.random.default_rng(7)
    tree = vis.build_bsp_2d(segs)
    tree3 = vis.build_bsp(extrude(segs))
    assert tree3.n_splits == 0 and tree3.n_nodes == tree.n_nodes
    assert np.allclose(tree3.root.normal[:2], tree.root.normal)
    for eye in rng.uniform(-6, 6, (3, 2)):
        two = [f.source for f in vis.bsp2d_back_to_front(tree, eye).fragments]
        _, ids = vis.bsp_back_to_front(tree3, np.append(eye, 0.5))
        assert [int(i) // 2 for i in ids[::2]] == two and [int(i) // 2 for i in ids[1::2]] == two


@pytest.mark.parametrize("bad, match", [
    ([[[0, 0, 0], [1, 1, 2]]], "shape"),
    ([[0, 0], [1, 1]], "shape"),
    ([[[0, 0], [0, 0]]], "zero length"),
    ([[[0, np.nan], [1, 0]]], "finite"),
    (np.zeros((0, 2, 2)), "n >= 1"),
])
def test_bad_segments(bad, match):
    with pytest.raises(TypeError, match="segments"):          # ragged rows
        vis.build_bsp_2d([[[0, 0], [1, 1, 2]]])
    with pytest.raises(ValueError, match=match):
        vis.build_bsp_2d(bad)


def test_bad_labels_order_and_eye():
    segs = HAND[:2]
    with pytest.raises(ValueError, match="distinct"):
        vis.build_bsp_2d(segs, labels=["a", "a"])
    with pytest.raises(ValueError, match="labels"):
        vis.build_bsp_2d(segs, labels=["a"])
    with pytest.raises(ValueError, match="permutation"):
        vis.build_bsp_2d(segs, order=[0, 0])
    with pytest.raises(ValueError, match="permutation"):
        vis.build_bsp_2d(segs, order=[0, 2])
    with pytest.raises(ValueError, match="choose"):
        vis.build_bsp_2d(segs, choose="best")
    tree = vis.build_bsp_2d(segs)
    with pytest.raises(ValueError, match="eye"):
        vis.bsp2d_back_to_front(tree, [1, 2, 3])
    with pytest.raises(ValueError, match="eye"):
        vis.bsp2d_back_to_front(tree, [np.inf, 2])
    with pytest.raises(TypeError, match="BSPTree2D"):
        vis.bsp2d_back_to_front("tree", [1, 2])


def test_a_deep_chain_needs_no_recursion():
    # the edges of a convex polygon, counter-clockwise: each has all the others in front (its
    # left is the inside), so the tree is a chain as deep as the polygon has edges
    t = np.linspace(0, 2 * np.pi, 1501)[:-1]
    p = np.c_[np.cos(t), np.sin(t)]
    tree = vis.build_bsp_2d(np.stack([p, np.roll(p, -1, axis=0)], axis=1))
    assert tree.depth == tree.n_nodes == 1500 and tree.n_splits == 0
    out = vis.bsp2d_back_to_front(tree, [0, 0])     # inside: every edge is seen from its front
    assert len(out.labels) == 1500 and all(s.side == 1 for s in out.steps)
    assert tree.describe().count("\n") == 1499
