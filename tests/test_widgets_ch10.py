"""Headless tests of the chapter 10 explorers: the transfer-function editor and the colour-map
explorer. Scenes are checked against independent maths (numpy.interp, a hand-written front-to-
back compositing loop, Beer-Lambert's law, matplotlib's colour maps, scikit-image's CIE L*a*b*)
and the wiring by driving the controls and the mouse gestures and reading the artists back."""
import matplotlib
import numpy as np
import pytest
from skimage import color as skcolor

from course_lib import colormaps, scivis
from course_lib.widgets import colormap, transfer_function as tfw


def interp_rgba(points, colors, opacities, s):
    """The editor's transfer function, evaluated independently with numpy.interp."""
    table = np.column_stack([colors, opacities])
    return np.stack([np.interp(s, points, table[:, c]) for c in range(4)], axis=-1)


def checkerboard(shape, squares=8, light=0.93, dark=0.78):
    size = max(1, shape[1] // squares)
    rows, cols = np.meshgrid(np.arange(shape[0]), np.arange(shape[1]), indexing="ij")
    return np.where((rows // size + cols // size) % 2 == 0, light, dark)


def srgb_to_linear(c):
    c = np.asarray(c, float)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(y):
    return np.where(y <= 0.0031308, 12.92 * y, 1.055 * y ** (1 / 2.4) - 0.055)


# --- transfer-function editor: the pure part ---------------------------------------------------

@pytest.mark.parametrize("field", ["hills", "ripple", "CT slice"])
@pytest.mark.parametrize("preset", tfw.PRESETS)
def test_field_is_the_transfer_function_blended_over_a_checkerboard(field, preset):
    points, colors, opacities = tfw.preset_points(preset)
    state = tfw.State(points=points, colors=colors, opacities=opacities, field=field,
                      thickness=7.0, preview=True)
    s = tfw.scene(state)
    data = tfw.example_data(field).values
    rgba = interp_rgba(points, colors, opacities, data)
    alpha = 1 - (1 - rgba[..., 3:]) ** 7.0          # a slab 7 voxels thick
    expected = alpha * rgba[..., :3] + (1 - alpha) * checkerboard(data.shape)[..., None]
    assert np.allclose(s["field_rgb"], expected, atol=1e-12)
    grid = np.linspace(0, 1, tfw.CURVE_SAMPLES)
    assert np.allclose(s["curve"], np.column_stack([grid, np.interp(grid, points, opacities)]))
    assert np.allclose(s["strip"][0], interp_rgba(points, colors, opacities, grid)[:, :3])
    assert np.allclose(s["handles"], np.column_stack([points, opacities]))


def test_presets_are_the_library_presets():
    # the bone preset: transparent below 0.55, opaque bone from 0.75 (colormaps.transfer_preset)
    points, colors, opacities = tfw.preset_points("bone")
    assert np.allclose(points, [0.0, 0.55, 0.75, 0.9, 1.0])
    assert np.allclose(opacities, [0.0, 0.0, 0.8, 0.8, 1.0])
    with pytest.raises(ValueError, match="name must be one of"):
        tfw.preset_points("lungs")
    with pytest.raises(ValueError, match="kind must be one of"):
        tfw.example_data("teapot")


def test_example_data_is_normalised():
    for kind in tfw.FIELDS + ("ct",):
        values = tfw.example_data(kind).values
        assert values.min() == 0.0 and values.max() == 1.0


def uniform_volume(value=0.5, n=16):
    h = 2.0 / (n - 1)
    return scivis.Field(np.full((n, n, n), value), (h, h, h), (-1.0, -1.0, -1.0), value)


@pytest.mark.parametrize("alpha", [0.05, 0.2, 0.6])
def test_preview_obeys_beer_lambert_through_a_uniform_block(alpha):
    # a uniform cube [-1, 1]^3 seen along z: every central ray crosses a path of length 2;
    # with opacity alpha per voxel (length h) the transmittance is (1 - alpha)^(2 / h), up to
    # one sampling step more or less
    vol = uniform_volume()
    tf = colormaps.TransferFunction([0, 1], [[1, 1, 1, alpha], [1, 1, 1, alpha]])
    rays = tfw.RaySamples(vol, 0.0, 0.0, image_size=(9, 9), step=0.5)
    img = rays.composite(tf)
    h = vol.spacing[0]
    step = 0.5 * h
    a = img.alpha[4, 4]                             # the centre pixel, u = v = 0
    low, high = (1 - (1 - alpha) ** ((2 - step) / h), 1 - (1 - alpha) ** ((2 + step) / h))
    assert low - 1e-9 <= a <= high + 1e-9
    assert np.allclose(img.rgb[4, 4], a)            # white over black: the colour is A


def test_preview_compositing_against_a_hand_written_loop():
    rays = tfw.RaySamples(tfw.example_data("ct"), 25.0, -15.0, image_size=(12, 12), step=1.0)
    points, colors, opacities = tfw.preset_points("skin")
    tf = colormaps.TransferFunction(points, np.column_stack([colors, opacities]))
    img = rays.composite(tf)
    step_over_unit = rays.step / rays.unit
    expected = np.zeros((rays.hit.sum(), 4))
    for r, (values, inside) in enumerate(zip(rays.samples, rays.inside)):
        c, a = np.zeros(3), 0.0
        for v, ok in zip(values, inside):
            if not ok:
                continue
            rgba = interp_rgba(points, colors, opacities, v)
            ak = 1 - (1 - rgba[3]) ** step_over_unit
            c += (1 - a) * ak * rgba[:3]
            a += (1 - a) * ak
        expected[r] = [*c, a]
    got = np.column_stack([img.rgb.reshape(-1, 3), img.alpha.ravel()])[rays.hit]
    # classification through a 1024-entry table: the error is below slope / 2046 per sample
    assert np.abs(got - expected).max() < 5e-3
    assert (img.alpha[~rays.hit.reshape(12, 12)] == 0.0).all()


def test_preview_matches_the_library_ray_caster():
    ct = tfw.example_data("ct")
    tf = colormaps.transfer_preset("skin")
    rays = tfw.RaySamples(ct, -30.0, 10.0, image_size=(32, 32), step=0.5)
    preview = rays.composite(tf)
    voxel = min(ct.spacing)
    full = scivis.volume_render(
        ct.values, tf, rotation=scivis.view_rotation(*np.radians([-30.0, 10.0])),
        image_size=(32, 32), step=0.5 * voxel, spacing=ct.spacing, origin=ct.origin,
        extent=tfw.EXTENT, unit_length=voxel, early_termination=None)
    # same rays, samples offset by less than a step along them: the same picture
    assert np.abs(preview.rgb - full.rgb).mean() < 0.01
    assert np.abs(preview.alpha - full.alpha).mean() < 0.01
    assert np.abs(preview.rgb - full.rgb).max() < 0.15


# --- transfer-function editor: the wiring ------------------------------------------------------

def test_dragging_a_point_edits_the_function_and_redraws():
    ex = tfw.TransferFunctionExplorer()
    ex.fig.canvas.draw()
    before_volume = np.array(ex.volume_image.get_array())
    before_field = np.array(ex.field_image.get_array())
    x, y = ex.drag.points[6]
    ex.drag.press(x, y)
    assert ex.state.selected == 6 and ex.point.value == 6
    ex.drag.move(x + 0.02, 0.55)
    assert ex.state.preview and ex.preset.value == "custom"
    assert np.isclose(ex.state.points[6], x + 0.02) and np.isclose(ex.state.opacities[6], 0.55)
    assert np.allclose(ex.handles.get_offsets()[6], [x + 0.02, 0.55])
    curve = np.array(ex.curve.get_xydata())
    assert np.allclose(curve[:, 1], np.interp(curve[:, 0], ex.state.points, ex.state.opacities))
    assert np.asarray(ex.volume_image.get_array()).shape[:2] == tfw.PREVIEW_SIZE
    assert not np.allclose(np.asarray(ex.field_image.get_array()), before_field)
    ex.drag.release()
    assert not ex.state.preview
    assert ex.value.value == pytest.approx(x + 0.02, abs=0.005)
    assert ex.opacity.value == pytest.approx(0.55, abs=0.005)
    volume = np.asarray(ex.volume_image.get_array())
    assert volume.shape[:2] == tfw.IMAGE_SIZE and not np.allclose(volume, before_volume)
    assert np.allclose(volume, tfw.render(tfw.transfer(ex.state)).rgb)
    # more opaque bone hides more: the mean accumulated brightness rises
    assert volume.mean() > before_volume.mean()


def test_drag_keeps_points_in_order_and_opacity_in_range():
    ex = tfw.TransferFunctionExplorer()
    x, y = ex.drag.points[3]
    ex.drag.press(x, y)
    ex.drag.move(0.95, 1.05)                       # beyond the next point and above 1
    assert ex.state.points[3] < ex.state.points[4]
    assert ex.state.points[3] == pytest.approx(ex.state.points[4] - tfw.MIN_GAP)
    assert ex.state.opacities[3] == 1.0
    assert np.all(np.diff(ex.state.points) > 0)
    ex.drag.release()


def test_controls_presets_and_buttons():
    ex = tfw.TransferFunctionExplorer()
    ex.preset.value = "bone"
    assert np.allclose(ex.state.points, [0.0, 0.55, 0.75, 0.9, 1.0])
    assert np.allclose(ex.handles.get_offsets(), np.column_stack([ex.state.points,
                                                                  ex.state.opacities]))
    curve = np.array(ex.curve.get_xydata())
    ex.point.value = 1
    ex.add_point()                                 # on the function: nothing changes
    assert len(ex.state.points) == 6 and ex.state.selected == 2
    assert np.allclose(ex.curve.get_xydata(), curve)
    ex.opacity.value = 0.4
    assert ex.state.opacities[2] == pytest.approx(0.4)
    assert np.interp(ex.state.points[2], *np.array(ex.curve.get_xydata()).T) == \
        pytest.approx(0.4, abs=0.01)
    ex.color.value = "#00ff00"
    assert np.allclose(ex.state.colors[2], [0, 1, 0])
    ex.remove_point()
    assert len(ex.state.points) == 5
    ex.recolor.value = "grey"                      # colours from a map at the points
    assert np.allclose(ex.state.colors, np.repeat(ex.state.points[:, None], 3, axis=1),
                       atol=1e-9)
    ex.field.value = "ripple"
    data = tfw.example_data("ripple").values
    rgba = interp_rgba(ex.state.points, ex.state.colors, ex.state.opacities, data)
    alpha = 1 - (1 - rgba[..., 3:]) ** ex.state.thickness
    expected = alpha * rgba[..., :3] + (1 - alpha) * checkerboard(data.shape)[..., None]
    assert np.allclose(np.asarray(ex.field_image.get_array()), expected)
    before = np.array(ex.volume_image.get_array())
    ex.azimuth.value = 60
    assert not np.allclose(np.asarray(ex.volume_image.get_array()), before)
    bundle = ex._repr_mimebundle_()
    assert bundle["text/plain"] == ex.summary and "image/png" in bundle


def test_editor_figure_is_an_ipympl_canvas():
    ex = tfw.TransferFunctionExplorer()
    assert type(ex.fig.canvas).__module__.startswith("ipympl")
    assert ex.fig.canvas in ex.widget.children


# --- colour-map explorer -------------------------------------------------------------------------

@pytest.mark.parametrize("name", ["viridis", "magma", "cividis", "jet", "turbo", "coolwarm"])
def test_lightness_against_matplotlib_and_skimage(name):
    s = colormap.scene(colormap.State(name=name))
    reference = matplotlib.colormaps[name](np.linspace(0, 1, colormap.SAMPLES))[:, :3]
    assert np.abs(s["colors"] - reference).max() < 0.02
    assert np.abs(s["lightness"] - skcolor.rgb2lab(reference)[:, 0]).max() < 1.0


def test_monotonic_verdicts():
    verdicts = {name: colormap.scene(colormap.State(name=name))["monotonic"]
                for name in ("viridis", "magma", "cividis", "grey", "jet", "rainbow", "bwr")}
    assert verdicts == {"viridis": True, "magma": True, "cividis": True, "grey": True,
                        "jet": False, "rainbow": False, "bwr": False}


def test_greyscale_print_keeps_luminance_and_lightness():
    s = colormap.scene(colormap.State(name="jet", data="hills"))
    lin = srgb_to_linear(s["rgb"])
    y = lin @ [0.2126, 0.7152, 0.0722]
    assert np.allclose(s["grey"], linear_to_srgb(y), atol=2e-4)
    # L* depends on the luminance Y only, so the grey print keeps each colour's lightness
    grey_rgb = np.repeat(s["grey"][..., None], 3, axis=-1)
    assert np.allclose(skcolor.rgb2lab(grey_rgb)[..., 0], skcolor.rgb2lab(s["rgb"])[..., 0],
                       atol=0.1)


def test_print_ambiguity():
    assert colormap.print_ambiguity("grey") == 0.0
    # black - white - black: every value prints like its mirror image 1 - t, which is at
    # least 0.1 away except for the middle tenth
    share = colormap.print_ambiguity([[0, 0, 0], [1, 1, 1], [0, 0, 0]])
    assert 0.85 <= share <= 0.95
    assert colormap.print_ambiguity("jet") > colormap.print_ambiguity("viridis")


def test_colormap_explorer_wiring():
    ex = colormap.ColormapExplorer()
    data = colormap.example_data("smooth ramp")
    ex.name.value = "viridis"
    reference = matplotlib.colormaps["viridis"](data)[..., :3]
    assert np.abs(np.asarray(ex.color_image.get_array()) - reference).max() < 0.02
    assert "monotonic" in ex.info.value and "not monotonic" not in ex.info.value
    segments = ex.line.get_segments()
    lstar = skcolor.rgb2lab(matplotlib.colormaps["viridis"](np.linspace(0, 1, 256))[:, :3])
    assert np.abs(np.array([seg[0, 1] for seg in segments]) - lstar[:-1, 0]).max() < 1.0
    strip = np.asarray(ex.strip.get_array())[0].copy()
    ex.reverse.value = True
    assert np.allclose(np.asarray(ex.strip.get_array())[0], strip[::-1], atol=1e-12)
    ex.name.value = "rainbow"
    assert "not monotonic" in ex.info.value
    ex.data.value = "ripple"
    expected = colormaps.apply_colormap(colormap.example_data("ripple"), "rainbow_r",
                                        in_range=(0, 1))
    assert np.allclose(np.asarray(ex.color_image.get_array()), expected)
    with pytest.raises(ValueError, match="kind must be one of"):
        colormap.example_data("noise")
