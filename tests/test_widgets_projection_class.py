"""Headless tests of the projection-class explorer: its scene against perspective images and
vanishing points computed here with plain numpy (similar triangles in the camera frame, the
limit of far points), the class it names, and its wiring (every control changes the picture or
the text)."""
import math

import matplotlib
import numpy as np
import pytest

matplotlib.use("module://ipympl.backend_nbagg")

from course_lib.widgets import projection_class as W  # noqa: E402


def _camera_image(state, points):
    """The perspective image typed out: eye on the viewing sphere, plane at W.PLANE."""
    a, e = math.radians(state.azimuth_deg), math.radians(state.elevation_deg)
    v = np.array([math.sin(a) * math.cos(e), -math.cos(a) * math.cos(e), math.sin(e)])
    right = np.array([math.cos(a), math.sin(a), 0.0])
    up = np.cross(v, right)
    eye = state.distance * v
    rel = points - eye
    depth = -(rel @ v)
    return np.c_[rel @ right, rel @ up] * W.PLANE / depth[:, None]


def test_perspective_corners_and_vanishing_points():
    state = W.State(kind="perspective", azimuth_deg=35, elevation_deg=20, distance=4.0)
    s = W.scene(state)
    assert np.allclose(s["corners"], _camera_image(state, W._CORNERS))
    for axis in range(3):
        d = np.eye(3)[axis]
        far = _camera_image(state, np.array([W._CORNERS[0] + 1e8 * d]))[0]
        assert np.allclose(s["vanishing"][axis], far, atol=1e-5)
        # every extension ends at the vanishing point and starts on an edge end
        ext = s["extensions"][axis].reshape(-1, 3, 2)
        assert np.allclose(ext[:, 1], s["vanishing"][axis])
    assert s["classification"]["name"] == "three-point perspective"


@pytest.mark.parametrize("state, name", [
    (W.State(kind="perspective", azimuth_deg=0, elevation_deg=0), "one-point perspective"),
    (W.State(kind="perspective", azimuth_deg=35, elevation_deg=0), "two-point perspective"),
    (W.State(kind="parallel", azimuth_deg=45, elevation_deg=35.26), "isometric"),
    (W.State(kind="parallel", azimuth_deg=45, elevation_deg=35.3), "isometric"),
    (W.State(kind="parallel", azimuth_deg=45, elevation_deg=20), "dimetric"),
    (W.State(kind="parallel", azimuth_deg=30, elevation_deg=20), "trimetric"),
    (W.State(kind="parallel", azimuth_deg=90, elevation_deg=0), "orthographic multiview"),
    (W.State(kind="oblique", oblique_length=1.0), "oblique cavalier"),
    (W.State(kind="oblique", oblique_length=0.5), "oblique cabinet"),
    (W.State(kind="oblique", oblique_length=0.7), "oblique (general)"),
])
def test_class_named(state, name):
    s = W.scene(state)
    assert s["classification"]["name"] == name
    assert name in s["text"]


def test_two_point_has_parallel_vertical_edges():
    s = W.scene(W.State(kind="perspective", azimuth_deg=35, elevation_deg=0))
    assert s["vanishing"][2] is None and len(s["extensions"][2]) == 0
    z = s["edges"][2].reshape(-1, 3, 2)
    assert np.allclose(z[:, 0, 0], z[:, 1, 0])            # vertical in the picture


def test_oblique_depth_drawn_at_angle_and_length():
    s = W.scene(W.State(kind="oblique", oblique_angle_deg=30, oblique_length=0.5))
    y = s["edges"][1].reshape(-1, 3, 2)
    step = (y[0, 1] - y[0, 0]) / (2 * W.HALF[1] * W.PARALLEL_SCALE)
    assert np.allclose(np.abs(step), [0.5 * math.cos(math.radians(30)), 0.5 * math.sin(math.radians(30))])


def test_bad_kind():
    with pytest.raises(ValueError, match="kind"):
        W.scene(W.State(kind="fisheye"))


def test_every_control_changes_the_picture_or_text():
    ex = W.ProjectionClassExplorer()

    def picture():
        return ([np.array(line.get_xydata()).copy() for line in ex.edge_lines],
                ex.title.get_text(), ex.info.value)

    def changed(a, b):
        return (any(x.shape != y.shape or not np.allclose(x, y, equal_nan=True)
                    for x, y in zip(a[0], b[0])) or a[1:] != b[1:])

    for control, value in [(ex.azimuth, 60.0), (ex.elevation, 15.0), (ex.distance, 7.0)]:
        before = picture()
        control.value = value
        assert changed(before, picture()), control.description
    before = picture()
    ex.kind.value = "parallel"
    assert changed(before, picture()) and ex.distance.disabled and not ex.azimuth.disabled
    ex.kind.value = "oblique"
    assert ex.azimuth.disabled and not ex.angle.disabled
    for control, value in [(ex.angle, 60.0), (ex.length, 1.0)]:
        before = picture()
        control.value = value
        assert changed(before, picture()), control.description
    assert ex.title.get_text() == "oblique cavalier"
    expected = W.scene(ex.state)
    for axis in range(3):
        assert np.allclose(ex.edge_lines[axis].get_xydata(), expected["edges"][axis], equal_nan=True)
