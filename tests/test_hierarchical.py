"""Tests of course_lib.visibility.hierarchical: the z-pyramid against skimage's block_reduce and a
numpy reshape typed here, the conservativeness of the hierarchical z-buffer on seeded random
scenes rasterized by visibility.zbuffer (it never rejects a box the full buffer shows, and it does
reject clearly hidden boxes), occlusion queries against a brute-force loop, the occlusion map
against block_reduce(np.mean), and the error messages."""
import numpy as np
import pytest
from skimage.measure import block_reduce

from course_lib import visibility as V


def _scene(seed, size=64, n=25):
    """A depth buffer of random screen triangles rasterized by the z-buffer."""
    rng = np.random.default_rng(seed)
    tris = np.empty((n, 3, 3))
    centres = rng.uniform(0, size, (n, 1, 2))
    tris[:, :, :2] = centres + rng.uniform(-size / 3, size / 3, (n, 3, 2))
    tris[:, :, 2] = rng.uniform(0.1, 0.9, (n, 1)) + rng.uniform(-0.05, 0.05, (n, 3))
    back = [[[0, 0, 0.95], [size, 0, 0.95], [size, size, 0.95]],     # a far wall behind all
            [[0, 0, 0.95], [size, size, 0.95], [0, size, 0.95]]]
    return V.zbuffer(np.concatenate([tris, back]), size, size).depth


def _random_rects(rng, n, w, h, big=24):
    i0 = rng.integers(0, w, n)
    j0 = rng.integers(0, h, n)
    i1 = np.minimum(i0 + rng.integers(0, big, n), w - 1)
    j1 = np.minimum(j0 + rng.integers(0, big, n), h - 1)
    return np.stack([i0, j0, i1, j1], axis=1)


@pytest.mark.parametrize("shape", [(8, 8), (64, 64), (5, 7), (33, 17), (1, 6)])
def test_pyramid_levels_are_block_maxima(shape):
    d = np.random.default_rng(1).uniform(0, 1, shape)
    d[0, 0] = np.inf
    p = V.z_pyramid(d)
    assert np.array_equal(p.levels[0], d)
    assert p.levels[-1].shape == (1, 1) and p.levels[-1][0, 0] == np.inf
    for k in range(1, len(p.levels)):
        # level k = the max over the 2^k x 2^k block of real pixels (padding never adds a value)
        f = 2 ** k
        ref = block_reduce(d, (f, f), np.max, cval=-np.inf)
        assert np.array_equal(p.levels[k], ref), k


def test_pyramid_level_one_by_reshape():
    d = np.random.default_rng(2).uniform(0, 1, (16, 16))
    ref = d.reshape(8, 2, 8, 2).transpose(0, 2, 1, 3).reshape(8, 8, 4).max(axis=2)
    assert np.array_equal(V.z_pyramid(d).levels[1], ref)


@pytest.mark.parametrize("seed", range(4))
def test_hzb_never_rejects_a_box_the_full_buffer_shows(seed):
    depth = _scene(seed)
    rng = np.random.default_rng(100 + seed)
    rects = _random_rects(rng, 3000, 64, 64)
    z = rng.uniform(0, 1, len(rects))
    z[::3] = rng.uniform(0.9, 1.0, 1000)               # many boxes behind, near the far wall
    res = V.hzb_cull(V.z_pyramid(depth), rects, z)
    for (i0, j0, i1, j1), zn, rej in zip(rects, z, res.rejected):
        visible = (depth[j0:j1 + 1, i0:i1 + 1] > zn).any()
        assert not (rej and visible)
    full = V.full_cull(depth, rects, z)
    assert not (res.rejected & ~full.rejected).any()
    assert res.rejected.sum() > 200             # it does reject hidden boxes
    assert (res.texels <= 4).all()


def test_hidden_boxes_are_rejected():
    depth = np.full((32, 32), 0.3)
    p = V.z_pyramid(depth)
    assert V.hzb_test(p, (3, 5, 20, 27), 0.31)[0]
    assert not V.hzb_test(p, (3, 5, 20, 27), 0.3)[0]      # equal depth is not hidden
    depth[10, 10] = np.inf                               # a hole: the boxes over it are kept
    p = V.z_pyramid(depth)
    assert not V.hzb_test(p, (3, 5, 20, 27), 0.9)[0]
    assert V.hzb_test(p, (16, 16, 31, 31), 0.9)[0]


def test_level_and_texels_read():
    p = V.z_pyramid(np.zeros((64, 64)))
    for rect in [(0, 0, 0, 0), (5, 9, 6, 10), (3, 3, 40, 17), (0, 0, 63, 63), (31, 0, 32, 63)]:
        rej, k, texels = V.hzb_test(p, rect, 0.5)
        i0, j0, i1, j1 = rect
        spans = [(i1 >> k) - (i0 >> k) + 1, (j1 >> k) - (j0 >> k) + 1]
        assert max(spans) <= 2 and texels == spans[0] * spans[1]
        if k > 0:   # one level finer is too fine
            assert max((i1 >> (k - 1)) - (i0 >> (k - 1)), (j1 >> (k - 1)) - (j0 >> (k - 1))) >= 2


def test_single_test_equals_vectorized():
    depth = _scene(7)
    rng = np.random.default_rng(3)
    rects = _random_rects(rng, 200, 64, 64)
    z = rng.uniform(0, 1, 200)
    p = V.z_pyramid(depth)
    res = V.hzb_cull(p, rects, z)
    for k in range(200):
        assert V.hzb_test(p, rects[k], z[k]) == (res.rejected[k], res.level[k], res.texels[k])
        assert V.full_test(depth, rects[k], z[k])[0] == (z[k] > depth[rects[k][1]:rects[k][3] + 1,
                                                          rects[k][0]:rects[k][2] + 1].max())


def test_rectangles_are_clamped_or_refused():
    p = V.z_pyramid(np.full((8, 8), 0.5))
    assert V.hzb_test(p, (-5, -5, 20, 3), 0.7)[0]
    with pytest.raises(ValueError, match="off the"):
        V.hzb_test(p, (8, 0, 9, 3), 0.7)
    with pytest.raises(ValueError, match="negative size"):
        V.hzb_test(p, (4, 0, 3, 3), 0.7)
    with pytest.raises(ValueError, match="whole pixel"):
        V.hzb_test(p, (0.5, 0, 3, 3), 0.7)
    with pytest.raises(ValueError, match=r"\(n, 4\)"):
        V.hzb_cull(p, [(0, 0, 3)], [0.7])
    with pytest.raises(ValueError, match="z_nears"):
        V.hzb_cull(p, [(0, 0, 3, 3)], [0.7, 0.2])
    with pytest.raises(TypeError, match="Pyramid"):
        V.hzb_cull(np.zeros((8, 8)), [(0, 0, 3, 3)], [0.7])


def test_bad_buffers():
    with pytest.raises(ValueError, match="2D"):
        V.z_pyramid(np.zeros(5))
    with pytest.raises(ValueError, match="2D"):
        V.z_pyramid(np.zeros((0, 3)))
    with pytest.raises(ValueError, match="NaN"):
        V.z_pyramid([[0.1, np.nan]])
    with pytest.raises(TypeError, match="depth"):
        V.z_pyramid("deep")
    with pytest.raises(ValueError, match=r"\[0, 1\]"):
        V.occlusion_map_pyramid([[0.5, 1.5]])
    with pytest.raises(ValueError, match="NaN or infinite"):
        V.occlusion_map_pyramid([[0.5, np.inf]])
    with pytest.raises(ValueError, match="width"):
        V.draw_if_visible([(0, 0, 1, 1)], [0.5], -2, 4)
    with pytest.raises(ValueError, match="order"):
        V.draw_if_visible([(0, 0, 1, 1)], [0.5], 4, 4, order="random")


def test_occlusion_query_counts_like_a_loop():
    depth = _scene(3, size=32)
    rng = np.random.default_rng(5)
    for rect, z in zip(_random_rects(rng, 100, 32, 32, 12), rng.uniform(0, 1, 100)):
        i0, j0, i1, j1 = rect
        count = 0
        for j in range(j0, j1 + 1):
            for i in range(i0, i1 + 1):
                if z < depth[j, i]:
                    count += 1
        assert V.occlusion_query(depth, rect, z) == count


def test_occlusion_query_with_triangles():
    depth = np.full((8, 8), 0.5)
    depth[:, 4:] = np.inf
    square = [[[0, 0, 0.6], [8, 0, 0.6], [8, 8, 0.6]], [[0, 0, 0.6], [8, 8, 0.6], [0, 8, 0.6]]]
    assert V.occlusion_query(depth, square) == 32        # only the empty right half passes
    near = [[[0, 0, 0.4], [8, 0, 0.4], [8, 8, 0.4]], [[0, 0, 0.4], [8, 8, 0.4], [0, 8, 0.4]]]
    assert V.occlusion_query(depth, near) == 64


def test_draw_if_visible_front_to_back_culls_more():
    rng = np.random.default_rng(9)
    rects = _random_rects(rng, 60, 48, 48, 20)
    rects[0] = (0, 0, 47, 47)                           # a wall in front of half the objects
    z = rng.uniform(0.2, 1, 60)
    z[0] = 0.5
    f2b = V.draw_if_visible(rects, z, 48, 48)
    b2f = V.draw_if_visible(rects, z, 48, 48, order="back_to_front")
    assert b2f.drawn.all()
    assert not f2b.drawn[z > 0.5].any() and f2b.drawn[0]
    # the final pictures agree: culling changes the work, not the result
    assert np.array_equal(f2b.depth, b2f.depth)
    assert np.array_equal(np.sort(f2b.order), np.arange(60))
    assert (np.diff(z[f2b.order]) >= 0).all()


def test_threshold_skips_barely_visible_objects():
    depth = np.full((8, 8), 0.2)
    depth[0, 0] = np.inf
    r0 = V.draw_if_visible([(0, 0, 7, 7)], [0.5], 8, 8, depth=depth)
    r2 = V.draw_if_visible([(0, 0, 7, 7)], [0.5], 8, 8, threshold=2, depth=depth)
    assert r0.samples[0] == 1 and r0.drawn[0] and not r2.drawn[0]


@pytest.mark.parametrize("shape", [(16, 16), (12, 20), (7, 9)])
def test_occlusion_map_levels_are_block_means(shape):
    c = (np.random.default_rng(4).uniform(0, 1, shape) > 0.4).astype(float)
    p = V.occlusion_map_pyramid(c)
    for k in range(1, len(p.levels)):
        f = 2 ** k
        # pad with zeros to a multiple of 2^k, as block_reduce does with cval=0
        assert np.allclose(p.levels[k], block_reduce(c, (f, f), np.mean, cval=0)), k


def test_hom_threshold_makes_the_test_approximate():
    cov = np.ones((16, 16))
    cov[5, 6] = 0                                     # a one-pixel gap
    occ = np.where(cov > 0, 0.3, np.inf)
    deb = V.depth_estimation_buffer(occ, 4)
    p = V.occlusion_map_pyramid(cov)
    rect = (0, 0, 15, 15)
    exact = V.hom_test(p, rect, 0.8, deb, threshold=1.0)
    approx = V.hom_test(p, rect, 0.8, deb, threshold=0.9)
    assert not exact.culled and approx.culled and approx.level == 3
    assert np.isclose(approx.opacities.min(), 63 / 64)
    assert not V.hom_test(p, rect, 0.2, deb, threshold=0.9).culled   # in front of the occluder
    # the box really is visible through the gap: the HZB (conservative) keeps it
    assert not V.hzb_test(V.z_pyramid(occ), rect, 0.8)[0]


def test_depth_estimation_buffer_is_the_farthest_occluder_per_tile():
    d = np.random.default_rng(6).uniform(0, 1, (12, 12))
    d[d > 0.8] = np.inf
    d[:4, :4] = np.inf
    deb = V.depth_estimation_buffer(d, 4)
    for a in range(3):
        for b in range(3):
            block = d[4 * a:4 * a + 4, 4 * b:4 * b + 4]
            finite = block[np.isfinite(block)]
            assert deb[a, b] == (finite.max() if finite.size else np.inf)


def test_screen_rect_of_a_box():
    corners = np.array([[x, y, z] for x in (2.5, 9.5) for y in (1.0, 4.2) for z in (0.3, 0.6)])
    rect, zn = V.screen_rect(corners, 16, 16)
    assert rect == (2, 1, 9, 4) and zn == 0.3
    rect, _ = V.screen_rect(corners + [10, 0, 0], 16, 16)   # reaches past the right edge
    assert rect == (12, 1, 15, 4)
    with pytest.raises(ValueError, match="points"):
        V.screen_rect([[1, 2]], 16, 16)


def test_a_chosen_level_reads_every_covering_texel():
    depth = _scene(11)
    p = V.z_pyramid(depth)
    rect, z = (5, 9, 30, 20), 0.7
    full = V.full_test(depth, rect, z)[0]
    previous = True
    for k in range(len(p.levels)):
        rej, level, texels = V.hzb_test(p, rect, z, level=k)
        tex = p.levels[k][9 >> k:(20 >> k) + 1, 5 >> k:(30 >> k) + 1]
        assert level == k and texels == tex.size and rej == (z > tex.max())
        assert not rej or previous            # coarser levels reject no more than finer ones
        previous = rej
    assert V.hzb_test(p, rect, z, level=0)[0] == full
    with pytest.raises(ValueError, match="level"):
        V.hzb_test(p, rect, z, level=len(p.levels))


def test_more_errors_name_the_argument():
    p = V.z_pyramid(np.full((8, 8), 0.5))
    with pytest.raises(TypeError, match="z_nears"):
        V.hzb_cull(p, [(0, 0, 3, 3)], ["far"])
    with pytest.raises(ValueError, match="z_nears"):
        V.hzb_cull(p, [(0, 0, 3, 3)], [np.nan])
    with pytest.raises(ValueError, match="proxy"):
        V.occlusion_query(np.ones((4, 4)), (5, 5, 6, 6), 0.5)
    with pytest.raises(ValueError, match="tile"):
        V.depth_estimation_buffer(np.ones((4, 4)), 0)
    hom = V.occlusion_map_pyramid(np.ones((4, 4)))
    with pytest.raises(ValueError, match="threshold"):
        V.hom_test(hom, (0, 0, 1, 1), 0.5, np.zeros((1, 1)), threshold=1.5)
    with pytest.raises(TypeError, match="occlusion-map"):
        V.hom_test(p, (0, 0, 1, 1), 0.5, np.zeros((1, 1)))
    with pytest.raises(ValueError, match="deb"):
        V.hom_test(hom, (0, 0, 1, 1), 0.5, np.zeros(3))
    with pytest.raises(ValueError, match="max_span"):
        V.hzb_test(p, (0, 0, 1, 1), 0.5, max_span=0)


def test_hom_descent_with_threshold_one_is_exact_coverage():
    rng = np.random.default_rng(12)
    cov = np.ones((32, 32))
    cov[rng.integers(0, 32, 12), rng.integers(0, 32, 12)] = 0     # a few holes
    p = V.occlusion_map_pyramid(cov)
    deb = np.zeros((4, 4))                                        # every box is behind
    checked = 0
    for rect in _random_rects(rng, 400, 32, 32, 16):
        i0, j0, i1, j1 = rect
        covered = bool((cov[j0:j1 + 1, i0:i1 + 1] == 1).all())
        t = V.hom_test(p, rect, 0.5, deb, threshold=1.0)
        assert t.opaque == covered and t.culled == covered
        flat = V.hom_test(p, rect, 0.5, deb, threshold=1.0, descend=False)
        assert not flat.opaque or covered and t.reads >= flat.reads
        checked += covered
    assert checked > 20


def _box_mesh(lo, hi):
    v = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                  for z in (lo[2], hi[2])], float)
    f = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
         [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]
    return v, np.array(f)


def test_box_screen_rect_bounds_the_rendered_box():
    from course_lib import viewing
    rng = np.random.default_rng(13)
    view = viewing.look_at([1.0, 2.0, 6.0], [-0.1, -0.3, -1.0], [0, 1, 0])
    proj = viewing.perspective(np.radians(50), 1.0, 0.5, 20.0)
    for _ in range(20):
        c = rng.uniform(-2, 2, 3)
        lo, hi = c - rng.uniform(0.2, 1, 3), c + rng.uniform(0.2, 1, 3)
        v, f = _box_mesh(lo, hi)
        zb = V.render_depth(v, f, view, proj, 48, 48)
        shown = np.isfinite(zb.depth)
        if not shown.any():
            continue
        (i0, j0, i1, j1), zn = V.box_screen_rect(lo, hi, view, proj, 48, 48)
        rows, cols = np.nonzero(shown)
        assert i0 <= cols.min() and cols.max() <= i1 and j0 <= rows.min() and rows.max() <= j1
        assert zn <= zb.depth[shown].min() + 1e-12
    # a box around the eye: the whole screen, never culled
    assert V.box_screen_rect([0, 1, 5], [2, 3, 7], view, proj, 48, 48) == ((0, 0, 47, 47), 0.0)
    with pytest.raises(ValueError, match="negative size"):
        V.box_screen_rect([1, 1, 1], [0, 2, 2], view, proj, 48, 48)
