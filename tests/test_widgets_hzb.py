"""Headless tests of the hierarchical z-buffer explorer: its scene against the library and a
per-pixel check typed here (the z-pyramid level as block maxima by a numpy reshape, the texels
read, the decisions), and its wiring (every control changes the picture or the text)."""
import numpy as np

from course_lib import visibility
from course_lib.widgets import hzb


def test_scene_level_is_the_block_max_and_the_decision_is_right():
    occ, full = hzb.depth_buffers()
    assert np.array_equal(np.isinf(occ), full == hzb.FAR_WALL)
    for level in range(4):
        st = hzb.State(level=level, x=10, y=12, size=14, z_near=0.5)
        s = hzb.scene(st)
        f = 2 ** level
        blocks = full.reshape(64 // f, f, 64 // f, f).max(axis=(1, 3))
        assert np.array_equal(s["level_values"], blocks)
        i0, j0, i1, j1 = s["rect"]
        assert s["rect"] == (10, 12, 23, 25) and s["pixels"] == 14 * 14
        tex = blocks[j0 // f:j1 // f + 1, i0 // f:i1 // f + 1]
        assert s["texels"] == tex.size
        assert s["rejected"] == (0.5 > tex.max())
        assert s["full_rejected"] == (0.5 > full[j0:j1 + 1, i0:i1 + 1].max())
        assert not s["rejected"] or s["full_rejected"]        # conservative
    assert hzb.scene(hzb.State(level=0))["rejected"]
    assert not hzb.scene(hzb.State(level=3))["rejected"]      # coarse texels reach the far wall


def test_hom_mode_uses_the_averaged_coverage():
    occ, _ = hzb.depth_buffers()
    cov = np.isfinite(occ).astype(float)
    s = hzb.scene(hzb.State(mode="HOM", level=2))
    assert np.allclose(s["level_values"], cov.reshape(16, 4, 16, 4).mean(axis=(1, 3)))
    deb = visibility.depth_estimation_buffer(occ, 8)
    t = visibility.hom_test(visibility.occlusion_map_pyramid(cov), s["rect"], 0.5, deb, 0.9,
                            level=2)
    assert s["rejected"] == t.culled


def test_the_image_is_opaque_rgb_and_shows_the_box():
    s = hzb.scene(hzb.State())
    img = s["image"]
    assert img.shape == (128, 128, 3) and img.min() >= 0 and img.max() <= 1
    plain = hzb.scene(hzb.State(x=50, y=50, size=1))["image"]
    assert not np.array_equal(img[30:40, 30:40], plain[30:40, 30:40])


def test_wiring_every_control_changes_the_picture_or_text():
    ex = hzb.HZBExplorer()
    for control, value in ((ex.level, 1), (ex.x, 30), (ex.y, 40), (ex.size, 6),
                           (ex.z_near, 0.97), (ex.mode, "HOM"), (ex.threshold, 0.5)):
        before = np.array(ex.image.get_array())
        text = ex.info.value
        control.value = value
        after = np.array(ex.image.get_array())
        assert not np.array_equal(before, after) or text != ex.info.value, control
    assert np.array_equal(np.array(ex.image.get_array()), hzb.scene(ex.state)["image"])


def test_threshold_in_hzb_mode_changes_the_text():
    ex = hzb.HZBExplorer()
    text = ex.info.value
    ex.threshold.value = 0.6
    assert ex.info.value != text and "0.60" in ex.info.value
