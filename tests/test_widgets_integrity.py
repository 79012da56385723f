"""Headless tests of the graphical-integrity explorer: its scene against closed forms typed here
(the truncated axis' v1 / (v1 - b), the radius encoding's ((1 + e)^2 - 1) / e, the perspective
bars' ((1 + e)(1 + r (n - 1)) - 1) / e), the drawn polygons measured independently (bar heights,
shoelace areas of the circles and icons), the line chart's mean angle measured on the drawn
line, and the wiring (every control changes the picture)."""
import io

import matplotlib
matplotlib.use("module://ipympl.backend_nbagg")
import numpy as np
import pytest

from course_lib.widgets import integrity as W


def shoelace(p):
    x, y = np.asarray(p).T
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def heights(polys):
    return np.array([np.ptp(np.asarray(p)[:, 1]) for p in polys])


@pytest.mark.parametrize("dataset", W.DATASETS)
def test_truncated_axis_lie_factor_and_bar_heights(dataset):
    values = np.array(W.DATASETS[dataset][3])
    for b in (0.0, 5.0, float(np.floor(0.9 * values.min()))):
        s = W.scene(W.State(dataset=dataset, baseline=b))
        v1 = values[0]
        assert s["lie_factor"] == pytest.approx(v1 / (v1 - b))
        h = heights(s["distorted"]["polys"])
        assert np.allclose(h / h[0], (values - b) / (v1 - b))        # lengths from b
        honest = heights(s["honest"]["polys"])
        assert np.allclose(honest / values, honest[0] / values[0])   # proportional from 0
        # the tick labels sit where their values are on the truncated axis
        (ya, la), (yb, lb) = s["distorted"]["ticks"][0], s["distorted"]["ticks"][-1]
        assert float(la) == pytest.approx(b)
        scale = (yb - ya) / (float(lb) - float(la))
        assert np.allclose(np.array([p[2, 1] for p in s["distorted"]["polys"]]),
                           ya + scale * (values - b))


def test_shapes_lie_factor_from_the_drawn_areas():
    values = np.array(W.DATASETS["electric cars"][3])
    e = (values[-1] - values[0]) / values[0]
    for kind in ("circles, radius ∝ value", "icons, both sides ∝ value"):
        s = W.scene(W.State(dataset="electric cars", distortion=kind))
        assert s["lie_factor"] == pytest.approx(((1 + e) ** 2 - 1) / e)
        a1, a2 = (shoelace(p) for p in s["distorted"]["polys"])
        assert ((a2 - a1) / a1) / e == pytest.approx(s["lie_factor"], rel=2e-3)
        assert len(s["distorted"]["labels"]) == 2


def test_perspective_bars():
    values = np.array(W.DATASETS["exam pass rate"][3])
    n, r = len(values), W.RECESSION
    e = (values[-1] - values[0]) / values[0]
    s = W.scene(W.State(dataset="exam pass rate", distortion="3D bars", baseline=70))
    assert s["lie_factor"] == pytest.approx(((1 + e) * (1 + r * (n - 1)) - 1) / e)
    fronts = s["distorted"]["polys"][1:][2::3]                  # after the floor: top, side, front
    distance = 1 + r * (n - 1 - np.arange(n))
    h = heights(fronts)
    assert np.allclose(h * distance / values, h[-1] / values[-1])
    assert np.allclose(h, s["distorted"]["sizes"])


def test_line_chart_is_banked_on_screen():
    for dataset in W.DATASETS:
        s = W.scene(W.State(dataset=dataset, aspect="banked to 45°"))
        a = s["aspect"]
        line = a["line"]
        angles = np.degrees(np.arctan2(np.abs(np.diff(line[:, 1])), np.abs(np.diff(line[:, 0]))))
        assert angles.mean() == pytest.approx(45.0, abs=1e-9)
        frame = a["frame"]
        assert np.ptp(frame[:, 1]) / np.ptp(frame[:, 0]) == pytest.approx(a["alpha"])
        assert np.ptp(line[:, 1]) / np.ptp(line[:, 0]) == pytest.approx(a["alpha"])
        square = W.scene(W.State(dataset=dataset, aspect="square 1:1"))["aspect"]
        assert square["mean_angle"] > 45 > W.scene(
            W.State(dataset=dataset, aspect="flat 1:4"))["aspect"]["mean_angle"]


def test_scene_checks_and_clamps():
    s = W.scene(W.State(baseline=1000))
    assert s["baseline"] == W._max_baseline(W.DATASETS["library budget"][3]) < 40
    with pytest.raises(ValueError, match="distortion"):
        W.scene(W.State(distortion="pie"))
    with pytest.raises(ValueError, match="dataset"):
        W.scene(W.State(dataset="stocks"))
    with pytest.raises(ValueError, match="aspect"):
        W.scene(W.State(aspect="golden"))


def picture(ex):
    ex.fig.canvas.draw()
    buffer = io.BytesIO()
    ex.blitter.savefig(buffer, format="rgba", dpi=40)
    return np.frombuffer(buffer.getvalue(), dtype=np.uint8)


def test_every_control_changes_the_picture():
    ex = W.GraphicalIntegrityExplorer()
    changes = [("baseline", 20.0), ("aspect", "tall 4:1"), ("distortion", "3D bars"),
               ("baseline", 30.0), ("distortion", "circles, radius ∝ value"),
               ("dataset", "electric cars"), ("distortion", "icons, both sides ∝ value"),
               ("aspect", "square 1:1"), ("dataset", "exam pass rate")]
    before, text = picture(ex), ex.info.value
    for name, value in changes:
        getattr(ex, name).value = value
        after = picture(ex)
        assert np.count_nonzero(after != before) > 100, name
        assert ex.info.value != text or name == "baseline", name
        before, text = after, ex.info.value
    s = W.scene(ex.state)
    assert ex.lie_title.get_text().startswith(f"lie factor {s['lie_factor']:.2f}")


def test_dataset_sets_the_slider_range():
    ex = W.GraphicalIntegrityExplorer()
    ex.dataset.value = "electric cars"
    assert ex.baseline.max == W._max_baseline(W.DATASETS["electric cars"][3])
    assert ex.baseline.value == W.DATASETS["electric cars"][4]
    assert ex.state.baseline == W.DATASETS["electric cars"][4]
    x = W.scene(ex.state)
    assert ex.lie_title.get_text().startswith(f"lie factor {x['lie_factor']:.2f}")
    assert x["lie_factor"] == pytest.approx(12 / (12 - 10))
    ex.baseline.value = 4.0
    assert np.allclose(ex.baseline_line.get_ydata(), W.scene(ex.state)["baseline_y"])
