"""Headless tests of the scattered-data explorer: its scene against scipy (griddata nearest and
linear, RBFInterpolator), Shepard's formula and Franke's function typed here, and its wiring
(every control changes the drawn picture; controls that do nothing are greyed out)."""
import math

import numpy as np
import pytest
from scipy.interpolate import RBFInterpolator, griddata

from course_lib.widgets import scattered as W


def franke(x, y):
    e = np.exp
    return (0.75 * e(-((9 * x - 2) ** 2 + (9 * y - 2) ** 2) / 4)
            + 0.75 * e(-(9 * x + 1) ** 2 / 49 - (9 * y + 1) / 10)
            + 0.5 * e(-((9 * x - 7) ** 2 + (9 * y - 3) ** 2) / 4)
            - 0.2 * e(-(9 * x - 4) ** 2 - (9 * y - 7) ** 2))


AXIS = np.linspace(0, 1, W.GRID)
X, Y = np.meshgrid(AXIS, AXIS)


def test_truth_and_samples():
    s = W.scene(W.State(method="nearest", n_points=40))
    assert np.allclose(s["truth"], franke(X, Y))
    p, f = W.sample_points(40)
    assert np.allclose(f, franke(p[:, 0], p[:, 1]))
    assert np.array_equal(W.sample_points(60)[0][:40], p)        # more points keep the old ones
    assert np.array_equal(s["points"], p)


@pytest.mark.parametrize("method", ["nearest", "linear"])
def test_nearest_and_linear_fields_are_griddatas(method):
    s = W.scene(W.State(method=method, n_points=50))
    p, f = W.sample_points(50)
    ref = griddata(p, f, (X, Y), method=method)
    assert np.allclose(s["field"], ref, equal_nan=True)
    error = ref - franke(X, Y)
    valid = ~np.isnan(error)
    assert math.isclose(s["rms"], float(np.sqrt(np.mean(error[valid] ** 2))), rel_tol=1e-9)
    assert math.isclose(s["max"], float(np.abs(error[valid]).max()), rel_tol=1e-9)
    assert math.isclose(s["coverage"], valid.mean())
    assert (s["coverage"] < 1) == (method == "linear")
    assert (len(s["edges"]) > 0) == (method == "linear")


def test_shepard_field_against_the_formula():
    s = W.scene(W.State(method="Shepard", n_points=30, power=3.0))
    p, f = W.sample_points(30)
    for j, i in [(0, 0), (10, 70), (41, 33), (79, 79)]:
        d = np.hypot(p[:, 0] - AXIS[i], p[:, 1] - AXIS[j])
        w = d ** -3.0
        assert math.isclose(s["field"][j, i], np.sum(w * f) / np.sum(w), rel_tol=1e-10)


@pytest.mark.parametrize("kernel, name, eps, degree", [
    ("Gaussian", "gaussian", 6.0, -1), ("multiquadric", "multiquadric", 3.0, -1),
    ("inverse multiquadric", "inverse_multiquadric", 4.0, -1),
    ("thin-plate spline", "thin_plate_spline", 1.0, 1),
])
def test_rbf_field_against_scipy(kernel, name, eps, degree):
    s = W.scene(W.State(method="RBF", n_points=40, kernel=kernel, epsilon=eps))
    p, f = W.sample_points(40)
    ref = RBFInterpolator(p, f, kernel=name, epsilon=eps, degree=degree)(
        np.column_stack([X.ravel(), Y.ravel()])).reshape(X.shape)
    assert np.allclose(s["field"], ref, atol=1e-7)
    assert s["solved"] and np.allclose(s["error"], s["field"] - franke(X, Y))


def test_unsolvable_rbf_is_reported_not_raised():
    s = W.scene(W.State(method="RBF", n_points=200, kernel="Gaussian", epsilon=0.5))
    assert not s["solved"] and np.isnan(s["field"]).all()
    assert "ill-conditioned" in s["text"] and "no solution" in s["title"]
    with pytest.raises(ValueError, match="method"):
        W.scene(W.State(method="kriging"))


def test_more_points_reduce_the_error():
    errors = [W.scene(W.State(method="linear", n_points=n))["rms"] for n in (20, 80, 200)]
    assert errors[0] > errors[1] > errors[2]


def _image(ex):
    return np.array(ex.image.get_array().filled(np.nan))


def test_every_control_changes_the_picture():
    ex = W.ScatteredDataExplorer()
    assert not ex.power.disabled and ex.kernel.disabled and ex.epsilon.disabled
    first = _image(ex)
    ex.power.value = 6.0
    assert not np.allclose(_image(ex), first, equal_nan=True)
    ex.power.value = 2.0
    assert np.allclose(_image(ex), first, equal_nan=True)          # moved back: the same
    ex.n_points.value = 120
    assert len(ex.samples.get_offsets()) == 120
    assert not np.allclose(_image(ex), first, equal_nan=True)
    before = _image(ex)
    ex.method.value = "RBF"
    assert ex.power.disabled and not ex.kernel.disabled and not ex.epsilon.disabled
    rbf = _image(ex)
    assert not np.allclose(rbf, before, equal_nan=True)
    ex.epsilon.value = 8.0
    assert not np.allclose(_image(ex), rbf, equal_nan=True)
    ex.kernel.value = "thin-plate spline"
    assert ex.epsilon.disabled
    tps = _image(ex)
    ex.kernel.value = "multiquadric"
    assert not np.allclose(_image(ex), tps, equal_nan=True)
    ex.method.value = "linear"
    assert np.isnan(_image(ex)).any() and len(ex.edges.get_segments()) > 0
    assert ex.kernel.disabled and ex.power.disabled
    ex.method.value = "nearest"
    assert len(ex.edges.get_segments()) == 0
    s = W.scene(ex.state)
    assert np.allclose(_image(ex), s["field"]) and "RMS" in ex.info.value
    assert ex.error_title.get_text().startswith("error: RMS")
