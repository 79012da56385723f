"""Tests of course_lib.dataviz.pipeline: the stages and the catalogue of actions against a
classification typed here, the median filter against scipy.ndimage, hill shading against the
closed form of a plane and an independent normal computation (cross products of the surface's
tangents), the min/max overview against a loop over the bins, and the example pipeline stage
by stage."""
import numpy as np
import pytest
from scipy import ndimage
from scipy.interpolate import RegularGridInterpolator

from course_lib import dataviz
from course_lib.dataviz import pipeline as P


def test_stages_in_order_with_descriptions():
    assert P.STAGES == ("data acquisition", "filtering and enrichment", "mapping", "rendering")
    assert list(P.STAGE_INFO) == list(P.STAGES)
    for name, stage in P.STAGE_INFO.items():
        assert stage.name == name and len(stage.what) > 60 and stage.examples
    # each stage takes what the previous one gives
    assert P.STAGE_INFO["mapping"].takes == P.STAGE_INFO["filtering and enrichment"].gives \
        .split(":")[0]
    assert P.STAGE_INFO["rendering"].takes == P.STAGE_INFO["mapping"].gives.split(" (")[0]


#: A classification typed by hand (not read from the catalogue).
BY_HAND = {
    "remove outliers": "filtering and enrichment",
    "apply a median filter": "filtering and enrichment",
    "compute the gradient magnitude": "filtering and enrichment",
    "resample onto a regular grid": "filtering and enrichment",
    "normalise the values to [0, 1]": "filtering and enrichment",
    "choose a colour map": "mapping",
    "extract an isosurface": "mapping",
    "design an opacity transfer function": "mapping",
    "place arrow glyphs on the flow field": "mapping",
    "ray cast the volume": "rendering",
    "apply Phong shading to the isosurface": "rendering",
    "set up the camera and the viewpoint": "rendering",
    "scan a patient with a CT scanner": "data acquisition",
    "run a fluid-flow simulation": "data acquisition",
}


def test_catalogue_classifies_actions():
    for action, stage in BY_HAND.items():
        assert P.pipeline_stage(action) == stage
        assert P.pipeline_stage("  " + action.upper() + " ") == stage
    for action, (stage, why) in P.ACTIONS.items():
        assert stage in P.STAGES and len(why) > 30
    counts = {s: sum(st == s for st, _ in P.ACTIONS.values()) for s in P.STAGES}
    assert min(counts.values()) >= 6
    assert dataviz.pipeline_stage is P.pipeline_stage


def test_unknown_action_lists_the_known_ones():
    with pytest.raises(ValueError, match="not in the catalogue") as err:
        P.pipeline_stage("paint the data")
    assert "'remove outliers'" in str(err.value) and "'ray cast the volume'" in str(err.value)
    with pytest.raises(TypeError, match="action"):
        P.pipeline_stage(3)


def test_stage_names_and_misplaced_actions():
    assert P.canonical_stage("Acquisition") == "data acquisition"
    assert P.canonical_stage("render") == "rendering"
    assert P.canonical_stage("FILTERING AND  ENRICHMENT") == "filtering and enrichment"
    with pytest.raises(ValueError, match="stage must be one of"):
        P.canonical_stage("colouring")
    with pytest.raises(TypeError, match="stage"):
        P.canonical_stage(None)
    wrong = P.misplaced_actions([("choose a colour map", "rendering"),
                                 ("remove outliers", "filtering"),
                                 ("ray cast the volume", "mapping")])
    assert [(a, g, r) for a, g, r, _ in wrong] == [
        ("choose a colour map", "rendering", "mapping"),
        ("ray cast the volume", "mapping", "rendering")]
    assert P.misplaced_actions({a: s for a, s in BY_HAND.items()}) == []
    with pytest.raises(ValueError, match="catalogue"):
        P.misplaced_actions({"dance": "mapping"})


def test_uses_and_mantra():
    assert tuple(P.USES) == ("exploratory", "confirmatory", "presentation")
    assert P.visualization_use("Analysis") is P.USES["confirmatory"]
    assert any("integrity" in need for need in P.USES["presentation"].needs)
    assert any("interactiv" in need for need in P.USES["exploratory"].needs)
    with pytest.raises(ValueError, match="use must be one of"):
        P.visualization_use("decoration")
    assert [s for s, _ in P.MANTRA] == ["overview", "zoom and filter", "details on demand"]
    assert P.mantra_step("zoom and filter") == "zoom and filter"
    for interaction, step in P.MANTRA_INTERACTIONS.items():
        assert P.mantra_step(interaction.title()) == step
    with pytest.raises(ValueError, match="known interactions"):
        P.mantra_step("print the chart")


def brute_minmax(y, bins):
    n = len(y)
    xs, ys = [], []
    for k in range(bins):
        lo, hi = k * n // bins, (k + 1) * n // bins
        part = list(y[lo:hi])
        i_min = lo + part.index(min(part))
        i_max = lo + part.index(max(part))
        for i in sorted((i_min, i_max)):
            xs.append(i)
            ys.append(y[i])
    return np.array(xs, float), np.array(ys, float)


@pytest.mark.parametrize("n, bins", [(1000, 7), (50, 50), (37, 5), (10, 1), (1000, 8),
                                     (600, 40)])
def test_minmax_decimate_against_a_loop(n, bins):
    rng = np.random.default_rng(n)
    y = np.round(rng.normal(size=n), 1)                 # rounded: ties occur
    xk, yk = P.minmax_decimate(y, bins)
    bx, by = brute_minmax(y, bins)
    assert np.array_equal(xk, bx) and np.array_equal(yk, by)
    # the overview keeps the global extremes, which subsampling may miss
    assert yk.max() == y.max() and yk.min() == y.min()
    xs, _ = P.minmax_decimate(y, bins, x=10 + 2 * np.arange(n))
    assert np.array_equal(xs, 10 + 2 * bx)


def test_minmax_decimate_errors():
    with pytest.raises(ValueError, match="bins must be at most"):
        P.minmax_decimate([1, 2, 3], 4)
    with pytest.raises(ValueError, match="bins"):
        P.minmax_decimate([1, 2, 3], 0)
    with pytest.raises(ValueError, match="x must have the shape"):
        P.minmax_decimate([1, 2, 3], 2, x=[1, 2])
    with pytest.raises(ValueError, match="1D"):
        P.minmax_decimate([[1, 2], [3, 4]], 1)


@pytest.mark.parametrize("shape, size", [((40,), 3), ((17, 23), 3), ((12, 9), 5), ((6, 7, 8), 3),
                                         ((5, 5), 1)])
def test_median_filter_against_scipy(shape, size):
    values = np.random.default_rng(1).normal(size=shape)
    ours = P.median_filter(values, size)
    ref = ndimage.median_filter(values, size=size, mode="nearest")
    assert np.allclose(ours, ref)


def test_median_filter_removes_a_spike_and_keeps_an_edge():
    step = np.r_[np.zeros(10), np.ones(10)]
    spiky = step.copy()
    spiky[4] = 50.0
    assert np.array_equal(P.median_filter(spiky, 3), step)
    with pytest.raises(ValueError, match="odd"):
        P.median_filter(step, 4)
    with pytest.raises(ValueError, match="size"):
        P.median_filter(step, 0)
    with pytest.raises(ValueError, match="finite"):
        P.median_filter([1.0, np.nan], 3)


def test_hillshade_of_a_plane_is_the_closed_form():
    a, b = 0.7, -0.4
    ys, xs = np.mgrid[0:6, 0:8] * 0.5
    heights = a * xs + b * ys
    az, el = np.radians(30.0), np.radians(50.0)
    shade = P.hillshade(heights, az, el, spacing=(0.5, 0.5))
    n = np.array([-a, -b, 1.0]) / np.sqrt(a * a + b * b + 1)
    light = [np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)]
    assert np.allclose(shade, max(0.0, n @ light))


def test_hillshade_against_tangent_cross_products():
    field = np.random.default_rng(4).normal(size=(9, 11)).cumsum(axis=1) * 0.3
    dx, dy, s = 0.5, 0.25, 2.0
    shade = P.hillshade(field, np.radians(200), np.radians(35), z_scale=s, spacing=(dx, dy))
    hx = np.gradient(field, dx, axis=1)
    hy = np.gradient(field, dy, axis=0)
    tu = np.stack([np.ones_like(field), 0 * field, s * hx], -1)      # dP/dx
    tv = np.stack([0 * field, np.ones_like(field), s * hy], -1)      # dP/dy
    normal = np.cross(tu, tv)
    normal /= np.linalg.norm(normal, axis=-1, keepdims=True)
    az, el = np.radians(200), np.radians(35)
    light = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
    assert np.allclose(shade, np.clip(normal @ light, 0, 1))
    with pytest.raises(ValueError, match="2D field"):
        P.hillshade(np.zeros(5))
    with pytest.raises(ValueError, match="z_scale"):
        P.hillshade(np.zeros((3, 3)), z_scale=0)


def test_pipeline_example_stage_by_stage():
    p = P.pipeline_example("hills", size=48, noise=0.02, spikes=0.03, seed=3)
    truth = p["truth"]
    span = np.ptp(truth)
    # acquisition: spikes far from the truth
    assert np.abs(p["acquired"] - truth).max() > 0.4 * span
    # filtering: the median filter removed them; the result is normalised
    ref = ndimage.median_filter(p["acquired"], 3, mode="nearest")
    assert np.allclose(p["filtered"], (ref - ref.min()) / np.ptp(ref))
    truth_n = (truth - truth.min()) / span
    assert np.abs(p["filtered"] - truth_n).max() < 0.2
    # enrichment: the gradient magnitude by numpy's central differences
    h = 2.0 / 47
    gy, gx = np.gradient(p["filtered"], h, h)
    assert np.allclose(p["gradient"], np.hypot(gx, gy))
    # mapping: colours in [0, 1], isolines on the level 0.5 of the filtered field
    assert p["mapped"].shape == (48, 48, 3) and 0 <= p["mapped"].min() <= p["mapped"].max() <= 1
    grid = np.linspace(-1, 1, 48)
    interp = RegularGridInterpolator((grid, grid), p["filtered"])
    points = np.concatenate(p["isolines"])
    assert np.allclose(interp(points[:, ::-1]), 0.5, atol=1e-9)
    # rendering: the colours lit by the hill shade
    shade = P.hillshade(p["filtered"], z_scale=0.5, spacing=(h, h))
    assert np.allclose(p["rendered"], p["mapped"] * (0.35 + 0.65 * shade[..., None]))
    assert np.allclose(p["extent"], (-1 - h / 2, 1 + h / 2, -1 - h / 2, 1 + h / 2))
    with pytest.raises(ValueError, match="spikes"):
        P.pipeline_example(spikes=0.5)
    with pytest.raises(ValueError, match="noise"):
        P.pipeline_example(noise=-1)
    with pytest.raises(ValueError, match="kind"):
        P.pipeline_example("volcano")
