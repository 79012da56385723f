"""Tests of the spatial subdivision explorer (course_lib/widgets/spatial.py).

The hit is checked against a 2D ray-segment intersection solved here (a 2 x 2 linear system per
segment, numpy.linalg.solve), the cells against a slab test typed here; the wiring by setting
every control and watching the picture or the text change.
"""
import numpy as np
import pytest

from course_lib.widgets import spatial as W


def nearest_segment(o, d, segs):
    best, best_t = -1, np.inf
    for k, (a, b) in enumerate(segs):
        m = np.column_stack([d, a - b])
        if abs(np.linalg.det(m)) < 1e-12:
            continue
        t, s = np.linalg.solve(m, a - o)
        if t >= 0 and 0 <= s <= 1 and t < best_t:
            best, best_t = k, t
    return best, best_t


RAYS = [(0.5, 2.0, 20.0), (9.5, 9.0, -135.0), (5.0, 0.2, 90.0), (0.2, 7.0, -10.0),
        (3.0, 3.0, 45.0), (8.0, 1.0, 150.0), (5.0, 5.0, -60.0), (1.0, 9.5, -80.0)]


@pytest.mark.parametrize("structure", W.STRUCTURES)
def test_the_hit_is_the_nearest_segment(structure):
    segs = W.segments()
    hits = 0
    for ox, oy, angle in RAYS:
        s = W.scene(W.State(structure=structure, ox=ox, oy=oy, angle_deg=angle, resolution=6,
                            leaf_size=2))
        o = np.array([ox, oy])
        d = np.array([np.cos(np.radians(angle)), np.sin(np.radians(angle))])
        k, t = nearest_segment(o, d, segs)
        assert s["hit"] == k
        if k >= 0:
            hits += 1
            assert s["t"] == pytest.approx(t, abs=1e-9)
            assert k in s["tested"]
            assert np.allclose(s["end"], o + t * d)
        assert s["tested_triangles"] < 48
    assert hits >= 4


@pytest.mark.parametrize("structure", ["grid", "quadtree", "kd-tree"])
def test_the_cells_are_crossed_by_the_ray_in_order(structure):
    for ox, oy, angle in RAYS:
        s = W.scene(W.State(structure=structure, ox=ox, oy=oy, angle_deg=angle, resolution=7,
                            leaf_size=1))
        o, d = s["origin"], s["direction"]
        entries = []
        for lo, hi in s["boxes"]:
            with np.errstate(divide="ignore", invalid="ignore"):
                t1, t2 = (lo - o) / d, (hi - o) / d
            t_in = max(np.nanmax(np.minimum(t1, t2)), 0.0)
            t_out = np.nanmin(np.maximum(t1, t2))
            assert t_in < t_out + 1e-9
            entries.append(t_in)
        assert np.all(np.diff(entries) > -1e-9)
        assert np.allclose(entries, s["entry"], atol=1e-9)
        if s["hit"] >= 0:                               # the walk stopped in the hit's cell
            lo, hi = s["boxes"][-1]
            assert np.all(s["end"] >= lo - 1e-6) and np.all(s["end"] <= hi + 1e-6)


def test_the_bvh_visits_boxes_the_ray_enters():
    for ox, oy, angle in RAYS:
        s = W.scene(W.State(structure="BVH", ox=ox, oy=oy, angle_deg=angle, leaf_size=2))
        o, d = s["origin"], s["direction"]
        for lo, hi in s["boxes"]:
            with np.errstate(divide="ignore", invalid="ignore"):
                t1, t2 = (lo - o) / d, (hi - o) / d
            assert max(np.nanmax(np.minimum(t1, t2)), 0.0) <= np.nanmin(np.maximum(t1, t2))


def test_the_image_is_opaque_rgb_and_marks_the_cells():
    s = W.scene(W.State())
    img = s["image"]
    assert img.shape == (W.SIZE, W.SIZE, 3) and img.min() >= 0 and img.max() <= 1
    lo, hi = s["boxes"][0]
    c = ((lo + hi) / 2 / W.VIEW * W.SIZE).astype(int)
    assert not np.allclose(img[c[1], c[0]], 1.0)          # the first cell is filled


def test_wiring_every_control_changes_the_picture_or_text():
    ex = W.SpatialExplorer()
    for control, value in [(ex.ox, 2.0), (ex.oy, 6.5), (ex.angle, -30.0),
                           (ex.resolution, 12), (ex.structure, "quadtree"),
                           (ex.leaf_size, 1), (ex.structure, "kd-tree"), (ex.structure, "BVH")]:
        before = (np.array(ex.image.get_array()).copy(), ex.info.value,
                  np.array(ex.ray.get_xydata()).copy())
        control.value = value
        after = (np.array(ex.image.get_array()), ex.info.value, np.array(ex.ray.get_xydata()))
        assert (not np.array_equal(before[0], after[0])) or before[1] != after[1] \
            or not np.array_equal(before[2], after[2]), control.description
        assert np.array_equal(after[0], W.scene(ex.state)["image"])
    assert "BVH" in ex.info.value
    labels = [t.get_text() for t in ex.numbers if t.get_text()]
    assert labels == [str(k + 1) for k in range(len(labels))]


def test_errors():
    with pytest.raises(ValueError, match="structure"):
        W.scene(W.State(structure="octree"))
    with pytest.raises(ValueError, match="resolution"):
        W.scene(W.State(resolution=0))
