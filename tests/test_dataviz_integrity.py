"""Tests of course_lib.dataviz.integrity: lie factors against closed forms typed here, the
data-ink ratio of a chart rasterised by matplotlib, banking to 45 degrees against a
brute-force search over aspect ratios and scipy's brentq, and the visual-variable table
against Bertin's properties and Mackinlay's ranking typed here."""
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from course_lib import dataviz
from course_lib.dataviz import integrity as I


# ---------------------------------------------------------------------------------------------
# Lie factor
# ---------------------------------------------------------------------------------------------

def test_relative_change_and_lie_factor_basics():
    assert I.relative_change(40, 50) == pytest.approx(0.25)
    assert I.relative_change(50, 40) == pytest.approx(0.2)
    assert I.lie_factor([40, 50], [40, 50]) == pytest.approx(1.0)
    assert I.lie_factor([1, 2], [10, 20]) == pytest.approx(1.0)      # any common scale
    pairs = I.lie_factor([[40, 50], [2, 3]], [[10, 20], [4, 9]])
    assert np.allclose(pairs, [4.0, 2.5])
    assert dataviz.lie_factor is I.lie_factor


@pytest.mark.parametrize("v1, v2", [(40, 50), (18, 27.5), (5, 4), (100, 160), (3, 1)])
def test_lie_factors_against_closed_forms(v1, v2):
    e = (v2 - v1) / v1
    # area honest
    assert I.encoding_lie_factor([v1, v2], "area") == pytest.approx(1.0)
    # radius or side ~ value: the area changes by (1 + e)^2 - 1
    closed = abs((1 + e) ** 2 - 1) / abs(e)
    assert I.encoding_lie_factor([v1, v2], "radius") == pytest.approx(closed)
    assert I.encoding_lie_factor([v1, v2], "icon") == pytest.approx(closed)
    assert closed == pytest.approx(abs(2 + e))
    # a cube scaled in three dimensions
    assert I.encoding_lie_factor([v1, v2], "volume") == pytest.approx(
        abs((1 + e) ** 3 - 1) / abs(e))
    # bars on a truncated axis: lengths v - b, lie factor v1 / (v1 - b)
    for b in (0.0, 0.5 * min(v1, v2), 0.9 * min(v1, v2)):
        assert I.encoding_lie_factor([v1, v2], "bar", baseline=b) == pytest.approx(
            v1 / (v1 - b))
    # perspective bars: the first one (1 + r) away, the last one at distance 1
    for r in (0.0, 0.5, 2.0):
        shown = ((v2 / 1) - (v1 / (1 + r))) / (v1 / (1 + r))
        assert I.encoding_lie_factor([v1, v2], "perspective", recession=r) == pytest.approx(
            abs(shown) / abs(e))


def test_middle_values_do_not_change_the_first_to_last_factor():
    assert I.encoding_lie_factor([40, 90, 10, 50], "bar", baseline=5) == pytest.approx(
        40 / 35)
    sizes = I.drawn_sizes([10, 20, 30], "perspective", recession=0.5)
    assert np.allclose(sizes, [10 / 2.0, 20 / 1.5, 30 / 1.0])


def test_lie_factor_errors():
    with pytest.raises(ValueError, match="same shape"):
        I.lie_factor([1, 2], [[1, 2], [3, 4]])
    with pytest.raises(ValueError, match="pair"):
        I.lie_factor([1, 2, 3], [1, 2, 3])
    with pytest.raises(ValueError, match="no effect"):
        I.lie_factor([5, 5], [1, 2])
    with pytest.raises(ValueError, match="must not be 0"):
        I.lie_factor([0, 5], [1, 2])
    with pytest.raises(ValueError, match="must not be 0"):
        I.relative_change(0, 1)
    with pytest.raises(ValueError, match="baseline"):
        I.drawn_sizes([10, 20], "bar", baseline=15)
    with pytest.raises(ValueError, match="encoding must be one of"):
        I.drawn_sizes([10, 20], "pie")
    with pytest.raises(ValueError, match=">= 0"):
        I.drawn_sizes([-1, 2], "radius")
    with pytest.raises(ValueError, match="recession"):
        I.drawn_sizes([1, 2], "perspective", recession=-1)
    with pytest.raises(ValueError, match="at least 2"):
        I.encoding_lie_factor([3], "bar")
    with pytest.raises(TypeError, match="values"):
        I.drawn_sizes("abc", "bar")


# ---------------------------------------------------------------------------------------------
# Data-ink ratio
# ---------------------------------------------------------------------------------------------

def _rasterise(draw_data, draw_decoration):
    """Boolean ink masks of a small chart drawn by matplotlib's Agg renderer."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure       # no pyplot: the backend of other tests stays

    def ink(with_data, with_decoration):
        fig = Figure(figsize=(2, 2), dpi=50)
        FigureCanvasAgg(fig)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_axis_off()
        ax.set(xlim=(0, 4), ylim=(0, 4))
        if with_decoration:
            draw_decoration(ax)
        if with_data:
            draw_data(ax)
        fig.canvas.draw()
        rgb = np.asarray(fig.canvas.buffer_rgba())[..., :3]
        return (rgb < 250).any(axis=-1)

    return ink(True, False), ink(True, True)


def test_data_ink_ratio_of_a_rasterised_chart():
    def bars(ax):
        ax.bar([1, 2, 3], [1, 2, 3], width=0.5, color="k")

    def grid(ax):
        for y in (0.5, 1.5, 2.5, 3.5):
            ax.axhline(y, color="0.5", lw=1)

    data_mask, total_mask = _rasterise(bars, grid)
    ratio = I.data_ink_ratio(data_mask, total_mask)
    # the bars cover 3 * 0.5 * 2 = 3 of the 16 square units; 4 grid lines cross the chart
    assert data_mask.mean() == pytest.approx(3 / 16, abs=0.03)
    assert ratio == pytest.approx(data_mask.sum() / total_mask.sum())
    assert 0.4 < ratio < 0.95
    assert I.data_ink_ratio(data_mask, data_mask) == 1.0


def test_ink_amounts_and_budget():
    assert I.data_ink_ratio(0, 10) == 0.0
    budget = I.ink_budget({"bars": (420, True), "3D sides": (180, False), "grid": (300, False),
                           "background": (300, False), "labels": (0, False)})
    assert budget["data"] == 420 and budget["non_data"] == 780
    assert budget["ratio"] == pytest.approx(420 / 1200)
    assert budget["erasable"] == ["background", "grid", "3D sides", "labels"]   # ties by name
    with pytest.raises(ValueError, match="cannot exceed"):
        I.data_ink_ratio(5, 4)
    with pytest.raises(ValueError, match="total_ink is 0"):
        I.data_ink_ratio(0, 0)
    with pytest.raises(ValueError, match=">= 0"):
        I.data_ink_ratio(-1, 4)
    with pytest.raises(ValueError, match="outside"):
        I.data_ink_ratio(np.array([True, True]), np.array([True, False]))
    with pytest.raises(TypeError, match="both"):
        I.data_ink_ratio(np.array([True]), 3)
    with pytest.raises(TypeError, match="pair"):
        I.ink_budget({"bars": 300})
    with pytest.raises(TypeError, match="non-empty dict"):
        I.ink_budget({})


# ---------------------------------------------------------------------------------------------
# Banking to 45 degrees
# ---------------------------------------------------------------------------------------------

def mean_orientation(x, y, alpha):
    """Mean |angle| on screen, computed from the raw differences (no library code)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    dx = np.diff(x) / (x.max() - x.min())
    dy = np.diff(y) / (y.max() - y.min())
    keep = (dx != 0) | (dy != 0)
    return np.mean(np.arctan2(alpha * np.abs(dy[keep]), np.abs(dx[keep])))


def brute_force_bank(x, y):
    alphas = np.exp(np.linspace(-8, 8, 400_001))
    err = np.array([mean_orientation(x, y, a) for a in alphas[::400]]) - np.pi / 4
    k = int(np.argmin(np.abs(err))) * 400
    fine = alphas[max(k - 400, 0):k + 401]
    err = np.array([mean_orientation(x, y, a) for a in fine]) - np.pi / 4
    return fine[int(np.argmin(np.abs(err)))]


POLYLINES = {
    "zigzag": ([0, 1, 2, 3, 4, 5], [0, 4, 1, 3, 2, 6]),
    "sunspots": (np.arange(80), 50 + 40 * np.abs(np.sin(np.arange(80) / 7.0))
                 + np.random.default_rng(2).normal(0, 3, 80)),
    "steps": ([0, 1, 1, 2, 3, 4], [0, 0, 2, 2, 5, 5.5]),     # a vertical and flat segments
    "uneven x": ([0, 0.5, 3, 3.2, 7], [1, 2, 2.5, 4, 0]),
}


@pytest.mark.parametrize("name", POLYLINES)
def test_average_orientation_banking_against_brute_force_and_brentq(name):
    x, y = POLYLINES[name]
    alpha = I.bank_to_45(x, y)
    assert mean_orientation(x, y, alpha) == pytest.approx(np.pi / 4, abs=1e-12)
    assert alpha == pytest.approx(brute_force_bank(x, y), rel=1e-4)
    ref = math.exp(brentq(lambda u: mean_orientation(x, y, math.exp(u)) - np.pi / 4, -30, 30,
                          xtol=1e-14))
    assert alpha == pytest.approx(ref, rel=1e-9)
    assert np.degrees(I.segment_orientations(x, y, alpha)).mean() == pytest.approx(45)


def test_median_banking_closed_form():
    x, y = [0, 1, 2, 3, 4, 5], [0, 4, 1, 3, 2, 6]
    # ranges 5 and 6: unit-square slopes |dy| / 6 * 5 = 10/3, 5/2, 5/3, 5/6, 10/3
    assert I.bank_to_45(x, y, "median") == pytest.approx(1 / (5 / 2))
    angles = np.degrees(I.segment_orientations(x, y, 0.4))
    assert np.median(angles) == pytest.approx(45)


def test_banking_is_invariant_to_units_and_direction():
    x, y = POLYLINES["uneven x"]
    a = I.bank_to_45(x, y)
    assert I.bank_to_45(np.multiply(x, 1000) - 7, np.multiply(y, 0.01) + 3) == pytest.approx(a)
    assert I.bank_to_45(x[::-1], y[::-1]) == pytest.approx(a)
    # a straight line is banked to a square: its one slope becomes 45 degrees
    assert I.bank_to_45([0, 1, 2], [0, 5, 10]) == pytest.approx(1.0)
    assert I.bank_to_45([0, 1, 2], [0, 5, 10], "median") == pytest.approx(1.0)


def test_banking_errors():
    with pytest.raises(ValueError, match="flat"):
        I.bank_to_45([0, 1, 2, 3], [0, 1, 1, 1])            # 2 of 3 segments flat
    with pytest.raises(ValueError, match="vertical"):
        I.bank_to_45([0, 0, 0, 1], [0, 1, 2, 3])
    with pytest.raises(ValueError, match="median slope is 0"):
        I.bank_to_45([0, 1, 2, 3], [0, 1, 1, 1], "median")
    with pytest.raises(ValueError, match="vary"):
        I.bank_to_45([0, 1, 2], [3, 3, 3])
    with pytest.raises(ValueError, match="same length"):
        I.bank_to_45([0, 1, 2], [3, 3])
    with pytest.raises(ValueError, match="method must be one of"):
        I.bank_to_45([0, 1, 2], [0, 1, 0], "mean")
    with pytest.raises(ValueError, match="aspect must be positive"):
        I.segment_orientations([0, 1], [0, 1], 0)


# ---------------------------------------------------------------------------------------------
# Visual variables
# ---------------------------------------------------------------------------------------------

#: Mackinlay's (1986) rankings, typed out, with his encodings named by Bertin's variables
#: (length and area -> size, density -> value, angle and slope -> orientation); only the
#: first places, where the two agree.
MACKINLAY_TOP = {"quantitative": ["position", "size"], "ordinal": ["position", "value"],
                 "nominal": ["position", "colour hue"]}


@pytest.mark.parametrize("level", I.DATA_LEVELS)
def test_ranking_lists_every_variable_once_best_first(level):
    rows = I.visual_variables_for(level)
    assert sorted(v for v, _, _ in rows) == sorted(I.VISUAL_VARIABLES)
    ranks = [I.QUALITIES.index(q) for _, q, _ in rows]
    assert ranks == sorted(ranks)
    assert [v for v, _, _ in rows][:2] == MACKINLAY_TOP[level]
    assert all(len(why) > 40 for _, _, why in rows)


def test_ranking_agrees_with_bertins_properties():
    props = I.VISUAL_VARIABLES
    for variable, quality, _ in I.visual_variables_for("ordinal"):
        if not props[variable].ordered:                 # no order: cannot show an order
            assert quality in ("poor", "misleading"), variable
    for variable, quality, _ in I.visual_variables_for("quantitative"):
        if quality in ("best", "good"):
            assert props[variable].quantitative, variable
    for variable, quality, _ in I.visual_variables_for("nominal"):
        if props[variable].ordered and not props[variable].associative:
            assert quality == "misleading", variable     # suggests an order of categories
    assert I.suitability("color", "interval") == I.suitability("colour hue", "quantitative")
    assert I.suitability("Lightness", "ordered")[0] == "good"


def test_visual_variable_errors():
    with pytest.raises(ValueError, match="level must be one of"):
        I.visual_variables_for("cardinal")
    with pytest.raises(ValueError, match="variable must be one of"):
        I.suitability("motion", "nominal")
    with pytest.raises(TypeError, match="level"):
        I.visual_variables_for(3)
