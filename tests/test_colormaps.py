"""Tests of course_lib.colormaps (chapter 10: normalisation, transfer functions, colour maps).

Expected values come from matplotlib (its colour maps and its hsv_to_rgb), from scikit-image
(``skimage.color``: rgb2xyz, rgb2lab, deltaE_cie76), from numpy's ``np.interp``, from closed
forms typed out below, and from published CIE L*a*b* values of the sRGB primaries. Nothing here
is copied from the output of the code under test.

Tolerances, stated once:
* colour maps against matplotlib at its 256 sample points: our perceptual maps are 64 control
  colours fitted to matplotlib's tables (see the module docstring): at most 3/255 per channel
  (0.0118; jet, with kinks between the control points, is the worst at 0.0101, cividis 0.0086)
  and a root-mean-square difference under 0.002; grey, rainbow and bwr are
  exact (1e-12), hot within 1e-4 (4-decimal rounding);
* L*a*b* against scikit-image: 0.01 (scikit-image uses 6-digit sRGB matrix coefficients and the
  rounded CIE constants 0.008856 and 7.787; we use the 7-digit matrix and the exact (6/29)^3).
"""
import subprocess
import sys
import warnings

import matplotlib
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib import colormaps as mpl_colormaps
from matplotlib.colors import Normalize, hsv_to_rgb
from skimage import color as skcolor

from course_lib import colormaps as CM

FAST = settings(max_examples=100, deadline=None, database=None)

# our name -> matplotlib's name; rainbow (the HSV hue sweep) is checked against hsv_to_rgb
MPL_NAME = {"grey": "gray", "jet": "jet", "turbo": "turbo", "hot": "hot", "bwr": "bwr",
            "coolwarm": "coolwarm", "viridis": "viridis", "magma": "magma",
            "inferno": "inferno", "plasma": "plasma", "cividis": "cividis"}
EXACT = {"grey": 1e-12, "bwr": 1e-12, "hot": 1e-4}
FITTED_MAX, FITTED_RMS = 3 / 255, 0.002


def rng(seed):
    return np.random.default_rng(seed)


def mpl_samples(name, n=256):
    return mpl_colormaps[name](np.linspace(0.0, 1.0, n))[:, :3]


def hsv_sweep(n=256):
    """The rainbow: hue from 240 degrees (blue) down to 0 (red), full saturation and value."""
    hue = np.linspace(2 / 3, 0.0, n)
    return hsv_to_rgb(np.stack([hue, np.ones(n), np.ones(n)], axis=-1))


# ---------------------------------------------------------------------------------------------
# normalize
# ---------------------------------------------------------------------------------------------

def test_normalize_matches_the_closed_form_on_random_data():
    data = rng(1).normal(5.0, 3.0, size=(40, 30))
    a, b = data.min(), data.max()
    expected = (data - a) / (b - a) * (7.0 - (-2.0)) + (-2.0)
    np.testing.assert_allclose(CM.normalize(data, out_range=(-2, 7)), expected, rtol=1e-13,
                               atol=1e-13)
    np.testing.assert_allclose(CM.normalize(data), (data - a) / (b - a), atol=1e-15)


def test_normalize_clips_or_extends_outside_in_range():
    data = np.array([-10.0, 0.0, 5.0, 10.0, 30.0])
    np.testing.assert_allclose(CM.normalize(data, in_range=(0, 10)), [0, 0, 0.5, 1, 1])
    np.testing.assert_allclose(CM.normalize(data, in_range=(0, 10), clip=False),
                               [-1, 0, 0.5, 1, 3])
    # a reversed out_range flips the scale
    np.testing.assert_allclose(CM.normalize(data, in_range=(0, 10), out_range=(1, 0)),
                               [1, 1, 0.5, 0, 0])


def test_normalize_constant_data_maps_to_the_middle_of_out_range():
    np.testing.assert_array_equal(CM.normalize(np.full(5, 3.0)), np.full(5, 0.5))
    np.testing.assert_array_equal(CM.normalize([7, 7], out_range=(10, 20)), [15.0, 15.0])
    assert CM.normalize(4.0, in_range=(4, 4), out_range=(-1, 1)) == 0.0


def test_normalize_propagates_nan_and_takes_the_range_from_the_other_values():
    out = CM.normalize([np.nan, 2.0, 4.0, np.nan, 3.0])
    assert np.isnan(out[[0, 3]]).all()
    np.testing.assert_allclose(out[[1, 2, 4]], [0.0, 1.0, 0.5])
    with pytest.raises(ValueError, match="all NaN"):
        CM.normalize([np.nan, np.nan])
    # with an explicit range an all-NaN input is fine: NaN out
    assert np.isnan(CM.normalize([np.nan], in_range=(0, 1))).all()


def test_normalize_scalar_gives_a_float():
    value = CM.normalize(5, in_range=(0, 10))
    assert isinstance(value, float) and value == 0.5


@pytest.mark.parametrize("kwargs, match", [
    ({"data": [1, np.inf]}, "data must not contain infinite"),
    ({"data": [1, 2], "in_range": (3, 1)}, "in_range must be \\(low, high\\)"),
    ({"data": [1, 2], "in_range": (1, 2, 3)}, "in_range must be a vector of 2"),
    ({"data": [], "in_range": None}, "data has no values"),
    ({"data": [1, 2], "out_range": (0, np.nan)}, "out_range must be finite"),
])
def test_normalize_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        CM.normalize(**kwargs)


def test_normalize_rejects_text():
    with pytest.raises(TypeError, match="data must be numbers"):
        CM.normalize("1, 2, 3")


@FAST
@given(st.lists(st.floats(-1e6, 1e6), min_size=2, max_size=30),
       st.tuples(st.floats(-100, 100), st.floats(-100, 100)))
def test_normalize_properties(values, out_range):
    data = np.array(values)
    out = CM.normalize(data, out_range=out_range)
    lo, hi = min(out_range), max(out_range)
    assert np.all(out >= lo - 1e-9 * (1 + abs(lo))) and np.all(out <= hi + 1e-9 * (1 + abs(hi)))
    if data.max() > data.min():
        # order is kept (or reversed with the range), the ends hit the ends
        order = np.argsort(data, kind="stable")
        steps = np.diff(out[order]) * np.sign(out_range[1] - out_range[0] or 1)
        assert np.all(steps >= -1e-9 * (1 + hi - lo))
        np.testing.assert_allclose(out[np.argmin(data)], out_range[0], atol=1e-9 * (1 + abs(lo)))
        np.testing.assert_allclose(out[np.argmax(data)], out_range[1], atol=1e-9 * (1 + abs(hi)))


# ---------------------------------------------------------------------------------------------
# transfer functions
# ---------------------------------------------------------------------------------------------

def test_linear_transfer_function_matches_np_interp_per_channel():
    gen = rng(2)
    points = np.sort(gen.uniform(-5, 5, 8))
    values = gen.uniform(0, 1, (8, 4))
    tf = CM.TransferFunction(points, values)
    s = gen.uniform(-7, 7, (50, 3))
    out = tf(s)
    assert out.shape == (50, 3, 4)
    for c in range(4):
        np.testing.assert_allclose(out[..., c], np.interp(s, points, values[:, c]), atol=1e-14)
    scalar = CM.TransferFunction(points, values[:, 0])
    np.testing.assert_allclose(scalar(s), np.interp(s, points, values[:, 0]), atol=1e-14)
    assert scalar(s).shape == s.shape and tf.channels == 4 and scalar.channels == 1


def test_step_transfer_function_holds_each_value_until_the_next_point():
    points = [0.0, 1.0, 2.5, 4.0]
    values = [10.0, 20.0, 30.0, 40.0]
    tf = CM.TransferFunction(points, values, kind="step")
    s = np.array([-1.0, 0.0, 0.5, 0.999, 1.0, 2.0, 2.5, 3.9, 4.0, 100.0])
    # written out by hand from the definition: value i on [p_i, p_{i+1})
    expected = [10, 10, 10, 10, 20, 20, 30, 30, 40, 40]
    np.testing.assert_array_equal(tf(s), expected)


def test_repeated_point_makes_a_right_continuous_jump():
    tf = CM.TransferFunction([0, 1, 1, 2], [0.0, 0.5, 0.8, 1.0])
    np.testing.assert_allclose(tf([0.5, 1 - 1e-12, 1.0, 1.5, 2.0, 3.0]),
                               [0.25, 0.5, 0.8, 0.9, 1.0, 1.0], atol=1e-9)


@pytest.mark.parametrize("points, values, kind, match", [
    ([0, 2, 1], [0, 1, 2], "linear", "non-decreasing"),
    ([0, 1, 1, 1], [0, 1, 2, 3], "linear", "at most twice"),
    ([0, 1, 1], [0, 1, 2], "step", "strictly increasing"),
    ([0, 1], [0, 1, 2], "linear", "one entry per point"),
    ([0, 1], [[0] * 5, [1] * 5], "linear", "one entry per point"),
    ([0], [0], "linear", "at least 2"),
    ([0, 1], [0, 1], "cubic", "kind must be"),
    ([0, np.nan], [0, 1], "linear", "points must be finite"),
])
def test_transfer_function_bad_input(points, values, kind, match):
    with pytest.raises(ValueError, match=match):
        CM.TransferFunction(points, values, kind=kind)


def test_transfer_function_rejects_nan_scalars():
    with pytest.raises(ValueError, match="scalars must be finite"):
        CM.TransferFunction([0, 1], [0, 1])([0.5, np.nan])


def test_opacity_and_color_transfer_check_the_unit_interval():
    with pytest.raises(ValueError, match="opacities must lie in \\[0, 1\\].*-0.1 at index 0"):
        CM.opacity_transfer([0, 1], [-0.1, 0.5])
    with pytest.raises(ValueError, match="opacities must lie in \\[0, 1\\]"):
        CM.opacity_transfer([0, 1], [0.2, 1.01])
    with pytest.raises(ValueError, match="colors must lie in \\[0, 1\\]"):
        CM.color_transfer([0, 1], [[0, 0, 0], [1, 2, 0]])
    with pytest.raises(ValueError, match="shape \\(n, 3\\)"):
        CM.color_transfer([0, 1], [0, 1])
    alpha = CM.opacity_transfer([0, 1], [0.0, 1.0], kind="step")
    np.testing.assert_array_equal(alpha([0.5, 1.0]), [0.0, 1.0])


def test_lookup_table_samples_evenly():
    tf = CM.TransferFunction([0, 10], [[0, 0, 0], [1, 1, 1]])
    table = tf.lookup_table(11)
    np.testing.assert_allclose(table, np.repeat(np.linspace(0, 1, 11)[:, None], 3, axis=1))
    np.testing.assert_allclose(tf.lookup_table(3, in_range=(-10, 20))[:, 0], [0, 0.5, 1])


@pytest.mark.parametrize("color_kind, opacity_kind", [("linear", "linear"), ("step", "linear"),
                                                      ("linear", "step"), ("step", "step")])
def test_rgba_transfer_equals_both_functions_side_by_side(color_kind, opacity_kind):
    gen = rng(3)
    cp = np.sort(gen.choice(np.linspace(0, 1, 21), 6, replace=False))
    op = np.sort(gen.choice(np.linspace(0, 1, 21), 5, replace=False))
    color = CM.color_transfer(cp, gen.uniform(0, 1, (6, 3)), kind=color_kind)
    opacity = CM.opacity_transfer(op, gen.uniform(0, 1, 5), kind=opacity_kind)
    rgba = CM.rgba_transfer(color, opacity)
    # random scalars, and exactly the control points (where jumps happen)
    s = np.concatenate([gen.uniform(-0.2, 1.2, 500), cp, op])
    expected = np.concatenate([color(s), opacity(s)[:, None]], axis=1)
    np.testing.assert_allclose(rgba(s), expected, atol=1e-12)
    assert rgba.channels == 4


def test_rgba_transfer_with_a_colormap_name_and_a_grey_function():
    opacity = CM.opacity_transfer([10, 20], [0.1, 0.9])
    rgba = CM.rgba_transfer("viridis", opacity)
    s = np.linspace(5, 25, 41)
    np.testing.assert_allclose(rgba(s)[:, :3], CM.apply_colormap(s, "viridis", (10, 20)),
                               atol=1e-12)
    grey = CM.TransferFunction([0, 1], [0.0, 1.0])
    out = CM.rgba_transfer(grey, CM.opacity_transfer([0, 1], [1, 1]))(0.25)
    np.testing.assert_allclose(out, [0.25, 0.25, 0.25, 1.0])
    with pytest.raises(TypeError, match="opacity must be a one-channel"):
        CM.rgba_transfer("grey", CM.color_transfer([0, 1], [[0, 0, 0], [1, 1, 1]]))


@pytest.mark.parametrize("name", ["ramp", "skin", "bone"])
def test_presets_are_rgba_in_the_unit_interval_and_scale_with_in_range(name):
    tf = CM.transfer_preset(name)
    s = np.linspace(-0.5, 1.5, 401)
    out = tf(s)
    assert out.shape == (401, 4) and out.min() >= 0 and out.max() <= 1
    assert out[0, 3] == 0.0                  # air is transparent in every preset
    scaled = CM.transfer_preset(name, in_range=(-1000, 3000))
    np.testing.assert_allclose(scaled(-1000 + 4000 * s), out, atol=1e-12)
    with pytest.raises(ValueError, match="name must be one of"):
        CM.transfer_preset("lungs")


# ---------------------------------------------------------------------------------------------
# colour maps against matplotlib
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", sorted(MPL_NAME))
def test_colormap_matches_matplotlib_at_its_sample_points(name):
    ours = CM.sample_colormap(name, 256)
    ref = mpl_samples(MPL_NAME[name])
    err = np.abs(ours - ref)
    if name in EXACT:
        assert err.max() <= EXACT[name], err.max()
    else:
        assert err.max() <= FITTED_MAX, f"{name}: max difference {err.max():.4f}"
        assert np.sqrt((err ** 2).mean()) <= FITTED_RMS


def test_rainbow_is_the_hsv_hue_sweep_from_blue_to_red():
    np.testing.assert_allclose(CM.sample_colormap("rainbow", 256), hsv_sweep(256), atol=1e-12)


def test_every_shipped_map_is_checked_against_a_reference():
    assert set(CM.COLORMAP_NAMES) == set(MPL_NAME) | {"rainbow"}


def test_reversed_maps_aliases_and_custom_arrays():
    np.testing.assert_array_equal(CM.colormap("viridis_r"), CM.colormap("viridis")[::-1])
    np.testing.assert_allclose(CM.sample_colormap("magma_r", 256), mpl_samples("magma_r"),
                               atol=FITTED_MAX)
    np.testing.assert_array_equal(CM.colormap("gray"), CM.colormap("grey"))
    np.testing.assert_array_equal(CM.colormap("heat"), CM.colormap("hot"))
    custom = [[0, 0, 0], [1, 0, 0], [1, 1, 1]]
    np.testing.assert_allclose(CM.sample_colormap(custom, 5),
                               [[0, 0, 0], [0.5, 0, 0], [1, 0, 0], [1, 0.5, 0.5], [1, 1, 1]])
    # the module's data cannot be changed through what colormap returns
    c = CM.colormap("viridis")
    c[:] = 0
    assert CM.colormap("viridis").max() > 0


@pytest.mark.parametrize("cmap, error, match", [
    ("rainbows", ValueError, "cmap must be one of grey, rainbow"),
    ([[0, 0, 0]], ValueError, "n >= 2 colours"),
    ([[0, 0], [1, 1]], ValueError, "\\(n, 3\\) / \\(n, 4\\)"),
    ([[0, 0, 0], [1, 1, 1.5]], ValueError, "cmap must lie in \\[0, 1\\]"),
    (None, TypeError, "cmap must be numbers"),
])
def test_colormap_bad_input(cmap, error, match):
    with pytest.raises(error, match=match):
        CM.colormap(cmap)


@pytest.mark.parametrize("name", ["viridis", "grey", "coolwarm", "hot"])
def test_apply_colormap_matches_matplotlib_on_random_data(name):
    data = rng(4).normal(size=(30, 20))
    vmin, vmax = -1.5, 2.0
    ours = CM.apply_colormap(data, name, in_range=(vmin, vmax))
    # matplotlib: normalise, clip, look up in its 256-entry table (nearest entry); our map is
    # interpolated, so allow one table step of change on top of the fitting tolerance
    ref = mpl_colormaps[MPL_NAME[name]](Normalize(vmin, vmax, clip=True)(data))[..., :3]
    step = np.abs(np.diff(mpl_samples(MPL_NAME[name]), axis=0)).max()
    assert ours.shape == (30, 20, 3)
    assert np.abs(ours - ref).max() <= FITTED_MAX + step


def test_apply_colormap_paints_nan_in_nan_color_and_adds_alpha():
    data = np.array([[0.0, np.nan], [1.0, 2.0]])
    rgb = CM.apply_colormap(data, "grey")
    np.testing.assert_allclose(rgb[0, 1], [1.0, 0.0, 1.0])            # magenta: visible
    np.testing.assert_allclose(rgb[[0, 1, 1], [0, 0, 1]], [[0, 0, 0], [0.5] * 3, [1, 1, 1]])
    rgba = CM.apply_colormap(data, "grey", opacity=0.4, nan_color=(0, 0, 0, 0))
    assert rgba.shape == (2, 2, 4)
    np.testing.assert_allclose(rgba[0, 1], [0, 0, 0, 0])
    np.testing.assert_allclose(rgba[1, 1], [1, 1, 1, 0.4])
    tf = CM.opacity_transfer([0, 2], [0.0, 1.0])
    np.testing.assert_allclose(CM.apply_colormap(data, "grey", opacity=tf)[..., 3],
                               [[0.0, 1.0], [0.5, 1.0]])                # NaN: nan_color alpha 1
    assert np.all(CM.apply_colormap([np.nan, np.nan], "grey") == [1.0, 0.0, 1.0])


def test_apply_colormap_clamps_outside_in_range():
    np.testing.assert_allclose(CM.apply_colormap([-5, 15], "bwr", in_range=(0, 10)),
                               [[0, 0, 1], [1, 0, 0]])


@pytest.mark.parametrize("kwargs, match", [
    ({"opacity": 1.5}, "opacity must lie in \\[0, 1\\]"),
    ({"nan_color": (1, 0)}, "nan_color must be \\(r, g, b\\)"),
    ({"nan_color": (2, 0, 0)}, "nan_color must lie in \\[0, 1\\]"),
    ({"cmap": "nope"}, "cmap must be one of"),
    ({"in_range": (1, 0)}, "in_range must be \\(low, high\\)"),
])
def test_apply_colormap_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        CM.apply_colormap([0.0, np.nan, 1.0], **kwargs)


# ---------------------------------------------------------------------------------------------
# colour science
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("rgb, lab", [
    ([1, 1, 1], [100.0, 0.0, 0.0]),
    ([0, 0, 0], [0.0, 0.0, 0.0]),
    ([0.5, 0.5, 0.5], [53.39, 0.0, 0.0]),
    ([1, 0, 0], [53.24, 80.09, 67.20]),
    ([0, 1, 0], [87.73, -86.18, 83.18]),
    ([0, 0, 1], [32.30, 79.19, -107.86]),
])
def test_lab_of_reference_colours(rgb, lab):
    # published CIE L*a*b* (D65) values of sRGB white, black, mid grey and the primaries
    np.testing.assert_allclose(CM.srgb_to_lab(rgb), lab, atol=0.006)


def test_lab_and_xyz_match_scikit_image_on_random_colours():
    colours = rng(5).random((3000, 3))
    np.testing.assert_allclose(CM.srgb_to_xyz(colours), skcolor.rgb2xyz(colours), atol=2e-4)
    np.testing.assert_allclose(CM.srgb_to_lab(colours), skcolor.rgb2lab(colours), atol=0.01)
    dark = rng(6).random((500, 3)) * 0.05           # the linear parts of both curves
    np.testing.assert_allclose(CM.srgb_to_lab(dark), skcolor.rgb2lab(dark), atol=0.01)
    shaped = colours.reshape(10, 300, 3)
    assert CM.srgb_to_lab(shaped).shape == (10, 300, 3)


def test_gamma_encoding_round_trip_and_closed_forms():
    c = np.linspace(0, 1, 1001)
    np.testing.assert_allclose(CM.linear_to_srgb(CM.srgb_to_linear(c)), c, atol=1e-12)
    # below the knee the curve is the straight line c / 12.92
    np.testing.assert_allclose(CM.srgb_to_linear([0.02, 0.04]), [0.02 / 12.92, 0.04 / 12.92])
    np.testing.assert_allclose(CM.srgb_to_linear(0.5), ((0.5 + 0.055) / 1.055) ** 2.4)


def test_luminance_and_greyscale_closed_forms():
    np.testing.assert_allclose(CM.luminance(np.eye(3)), [0.2126729, 0.7151522, 0.0721750])
    greys = np.linspace(0, 1, 11)
    np.testing.assert_allclose(CM.greyscale(np.repeat(greys[:, None], 3, axis=1)), greys,
                               atol=1e-6)
    # pure yellow is lighter in print than pure blue: the eye's weights, not the average
    yellow, blue = CM.greyscale([[1, 1, 0], [0, 0, 1]])
    assert yellow > 0.9 and blue < 0.3


def test_delta_e_matches_scikit_image():
    gen = rng(7)
    a, b = CM.srgb_to_lab(gen.random((200, 3))), CM.srgb_to_lab(gen.random((200, 3)))
    np.testing.assert_allclose(CM.delta_e(a, b), skcolor.deltaE_cie76(a, b), rtol=1e-12)


@pytest.mark.parametrize("bad, match", [([1.2, 0, 0], "rgb must lie in \\[0, 1\\]"),
                                        ([[0, 0]], "3 components"),
                                        ([0, np.nan, 0], "rgb must be finite")])
def test_colour_conversion_bad_input(bad, match):
    with pytest.raises(ValueError, match=match):
        CM.srgb_to_lab(bad)


# ---------------------------------------------------------------------------------------------
# perceptual analysis: rainbow maps mislead
# ---------------------------------------------------------------------------------------------

def _skimage_lightness(rgb):
    return skcolor.rgb2lab(rgb)[:, 0]


def test_lightness_of_grey_rises_nearly_linearly():
    L = CM.lightness("grey", 256)
    np.testing.assert_allclose(L, _skimage_lightness(mpl_samples("gray")), atol=0.01)
    assert np.all(np.diff(L) > 0) and L[0] == pytest.approx(0, abs=1e-9)
    assert L[-1] == pytest.approx(100, abs=1e-6)
    assert np.corrcoef(np.linspace(0, 1, 256), L)[0, 1] > 0.99


@pytest.mark.parametrize("name", ["viridis", "magma", "inferno", "plasma", "cividis", "grey",
                                  "hot"])
def test_sequential_maps_have_monotonic_lightness(name):
    assert CM.is_monotonic_lightness(name)
    ref = _skimage_lightness(mpl_samples(MPL_NAME[name]))       # independent: mpl + skimage
    assert np.all(np.diff(ref) > -0.05)                           # mpl's own tables, rounded


@pytest.mark.parametrize("name", ["rainbow", "jet", "turbo"])
def test_rainbow_maps_do_not_have_monotonic_lightness(name):
    assert not CM.is_monotonic_lightness(name)
    assert not CM.is_monotonic_lightness(name, tolerance=5.0)     # not a rounding artefact
    L = CM.lightness(name)
    # the lightness goes up and then down again by a large amount
    assert L.max() - L[-1] > 20 and L.max() - L[0] > 20
    ref = hsv_sweep() if name == "rainbow" else mpl_samples(name)
    ref_L = _skimage_lightness(ref)
    assert ref_L.max() - ref_L[-1] > 20


def test_diverging_maps_peak_in_the_middle():
    for name in ("bwr", "coolwarm"):
        L = CM.lightness(name, 257)
        assert not CM.is_monotonic_lightness(name)
        assert abs(int(np.argmax(L)) - 128) <= 3


def test_perceptual_steps_match_scikit_image_and_show_uniformity():
    steps = CM.perceptual_steps("viridis", 64)
    lab = skcolor.rgb2lab(CM.sample_colormap("viridis", 64))
    np.testing.assert_allclose(steps, skcolor.deltaE_cie76(lab[1:], lab[:-1]), atol=0.02)

    def unevenness(name):
        s = CM.perceptual_steps(name, 64)
        return s.std() / s.mean()

    # (viridis was made even in CAM02-UCS, so its CIE76 steps are not perfectly even either)
    assert unevenness("viridis") < 0.25 and unevenness("grey") < 0.15
    for name in ("jet", "rainbow", "turbo"):
        assert unevenness(name) > 1.5 * unevenness("viridis"), name


# ---------------------------------------------------------------------------------------------
# the module's promises
# ---------------------------------------------------------------------------------------------

def test_module_imports_no_drawing_library():
    code = ("import sys, course_lib.colormaps\n"
            "print(sorted(m for m in ('matplotlib', 'pyvista', 'vtk', 'ipywidgets', 'scipy') "
            "if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_no_warnings_on_ordinary_use():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        CM.apply_colormap(rng(8).normal(size=100), "turbo")
        CM.normalize([1.0, np.nan, 3.0])
        CM.lightness("cividis")
    assert matplotlib.__version__       # the reference library is the one installed
