"""Headless tests of the normals explorer: its scene against closed forms typed here (the
ellipse x^2/a^2 + y^2/b^2 = 1 has the normal (x/a^2, y/b^2); a polygon's transformed edge
has the normal perpendicular to its transformed edge vector) and its wiring (each control
changes the drawn lines and the text)."""
import math

import numpy as np
import pytest

from course_lib.widgets import normals as W


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def test_circle_under_a_scale_has_the_ellipse_normals():
    a, b = 2.5, 0.6
    s = W.scene(W.State(shape="circle", sx=a, sy=b, shear=0.0))
    x, y = s["base"].T
    assert np.allclose(x ** 2 / a ** 2 + y ** 2 / b ** 2, 1.0)          # on the ellipse
    expected = unit(np.stack([x / a ** 2, y / b ** 2], axis=-1))         # gradient of the ellipse
    assert np.allclose(s["correct"], expected)
    naive = unit(np.stack([x, y], axis=-1))                              # A n with n = p on the circle
    err = np.degrees(np.arccos(np.clip(np.sum(naive * expected, 1), -1, 1)))
    assert s["worst_deg"] == pytest.approx(err.max())
    assert s["worst_deg"] > 20


def test_polygon_normals_are_perpendicular_to_the_transformed_edges():
    s = W.scene(W.State(shape="polygon", sx=1.5, sy=0.5, shear=0.8))
    A = np.array([[1.0, 0.8], [0.0, 1.0]]) @ np.diag([1.5, 0.5])
    edges = np.diff(np.vstack([W._POLYGON, W._POLYGON[:1]]), axis=0) @ A.T
    assert np.allclose(np.sum(s["correct"] * edges, axis=1), 0.0)
    # outward: the transformed polygon is still counter-clockwise (det A > 0), outward = (dy, -dx)
    assert np.allclose(s["correct"], unit(np.stack([edges[:, 1], -edges[:, 0]], axis=-1)))
    assert not np.allclose(np.sum(s["naive"] * edges, axis=1), 0.0)


def test_uniform_scale_and_identity_have_no_error():
    for sx in (1.0, 2.0):
        s = W.scene(W.State(sx=sx, sy=sx, shear=0.0))
        assert s["worst_deg"] == pytest.approx(0.0, abs=1e-6)
        assert "uniform scale" in s["text"]
    with pytest.raises(ValueError, match="shape"):
        W.scene(W.State(shape="star"))
    with pytest.raises(ValueError, match="sx and sy"):
        W.scene(W.State(sx=0.0))


def test_every_control_changes_the_picture_and_text():
    ex = W.NormalsExplorer()
    for control, value in [(ex.sx, 1.0), (ex.sy, 2.5), (ex.shear, 1.2), (ex.shape, "polygon")]:
        before = (np.array(ex.naive_line.get_xydata()), np.array(ex.shape_line.get_xydata()),
                  ex.info.value, ex.title.get_text())
        control.value = value
        after = np.array(ex.naive_line.get_xydata())
        assert before[0].shape != after.shape or not np.allclose(before[0], after,
                                                                 equal_nan=True)
        assert ex.info.value != before[2]
    s = W.scene(W.State(shape="polygon", sx=1.0, sy=2.5, shear=1.2))
    assert np.allclose(np.array(ex.correct_line.get_xydata()), s["correct_lines"],
                       equal_nan=True)
    assert f"{s['worst_deg']:.1f}" in ex.title.get_text()
    assert math.isfinite(s["worst_deg"])


def test_the_worst_sample_is_ringed_and_hidden_without_error():
    ex = W.NormalsExplorer(W.State(sx=2.0, sy=0.5, shear=0.7))
    s = W.scene(ex.state)
    errors = []
    for p, nn, nc in zip(s["base"], s["naive"], s["correct"]):
        errors.append(math.degrees(math.acos(max(-1.0, min(1.0, float(nn @ nc))))))
    ringed = np.array(ex.worst_marker.get_xydata())[0]
    k = int(np.argmin(np.linalg.norm(s["base"] - ringed, axis=1)))
    assert errors[k] == pytest.approx(max(errors), abs=1e-6)
    ex.sx.value, ex.sy.value, ex.shear.value = 1.0, 1.0, 0.0
    assert len(ex.worst_marker.get_xydata()) == 0
