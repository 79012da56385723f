"""Headless tests of the LIC explorer: its cached prefix-sum images against a direct call of
scivis.lic on the same field and noise, the preset fields against their formulas typed here,
and the wiring (every control changes the image)."""
import matplotlib
matplotlib.use("module://ipympl.backend_nbagg")
import numpy as np                                                          # noqa: E402
import pytest                                                               # noqa: E402

from course_lib import scivis                                               # noqa: E402
from course_lib.widgets import lic as W                                     # noqa: E402


def test_preset_fields_on_pixels():
    u, v = W.field_on_pixels("vortex", size=8)
    c = -1 + (np.arange(8) + 0.5) / 4
    x, y = np.meshgrid(c, c)
    assert np.allclose(u, -y) and np.allclose(v, x)
    u, v = W.field_on_pixels("vortex pair", size=8)
    r1, r2 = (x + 0.4) ** 2 + y ** 2 + 0.05, (x - 0.4) ** 2 + y ** 2 + 0.05
    assert np.allclose(u, -y / r1 + y / r2) and np.allclose(v, (x + 0.4) / r1 - (x - 0.4) / r2)


@pytest.mark.parametrize("length,kernel", [(3.0, "box"), (8.5, "box"), (6.0, "hann")])
def test_scene_equals_a_direct_lic(length, kernel):
    s = W.scene(W.State(preset="saddle", kernel_length=length, kernel=kernel))
    u, v = W.field_on_pixels("saddle")
    noise = np.random.default_rng(18).random((W.SIZE, W.SIZE))
    direct = scivis.lic(u, v, noise, kernel_length=length, step=W.STEP, kernel=kernel)
    assert np.allclose(s["lic"], direct, atol=1e-12)
    assert s["samples"] == 2 * int(length / W.STEP) + 1
    assert s["rgb"].shape == (W.SIZE, W.SIZE, 3)
    assert 0 <= s["rgb"].min() and s["rgb"].max() <= 1


def test_longer_kernels_smooth_more():
    spreads = [W.scene(W.State(kernel_length=L))["lic"].std() for L in (1, 4, 16)]
    assert spreads[0] > spreads[1] > spreads[2]


def test_every_control_changes_the_image():
    ex = W.LICExplorer()
    for control, value in ((ex.length, 16.0), (ex.kernel, "hann"), (ex.colour, True),
                           (ex.preset, "spiral")):
        before, text = np.array(ex.image.get_array()), ex.info.value
        control.value = value
        assert not np.allclose(before, np.array(ex.image.get_array())), control.description
        assert ex.info.value != text
    bar = ex.bar.get_xydata()
    assert bar[1, 0] - bar[0, 0] == pytest.approx(32.0)
