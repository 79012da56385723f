"""Headless tests of the SSAO explorer: its scene against the library computed here (SSAO of the
cached G-buffer, the ray-traced AO as the fraction-weighted hit distances typed here) and its
wiring (every control moves the picture)."""
import numpy as np

from course_lib import shading
from course_lib.widgets import ssao


def test_scene_matches_the_library_and_a_hand_falloff():
    state = ssao.State(radius=0.6, samples=8, bias=0.02, blur=1, range_check=True, seed=3)
    s = ssao.scene(state)
    sc, gb = ssao.buffers()
    expected = shading.ssao(gb.positions, gb.normals, sc.projection, gb.mask, radius=0.6,
                            samples=8, bias=0.02, blur=1, seed=3)
    assert np.array_equal(s["ssao"], expected)
    # the ray-traced AO with the linear falloff, typed here: 1 - mean over the first 8 rays of
    # max(0, 1 - t / R)
    t = ssao.ray_distances().distances[..., :8]
    ray = 1 - np.mean(np.maximum(0, 1 - t / 0.6), axis=-1)
    assert np.allclose(s["ray"], ray)
    assert np.allclose(s["difference"], s["ssao"] - ray)
    assert np.isclose(s["mean_abs_difference"], np.abs(s["ssao"] - ray).mean())


def test_range_check_off_makes_halos_and_the_text_says_so():
    on = ssao.scene(ssao.State(range_check=True))
    off = ssao.scene(ssao.State(range_check=False))
    assert (off["ssao"] <= on["ssao"] + 1e-12).all()        # only more occluders, never fewer
    assert off["ssao"].mean() < on["ssao"].mean() - 0.005
    assert "halos" in off["text"] and "Range check off" in off["text"]
    assert "Range check off" not in on["text"]


def test_agreement_under_the_shelf():
    s = ssao.scene(ssao.State(samples=32))
    us, ur = s["under_shelf"]
    assert ur < 0.97 and abs(us - ur) < 0.06
    assert s["mean_abs_difference"] < 0.05


def test_wiring_every_control_moves_the_picture():
    ex = ssao.SSAOExplorer()
    first = np.array(ex.images[0].get_array())
    ex.radius.value = 0.9
    assert "R = 0.90" in ex.info.value
    after_radius = np.array(ex.images[0].get_array())
    assert not np.array_equal(first, after_radius)
    expected = ssao.scene(ssao.State(radius=0.9))
    assert np.array_equal(after_radius, expected["ssao"])
    assert np.allclose(ex.images[1].get_array(), expected["ray"])
    for control, value in ((ex.samples, 24), (ex.bias, 0.0), (ex.blur, 1),
                           (ex.range_check, False)):
        before = np.array(ex.images[0].get_array())
        control.value = value
        assert not np.array_equal(before, np.array(ex.images[0].get_array())), control
    assert "Small bias" in ex.info.value and "noise tile" in ex.info.value
