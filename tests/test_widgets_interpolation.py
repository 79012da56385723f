"""Headless tests of the interpolation explorer: its scene against scipy.interpolate
(BarycentricInterpolator, CubicSpline natural / clamped, CubicHermiteSpline) and the closed form of
Catmull-Rom's tangents, the curvature comb against scipy's derivatives, and the wiring (each
control, a point drag and a handle drag change the picture)."""
import matplotlib

matplotlib.use("module://ipympl.backend_nbagg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from scipy import interpolate as si  # noqa: E402

from course_lib.widgets import interpolation as W  # noqa: E402


def _grid(nodes):
    u = np.linspace(0, 1, W.PER_SEGMENT + 1)[:-1]
    return np.append((nodes[:-1, None] + u * np.diff(nodes)[:, None]).ravel(), nodes[-1])


def _chord(p, alpha=1.0):
    return np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1) ** alpha)])


@pytest.mark.parametrize("params, alpha", [("uniform", 0.0), ("chord", 1.0),
                                           ("centripetal", 0.5)])
def test_natural_and_polynomial_against_scipy(params, alpha):
    state = W.State(method="natural spline", params=params)
    s = W.scene(state)
    p = state.points[:state.count]
    nodes = _chord(p, alpha)
    assert np.allclose(s["nodes"], nodes)
    assert np.allclose(s["curve"], si.CubicSpline(nodes, p, bc_type="natural")(_grid(nodes)))
    s = W.scene(W.State(method="polynomial", params=params))
    assert np.allclose(s["curve"], si.BarycentricInterpolator(nodes, p)(_grid(nodes)))


def test_clamped_and_hermite_use_the_handles():
    state = W.State(method="clamped spline", count=5)
    s = W.scene(state)
    p, nodes = state.points[:5], _chord(state.points[:5])
    scale = nodes[-1] / 4 / 3
    ends = state.end_offsets / scale
    ref = si.CubicSpline(nodes, p, bc_type=((1, ends[0]), (1, ends[1])))
    assert np.allclose(s["curve"], ref(_grid(nodes)))
    assert np.allclose(s["handles"][[0, -1]], p[[0, -1]] + state.end_offsets)
    assert s["draggable"].tolist() == [0, 4]
    state = W.State(method="Hermite", params="uniform", count=7)
    s = W.scene(state)
    ref = si.CubicHermiteSpline(np.arange(7.0), state.points, state.offsets * 3)
    assert np.allclose(s["curve"], ref(_grid(np.arange(7.0))))
    assert s["draggable"].tolist() == list(range(7))


def test_catmull_rom_tangents_and_tension():
    state = W.State(method="cardinal", params="uniform", tension=0.5)
    p = state.points[:state.count]
    s = W.scene(state)
    assert np.allclose(s["tangents"][1:-1], (p[2:] - p[:-2]) / 2)
    s = W.scene(W.State(method="cardinal", params="uniform", tension=0.0))
    assert np.allclose(s["tangents"], 0)                    # zero tangents: s = 0


def test_comb_is_the_curvature():
    state = W.State(method="natural spline", params="chord")
    s = W.scene(state)
    p = state.points[:state.count]
    nodes = _chord(p)
    t = _grid(nodes)[::W.COMB_EVERY]
    cs = si.CubicSpline(nodes, p, bc_type="natural")
    d1, d2 = cs(t, 1), cs(t, 2)
    kappa = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    spikes = s["comb"].reshape(-1, 3, 2)
    length = np.linalg.norm(spikes[:, 1] - spikes[:, 0], axis=1)
    expected = np.minimum(W.COMB_SCALE * np.abs(kappa), W.COMB_MAX)
    inner = slice(2, -2)                 # np.gradient is one-sided (less exact) at the ends
    assert np.allclose(length[inner], expected[inner], rtol=0.05, atol=0.01)


def test_polynomial_overshoots_more_than_the_spline():
    poly = W.scene(W.State(method="polynomial", params="uniform", count=7))
    spline = W.scene(W.State(method="natural spline", params="uniform", count=7))
    assert poly["overshoot"] > spline["overshoot"]
    assert "Passes through 7 of 7" in poly["text"]


def _picture(ex):
    return np.frombuffer(ex.png(), dtype=np.uint8).copy()


def test_every_control_changes_the_picture():
    ex = W.InterpolationExplorer()
    for control, value in ((ex.method, "cardinal"), (ex.tension, 1.2), (ex.params, "uniform"),
                           (ex.count, 7), (ex.comb_box, True), (ex.method, "polynomial")):
        before = ex.curve.get_xydata().copy(), ex.comb.get_xydata().copy(), _picture(ex)
        control.value = value
        after = ex.curve.get_xydata(), ex.comb.get_xydata(), _picture(ex)
        changed = (before[0].shape != after[0].shape or not np.allclose(before[0], after[0])
                   or before[1].shape != after[1].shape)
        assert changed, control.description
        assert not np.array_equal(before[2], after[2])
        assert np.allclose(ex.curve.get_xydata(), W.scene(ex.state)["curve"])


def test_dragging_a_point_and_a_handle():
    ex = W.InterpolationExplorer(W.State(method="Hermite"))
    ex.drag.press(*ex.state.points[2])
    ex.drag.move(2.0, 2.5)
    ex.drag.release()
    assert ex.state.points[2].tolist() == [2.0, 2.5]
    assert np.allclose(ex.curve.get_xydata()[2 * W.PER_SEGMENT], [2.0, 2.5])
    handle = ex._scene["handles"][3].copy()
    before = ex.curve.get_xydata().copy()
    ex.handle_drag.press(*handle)
    ex.handle_drag.move(handle[0] + 0.5, handle[1] - 0.4)
    ex.handle_drag.release()
    assert np.allclose(ex.state.offsets[3], handle + [0.5, -0.4] - ex.state.points[3])
    assert not np.allclose(before, ex.curve.get_xydata())
    ex.method.value = "clamped spline"
    end = ex._scene["handles"][0].copy()
    ex.handle_drag.press(*end)
    ex.handle_drag.move(end[0] + 0.3, end[1])
    assert np.allclose(ex.state.end_offsets[0], end + [0.3, 0] - ex.state.points[0])
    assert ex.mouse_gestures()[0]["kind"] == "drag"


def test_the_tension_slider_works_only_for_the_cardinal_spline():
    ex = W.InterpolationExplorer()
    ex.method.value = "natural spline"
    assert ex.tension.disabled
    ex.method.value = "cardinal"
    assert not ex.tension.disabled
