"""Headless tests of the volume-rendering comparison explorer: its scene against the library
called here directly (ray casting, slicing, splatting of the same volume and view), the
differences recomputed, and the wiring (every control moves the picture or its text)."""
import matplotlib

matplotlib.use("module://ipympl.backend_nbagg")
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from course_lib import scivis  # noqa: E402
from course_lib.widgets import volume_compare as vc  # noqa: E402


def _geometry(az):
    vol = vc.volume()
    return vol, dict(rotation=scivis.view_rotation(np.radians(az), -0.35),
                     image_size=(vc.IMAGE, vc.IMAGE), spacing=vol.spacing, origin=vol.origin,
                     extent="sphere")


def test_scene_matches_the_library():
    state = vc.State(azimuth_deg=45, slices=32, kernel_radius=2.0, classification="pre",
                     preset="bone")
    s = vc.scene(state)
    vol, g = _geometry(45)
    ray = scivis.volume_render(vol.values, "bone", early_termination=None, **g).rgb
    diameter = np.linalg.norm(np.array(vol.spacing) * 31)
    sl = scivis.slice_render(vol.values, "bone", slice_spacing=diameter / 32,
                             classification="pre", **g).rgb
    sp = scivis.splat_render(vol.values, "bone", kernel_radius=2.0, **g).rgb
    for name, img in (("ray casting", ray), ("slicing", sl), ("splatting", sp)):
        assert np.allclose(s["images"][name], np.clip(img, 0, 1))
        assert np.isclose(s["differences"][name], np.abs(np.clip(img, 0, 1)
                                                         - np.clip(ray, 0, 1)).mean())
    assert s["differences"]["ray casting"] == 0.0
    assert "bone" in s["text"] and "Pre-classification" in s["text"]


def test_more_slices_come_closer_to_ray_casting():
    few = vc.scene(vc.State(slices=16))["differences"]["slicing"]
    many = vc.scene(vc.State(slices=128))["differences"]["slicing"]
    assert many < 0.5 * few
    assert "Few slices" in vc.scene(vc.State(slices=16))["text"]


def test_bad_state_is_named():
    with pytest.raises(ValueError, match="classification"):
        vc.scene(vc.State(classification="during"))
    with pytest.raises(ValueError, match="method"):
        vc.render("ray tracing", 0.0, "skin")


def test_wiring_every_control_moves_the_picture():
    ex = vc.VolumeCompareExplorer()
    for control, value, index in ((ex.azimuth, 90.0, 0), (ex.slices, 16, 1), (ex.kernel, 0.75, 2),
                                  (ex.classification, "pre", 1), (ex.preset, "bone", 0)):
        before = np.array(ex.images[index].get_array())
        text = ex.info.value
        control.value = value
        assert not np.array_equal(before, np.array(ex.images[index].get_array())), control
        assert ex.info.value != text
    expected = vc.scene(ex.state)
    for image, m in zip(ex.images, vc.METHODS):
        assert np.allclose(image.get_array(), expected["images"][m])
